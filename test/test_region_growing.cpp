// growRegions (the watershed that gives every band cell a region) and bandPieceSizes
// on hand-painted rows of cells.

#include "sheet_bands.h"

#include <visfeat/core/band/band_pieces.h>
#include <visfeat/core/segmentation/region_growing.h>

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace {

using visfeat_test::paintSheet;
using visfeat_test::Sheet;

/** Seeds: per picture cell x of row 0, the given label. */
std::vector<std::uint32_t>
seedsOf(const Sheet& sheet, const std::vector<std::pair<int, std::uint32_t>>& seeds)
{
  std::vector<std::uint32_t> labels(sheet.band.size(), 0);
  for (const auto& [x, label] : seeds)
    labels[std::size_t(sheet.at(x, 0))] = label;
  return labels;
}

std::vector<std::uint32_t>
row(const Sheet& sheet, const std::vector<std::uint32_t>& labels, int width)
{
  std::vector<std::uint32_t> out;
  for (int x = 0; x < width; ++x)
    out.push_back(labels[std::size_t(sheet.at(x, 0))]);
  return out;
}

TEST(GrowRegions, FloodsByRadiusNotByDistance)
{
  // Cell 2 is two steps from seed 1 and four from seed 2, but the flood from seed 2
  // runs along radius 4 and reaches it before seed 1's flood leaves its radius-2 cell.
  const auto sheet = paintSheet({"5204445"}, 5);
  const auto labels =
    visfeat::growRegions(sheet.band, sheet.map, seedsOf(sheet, {{0, 1}, {6, 2}}));
  EXPECT_EQ(row(sheet, labels, 7), (std::vector<std::uint32_t>{1, 1, 2, 2, 2, 2, 2}));
}

TEST(GrowRegions, TiesGoToTheFloodReachedFirstInCellOrder)
{
  // Symmetric valley: both floods reach radius 3 at the same level; the middle cell
  // goes to the flood whose cell was reached first, which follows cell ids (the seed
  // at x = 0 is queued first), whatever the label values.
  const auto sheet = paintSheet({"53135"}, 5);
  EXPECT_EQ(
    row(sheet,
        visfeat::growRegions(sheet.band, sheet.map, seedsOf(sheet, {{0, 1}, {4, 2}})),
        5),
    (std::vector<std::uint32_t>{1, 1, 1, 2, 2}));
  EXPECT_EQ(
    row(sheet,
        visfeat::growRegions(sheet.band, sheet.map, seedsOf(sheet, {{0, 7}, {4, 3}})),
        5),
    (std::vector<std::uint32_t>{7, 7, 7, 3, 3}));
}

TEST(GrowRegions, PiecesWithoutASeedStayUnlabelled)
{
  // Two pieces of the band: x 0..3 (seeded) and x 5..7 (not).
  const auto sheet = paintSheet({"4321 567"}, 7);
  const auto labels =
    visfeat::growRegions(sheet.band, sheet.map, seedsOf(sheet, {{3, 9}}));
  for (int x : {0, 1, 2, 3})
    EXPECT_EQ(labels[std::size_t(sheet.at(x, 0))], 9u) << x;
  for (int x : {5, 6, 7})
    EXPECT_EQ(labels[std::size_t(sheet.at(x, 0))], 0u) << x;
}

TEST(BandPieceSizes, CountsSixConnectedPieces)
{
  // Pieces: 5 cells (row 0, x 0..4), 1 cell (x 6), and the two cells at (8, 0) and
  // (9, 1), which touch only by an edge: two pieces of 1 without the repair.
  const auto sheet = paintSheet({"11111 1 1 ", //
                                 "         1"},
                                1);
  const auto sizes = visfeat::bandPieceSizes(sheet.band);
  ASSERT_EQ(sizes.size(), 8u);
  for (int x = 0; x < 5; ++x)
    EXPECT_EQ(sizes[std::size_t(sheet.at(x, 0))], 5u) << x;
  EXPECT_EQ(sizes[std::size_t(sheet.at(6, 0))], 1u);
  EXPECT_EQ(sizes[std::size_t(sheet.at(8, 0))], 1u);
  EXPECT_EQ(sizes[std::size_t(sheet.at(9, 1))], 1u);
}

TEST(BandPieceSizes, TheRepairJoinsDiagonalCells)
{
  // The same two diagonal cells with the repair: one cell added, one piece of 3.
  visfeat::GridSpec grid;
  grid.dims = visfeat::CellCoord(6, 6, 3);
  const std::vector<visfeat::CellCoord> cells{{1, 1, 1}, {2, 2, 1}};
  const auto band = visfeat::VoxelBand::fromCells(grid, cells, {});
  ASSERT_EQ(band.size(), 3u);
  EXPECT_EQ(visfeat::bandPieceSizes(band), (std::vector<std::uint32_t>{3, 3, 3}));
}

TEST(BandPieceSizes, EmptyBand)
{
  EXPECT_TRUE(visfeat::bandPieceSizes(visfeat::VoxelBand()).empty());
}

} // namespace
