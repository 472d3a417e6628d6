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

/** Whether a band neighbour of `cell` is stamped `mark`. */
bool
besideStamp(const VoxelBand& band,
            const std::vector<std::uint32_t>& stamp,
            CellId cell,
            std::uint32_t mark)
{
  for (const CellId nb : band.neighbours(cell))
    if (nb != kNoCell && stamp[static_cast<std::size_t>(nb)] == mark)
      return true;
  return false;
}

} // namespace

RidgeSplit
attachedRidges(const VoxelBand& band,
               const std::vector<CellId>& members,
               const std::vector<std::uint32_t>& depth,
               int min_radius,
               std::vector<std::uint32_t>& stamp,
               std::uint32_t& next_stamp)
{
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
  std::vector<CellId> gap, candidates;
  for (const CellId c : members)
    if (stamp[static_cast<std::size_t>(c)] == member)
      (besideStamp(band, stamp, c, opened) ? gap : candidates).push_back(c);
  for (const CellId c : candidates)
    stamp[static_cast<std::size_t>(c)] = thin;
  const std::uint32_t done = ++next_stamp;
  // The bend last: fadingCreaseCore() restamps the cells around each piece.
  RidgeSplit split;
  for (std::vector<CellId>& piece : pieces(band, candidates, stamp, thin, done))
    if (fadingCreaseCore(band, piece, min_radius, stamp, next_stamp))
      split.ridges.push_back(std::move(piece));
  if (split.ridges.empty())
    return split;
  // Only the gap cells beside a kept ridge leave the face core; the rest of the members
  // is the face core, in pieces.
  const std::uint32_t ridge_mark = ++next_stamp;
  for (const auto& ridge : split.ridges)
    for (const CellId c : ridge)
      stamp[static_cast<std::size_t>(c)] = ridge_mark;
  for (const CellId c : gap)
    if (besideStamp(band, stamp, c, ridge_mark))
      split.gap.push_back(c);
  const std::uint32_t face = ++next_stamp;
  for (const CellId c : members)
    if (stamp[static_cast<std::size_t>(c)] != ridge_mark)
      stamp[static_cast<std::size_t>(c)] = face;
  const std::uint32_t left_out = ++next_stamp;
  for (const CellId c : split.gap)
    stamp[static_cast<std::size_t>(c)] = left_out;
  split.face_pieces = pieces(band, members, stamp, face, ++next_stamp);
  return split;
}

} // namespace visfeat
