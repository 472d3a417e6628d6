#include <visfeat/core/band/band_dilation.h>
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
  // the cells within reach of an edge or vertex cell (one dilation from all of them)
  std::vector<CellId> features;
  for (std::size_t c = 0; c < n; ++c) {
    const FeatureClass k = segmentation.cellClass(static_cast<CellId>(c));
    if (k == FeatureClass::kEdge || k == FeatureClass::kVertex)
      features.push_back(static_cast<CellId>(c));
  }
  std::vector<std::uint8_t> near(n, 0);
  BandDilation(band).run(features, static_cast<std::uint32_t>(std::max(reach, 0)),
                         [&](CellId c) { near[static_cast<std::size_t>(c)] = 1; });
  MergedValleys found;
  for (std::size_t c = 0; c < n; ++c) {
    const auto id = static_cast<CellId>(c);
    const int radius = map.radius(id);
    if (radius > valley_radius || near[c] ||
        segmentation.cellClass(id) != FeatureClass::kFace)
      continue;
    found.deepest = found.cells == 0 ? radius : std::min(found.deepest, radius);
    ++found.cells;
  }
  return found;
}

} // namespace visfeat
