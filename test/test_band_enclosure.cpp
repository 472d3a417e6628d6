// bandEnclosure(): the volume a band closes off from its grid's border, which tells a
// cloud sampled all around a solid from an open scan (the resolution search's graph
// gaps count on closed surfaces only).

#include "band_fixtures.h"

#include <visfeat/core/band/band_enclosure.h>
#include <visfeat/core/band/voxel_band.h>

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace {

using visfeat::CellCoord;

/** The walls (one cell thick) of the box of cells lo .. hi (inclusive), without the
 * wall at x = hi when `open_side`, and without the cells within `hole_size` / 2
 * (Chebyshev) of `hole` when set. */
std::vector<CellCoord>
boxWalls(const CellCoord& lo,
         const CellCoord& hi,
         bool open_side = false,
         const CellCoord* hole = nullptr,
         int hole_size = 1)
{
  std::vector<CellCoord> cells;
  for (int z = lo.z(); z <= hi.z(); ++z)
    for (int y = lo.y(); y <= hi.y(); ++y)
      for (int x = lo.x(); x <= hi.x(); ++x) {
        const CellCoord c(x, y, z);
        const bool wall =
          (c.array() == lo.array()).any() || (c.array() == hi.array()).any();
        if (!wall || (open_side && x == hi.x() && y > lo.y() && y < hi.y() &&
                      z > lo.z() && z < hi.z()))
          continue;
        if (hole && 2 * (c - *hole).cwiseAbs().maxCoeff() < hole_size)
          continue;
        cells.push_back(c);
      }
  return cells;
}

visfeat::VoxelBand
band(int grid, const std::vector<CellCoord>& cells)
{
  visfeat::VoxelBand::Options options;
  options.repair = false;
  return visfeat::VoxelBand::fromCells(visfeat_test::cubeGrid(grid), cells, options);
}

TEST(BandEnclosure, ABoxShellEnclosesItsInsideExactly)
{
  // grid below kEnclosureBlocksPerSide: blocks of one cell, the count exact: the
  // inside (26 x 20 x 14 cells) less the walls' 26-neighbours
  const visfeat::VoxelBand closed = band(40, boxWalls({3, 4, 5}, {30, 25, 20}));
  const visfeat::BandEnclosure enclosure = visfeat::bandEnclosure(closed);
  EXPECT_EQ(enclosure.block, 1);
  EXPECT_EQ(enclosure.enclosed_cells, std::uint64_t{24} * 18 * 12);
  EXPECT_TRUE(visfeat::bandIsClosed(closed));
  // a cell missing from a wall (a point-sampled band misses cells the surface only
  // clips) does not let the outside in: the walls count with their 26-neighbours
  const CellCoord hole(17, 4, 12);
  EXPECT_EQ(
    visfeat::bandEnclosure(band(40, boxWalls({3, 4, 5}, {30, 25, 20}, false, &hole)))
      .enclosed_cells,
    enclosure.enclosed_cells);
}

TEST(BandEnclosure, AnOpenSideOrAHoleLetsTheOutsideIn)
{
  EXPECT_EQ(visfeat::bandEnclosure(band(40, boxWalls({3, 4, 5}, {30, 25, 20}, true)))
              .enclosed_cells,
            0u);
  // a hole of 5 x 5 cells in a wall: the outside floods in through it
  const CellCoord hole(17, 4, 12);
  const visfeat::VoxelBand holed =
    band(40, boxWalls({3, 4, 5}, {30, 25, 20}, false, &hole, 5));
  EXPECT_EQ(visfeat::bandEnclosure(holed).enclosed_cells, 0u);
  EXPECT_FALSE(visfeat::bandIsClosed(holed));
  // open surfaces: a rotated digital plane and a crease enclose nothing
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    for (const visfeat_test::CellBand& open :
         {visfeat_test::digitalPlane(seed, 12.0), visfeat_test::creaseBand(seed)}) {
      const visfeat::VoxelBand b = band(open.grid.dims.maxCoeff(), open.cells);
      EXPECT_EQ(visfeat::bandEnclosure(b).enclosed_cells, 0u) << open.name;
    }
  }
}

TEST(BandEnclosure, ASmallPocketIsNotAClosedSurface)
{
  // 11 x 9 x 6 inside, 9 x 7 x 4 = 252 cells beyond the walls' neighbours: below
  // kMinEnclosedCells, like a fold of a noisy scan
  const visfeat::VoxelBand pocket = band(24, boxWalls({2, 3, 2}, {14, 13, 9}));
  EXPECT_EQ(visfeat::bandEnclosure(pocket).enclosed_cells, 252u);
  EXPECT_FALSE(visfeat::bandIsClosed(pocket));
  EXPECT_FALSE(visfeat::bandIsClosed(visfeat::VoxelBand()));
}

TEST(BandEnclosure, LargeGridsFloodInBlocks)
{
  // a 600-cell grid: blocks of several cells; the inside less the walls' neighbours is
  // counted in whole blocks, between the blocks that no wall touches and all of it
  const int n = 600;
  const CellCoord lo(10, 20, 30), hi(400, 300, 200);
  const visfeat::VoxelBand box = band(n, boxWalls(lo, hi));
  const visfeat::BandEnclosure enclosure = visfeat::bandEnclosure(box);
  const int b =
    (n + visfeat::kEnclosureBlocksPerSide - 1) / visfeat::kEnclosureBlocksPerSide;
  ASSERT_GT(b, 1);
  EXPECT_EQ(enclosure.block, b);
  const Eigen::Vector3i inside = hi - lo - Eigen::Vector3i::Constant(3);
  const auto volume = [](const Eigen::Vector3i& s) {
    return static_cast<std::uint64_t>(s.x()) * static_cast<std::uint64_t>(s.y()) *
           static_cast<std::uint64_t>(s.z());
  };
  EXPECT_LE(enclosure.enclosed_cells, volume(inside));
  EXPECT_GE(enclosure.enclosed_cells,
            volume(inside - Eigen::Vector3i::Constant(2 * enclosure.block)));
  EXPECT_EQ(enclosure.enclosed_cells % static_cast<std::uint64_t>(b * b * b), 0u);
  // and the same box with its side open encloses nothing
  EXPECT_EQ(visfeat::bandEnclosure(band(n, boxWalls(lo, hi, true))).enclosed_cells, 0u);
}

} // namespace
