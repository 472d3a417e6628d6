// Step 4 of FeatureSegmentation: fragments of one edge become one edge, and vertex
// candidates of one corner one vertex.

#include "segmentation_steps.h"

#include <cmath>
#include <iterator>
#include <map>
#include <vector>

namespace visfeat {
namespace segmentation {
namespace {

/** Both labels are edges of the same two faces. */
bool
sameFacePair(const SegmentationState& state, std::uint32_t a, std::uint32_t b)
{
  const auto sa = state.signature.find(a);
  const auto sb = state.signature.find(b);
  return sa != state.signature.end() && sb != state.signature.end() &&
         sa->second == sb->second;
}

/** Some core cell of a lies within join_distance cells of some core cell of b. */
bool
gapWithin(const SegmentationState& state, std::uint32_t a, std::uint32_t b)
{
  const int join = state.parameters.join_distance;
  const int limit = join * join;
  for (const CellId x : state.core_cells[a])
    for (const CellId y : state.core_cells[b])
      if ((state.band.coord(x) - state.band.coord(y)).squaredNorm() <= limit)
        return true;
  return false;
}

/** Per edge label with core cells, the edges of its face pair whose cores lie within
 * join_distance cells of its own and joinSteps() 6-steps through the band (found in
 * edge_reach). */
std::map<std::uint32_t, std::set<std::uint32_t>>
nearbyPiecesOfEdges(const SegmentationState& state)
{
  std::map<std::uint32_t, std::set<std::uint32_t>> edge_reach;
  for (const auto& [l, own] : state.signature) {
    if (state.cls[l] != FeatureClass::kEdge || state.core_cells[l].empty())
      continue;
    std::set<std::uint32_t> near;
    for (const std::uint32_t m : state.edge_reach.at(l))
      if (const auto other = state.signature.find(m); other != state.signature.end() &&
                                                      other->second == own &&
                                                      gapWithin(state, l, m))
        near.insert(m);
    edge_reach[l] = std::move(near);
  }
  return edge_reach;
}

/** Per vertex set (root), the core cells of its vertex candidates. */
std::map<std::uint32_t, std::vector<CellId>>
vertexSetCells(SegmentationState& state)
{
  std::map<std::uint32_t, std::vector<CellId>> cells;
  for (const std::uint32_t l : state.vertices) {
    std::vector<CellId>& into = cells[state.sets.find(l)];
    into.insert(into.end(), state.core_cells[l].begin(), state.core_cells[l].end());
  }
  return cells;
}

/** Some candidate core cell of vertex set a lies within vertex_reach cells of one of
 * set b's (straight distance): the two are parts of one corner. */
bool
candidatesWithinReach(const SegmentationState& state,
                      const std::map<std::uint32_t, std::vector<CellId>>& cells,
                      std::uint32_t a,
                      std::uint32_t b)
{
  const auto ia = cells.find(a), ib = cells.find(b);
  if (ia == cells.end() || ib == cells.end())
    return false;
  const double reach = state.parameters.vertex_reach;
  for (const CellId x : ia->second)
    for (const CellId y : ib->second)
      if ((state.band.coord(x) - state.band.coord(y)).cast<double>().squaredNorm() <=
          reach * reach)
        return true;
  return false;
}

/** Touching sets of one class: edges of the same two faces, or vertices whose
 * candidates lie within vertex_reach of each other. Vertex regions far apart touch
 * where the crease between them broke into specks that merged into both (the
 * icosahedron in its file's orientation, a mirror plane on the grid: two corners 170
 * cells apart, then through the shared edges all 12, joined into 2 vertices); they
 * stay two corners. */
bool
joinTouching(SegmentationState& state, const Contacts& contacts)
{
  bool changed = false;
  const std::map<std::uint32_t, std::vector<CellId>> vertex_cells =
    vertexSetCells(state);
  for (const auto& [pair, count] : contacts) {
    const auto [a, b] = pair;
    if (a > b || state.cls[a] != state.cls[b])
      continue;
    const bool same_edge =
      state.cls[a] == FeatureClass::kEdge && sameFacePair(state, a, b);
    const bool same_corner = state.cls[a] == FeatureClass::kVertex &&
                             candidatesWithinReach(state, vertex_cells, a, b);
    if (same_edge || same_corner) {
      state.sets.join(a, b);
      changed = true;
    }
  }
  return changed;
}

/** Pieces of one edge with something else between them (a speck merged into a face,
 * a vertex, a gap that noise opened): same two faces, near each other. */
bool
joinNearby(SegmentationState& state,
           const std::map<std::uint32_t, std::set<std::uint32_t>>& edge_reach)
{
  bool changed = false;
  for (const auto& [a0, near] : edge_reach)
    for (const std::uint32_t b0 : near) {
      const std::uint32_t a = state.sets.find(a0), b = state.sets.find(b0);
      if (a != b && state.cls[a] == FeatureClass::kEdge &&
          state.cls[b] == FeatureClass::kEdge && sameFacePair(state, a, b)) {
        state.sets.join(a, b);
        changed = true;
      }
    }
  return changed;
}

/** Pieces of one edge that a vertex region sits between: same two faces, both
 * touching the same vertex. (Two faces may meet along several edges, e.g. a
 * half-cylinder on a plane, but those do not share a vertex.) */
bool
joinAcrossVertices(SegmentationState& state, const Contacts& contacts)
{
  std::map<std::uint32_t, std::vector<std::uint32_t>> edges_at;
  for (const auto& [pair, count] : contacts)
    if (state.cls[pair.first] == FeatureClass::kVertex &&
        state.cls[pair.second] == FeatureClass::kEdge)
      edges_at[pair.first].push_back(pair.second);
  bool changed = false;
  for (const auto& [vertex, edges] : edges_at)
    for (std::size_t i = 0; i < edges.size(); ++i)
      for (std::size_t j = i + 1; j < edges.size(); ++j) {
        const std::uint32_t a = state.sets.find(edges[i]),
                            b = state.sets.find(edges[j]);
        if (a != b && sameFacePair(state, a, b)) {
          state.sets.join(a, b);
          changed = true;
        }
      }
  return changed;
}

/** Pieces of one straight edge with a longer gap than join_distance (a shallow crease
 * under noise loses its ridge for tens of cells): same two faces, and the smaller
 * piece on the line of the larger. Two edges of the same two faces are never on one
 * line. Joins the first such pair only. */
bool
joinOnOneLine(SegmentationState& state)
{
  std::map<std::uint32_t, std::vector<CellId>> cells_of;
  for (const auto& [l, own] : state.signature) {
    const std::uint32_t root = state.sets.find(l);
    if (state.cls[root] == FeatureClass::kEdge)
      cells_of[root].insert(cells_of[root].end(), state.core_cells[l].begin(),
                            state.core_cells[l].end());
  }
  std::map<std::uint32_t, CoreLine> line_of;
  for (const auto& [root, cells] : cells_of)
    line_of[root] = fitCoreLine(state.band, cells);
  for (auto a = line_of.begin(); a != line_of.end(); ++a)
    for (auto b = std::next(a); b != line_of.end(); ++b) {
      if (!sameFacePair(state, a->first, b->first))
        continue;
      const bool a_longer = a->second.length >= b->second.length;
      const CoreLine& longer = a_longer ? a->second : b->second;
      const CoreLine& shorter = a_longer ? b->second : a->second;
      if (longer.onLine(shorter)) {
        state.sets.join(a->first, b->first);
        return true;
      }
    }
  return false;
}

} // namespace

std::uint32_t
joinSteps(const SegmentationParameters& parameters)
{
  // A path of 6-steps is up to sqrt(3) times longer than the straight gap it spans
  // (the diagonal of a cube of cells), so the band is searched this many times
  // join_distance steps wide. Geometry, not tuning; before it, an edge at an angle to
  // the grid joined shorter gaps than one along it (triangular prism seed 2 at sigma
  // 0.32, 256: 10 edges for 9).
  const double lattice_path_factor = std::sqrt(3.0);
  return static_cast<std::uint32_t>(
    std::ceil(lattice_path_factor * static_cast<double>(parameters.join_distance)));
}

void
joinEdgeFragments(SegmentationState& state)
{
  const std::map<std::uint32_t, std::set<std::uint32_t>> edge_reach =
    nearbyPiecesOfEdges(state);
  for (bool changed = true; changed;) {
    const Contacts contacts = state.contacts.through(state.sets);
    changed = joinTouching(state, contacts);
    changed = joinNearby(state, edge_reach) || changed;
    changed = joinAcrossVertices(state, contacts) || changed;
    // join_distance 0 turns joining off, this too.
    if (!changed && state.parameters.join_distance > 0)
      changed = joinOnOneLine(state);
  }
}

void
joinCornersSharingEdges(SegmentationState& state)
{
  for (bool changed = true; changed;) {
    changed = false;
    std::map<std::uint32_t, std::set<std::uint32_t>> edges_of;
    for (const std::uint32_t l : state.vertices)
      for (const std::uint32_t m : state.reached.at(l))
        if (state.cls[state.sets.find(m)] == FeatureClass::kEdge)
          edges_of[state.sets.find(l)].insert(state.sets.find(m));
    for (auto a = edges_of.begin(); a != edges_of.end() && !changed; ++a)
      for (auto b = std::next(a); b != edges_of.end() && !changed; ++b) {
        std::size_t shared = 0;
        for (const std::uint32_t e : a->second)
          shared += b->second.count(e);
        if (shared >= 2) {
          state.sets.join(a->first, b->first);
          changed = true;
        }
      }
  }
}

} // namespace segmentation
} // namespace visfeat
