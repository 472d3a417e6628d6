// Step 5 of FeatureSegmentation (complete regions): which vertex ends which edge, and
// vertices that hold two corners split in two.

#include "segmentation_steps.h"

#include <algorithm>

namespace visfeat {
namespace segmentation {
namespace {

/** A straight edge whose core stops more than vertex_reach short of its corner links
 * the vertex ahead on its line within this many times vertex_reach... */
constexpr double kAheadReach = 2.0;
/** ... whose core cell lies within this slope of the line (about 11 degrees; at least
 * kStraightTolerance cells). Both set on the icosahedron at sigma 0.32 (256, 3
 * rotations), whose shallow creases lost their ridge for up to ~40 cells and left
 * vertices with 4 of their 5 edges; not swept. */
constexpr double kAheadSlope = 0.2;

/** An edge whose two ends link to the same vertex marks two merged corners when the
 * ends lie more than this fraction of vertex_reach apart (nearer ends are one blob at
 * one corner). Set on the U prism (seed 3, sigma 0.22, 256: 15 vertices for 16 before
 * the split); not swept. */
constexpr double kMergedCornerSpan = 0.5;

/** Vertex regions touching edge regions (face-adjacent cells). */
void
touchingPairs(ThinningState& state)
{
  for (std::size_t c = 0; c < state.band.size(); ++c) {
    const std::uint32_t l = state.labels[c];
    if (l == 0 || state.cls[l] != FeatureClass::kVertex)
      continue;
    for (const CellId nb : state.band.neighbours(static_cast<CellId>(c))) {
      if (nb == kNoCell)
        continue;
      const std::uint32_t m = state.labels[static_cast<std::size_t>(nb)];
      if (m != 0 && state.cls[m] == FeatureClass::kEdge)
        state.pairs.emplace(l, m);
    }
  }
}

/** The vertex whose core cell is nearest to `end`, within vertex_reach cells (the
 * last of equals); 0 if none. */
std::uint32_t
nearestVertex(const ThinningState& state, CellId end)
{
  std::uint32_t best = 0;
  double nearest_distance = static_cast<double>(state.parameters.vertex_reach);
  for (const auto& [vertex, vertex_cells] : state.vertex_cores)
    for (const CellId c : vertex_cells)
      if (const double d = state.distance(end, c); d <= nearest_distance) {
        nearest_distance = d;
        best = vertex;
      }
  return best;
}

/** A straight edge whose core stops more than vertex_reach short of its corner (a
 * shallow crease under noise): the vertex nearest ahead of that end on its line,
 * within kAheadReach * vertex_reach; 0 if none. */
std::uint32_t
vertexAhead(const ThinningState& state, std::uint32_t edge, CellId end)
{
  const CoreLine& line = state.core_line.at(edge);
  if (!line.straight())
    return 0;
  const Eigen::Vector3d from = state.band.coord(end).cast<double>();
  const Eigen::Vector3d out =
    (from - line.point).dot(line.direction) >= 0.0 ? line.direction : -line.direction;
  std::uint32_t best = 0;
  double best_along = kAheadReach * static_cast<double>(state.parameters.vertex_reach);
  for (const auto& [vertex, vertex_cells] : state.vertex_cores)
    for (const CellId c : vertex_cells) {
      const Eigen::Vector3d d = state.band.coord(c).cast<double>() - from;
      const double along = d.dot(out);
      if (along > 0.0 && along <= best_along &&
          (d - along * out).norm() <=
            std::max(kStraightTolerance, kAheadSlope * along)) {
        best_along = along;
        best = vertex;
      }
    }
  return best;
}

/** Cell c lies on b's side of the plane halfway between a and b (strictly nearer to
 * b; cell index units). */
bool
onFarSide(const VoxelBand& band,
          CellId c,
          const Eigen::Vector3d& a,
          const Eigen::Vector3d& b)
{
  const Eigen::Vector3d x = band.coord(c).cast<double>();
  return (x - b).squaredNorm() < (x - a).squaredNorm();
}

/** Moves the cells of `vertex` on b's side (onFarSide) to `other`, now a vertex of
 * its own. */
void
moveFarSide(ThinningState& state,
            std::uint32_t vertex,
            std::uint32_t other,
            const Eigen::Vector3d& a,
            const Eigen::Vector3d& b)
{
  auto farSide = [&](CellId c) { return onFarSide(state.band, c, a, b); };
  for (std::size_t c = 0; c < state.band.size(); ++c)
    if (state.labels[c] == vertex && farSide(static_cast<CellId>(c)))
      state.labels[c] = other;
  state.cls[other] = FeatureClass::kVertex;
  std::vector<CellId>& cells = state.vertex_cores.at(vertex);
  std::vector<CellId> stay;
  for (const CellId c : cells)
    (farSide(c) ? state.vertex_cores[other] : stay).push_back(c);
  cells = stay;
}

} // namespace

void
findVertexEdgePairs(ThinningState& state)
{
  state.pairs.clear();
  state.ends.clear();
  touchingPairs(state);
  for (const auto& [edge, cells] : state.edge_cores) {
    EdgeEnds& e = state.ends[edge];
    e.cell[0] = state.farthestFrom(cells.front(), cells);
    e.cell[1] = state.farthestFrom(e.cell[0], cells);
    for (int k = 0; k < 2; ++k) {
      e.vertex[k] = nearestVertex(state, e.cell[k]);
      if (e.vertex[k] == 0)
        e.vertex[k] = vertexAhead(state, edge, e.cell[k]);
      if (e.vertex[k] != 0)
        state.pairs.emplace(e.vertex[k], edge);
    }
  }
}

bool
splitMergedCorners(ThinningState& state)
{
  const double span =
    kMergedCornerSpan * static_cast<double>(state.parameters.vertex_reach);
  bool split = false;
  for (const auto& [edge, e] : state.ends) {
    const std::uint32_t vertex = e.vertex[0];
    if (vertex == 0 || e.vertex[1] != vertex ||
        state.distance(e.cell[0], e.cell[1]) <= span)
      continue;
    // Across the middle of the edge: the far side is nearer to its end b.
    const Eigen::Vector3d a = state.band.coord(e.cell[0]).cast<double>();
    const Eigen::Vector3d b = state.band.coord(e.cell[1]).cast<double>();
    auto farSide = [&](CellId c) { return onFarSide(state.band, c, a, b); };
    // The far half takes the smallest label of its own cores.
    std::uint32_t other = 0;
    bool near_side = false;
    for (const CellId c : state.vertex_cores.at(vertex)) {
      const std::uint32_t core = state.core_of[static_cast<std::size_t>(c)];
      if (farSide(c) && core != vertex && (other == 0 || core < other))
        other = core;
      near_side = near_side || !farSide(c);
    }
    if (other == 0 || !near_side)
      continue;
    moveFarSide(state, vertex, other, a, b);
    split = true;
  }
  return split;
}

} // namespace segmentation
} // namespace visfeat
