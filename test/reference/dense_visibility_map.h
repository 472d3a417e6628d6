#pragma once

// The visibility map as visfeat computed it before the sparse mask (issue 12), kept as
// the reference for whole maps on large bands: one dense bit per subcell of the whole
// grid, the stretches of every offset from decomposeLatticeSegment (itself checked
// against the brute-force reference on every pair of the small bands), and the ring
// BFS of DESIGN.md. Simple, two threads, (2 dims)^3 bits: for tests at 256 cells.
// It shares no code with FreeSpace, FreeSpaceWindow, SegmentTable, BandTiles or
// VisibilityMap.

#include <visfeat/core/band/voxel_band.h>

#include <vector>

namespace visfeat_test {
namespace reference {

/** \brief The radius of every cell of the band (band order), rings, capped at
 * max_radius, with the given opacity (cell edges). */
std::vector<int>
denseRadii(const visfeat::VoxelBand& band, int max_radius, double opacity);

} // namespace reference
} // namespace visfeat_test
