// BandTiles: the band's cells grouped by brick of 8^3 cells, the visibility map's unit
// of work.

#include "band_fixtures.h"

#include <visfeat/core/visibility/band_tiles.h>

#include <gtest/gtest.h>

#include <random>
#include <set>

namespace {

using visfeat::BandTiles;
using visfeat::CellCoord;
using visfeat::CellId;

TEST(BandTiles, EveryCellOnceInTheTileOfItsBrickInKeyOrder)
{
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> coord(0, 39);
  std::set<std::array<int, 3>> unique;
  std::vector<CellCoord> cells;
  while (cells.size() < 700) {
    const CellCoord c(coord(rng), coord(rng), coord(rng));
    if (unique.insert({c.x(), c.y(), c.z()}).second)
      cells.push_back(c);
  }
  visfeat::VoxelBand::Options options;
  options.repair = false;
  const visfeat::VoxelBand band =
    visfeat::VoxelBand::fromCells(visfeat_test::cubeGrid(40), cells, options);
  const BandTiles tiles(band);
  ASSERT_GT(tiles.size(), 50u);
  EXPECT_LE(tiles.size(), 125u); // 5^3 bricks in a 40^3 grid
  std::vector<int> seen(band.size(), 0);
  for (std::size_t t = 0; t < tiles.size(); ++t) {
    ASSERT_GT(tiles.cellCount(t), 0u);
    EXPECT_EQ(tiles.find(tiles.brick(t)), static_cast<std::int64_t>(t));
    if (t > 0) {
      const Eigen::Vector3i a = tiles.brick(t - 1), b = tiles.brick(t);
      EXPECT_TRUE(std::make_tuple(a.z(), a.y(), a.x()) <
                  std::make_tuple(b.z(), b.y(), b.x()));
    }
    CellId previous = -1;
    for (const CellId* c = tiles.cellsBegin(t); c != tiles.cellsEnd(t); ++c) {
      ++seen[static_cast<std::size_t>(*c)];
      EXPECT_EQ(BandTiles::brickOf(band.coord(*c)), tiles.brick(t));
      EXPECT_GT(*c, previous); // the band's order inside a tile
      previous = *c;
    }
  }
  for (int count : seen)
    EXPECT_EQ(count, 1);
  EXPECT_EQ(tiles.find(Eigen::Vector3i(5, 0, 0)), -1); // outside the grid
  EXPECT_EQ(tiles.find(Eigen::Vector3i(-1, 0, 0)), -1);
}

} // namespace
