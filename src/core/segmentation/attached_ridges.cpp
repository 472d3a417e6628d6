#include <visfeat/core/segmentation/attached_ridges.h>
#include <visfeat/core/segmentation/flat_cores.h>

namespace visfeat {
namespace {

/** Connected pieces of the cells stamped `in` (6-steps through the band), in the order
 * of their first cell in `order`; their cells are stamped `done`. */
std::vector<std::vector<CellId>>
pieces(const VoxelBand& band,
       const std::vector<CellId>& order,
       std::vector<std::uint32_t>& stamp,
       std::uint32_t in,
       std::uint32_t done)
{
  std::vector<std::vector<CellId>> result;
  for (const CellId seed : order) {
    if (stamp[static_cast<std::size_t>(seed)] != in)
      continue;
    std::vector<CellId> piece(1, seed);
    stamp[static_cast<std::size_t>(seed)] = done;
    for (std::size_t head = 0; head < piece.size(); ++head)
      for (const CellId nb : band.neighbours(piece[head]))
        if (nb != kNoCell && stamp[static_cast<std::size_t>(nb)] == in) {
          stamp[static_cast<std::size_t>(nb)] = done;
          piece.push_back(nb);
        }
    result.push_back(std::move(piece));
  }
  return result;
}

} // namespace

std::vector<std::vector<CellId>>
attachedRidges(const VoxelBand& band,
               const std::vector<CellId>& members,
               const std::vector<std::uint32_t>& depth,
               std::size_t min_cells,
               std::vector<std::uint32_t>& stamp,
               std::uint32_t& next_stamp,
               std::vector<CellId>& gap)
{
  gap.clear();
  // Members, then the opened face core within them (erosion, then dilation).
  const std::uint32_t member = ++next_stamp;
  const std::uint32_t opened = ++next_stamp;
  for (const CellId c : members)
    stamp[static_cast<std::size_t>(c)] = member;
  std::vector<std::pair<CellId, std::uint32_t>> queue;
  for (const CellId c : members)
    if (depth[static_cast<std::size_t>(c)] >= kRidgeOpeningSteps) {
      stamp[static_cast<std::size_t>(c)] = opened;
      queue.emplace_back(c, 0);
    }
  if (queue.empty())
    return {};
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const auto [cell, steps] = queue[head];
    if (steps == kRidgeOpeningSteps)
      continue;
    for (const CellId nb : band.neighbours(cell))
      if (nb != kNoCell && stamp[static_cast<std::size_t>(nb)] == member) {
        stamp[static_cast<std::size_t>(nb)] = opened;
        queue.emplace_back(nb, steps + 1);
      }
  }
  // Thin cells next to the face core are the gap; the rest falls into pieces.
  const std::uint32_t thin = ++next_stamp;
  std::vector<CellId> candidates;
  for (const CellId c : members) {
    if (stamp[static_cast<std::size_t>(c)] != member)
      continue;
    bool touches = false;
    for (const CellId nb : band.neighbours(c))
      touches =
        touches || (nb != kNoCell && stamp[static_cast<std::size_t>(nb)] == opened);
    if (touches)
      gap.push_back(c);
    else
      candidates.push_back(c);
  }
  for (const CellId c : candidates)
    stamp[static_cast<std::size_t>(c)] = thin;
  const std::uint32_t done = ++next_stamp;
  std::vector<std::vector<CellId>> ridges;
  std::vector<CellId> kept_gap;
  for (std::vector<CellId>& piece : pieces(band, candidates, stamp, thin, done))
    if (piece.size() > min_cells)
      ridges.push_back(std::move(piece));
  // The bend last: coreVariation() restamps the cells around each piece.
  std::vector<std::vector<CellId>> result;
  for (std::vector<CellId>& ridge : ridges)
    if (coreVariation(band, ridge, stamp, next_stamp) >= kFadingCreaseVariation)
      result.push_back(std::move(ridge));
  if (result.empty()) {
    gap.clear();
    return result;
  }
  // Only the gap cells beside a kept ridge leave the face core.
  const std::uint32_t ridge_mark = ++next_stamp;
  for (const auto& ridge : result)
    for (const CellId c : ridge)
      stamp[static_cast<std::size_t>(c)] = ridge_mark;
  for (const CellId c : gap) {
    bool beside = false;
    for (const CellId nb : band.neighbours(c))
      beside =
        beside || (nb != kNoCell && stamp[static_cast<std::size_t>(nb)] == ridge_mark);
    if (beside)
      kept_gap.push_back(c);
  }
  gap = std::move(kept_gap);
  return result;
}

} // namespace visfeat
