// Step 5 of FeatureSegmentation (complete regions): edge and vertex regions end where
// the watershed met the faces, in the valleys 3-4 cells out; they are cut back to their
// skeleton widened by feature_width cells, and the rest goes to the faces.

#include "segmentation_steps.h"

#include <map>

namespace visfeat {
namespace segmentation {
namespace {

/** A vertex-edge pair left apart by the cut is joined through at most this many band
 * cells (6-steps): the cut opens gaps of a cell or two between a drawn edge and its
 * corner (U-prism, 20,000 points, seed 33: 2 cells, and the graph, which joins regions
 * within 2 steps, lost the corner's arc). Farther apart, the pair is left as it is. */
constexpr int kMaxRejoinSteps = 3;

/** Whether a cell of `edge` has a face neighbour labelled `vertex`. */
bool
touches(const ThinningState& state,
        const std::vector<CellId>& edge_cells,
        std::uint32_t vertex)
{
  for (const CellId c : edge_cells)
    for (const CellId nb : state.band.neighbours(c))
      if (nb != kNoCell && state.labels[static_cast<std::size_t>(nb)] == vertex)
        return true;
  return false;
}

/** The shortest path (6-steps through the band, at most kMaxRejoinSteps) from a cell
 * of the edge to a cell of the vertex, through cells of no other feature; its inner
 * cells join the edge. */
void
rejoin(ThinningState& state,
       const std::vector<CellId>& edge_cells,
       std::uint32_t vertex,
       std::uint32_t edge)
{
  std::vector<std::pair<CellId, std::int64_t>> visited; // cell, parent entry
  std::map<CellId, int> depth;
  for (const CellId c : edge_cells) {
    visited.emplace_back(c, -1);
    depth.emplace(c, 0);
  }
  for (std::size_t head = 0; head < visited.size(); ++head) {
    const CellId c = visited[head].first;
    const int d = depth.at(c);
    if (d >= kMaxRejoinSteps)
      continue;
    for (const CellId nb : state.band.neighbours(c)) {
      if (nb == kNoCell || depth.count(nb) != 0)
        continue;
      const std::uint32_t l = state.labels[static_cast<std::size_t>(nb)];
      if (l == vertex) {
        for (std::int64_t at = static_cast<std::int64_t>(head);
             visited[static_cast<std::size_t>(at)].second >= 0;
             at = visited[static_cast<std::size_t>(at)].second)
          state.labels[static_cast<std::size_t>(
            visited[static_cast<std::size_t>(at)].first)] = edge;
        return;
      }
      if (state.isFeature(l))
        continue; // another feature's cell stays its own
      depth.emplace(nb, d + 1);
      visited.emplace_back(nb, static_cast<std::int64_t>(head));
    }
  }
}

/** Per cell, its 6-steps from the skeleton through its own region, up to `width`; -1
 * beyond (or unreached). */
std::vector<int>
stepsFromSkeleton(const ThinningState& state, int width)
{
  std::vector<int> steps(state.band.size(), -1);
  std::vector<CellId> queue;
  for (std::size_t c = 0; c < state.band.size(); ++c)
    if (state.skeleton[c]) {
      steps[c] = 0;
      queue.push_back(static_cast<CellId>(c));
    }
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const CellId c = queue[head];
    const auto i = static_cast<std::size_t>(c);
    if (steps[i] >= width)
      continue;
    for (const CellId nb : state.band.neighbours(c))
      if (nb != kNoCell && steps[static_cast<std::size_t>(nb)] < 0 &&
          state.labels[static_cast<std::size_t>(nb)] == state.labels[i]) {
        steps[static_cast<std::size_t>(nb)] = steps[i] + 1;
        queue.push_back(nb);
      }
  }
  return steps;
}

} // namespace

void
cutToSkeletonWidth(ThinningState& state)
{
  const std::vector<int> steps =
    stepsFromSkeleton(state, state.parameters.feature_width);
  // The rest of the feature cells go to the nearest face region (BFS from the faces).
  std::vector<std::uint32_t>& labels = state.labels;
  const std::vector<std::uint32_t> original = labels;
  std::vector<CellId> queue;
  for (std::size_t c = 0; c < labels.size(); ++c) {
    if (state.isFeature(labels[c]) && steps[c] < 0)
      labels[c] = 0;
    else if (labels[c] != 0 && state.cls[labels[c]] == FeatureClass::kFace)
      queue.push_back(static_cast<CellId>(c));
  }
  for (std::size_t head = 0; head < queue.size(); ++head)
    for (const CellId nb : state.band.neighbours(queue[head]))
      if (nb != kNoCell && labels[static_cast<std::size_t>(nb)] == 0 &&
          original[static_cast<std::size_t>(nb)] != 0) {
        labels[static_cast<std::size_t>(nb)] =
          labels[static_cast<std::size_t>(queue[head])];
        queue.push_back(nb);
      }
  for (std::size_t c = 0; c < labels.size(); ++c) // enclosed cells no face reaches
    if (labels[c] == 0)                           // keep their label
      labels[c] = original[c];
}

void
rejoinCutPairs(ThinningState& state)
{
  std::map<std::uint32_t, std::vector<CellId>> cells; // of the paired edges
  for (const auto& pair : state.pairs)
    cells[pair.second];
  for (std::size_t c = 0; c < state.labels.size(); ++c)
    if (const auto it = cells.find(state.labels[c]); it != cells.end())
      it->second.push_back(static_cast<CellId>(c));
  for (const auto& [vertex, edge] : state.pairs) {
    const std::vector<CellId>& edge_cells = cells.at(edge);
    if (edge_cells.empty() || state.cls[vertex] != FeatureClass::kVertex ||
        state.cls[edge] != FeatureClass::kEdge || touches(state, edge_cells, vertex))
      continue;
    rejoin(state, edge_cells, vertex, edge);
  }
}

} // namespace segmentation
} // namespace visfeat
