#include <visfeat/core/segmentation/merged_valleys.h>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace visfeat {

MergedValleys
mergedValleys(const VoxelBand& band,
              const VisibilityMap& map,
              const FeatureSegmentation& segmentation,
              int valley_radius,
              int reach)
{
  const std::size_t n = band.size();
  // rings from the nearest edge or vertex cell, up to reach + 1 (a breadth-first search
  // from all of them at once)
  const int beyond = reach + 1;
  std::vector<std::uint8_t> rings(n, static_cast<std::uint8_t>(std::min(beyond, 255)));
  std::vector<CellId> ring, next;
  for (std::size_t c = 0; c < n; ++c) {
    const FeatureClass k = segmentation.cellClass(static_cast<CellId>(c));
    if (k == FeatureClass::kEdge || k == FeatureClass::kVertex) {
      rings[c] = 0;
      ring.push_back(static_cast<CellId>(c));
    }
  }
  for (int r = 1; r <= reach && !ring.empty(); ++r) {
    next.clear();
    for (const CellId id : ring)
      for (const CellId nb : band.neighbours(id))
        if (nb != kNoCell && rings[static_cast<std::size_t>(nb)] > r) {
          rings[static_cast<std::size_t>(nb)] = static_cast<std::uint8_t>(r);
          next.push_back(nb);
        }
    ring.swap(next);
  }
  MergedValleys found;
  std::vector<std::uint8_t> valley(n, 0);
  for (std::size_t c = 0; c < n; ++c) {
    const auto id = static_cast<CellId>(c);
    const int radius = map.radius(id);
    if (radius > valley_radius || rings[c] <= reach ||
        segmentation.cellClass(id) != FeatureClass::kFace)
      continue;
    valley[c] = 1;
    found.deepest = found.cells == 0 ? radius : std::min(found.deepest, radius);
    ++found.cells;
  }
  // the largest 6-connected group (each cell visited once: marked 2 when reached)
  for (std::size_t c = 0; c < n; ++c) {
    if (valley[c] != 1)
      continue;
    std::size_t size = 0;
    ring.assign(1, static_cast<CellId>(c));
    valley[c] = 2;
    while (!ring.empty()) {
      const CellId id = ring.back();
      ring.pop_back();
      ++size;
      for (const CellId nb : band.neighbours(id))
        if (nb != kNoCell && valley[static_cast<std::size_t>(nb)] == 1) {
          valley[static_cast<std::size_t>(nb)] = 2;
          ring.push_back(nb);
        }
    }
    found.largest = std::max(found.largest, size);
  }
  return found;
}

} // namespace visfeat
