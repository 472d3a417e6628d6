// Step 5 of FeatureSegmentation (complete regions): edge and vertex regions end where
// the watershed met the faces, in the valleys 3-4 cells out; they are cut back to their
// skeleton widened by feature_width cells, and the rest goes to the faces.

#include "segmentation_steps.h"

namespace visfeat {
namespace segmentation {
namespace {

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

} // namespace segmentation
} // namespace visfeat
