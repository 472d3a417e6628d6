#include <visfeat/core/band/triangle_cells.h>
#include <visfeat/core/common/error.h>
#include <visfeat/core/common/threads.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace visfeat {

namespace {

/** Triangles with an edge longer than this (cells) are split in four before their
 * bounding box is scanned: the scan then costs about the area, not the box (a long
 * sliver across a face would otherwise scan a square of its length). */
constexpr double kMaxScannedEdge = 4.0;

/** Deepest split (an edge of 4 * 2^24 cells is far beyond kMaxResolution). */
constexpr int kMaxSplitDepth = 24;

/** Triangles per chunk of the parallel rasterisation. */
constexpr std::size_t kTrianglesPerChunk = 256;

/** Whether the projections p of the triangle on an axis miss [-r, r]. */
bool
separated(double p0, double p1, double p2, double r)
{
  return std::min({p0, p1, p2}) > r || std::max({p0, p1, p2}) < -r;
}

void
scanTriangle(const Eigen::Vector3d& a,
             const Eigen::Vector3d& b,
             const Eigen::Vector3d& c,
             const Eigen::Vector3i& dims,
             std::vector<CellCoord>& out,
             int depth)
{
  const double longest =
    std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
  if (longest > kMaxScannedEdge * kMaxScannedEdge && depth < kMaxSplitDepth) {
    const Eigen::Vector3d ab = 0.5 * (a + b), bc = 0.5 * (b + c), ca = 0.5 * (c + a);
    scanTriangle(a, ab, ca, dims, out, depth + 1);
    scanTriangle(ab, b, bc, dims, out, depth + 1);
    scanTriangle(ca, bc, c, dims, out, depth + 1);
    scanTriangle(ab, bc, ca, dims, out, depth + 1);
    return;
  }
  const Eigen::Vector3d lo = a.cwiseMin(b).cwiseMin(c);
  const Eigen::Vector3d hi = a.cwiseMax(b).cwiseMax(c);
  CellCoord first, last;
  for (int k = 0; k < 3; ++k) {
    first[k] = static_cast<int>(std::max(0.0, std::floor(lo[k])));
    last[k] =
      static_cast<int>(std::min(static_cast<double>(dims[k] - 1), std::floor(hi[k])));
    if (first[k] > last[k])
      return;
  }
  for (int z = first.z(); z <= last.z(); ++z)
    for (int y = first.y(); y <= last.y(); ++y)
      for (int x = first.x(); x <= last.x(); ++x) {
        const CellCoord cell(x, y, z);
        if (triangleTouchesCell(a, b, c, cell))
          out.push_back(cell);
      }
}

} // namespace

bool
triangleTouchesCell(const Eigen::Vector3d& a,
                    const Eigen::Vector3d& b,
                    const Eigen::Vector3d& c,
                    const CellCoord& cell)
{
  const double h = 0.5 * (1.0 - kUpperFaceInset);
  const Eigen::Vector3d centre = cell.cast<double>() + Eigen::Vector3d::Constant(h);
  const Eigen::Vector3d v0 = a - centre, v1 = b - centre, v2 = c - centre;
  // the box's axes
  for (int k = 0; k < 3; ++k)
    if (separated(v0[k], v1[k], v2[k], h))
      return false;
  // the 9 cross products of the triangle's edges with the box's axes
  const Eigen::Vector3d edges[3] = {v1 - v0, v2 - v1, v0 - v2};
  for (const Eigen::Vector3d& e : edges)
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d axis = Eigen::Vector3d::Unit(k).cross(e);
      const double r = h * axis.cwiseAbs().sum();
      if (separated(axis.dot(v0), axis.dot(v1), axis.dot(v2), r))
        return false;
    }
  // the triangle's plane (a zero normal, a degenerate triangle, separates nothing)
  const Eigen::Vector3d n = edges[0].cross(edges[1]);
  const double r = h * n.cwiseAbs().sum();
  const double d = n.dot(v0);
  return !(d > r || d < -r);
}

void
appendTriangleCells(const Eigen::Vector3d& a,
                    const Eigen::Vector3d& b,
                    const Eigen::Vector3d& c,
                    const Eigen::Vector3i& dims,
                    std::vector<CellCoord>& out)
{
  scanTriangle(a, b, c, dims, out, 0);
}

std::vector<CellCoord>
rasterizeTriangles(const GridSpec& grid,
                   const std::vector<Eigen::Vector3d>& vertices,
                   const std::vector<TriangleIndices>& triangles,
                   int threads)
{
  for (std::size_t v = 0; v < vertices.size(); ++v)
    if (!vertices[v].allFinite()) {
      std::ostringstream msg;
      msg << "vertex " << v << " has a NaN or infinite coordinate";
      throw Error(msg.str());
    }
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (const std::uint32_t i : triangles[t])
      if (i >= vertices.size()) {
        std::ostringstream msg;
        msg << "triangle " << t << " refers to vertex " << i << " of "
            << vertices.size();
        throw Error(msg.str());
      }
  std::vector<Eigen::Vector3d> local(vertices.size());
  for (std::size_t v = 0; v < vertices.size(); ++v)
    local[v] = grid.toCellUnits(vertices[v]);

  const std::size_t chunks =
    (triangles.size() + kTrianglesPerChunk - 1) / kTrianglesPerChunk;
  std::vector<std::vector<std::uint64_t>> keys(chunks);
  parallelFor(chunks, threads, 1, [&](std::size_t first, std::size_t last) {
    std::vector<CellCoord> cells;
    for (std::size_t k = first; k < last; ++k) {
      cells.clear();
      const std::size_t end = std::min(triangles.size(), (k + 1) * kTrianglesPerChunk);
      for (std::size_t t = k * kTrianglesPerChunk; t < end; ++t) {
        const TriangleIndices& tri = triangles[t];
        scanTriangle(local[tri[0]], local[tri[1]], local[tri[2]], grid.dims, cells, 0);
      }
      std::vector<std::uint64_t>& chunk = keys[k];
      chunk.reserve(cells.size());
      for (const CellCoord& cell : cells)
        chunk.push_back(grid.linearKey(cell));
      std::sort(chunk.begin(), chunk.end());
      chunk.erase(std::unique(chunk.begin(), chunk.end()), chunk.end());
    }
  });
  std::vector<std::uint64_t> all;
  for (std::vector<std::uint64_t>& chunk : keys) {
    all.insert(all.end(), chunk.begin(), chunk.end());
    chunk = {};
  }
  std::sort(all.begin(), all.end());
  all.erase(std::unique(all.begin(), all.end()), all.end());
  std::vector<CellCoord> out(all.size());
  const auto nx = static_cast<std::uint64_t>(grid.dims.x());
  const auto ny = static_cast<std::uint64_t>(grid.dims.y());
  for (std::size_t i = 0; i < all.size(); ++i) {
    const std::uint64_t key = all[i];
    out[i] = CellCoord(static_cast<int>(key % nx), static_cast<int>((key / nx) % ny),
                       static_cast<int>(key / (nx * ny)));
  }
  return out;
}

} // namespace visfeat
