// Step 5 of FeatureSegmentation (complete regions): corners from edge lines. Near a
// corner the radius drops below min_radius, so an edge's core stops short of it and a
// vertex's cores are specks at the ends of its edges rather than at the tip. Where a
// vertex has two or more straight edges, its corner is the point nearest to their
// lines, and each edge is drawn from its core's end to that corner.

#include "segmentation_steps.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace visfeat {
namespace segmentation {
namespace {

/** Smallest eigenvalue of sum(I - u u^T) over a corner's edge directions u: 1 -
 * |cos(angle)| for two edges, 0 when they are parallel. Below this (two edges within
 * about 26 degrees of parallel, e.g. a straight run through a speck) the lines give
 * no corner. Set with the corners from edge lines (7 models, 3 rotations at 256, the
 * smallest corner angle 60 degrees); not swept. */
constexpr double kMinCornerConditioning = 0.1;

/** A drawn edge ends at its first core cell (from the corner) with kEdgeEndCells more
 * within kEdgeEndRun cells beyond it along the line: the body of its core, not the
 * stray core cells noise leaves near the corner. Set on the U prism at sigma 0.22
 * (seed 1, 256), where the segment stopped at a stray cell 8 cells short of the edge's
 * body and the edge lost its vertex; not swept. */
constexpr std::size_t kEdgeEndCells = 2;
constexpr double kEdgeEndRun = 3.0;

/** Cells of a drawn edge within this distance (cells) of the corner join the vertex:
 * the corner's cell and its neighbours along each edge. Chosen with the corner
 * drawing (145ed0d), not measured separately. */
constexpr double kCornerCells = 1.5;

/** Free ends of straight edges (linked to no vertex) give a corner of their own when
 * at least this many edges' ends lie within vertex_reach of each other and of their
 * lines' meeting point: a corner whose radius stayed below min_radius everywhere, so
 * that no core (and no vertex candidate) formed there. Three: the generated models'
 * corners join three edges or more, and two ends near each other are as often the two
 * pieces of one crease broken by a narrow face. Found on the U prism (20,000 points,
 * rotation 4004: three edges ended 6-10 cells short of a corner without a region). */
constexpr std::size_t kMinFreeCornerEdges = 3;

/** The meeting point of a corner's edge lines may lie beyond the band: the tip of a
 * sharp corner is cut where the samples stop short of it, up to about a point spacing
 * on the sparsest filled clouds (the fill allows 4 cells a spacing). The corner is
 * then the band cell nearest to it within this many cells (its edges are drawn to
 * that cell). Found on the triangular prism at 10,000 points
 * (seeds 49 and 54, 4 cells a spacing): three free ends 10-17 cells apart met 2.2
 * cells outside the grid, and the corner was lost. */
constexpr int kCornerBeyondBandCells = 4;

/** Shortest segment length divided by, against a segment of length 0. Numeric guard.
 */
constexpr double kMinSegmentLength = 1e-9;

/** Straight here: narrow at any length (unlike joining), with enough core cells. */
bool
isStraightEdge(const ThinningState& state, std::uint32_t edge)
{
  return state.edge_cores.at(edge).size() >= kMinLineCells &&
         state.core_line.at(edge).narrow();
}

/** Per vertex, its straight edges (pairs in order). */
std::map<std::uint32_t, std::vector<std::uint32_t>>
straightEdgesOf(const ThinningState& state)
{
  std::map<std::uint32_t, std::vector<std::uint32_t>> straight_edges_of;
  for (const auto& [vertex, edge] : state.pairs)
    if (state.core_line.count(edge) && isStraightEdge(state, edge))
      straight_edges_of[vertex].push_back(edge);
  return straight_edges_of;
}

/** The point nearest to the lines of straight edges (least squares), in cell index
 * units; none when the lines are nearly parallel. */
std::optional<Eigen::Vector3d>
meetingPoint(const ThinningState& state, const std::vector<std::uint32_t>& edges)
{
  Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  for (const std::uint32_t e : edges) {
    const CoreLine& line = state.core_line.at(e);
    const Eigen::Matrix3d across =
      Eigen::Matrix3d::Identity() - line.direction * line.direction.transpose();
    a += across;
    b += across * line.point;
  }
  if (Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(a).eigenvalues()(0) <
      kMinCornerConditioning)
    return std::nullopt;
  return Eigen::Vector3d(a.ldlt().solve(b));
}

/** The point nearest to the lines of a vertex's straight edges (meetingPoint), or
 * where it lies outside the band the band cell nearest to it within
 * kCornerBeyondBandCells; none when the lines are nearly parallel, when it lies
 * farther than vertex_reach from the vertex's cores, or farther from the band. */
std::optional<Eigen::Vector3d>
cornerOf(const ThinningState& state,
         std::uint32_t vertex,
         const std::vector<std::uint32_t>& edges)
{
  const std::optional<Eigen::Vector3d> meeting = meetingPoint(state, edges);
  if (!meeting)
    return std::nullopt;
  const Eigen::Vector3d corner = *meeting;
  double to_vertex = std::numeric_limits<double>::infinity();
  for (const CellId c : valueOrEmpty(state.vertex_cores, vertex))
    to_vertex =
      std::min(to_vertex, (state.band.coord(c).cast<double>() - corner).norm());
  if (!(to_vertex <= state.parameters.vertex_reach))
    return std::nullopt;
  if (state.nearestCell(corner) != kNoCell)
    return corner;
  // beyond the band (a sharp tip cut short): the band cell nearest to it
  const CellId tip = state.nearestCellWithin(corner, kCornerBeyondBandCells);
  if (tip == kNoCell)
    return std::nullopt;
  return state.band.coord(tip).cast<double>();
}

/** The end of an edge's cores on the corner's side, as a position t along its line:
 * the core cell nearest to the corner with kEdgeEndCells more within kEdgeEndRun
 * beyond it (the nearest core cell if none has). Noise leaves stray core cells between
 * the corner and the edge's body; drawn to one of those, the segment would stop short
 * of the body and leave the edge apart from its vertex. */
double
edgeEndTowards(const ThinningState& state,
               std::uint32_t edge,
               const Eigen::Vector3d& corner)
{
  const CoreLine& line = state.core_line.at(edge);
  const double t_corner = (corner - line.point).dot(line.direction);
  std::vector<std::pair<double, double>> along; // (from the corner, t)
  for (const CellId c : state.edge_cores.at(edge)) {
    const double t =
      (state.band.coord(c).cast<double>() - line.point).dot(line.direction);
    along.emplace_back(std::abs(t - t_corner), t);
  }
  std::sort(along.begin(), along.end());
  for (std::size_t i = 0; i < along.size(); ++i) {
    std::size_t beyond = 0;
    for (std::size_t j = i + 1;
         j < along.size() && along[j].first <= along[i].first + kEdgeEndRun; ++j)
      ++beyond;
    if (beyond >= kEdgeEndCells)
      return along[i].second;
  }
  return along.front().second;
}

/** Draws edge e of `vertex` from the corner to its core's end: the cells the segment
 * passes join the skeleton and the edge (those within kCornerCells of the corner, or
 * on a sibling edge's skeleton where the edges meet, the vertex). Other features'
 * cells stay their own. A cell keeps the nearest centre on a drawn segment. */
void
drawEdgeToCorner(ThinningState& state,
                 std::uint32_t vertex,
                 const std::vector<std::uint32_t>& edges,
                 std::uint32_t e,
                 const Eigen::Vector3d& corner)
{
  const CoreLine& line = state.core_line.at(e);
  const Eigen::Vector3d end =
    line.point + edgeEndTowards(state, e, corner) * line.direction;
  const double length = (end - corner).norm();
  const int steps = std::max(1, static_cast<int>(std::ceil(length * kSamplesPerCell)));
  for (int k = 0; k <= steps; ++k) {
    const Eigen::Vector3d x = corner + (end - corner) * (double(k) / steps);
    const CellId c = state.nearestCell(x);
    if (c == kNoCell)
      continue;
    const auto i = static_cast<std::size_t>(c);
    const std::uint32_t l = state.labels[i];
    const bool sibling =
      std::find(edges.begin(), edges.end(), l) != edges.end() && l != e;
    if (l != vertex && l != e && state.isFeature(l) && !sibling)
      continue; // another feature's cell stays its own
    // Edges of one corner converge: a cell on another edge's skeleton is where they
    // meet, and joins the vertex; the rest of its region yields.
    const bool meeting = sibling && state.skeleton[i];
    const bool first = !state.skeleton[i] || std::isnan(state.centres[i].x());
    state.skeleton[i] = 1;
    state.labels[i] = meeting || (x - corner).norm() <= kCornerCells ? vertex : e;
    const Eigen::Vector3d at = state.band.coord(c).cast<double>();
    if (first || (x - at).norm() < (state.centres[i].cast<double>() -
                                    Eigen::Vector3d::Constant(0.5) - at)
                                     .norm())
      state.setCentre(c, x, (end - corner) / std::max(length, kMinSegmentLength));
  }
}

} // namespace

void
centreStraightEdges(ThinningState& state)
{
  for (const auto& [edge, line] : state.core_line)
    if (isStraightEdge(state, edge))
      for (const CellId c : state.edge_cores.at(edge)) {
        const Eigen::Vector3d d = state.band.coord(c).cast<double>() - line.point;
        state.setCentre(c, line.point + d.dot(line.direction) * line.direction,
                        line.direction);
      }
}

void
cornersAtFreeEnds(ThinningState& state)
{
  struct FreeEnd
  {
    std::uint32_t edge;
    int k;
  };
  std::vector<FreeEnd> free;
  for (const auto& [edge, e] : state.ends)
    for (int k = 0; k < 2; ++k)
      if (e.vertex[static_cast<std::size_t>(k)] == 0 && isStraightEdge(state, edge))
        free.push_back({edge, k});
  if (free.size() < kMinFreeCornerEdges)
    return;
  const auto endCell = [&](const FreeEnd& f) {
    return state.ends.at(f.edge).cell[static_cast<std::size_t>(f.k)];
  };
  // groups of ends of different edges within vertex_reach of one another (union-find)
  const double reach = static_cast<double>(state.parameters.vertex_reach);
  std::vector<std::size_t> root(free.size());
  for (std::size_t i = 0; i < free.size(); ++i)
    root[i] = i;
  const auto find = [&](std::size_t i) {
    while (root[i] != i)
      i = root[i] = root[root[i]];
    return i;
  };
  for (std::size_t i = 0; i < free.size(); ++i)
    for (std::size_t j = i + 1; j < free.size(); ++j)
      if (free[i].edge != free[j].edge &&
          state.distance(endCell(free[i]), endCell(free[j])) <= reach)
        root[find(i)] = find(j);
  for (std::size_t g = 0; g < free.size(); ++g) {
    if (find(g) != g)
      continue;
    std::vector<FreeEnd> ends;
    std::vector<std::uint32_t> edges;
    for (std::size_t i = 0; i < free.size(); ++i)
      if (find(i) == g) {
        ends.push_back(free[i]);
        edges.push_back(free[i].edge);
      }
    std::sort(edges.begin(), edges.end());
    if (edges.size() < kMinFreeCornerEdges ||
        std::adjacent_find(edges.begin(), edges.end()) != edges.end())
      continue; // too few, or both ends of one edge
    const std::optional<Eigen::Vector3d> corner = meetingPoint(state, edges);
    if (!corner)
      continue;
    const CellId at = state.nearestCellWithin(*corner, kCornerBeyondBandCells);
    bool near = at != kNoCell;
    for (const FreeEnd& f : ends)
      near =
        near && (state.band.coord(endCell(f)).cast<double>() - *corner).norm() <= reach;
    if (!near)
      continue;
    // a new label, after the cores' (numberRegions renumbers them all)
    const auto vertex = static_cast<std::uint32_t>(state.cls.size());
    state.cls.push_back(FeatureClass::kVertex);
    state.labels[static_cast<std::size_t>(at)] = vertex;
    state.vertex_cores[vertex] = {at};
    for (const FreeEnd& f : ends) {
      state.ends.at(f.edge).vertex[static_cast<std::size_t>(f.k)] = vertex;
      state.pairs.emplace(vertex, f.edge);
    }
  }
}

void
drawCorners(ThinningState& state)
{
  for (const auto& [vertex, edges] : straightEdgesOf(state)) {
    if (edges.size() < 2)
      continue;
    const std::optional<Eigen::Vector3d> corner = cornerOf(state, vertex, edges);
    if (!corner)
      continue;
    for (const std::uint32_t e : edges) {
      drawEdgeToCorner(state, vertex, edges, e, *corner);
      state.drawn.emplace(vertex, e);
    }
    // The vertex is now its corner: its own cores (specks at the ends of its edges,
    // pieces of faces) leave the skeleton.
    for (const CellId c : valueOrEmpty(state.vertex_cores, vertex))
      if (std::isnan(state.centres[static_cast<std::size_t>(c)].x()))
        state.skeleton[static_cast<std::size_t>(c)] = 0;
  }
}

} // namespace segmentation
} // namespace visfeat
