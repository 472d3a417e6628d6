#pragma once

#include <visfeat/core/band/voxel_band.h>

#include <cstdint>

namespace visfeat {

/** \brief The volume a band closes off from the outside of its grid: the cells that
 * no path of cells outside the band (6-connected) joins to the grid's border.
 *
 * A cloud sampled all around a solid (or a closed mesh) gives a band that encloses the
 * solid's inside; a one-view scan, or a cloud with a hole wider than about 2 blocks and
 * 2 cells (6 cells at 256), encloses nothing. The automatic resolution search reads a
 * graph with gaps as features the resolution did not separate only on a closed surface:
 * an open scan's border leaves such gaps too (see kMinEnclosedCells).
 *
 * Each band cell counts with its 26 neighbours (the band of a cloud sampled 0.5 cells
 * apart misses some cells the surface only clips, and the outside would leak in there;
 * the free space is dilated likewise). The flood runs on blocks of `block` cells a
 * side (block = ceil of the grid's largest dimension / kEnclosureBlocksPerSide, so at
 * most about 136^3 blocks: 2.5 MB at any resolution), a block being closed when it
 * holds such a cell: the enclosed volume is counted in whole blocks, and an inside
 * thinner than about 2 blocks plus the band's thickness and 2 cells may not show. The
 * grid's padding (2 cells, GridSpec) keeps the neighbours inside the grid. Cost: a
 * write or a few a band cell and one flood over the blocks: measured 2026-12-07, a
 * sphere's band (one cell thick) 28 ms at 256 (336,000 cells), 0.14-0.16 s at 1024
 * (5.6 M cells), on a quiet 2-core machine.
 */
struct BandEnclosure
{
  /** Cells in the blocks closed off from the grid's border (block^3 each). */
  std::uint64_t enclosed_cells = 0;
  /** Cells a side of the blocks the flood ran on (>= 1). */
  int block = 1;
};

/** Blocks along the grid's largest dimension at most (see BandEnclosure): 132, so that
 * a block is 2 cells at 256 (260 with the grid's padding), 4 at 512 and 8 at 1024, and
 * the flood costs milliseconds (blocks of one cell cost 0.4-0.6 s at 256). The
 * 12-cell thin plate at 256 still holds 4 blocks across its inside. */
constexpr int kEnclosureBlocksPerSide = 132;

/** \brief Smallest enclosed volume, in cells, that makes a band a closed surface: a
 * cube of 16 cells a side (min_radius's default), so that a few blocks shut in where a
 * noisy scan's band folds onto itself do not count. The generated models' insides at
 * 256 hold 10^5-10^7 cells (the 12-cell thin plate about 4 10^5). */
constexpr std::uint64_t kMinEnclosedCells = 16 * 16 * 16;

/** \brief The volume `band` closes off (see BandEnclosure). An empty band encloses
 * nothing. */
BandEnclosure bandEnclosure(const VoxelBand& band);

/** \brief True when `band` encloses at least kMinEnclosedCells cells: a closed surface.
 */
inline bool
bandIsClosed(const VoxelBand& band)
{
  return bandEnclosure(band).enclosed_cells >= kMinEnclosedCells;
}

} // namespace visfeat
