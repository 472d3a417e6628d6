#include <visfeat/core/segmentation/region_growing.h>

#include <queue>
#include <tuple>

namespace visfeat {

std::vector<std::uint32_t>
growRegions(const VoxelBand& band,
            const VisibilityMap& map,
            const std::vector<std::uint32_t>& seed_labels)
{
  std::vector<std::uint32_t> labels = seed_labels;
  // (radius, -sequence, cell): highest radius first, then first reached first.
  using Entry = std::tuple<int, std::int64_t, CellId>;
  std::priority_queue<Entry> queue;
  std::int64_t sequence = 0;
  for (std::size_t c = 0; c < labels.size(); ++c)
    if (labels[c] != 0)
      queue.emplace(map.radii()[c], -(sequence++), static_cast<CellId>(c));
  while (!queue.empty()) {
    const CellId c = std::get<2>(queue.top());
    queue.pop();
    for (const CellId nb : band.neighbours(c))
      if (nb != kNoCell && labels[static_cast<std::size_t>(nb)] == 0) {
        labels[static_cast<std::size_t>(nb)] = labels[static_cast<std::size_t>(c)];
        queue.emplace(map.radius(nb), -(sequence++), nb);
      }
  }
  return labels;
}

} // namespace visfeat
