#include <visfeat/core/band/crease_fill.h>
#include <visfeat/core/common/error.h>
#include <visfeat/core/common/threads.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace visfeat {

namespace {

constexpr double kPi = 3.14159265358979323846;

/** Neighbours of the first plane fit (nearest first). */
constexpr std::size_t kPlaneNeighbours = 8;

/** The refit keeps the neighbours closer to the first plane than this share of the
 * farthest one's distance: across a crease the neighbours of the other face are the
 * far ones. */
constexpr double kPlaneInlierShare = 0.5;

/** Sample step along a crease triangle (cells): several samples a cell, so every cell
 * the rebuilt faces cross receives one. */
constexpr double kCreaseSampleCells = 0.3;

/** Points and triangles per chunk of the parallel loops. */
constexpr std::size_t kPerChunk = 512;

Eigen::Vector3d
planeNormal(const Eigen::Vector3d& p, const std::vector<Eigen::Vector3d>& others)
{
  Eigen::Vector3d mean = p;
  for (const Eigen::Vector3d& q : others)
    mean += q;
  mean /= static_cast<double>(others.size() + 1);
  Eigen::Matrix3d cov = (p - mean) * (p - mean).transpose();
  for (const Eigen::Vector3d& q : others)
    cov += (q - mean) * (q - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(cov);
  return solver.eigenvectors().col(0).normalized();
}

} // namespace

std::vector<Eigen::Vector3d>
tangentNormals(const std::vector<Eigen::Vector3d>& points,
               const std::vector<std::uint32_t>& neighbours,
               int k,
               int threads)
{
  if (k < 0 || neighbours.size() != points.size() * static_cast<std::size_t>(k))
    throw Error("tangentNormals: the neighbour table does not match the points");
  std::vector<Eigen::Vector3d> normals(points.size(), Eigen::Vector3d::Zero());
  parallelFor(
    points.size(), threads, kPerChunk, [&](std::size_t begin, std::size_t end) {
      std::vector<Eigen::Vector3d> near;
      for (std::size_t i = begin; i < end; ++i) {
        const Eigen::Vector3d& p = points[i];
        if (!p.allFinite())
          continue;
        near.clear();
        for (int j = 0; j < k && near.size() < kPlaneNeighbours; ++j) {
          const std::uint32_t q = neighbours[i * static_cast<std::size_t>(k) + j];
          if (q < points.size() && q != i && points[q].allFinite() && points[q] != p)
            near.push_back(points[q]);
        }
        if (near.size() < 2)
          continue;
        Eigen::Vector3d n = planeNormal(p, near);
        double far = 0.0;
        for (const Eigen::Vector3d& q : near)
          far = std::max(far, std::abs(n.dot(q - p)));
        std::vector<Eigen::Vector3d> inliers;
        for (const Eigen::Vector3d& q : near)
          if (std::abs(n.dot(q - p)) <= kPlaneInlierShare * far)
            inliers.push_back(q);
        if (inliers.size() >= 3 && inliers.size() < near.size())
          n = planeNormal(p, inliers);
        normals[i] = n;
      }
    });
  return normals;
}

std::vector<CellCoord>
creaseFillCells(const GridSpec& grid,
                const std::vector<Eigen::Vector3d>& points,
                const std::vector<Eigen::Vector3d>& normals,
                const std::vector<TriangleIndices>& triangles,
                double crease_degrees,
                int threads)
{
  if (normals.size() != points.size())
    throw Error("creaseFillCells: one normal per point is needed");
  const double agree = std::cos(std::min(crease_degrees, 180.0) * kPi / 180.0);
  auto isCrease = [&](const TriangleIndices& t) {
    for (int a = 0; a < 3; ++a)
      for (int b = a + 1; b < 3; ++b) {
        const Eigen::Vector3d& na = normals[t[static_cast<std::size_t>(a)]];
        const Eigen::Vector3d& nb = normals[t[static_cast<std::size_t>(b)]];
        if (na.squaredNorm() > 0.0 && nb.squaredNorm() > 0.0 &&
            std::abs(na.dot(nb)) < agree)
          return true;
      }
    return false;
  };
  std::vector<TriangleIndices> flat, crease;
  for (const TriangleIndices& t : triangles) {
    for (const std::uint32_t i : t)
      if (i >= points.size())
        throw Error(
          "creaseFillCells: a triangle refers to a point that does not exist");
    (isCrease(t) ? crease : flat).push_back(t);
  }
  std::vector<CellCoord> cells = rasterizeTriangles(grid, points, flat, threads);

  // crease triangles: samples moved onto the nearest corner plane
  std::vector<std::vector<std::uint64_t>> keys((crease.size() + kPerChunk - 1) /
                                               kPerChunk);
  parallelFor(keys.size(), threads, 1, [&](std::size_t first, std::size_t last) {
    for (std::size_t c = first; c < last; ++c) {
      const std::size_t end = std::min(crease.size(), (c + 1) * kPerChunk);
      for (std::size_t t = c * kPerChunk; t < end; ++t) {
        const TriangleIndices& tri = crease[t];
        const Eigen::Vector3d& a = points[tri[0]];
        const Eigen::Vector3d& b = points[tri[1]];
        const Eigen::Vector3d& d = points[tri[2]];
        const double longest =
          std::max({(b - a).norm(), (d - b).norm(), (a - d).norm()}) / grid.cell_size;
        const int n =
          std::max(1, static_cast<int>(std::ceil(longest / kCreaseSampleCells)));
        for (int i = 0; i <= n; ++i)
          for (int j = 0; i + j <= n; ++j) {
            const double u = double(i) / n, v = double(j) / n;
            const Eigen::Vector3d x = a + u * (b - a) + v * (d - a);
            double best = std::numeric_limits<double>::infinity();
            Eigen::Vector3d moved = x;
            for (const std::uint32_t corner : tri) {
              const Eigen::Vector3d& normal = normals[corner];
              if (normal.squaredNorm() == 0.0)
                continue;
              const double off = normal.dot(x - points[corner]);
              if (std::abs(off) < best) {
                best = std::abs(off);
                moved = x - off * normal;
              }
            }
            const CellCoord cell = grid.cellOf(moved);
            if (grid.contains(cell))
              keys[c].push_back(grid.linearKey(cell));
          }
      }
      std::sort(keys[c].begin(), keys[c].end());
      keys[c].erase(std::unique(keys[c].begin(), keys[c].end()), keys[c].end());
    }
  });
  std::vector<std::uint64_t> all;
  all.reserve(cells.size());
  for (const CellCoord& cell : cells)
    all.push_back(grid.linearKey(cell));
  for (std::vector<std::uint64_t>& chunk : keys)
    all.insert(all.end(), chunk.begin(), chunk.end());
  return cellsOfKeys(grid, std::move(all));
}

} // namespace visfeat
