#pragma once

#include <visfeat/core/band/voxel_band.h>

#include <cstdint>
#include <vector>

namespace visfeat {

/** \brief Sizes of the 6-connected pieces of the band (through VoxelBand::neighbours):
 * per cell (size band.size()), the number of cells of the piece it belongs to.
 *
 * Used to find outlier clusters: pieces smaller than
 * SegmentationParameters::min_piece_cells get no region (DESIGN.md, "Mixed cells").
 * An empty band gives an empty vector. Cost: one breadth-first pass over the band.
 */
std::vector<std::uint32_t> bandPieceSizes(const VoxelBand& band);

} // namespace visfeat
