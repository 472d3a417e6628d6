#include "../common/angles.h"
#include <visfeat/core/band/crease_fill.h>
#include <visfeat/core/common/error.h>
#include <visfeat/core/common/threads.h>

#include <Eigen/Geometry>
#include <Eigen/LU>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

namespace visfeat {

namespace {

/** Sample step along a crease triangle (cells): several samples a cell, so every cell
 * the rebuilt faces cross receives one. */
constexpr double kCreaseSampleCells = 0.3;

/** Points and triangles per chunk of the parallel loops. */
constexpr std::size_t kPerChunk = 512;

/** A lift longer than this share of the triangle's longest side means the corner planes
 * do not describe one crease (nearly parallel planes, a wrong normal): the sample falls
 * back to the nearest plane. */
constexpr double kMaxLiftShare = 1.0;

/** Below this cosine between an edge of the triangle and a corner's plane, the other
 * corner lies too close to that plane to tell which side of the crease is solid. */
constexpr double kMinSideCosine = 0.05;

/** The corner planes of one crease triangle as a wedge: each plane oriented so that the
 * triangle's corners off it lie on its negative side, so the chord lies inside the
 * wedge (both sides of a convex crease or both of a concave one alike) and the surface
 * is the wedge's boundary. */
struct CreaseWedge
{
  std::array<Eigen::Vector3d, 3> normal{
    Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  std::array<Eigen::Vector3d, 3> origin{
    Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  int planes = 0;
  Eigen::Vector3d out = Eigen::Vector3d::Zero(); ///< unit, out of the wedge
};

/** The wedge of a triangle's corner planes: the corner pair whose normals differ most,
 * plus the third corner when its plane differs from both by more than `agree` (cosine);
 * planes = 0 when the sides cannot be told apart (see kMinSideCosine). */
CreaseWedge
creaseWedge(const std::vector<TangentPlane>& planes,
            const TriangleIndices& tri,
            double agree)
{
  auto normalOf = [&](int corner) -> const Eigen::Vector3d& {
    return planes[tri[std::size_t(corner)]].normal;
  };
  CreaseWedge wedge;
  int a = 0, b = 1;
  double lowest = 2.0;
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j) {
      const Eigen::Vector3d& ni = normalOf(i);
      const Eigen::Vector3d& nj = normalOf(j);
      if (ni.squaredNorm() == 0.0 || nj.squaredNorm() == 0.0)
        continue;
      const double c = std::abs(ni.dot(nj));
      if (c < lowest) {
        lowest = c;
        a = i;
        b = j;
      }
    }
  if (lowest >= agree)
    return wedge;
  const std::array<int, 3> used{a, b, 3 - a - b};
  const Eigen::Vector3d& n3 = normalOf(used[2]);
  const bool third = n3.squaredNorm() > 0.0 && std::abs(n3.dot(normalOf(a))) < agree &&
                     std::abs(n3.dot(normalOf(b))) < agree;
  const int count = third ? 3 : 2;
  for (int p = 0; p < count; ++p) {
    const TangentPlane& plane = planes[tri[std::size_t(used[std::size_t(p)])]];
    const Eigen::Vector3d& n = plane.normal;
    const Eigen::Vector3d& o = plane.point;
    int sign = 0;
    for (int q = 0; q < count; ++q) {
      if (q == p)
        continue;
      const Eigen::Vector3d d =
        planes[tri[std::size_t(used[std::size_t(q)])]].point - o;
      const double side = n.dot(d);
      if (std::abs(side) < kMinSideCosine * d.norm())
        return CreaseWedge{};
      const int s = side < 0.0 ? 1 : -1;
      if (sign != 0 && s != sign)
        return CreaseWedge{}; // a saddle: no wedge holds the chord
      sign = s;
    }
    wedge.normal[std::size_t(p)] = double(sign) * n;
    wedge.origin[std::size_t(p)] = o;
    wedge.out += wedge.normal[std::size_t(p)];
  }
  if (wedge.out.norm() < 1e-6)
    return CreaseWedge{};
  wedge.out.normalize();
  for (int p = 0; p < count; ++p)
    if (wedge.normal[std::size_t(p)].dot(wedge.out) < kMinSideCosine)
      return CreaseWedge{};
  wedge.planes = count;
  return wedge;
}

/** How far x moves along wedge.out to reach the wedge's boundary: the first plane it
 * crosses (the boundary of the intersection of the negative half-spaces). */
double
liftOntoWedge(const CreaseWedge& wedge, const Eigen::Vector3d& x)
{
  double t = std::numeric_limits<double>::infinity();
  for (int p = 0; p < wedge.planes; ++p) {
    const Eigen::Vector3d& n = wedge.normal[std::size_t(p)];
    t = std::min(t, -n.dot(x - wedge.origin[std::size_t(p)]) / n.dot(wedge.out));
  }
  return t;
}

} // namespace

std::vector<CellCoord>
creaseFillCells(const GridSpec& grid,
                const std::vector<Eigen::Vector3d>& points,
                const std::vector<TangentPlane>& planes,
                const std::vector<TriangleIndices>& triangles,
                double crease_degrees,
                int threads)
{
  if (planes.size() != points.size())
    throw Error("creaseFillCells: one tangent plane per point is needed");
  const double agree = detail::cosineOfDegrees(std::min(crease_degrees, 180.0));
  auto isCrease = [&](const TriangleIndices& t) {
    for (int a = 0; a < 3; ++a)
      for (int b = a + 1; b < 3; ++b) {
        const Eigen::Vector3d& na = planes[t[static_cast<std::size_t>(a)]].normal;
        const Eigen::Vector3d& nb = planes[t[static_cast<std::size_t>(b)]].normal;
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

  // crease triangles: samples lifted onto the corners' wedge, else moved onto the
  // nearest corner plane
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
        const CreaseWedge wedge = creaseWedge(planes, tri, agree);
        const double max_lift = kMaxLiftShare * longest * grid.cell_size;
        for (int i = 0; i <= n; ++i)
          for (int j = 0; i + j <= n; ++j) {
            const double u = double(i) / n, v = double(j) / n;
            const Eigen::Vector3d x = a + u * (b - a) + v * (d - a);
            if (wedge.planes > 0) {
              const double t = liftOntoWedge(wedge, x);
              if (std::abs(t) <= max_lift) {
                const CellCoord cell = grid.cellOf(x + t * wedge.out);
                if (grid.contains(cell))
                  keys[c].push_back(grid.linearKey(cell));
                continue;
              }
            }
            double best = std::numeric_limits<double>::infinity();
            Eigen::Vector3d moved = x;
            for (const std::uint32_t corner : tri) {
              const Eigen::Vector3d& normal = planes[corner].normal;
              if (normal.squaredNorm() == 0.0)
                continue;
              const double off = normal.dot(x - planes[corner].point);
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
