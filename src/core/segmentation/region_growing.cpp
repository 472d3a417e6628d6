#include <visfeat/core/segmentation/region_growing.h>

#include <algorithm>
#include <cstddef>

namespace visfeat {

std::vector<std::uint32_t>
growRegions(const VoxelBand& band,
            const VisibilityMap& map,
            const std::vector<std::uint32_t>& seed_labels)
{
  std::vector<std::uint32_t> labels = seed_labels;
  // Highest radius first, then first reached first: one FIFO per radius (radii are
  // 8-bit), the highest non-empty one served next. The same order as a priority queue
  // of (radius, -sequence) with a running sequence, at a fraction of its cost (the
  // heap of 216,000 tuples was a quarter of the segmentation's profile on the
  // icosahedron at 256, one thread).
  std::vector<std::vector<CellId>> fifo(256);
  std::vector<std::size_t> head(fifo.size(), 0);
  int top = -1; // the highest radius that may hold a waiting cell
  const auto push = [&](CellId c) {
    const int r = map.radius(c);
    fifo[static_cast<std::size_t>(r)].push_back(c);
    top = std::max(top, r);
  };
  for (std::size_t c = 0; c < labels.size(); ++c)
    if (labels[c] != 0)
      push(static_cast<CellId>(c));
  while (top >= 0) {
    const auto r = static_cast<std::size_t>(top);
    if (head[r] == fifo[r].size()) {
      fifo[r].clear();
      head[r] = 0;
      --top;
      continue;
    }
    const CellId c = fifo[r][head[r]++];
    for (const CellId nb : band.neighbours(c))
      if (nb != kNoCell && labels[static_cast<std::size_t>(nb)] == 0) {
        labels[static_cast<std::size_t>(nb)] = labels[static_cast<std::size_t>(c)];
        push(nb);
      }
  }
  return labels;
}

} // namespace visfeat
