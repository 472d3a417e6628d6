// BandDilation (the geodesic dilation through the band) on hand-made rows and a U of
// cells: the steps bound, BFS order, sources given twice, reuse between runs.

#include "sheet_bands.h"

#include <visfeat/core/band/band_dilation.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace {

using visfeat::CellId;
using visfeat_test::paintSheet;

std::vector<int>
xsOf(const visfeat_test::Sheet& sheet, const std::vector<CellId>& cells)
{
  std::vector<int> xs;
  for (const CellId c : cells)
    xs.push_back(sheet.position(c).x());
  return xs;
}

std::vector<CellId>
dilate(visfeat::BandDilation& dilation,
       const std::vector<CellId>& sources,
       std::uint32_t radius)
{
  std::vector<CellId> visited;
  dilation.run(sources, radius, [&](CellId c) { visited.push_back(c); });
  return visited;
}

TEST(BandDilation, VisitsCellsWithinTheRadiusInBreadthFirstOrder)
{
  const auto sheet = paintSheet({"0000000000"}, 1);
  visfeat::BandDilation dilation(sheet.band);
  // From x = 2, 3 steps: x = 2, then 1 and 3 (-x before +x), then 0 and 4, then 5.
  EXPECT_EQ(xsOf(sheet, dilate(dilation, {sheet.at(2, 0)}, 3)),
            (std::vector<int>{2, 1, 3, 0, 4, 5}));
  EXPECT_EQ(xsOf(sheet, dilate(dilation, {sheet.at(2, 0)}, 0)), (std::vector<int>{2}));
}

TEST(BandDilation, ASourceGivenTwiceIsVisitedOnce)
{
  const auto sheet = paintSheet({"0000000000"}, 1);
  visfeat::BandDilation dilation(sheet.band);
  EXPECT_EQ(
    xsOf(sheet, dilate(dilation, {sheet.at(2, 0), sheet.at(7, 0), sheet.at(2, 0)}, 1)),
    (std::vector<int>{2, 7, 1, 3, 6, 8}));
}

TEST(BandDilation, ARunDoesNotSeeTheLastOne)
{
  const auto sheet = paintSheet({"0000000000"}, 1);
  visfeat::BandDilation dilation(sheet.band);
  EXPECT_EQ(dilate(dilation, {sheet.at(0, 0)}, 20).size(), 10u);
  // Cells the first run marked are free again: the second run reaches them.
  EXPECT_EQ(xsOf(sheet, dilate(dilation, {sheet.at(9, 0)}, 1)),
            (std::vector<int>{9, 8}));
  EXPECT_EQ(xsOf(sheet, dilate(dilation, {sheet.at(0, 0)}, 1)),
            (std::vector<int>{0, 1}));
}

TEST(BandDilation, StepsGoThroughTheBandNotAcrossIt)
{
  // A U: the ends (0, 2) and (2, 2) are 2 cells apart but 6 steps through the band.
  const auto sheet = paintSheet({"000", //
                                 "0 0", "0 0"},
                                1);
  visfeat::BandDilation dilation(sheet.band);
  const auto five = dilate(dilation, {sheet.at(0, 2)}, 5);
  EXPECT_EQ(five.size(), 6u);
  EXPECT_EQ(std::count(five.begin(), five.end(), sheet.at(2, 2)), 0);
  const auto six = dilate(dilation, {sheet.at(0, 2)}, 6);
  EXPECT_EQ(six.size(), 7u);
  EXPECT_EQ(six.back(), sheet.at(2, 2));
}

} // namespace
