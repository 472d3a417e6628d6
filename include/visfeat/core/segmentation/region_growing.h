#pragma once

#include <visfeat/core/band/voxel_band.h>
#include <visfeat/core/visibility/visibility_map.h>

#include <cstdint>
#include <vector>

namespace visfeat {

/** \brief Grows labels through the band so every cell joins a region: a watershed that
 * floods from the labeled cells in order of decreasing visibility radius.
 *
 * Inputs: the band, its map, per cell a label (0 = unlabeled).
 * Output: per cell a label; region boundaries fall in the valleys of the map, where
 * the floods from two components meet. Cells of band pieces that hold no label stay 0.
 * Ties (equal radius) are broken by the order cells were reached, which depends only
 * on cell ids, so the result is deterministic.
 */
std::vector<std::uint32_t> growRegions(const VoxelBand& band,
                                       const VisibilityMap& map,
                                       const std::vector<std::uint32_t>& seed_labels);

/** \brief Sizes of the 6-connected pieces of the band: per cell, the cell count of its
 * piece (to find outlier clusters). */
std::vector<std::uint32_t> bandPieceSizes(const VoxelBand& band);

} // namespace visfeat
