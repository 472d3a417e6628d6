#include <visfeat/core/band/triangle_cells.h>
#include <visfeat/core/common/error.h>
#include <visfeat/core/common/threads.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <utility>

namespace visfeat {

namespace {

/** Triangles with an edge longer than this (cells) are split in four before they are
 * scanned: the scan then costs about the area, not the box (a long sliver across a
 * face would otherwise scan a square of its length). */
constexpr double kMaxScannedEdge = 32.0;

/** Deepest split (an edge of 4 * 2^24 cells is far beyond kMaxResolution). */
constexpr int kMaxSplitDepth = 24;

/** A column scan needs the normal's largest axis to carry at least this share of it
 * (it always carries 1/sqrt(3); below, the triangle is degenerate). */
constexpr double kMinColumnNormal = 0.5;

/** Cells a column's plane range is widened by on each side, against rounding. */
constexpr double kColumnSlack = 1e-6;

/** Pieces per chunk of the parallel rasterisation. */
constexpr std::size_t kPiecesPerChunk = 64;

/** Slack of the closed box for the edge and plane axes of the separating-axis test
 * (cells): rounding never separates a triangle that touches a cell. */
constexpr double kBoxSlack = 1e-9;

/** Whether the projections p of the triangle on an axis miss [-r, r]. */
bool
separated(double p0, double p1, double p2, double r)
{
  return std::min({p0, p1, p2}) > r || std::max({p0, p1, p2}) < -r;
}

/** A triangle to scan, in cell units. */
struct Piece
{
  Eigen::Vector3d a, b, c;
};

/** Splits the triangle in four until its edges are at most kMaxScannedEdge cells. */
void
splitTriangle(const Eigen::Vector3d& a,
              const Eigen::Vector3d& b,
              const Eigen::Vector3d& c,
              std::vector<Piece>& out,
              int depth = 0)
{
  const double longest =
    std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
  if (longest <= kMaxScannedEdge * kMaxScannedEdge || depth >= kMaxSplitDepth) {
    out.push_back({a, b, c});
    return;
  }
  const Eigen::Vector3d ab = 0.5 * (a + b), bc = 0.5 * (b + c), ca = 0.5 * (c + a);
  splitTriangle(a, ab, ca, out, depth + 1);
  splitTriangle(ab, b, bc, out, depth + 1);
  splitTriangle(ca, bc, c, out, depth + 1);
  splitTriangle(ab, bc, ca, out, depth + 1);
}

/** Whether 2D point p lies in the closed triangle (a, b, c), given twice its signed
 * area. */
bool
inside2d(const Eigen::Vector2d& p,
         const Eigen::Vector2d& a,
         const Eigen::Vector2d& b,
         const Eigen::Vector2d& c,
         double area2)
{
  auto cross = [](const Eigen::Vector2d& o, const Eigen::Vector2d& x,
                  const Eigen::Vector2d& y) {
    return (x - o).x() * (y - o).y() - (x - o).y() * (y - o).x();
  };
  const double s = area2 > 0.0 ? 1.0 : -1.0;
  return s * cross(a, b, p) > 0.0 && s * cross(b, c, p) > 0.0 &&
         s * cross(c, a, p) > 0.0;
}

/** The cells of one piece. Columns run along the normal's largest axis w: over cell
 * (u, v) the plane spans w in [w_min, w_max]. A column whose square lies strictly
 * inside the triangle's projection meets the triangle exactly where it meets the plane
 * (cells floor(w_min) .. floor(w_max), the half-open rule of triangleTouchesCell); the
 * other columns test their cells in that range. A degenerate piece tests its box. */
void
scanPiece(const Piece& piece, const Eigen::Vector3i& dims, std::vector<CellCoord>& out)
{
  const Eigen::Vector3d &a = piece.a, &b = piece.b, &c = piece.c;
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
  const Eigen::Vector3d n = (b - a).cross(c - a);
  int w = 0;
  n.cwiseAbs().maxCoeff(&w);
  const int u = (w + 1) % 3, v = (w + 2) % 3;
  const bool flat = n.norm() > 0.0 && std::abs(n[w]) > kMinColumnNormal * n.norm();
  const double d = n.dot(a);
  const Eigen::Vector2d a2(a[u], a[v]), b2(b[u], b[v]), c2(c[u], c[v]);
  const double area2 = (b2 - a2).x() * (c2 - a2).y() - (b2 - a2).y() * (c2 - a2).x();
  CellCoord cell;
  for (int i = first[u]; i <= last[u]; ++i)
    for (int j = first[v]; j <= last[v]; ++j) {
      int w0 = first[w], w1 = last[w];
      bool interior = false;
      if (flat) {
        double w_min = std::numeric_limits<double>::infinity(), w_max = -w_min;
        interior = true;
        for (int corner = 0; corner < 4; ++corner) {
          const double cu = i + (corner & 1), cv = j + (corner >> 1);
          const double at = (d - n[u] * cu - n[v] * cv) / n[w];
          w_min = std::min(w_min, at);
          w_max = std::max(w_max, at);
          interior = interior && inside2d(Eigen::Vector2d(cu, cv), a2, b2, c2, area2);
        }
        if (interior) {
          w0 = std::max(w0, static_cast<int>(std::floor(w_min)));
          w1 = std::min(w1, static_cast<int>(std::floor(w_max)));
        } else {
          w0 = std::max(w0, static_cast<int>(std::floor(w_min - kColumnSlack)));
          w1 = std::min(w1, static_cast<int>(std::floor(w_max + kColumnSlack)));
        }
      }
      cell[u] = i;
      cell[v] = j;
      for (int k = w0; k <= w1; ++k) {
        cell[w] = k;
        if (interior || triangleTouchesCell(a, b, c, cell))
          out.push_back(cell);
      }
    }
}

} // namespace

bool
triangleTouchesCell(const Eigen::Vector3d& a,
                    const Eigen::Vector3d& b,
                    const Eigen::Vector3d& c,
                    const CellCoord& cell)
{
  // the box's axes, half-open and exact: the cell holds [i, i + 1) on each axis
  for (int k = 0; k < 3; ++k) {
    const double lo = cell[k], hi = cell[k] + 1.0;
    if (std::max({a[k], b[k], c[k]}) < lo || std::min({a[k], b[k], c[k]}) >= hi)
      return false;
  }
  // the other axes on the closed box, widened by kBoxSlack against rounding
  const double h = 0.5 + kBoxSlack;
  const Eigen::Vector3d centre = cell.cast<double>() + Eigen::Vector3d::Constant(0.5);
  const Eigen::Vector3d v0 = a - centre, v1 = b - centre, v2 = c - centre;
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
  std::vector<Piece> pieces;
  splitTriangle(a, b, c, pieces);
  for (const Piece& piece : pieces)
    scanPiece(piece, dims, out);
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

  // Pieces of at most kMaxScannedEdge cells, so that threads share big triangles too.
  std::vector<Piece> pieces;
  for (const TriangleIndices& tri : triangles)
    splitTriangle(local[tri[0]], local[tri[1]], local[tri[2]], pieces);
  const std::size_t chunks = (pieces.size() + kPiecesPerChunk - 1) / kPiecesPerChunk;
  std::vector<std::vector<std::uint64_t>> keys(chunks);
  parallelFor(chunks, threads, 1, [&](std::size_t first, std::size_t last) {
    std::vector<CellCoord> cells;
    for (std::size_t k = first; k < last; ++k) {
      cells.clear();
      const std::size_t end = std::min(pieces.size(), (k + 1) * kPiecesPerChunk);
      for (std::size_t p = k * kPiecesPerChunk; p < end; ++p)
        scanPiece(pieces[p], grid.dims, cells);
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
  return cellsOfKeys(grid, std::move(all));
}

std::vector<CellCoord>
cellsOfKeys(const GridSpec& grid, std::vector<std::uint64_t> keys)
{
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  std::vector<CellCoord> out(keys.size());
  for (std::size_t i = 0; i < keys.size(); ++i)
    out[i] = grid.cellOfKey(keys[i]);
  return out;
}

} // namespace visfeat
