// Step 5 of FeatureSegmentation (complete regions): ridge paths join each edge to the
// vertices it was not drawn to.

#include "segmentation_steps.h"

#include <algorithm>
#include <functional>
#include <limits>
#include <queue>

namespace visfeat {
namespace segmentation {
namespace {

/** Dijkstra's scratch, reset only where the last search wrote. */
struct PathSearch
{
  explicit PathSearch(std::size_t cells)
      : cost(cells, std::numeric_limits<double>::infinity())
      , from(cells, kNoCell)
  {}

  void reset()
  {
    for (const CellId c : touched) {
      cost[static_cast<std::size_t>(c)] = std::numeric_limits<double>::infinity();
      from[static_cast<std::size_t>(c)] = kNoCell;
    }
    touched.clear();
  }

  std::vector<double> cost;
  std::vector<CellId> from; // the previous cell on the cheapest path
  std::vector<CellId> touched;
};

/** The cheapest path from the vertex's cores to a skeleton cell of the edge, through
 * the two regions and the faces; a step onto a cell costs 1 + (max_radius - its
 * radius). Returns the cell reached (kNoCell if none); the path runs back through
 * search.from. */
CellId
cheapestPath(const ThinningState& state,
             std::uint32_t vertex,
             std::uint32_t edge,
             PathSearch& search)
{
  const int cap = state.map.parameters().max_radius;
  using Entry = std::pair<double, CellId>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  for (const CellId c : valueOrEmpty(state.vertex_cores, vertex)) {
    search.cost[static_cast<std::size_t>(c)] = 0.0;
    search.touched.push_back(c);
    queue.emplace(0.0, c);
  }
  while (!queue.empty()) {
    const auto [d, c] = queue.top();
    queue.pop();
    if (d > search.cost[static_cast<std::size_t>(c)])
      continue;
    if (state.labels[static_cast<std::size_t>(c)] == edge &&
        state.skeleton[static_cast<std::size_t>(c)])
      return c;
    for (const CellId nb : state.band.neighbours(c)) {
      if (nb == kNoCell)
        continue;
      const std::uint32_t l = state.labels[static_cast<std::size_t>(nb)];
      if (l == 0 || (l != vertex && l != edge && state.isFeature(l)))
        continue;
      const double next = d + 1.0 + std::max(0, cap - state.map.radius(nb));
      if (next < search.cost[static_cast<std::size_t>(nb)]) {
        search.cost[static_cast<std::size_t>(nb)] = next;
        search.from[static_cast<std::size_t>(nb)] = c;
        search.touched.push_back(nb);
        queue.emplace(next, nb);
      }
    }
  }
  return kNoCell;
}

} // namespace

void
traceRidgePaths(ThinningState& state)
{
  PathSearch search(state.band.size());
  for (const auto& [vertex, edge] : state.pairs) {
    if (state.drawn.count({vertex, edge}))
      continue;
    search.reset();
    const CellId reached = cheapestPath(state, vertex, edge, search);
    for (CellId c = reached; c != kNoCell;
         c = search.from[static_cast<std::size_t>(c)]) {
      state.skeleton[static_cast<std::size_t>(c)] = 1;
      if (state.labels[static_cast<std::size_t>(c)] != vertex)
        state.labels[static_cast<std::size_t>(c)] = edge;
    }
  }
}

} // namespace segmentation
} // namespace visfeat
