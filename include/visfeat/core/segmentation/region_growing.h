#pragma once

#include <visfeat/core/band/voxel_band.h>
#include <visfeat/core/visibility/visibility_map.h>

#include <cstdint>
#include <vector>

namespace visfeat {

/** \brief Grows labels through the band so every cell joins a region: a watershed that
 * floods from the labeled cells in order of decreasing visibility radius.
 *
 * Inputs: the band (n cells), its map (one radius per cell), per cell a label (size
 * n, 0 = unlabeled). Output: per cell a label (size n); region boundaries fall in the
 * valleys of the map, where the floods from two components meet. Cells of band pieces
 * that hold no label stay 0. Ties (equal radius) are broken by the order cells were
 * reached, which depends only on cell ids, so the result is deterministic.
 */
std::vector<std::uint32_t> growRegions(const VoxelBand& band,
                                       const VisibilityMap& map,
                                       const std::vector<std::uint32_t>& seed_labels);

} // namespace visfeat
