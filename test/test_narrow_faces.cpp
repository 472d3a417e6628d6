// narrowFaces() on hand-painted sheets (a face between two creases too narrow for a
// core, the roughness of a band, a short face, a band piece without a core) and the
// step of the resolution search, nextSearchResolution().

#include "sheet_bands.h"

#include <visfeat/core/grid/resolution_search.h>
#include <visfeat/core/segmentation/narrow_faces.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>

namespace {

using visfeat::narrowFaces;
using visfeat::nextSearchResolution;
using visfeat_test::sheetFromRadius;

constexpr int kMinRadius = 16;

/** Radius across a sheet whose creases run along y at x = c1 and x = c2: the distance
 * to the nearest crease, capped at kMinRadius (two wide faces with cores, a face
 * between the creases c2 - c1 cells wide), plus `bump` on cells where (x, y) hashes
 * to 0 mod 3: the roughness of a band. */
int
creaseProfile(int x, int y, int c1, int c2, int bump)
{
  const int d = std::min(std::abs(x - c1), std::abs(x - c2));
  const int rough = ((x * 7 + y * 13) % 3 == 0) ? bump : 0;
  return std::min(d + rough, kMinRadius);
}

TEST(NarrowFaces, FaceBetweenTwoCreasesNarrowerThanACore)
{
  // faces of 40 cells, one of 12 between x = 40 and x = 52: it peaks at 6 rings
  const auto sheet = sheetFromRadius(
    92, 40, kMinRadius, [](int x, int y) { return creaseProfile(x, y, 40, 52, 0); });
  const auto faces = narrowFaces(sheet.band, sheet.map, kMinRadius, 3, 256);
  ASSERT_EQ(faces.size(), 1u);
  EXPECT_EQ(faces[0].peak, 6);
  EXPECT_EQ(faces[0].saddle, 0); // the crease cells at x = 40 and 52
  // cells above the saddle: x in 41..51, all 40 rows
  EXPECT_EQ(faces[0].cells, 11u * 40u);
}

TEST(NarrowFaces, WideFacesHaveNone)
{
  // the face between the creases is 40 cells wide: it reaches min_radius
  const auto sheet = sheetFromRadius(
    120, 40, kMinRadius, [](int x, int y) { return creaseProfile(x, y, 40, 80, 0); });
  EXPECT_TRUE(narrowFaces(sheet.band, sheet.map, kMinRadius, 1, 1).empty());
}

TEST(NarrowFaces, RoughnessOfTwoRingsIsNotAFace)
{
  // bumps of 2 rings on every slope: many peaks, none 3 rings above its saddle
  const auto sheet = sheetFromRadius(
    120, 40, kMinRadius, [](int x, int y) { return creaseProfile(x, y, 40, 80, 2); });
  EXPECT_TRUE(narrowFaces(sheet.band, sheet.map, kMinRadius, 3, 1).empty());
  // they are peaks all the same: persistence 1 finds them
  EXPECT_FALSE(narrowFaces(sheet.band, sheet.map, kMinRadius, 1, 1).empty());
}

TEST(NarrowFaces, ShortFaceNeedsEnoughCells)
{
  // the narrow face only 8 rows long, closed by a crease along row 8: 11 x 8 = 88
  // cells above the saddle
  const auto sheet = sheetFromRadius(92, 40, kMinRadius, [](int x, int y) {
    if (y < 8)
      return creaseProfile(x, y, 40, 52, 0);
    if (y == 8 && x >= 40 && x <= 52)
      return 0;
    return std::min(std::abs(x - 40), kMinRadius);
  });
  EXPECT_TRUE(narrowFaces(sheet.band, sheet.map, kMinRadius, 3, 256).empty());
  const auto faces = narrowFaces(sheet.band, sheet.map, kMinRadius, 3, 80);
  ASSERT_EQ(faces.size(), 1u);
  EXPECT_EQ(faces[0].peak, 6);
  EXPECT_EQ(faces[0].cells, 88u);
}

TEST(NarrowFaces, BandPieceWithoutCoreEndsAtZero)
{
  // a strip 11 cells wide alone (x = 0 and 10 are its rims, radius 0): peak 5
  const auto sheet =
    sheetFromRadius(11, 30, kMinRadius, [](int x, int) { return std::min(x, 10 - x); });
  const auto faces = narrowFaces(sheet.band, sheet.map, kMinRadius, 3, 1);
  ASSERT_EQ(faces.size(), 1u);
  EXPECT_EQ(faces[0].peak, 5);
  EXPECT_EQ(faces[0].saddle, 0);
  EXPECT_EQ(faces[0].cells, 11u * 30u);
}

TEST(NarrowFaces, TwoNarrowFacesMostCellsFirst)
{
  // creases at 20, 30 (a face of 10, peak 5) and 70, 84 (a face of 14, peak 7),
  // wide faces with cores between and around them
  const auto sheet = sheetFromRadius(110, 40, kMinRadius, [](int x, int) {
    const int d = std::min(
      {std::abs(x - 20), std::abs(x - 30), std::abs(x - 70), std::abs(x - 84)});
    return std::min(d, kMinRadius);
  });
  const auto faces = narrowFaces(sheet.band, sheet.map, kMinRadius, 3, 1);
  ASSERT_EQ(faces.size(), 2u);
  EXPECT_EQ(faces[0].peak, 7);
  EXPECT_EQ(faces[0].cells, 13u * 40u);
  EXPECT_EQ(faces[1].peak, 5);
  EXPECT_EQ(faces[1].cells, 9u * 40u);
}

TEST(ResolutionSearch, StepDoublesWithinTheCap)
{
  EXPECT_EQ(nextSearchResolution(256, 1024), 512);
  EXPECT_EQ(nextSearchResolution(300, 1024), 600);
  EXPECT_EQ(nextSearchResolution(256, 400), 400);
  EXPECT_EQ(nextSearchResolution(256, 320), 320); // exactly 1.25 times
  EXPECT_EQ(nextSearchResolution(256, 319), 0);   // less than 1.25 times
  EXPECT_EQ(nextSearchResolution(256, 256), 0);
  EXPECT_EQ(nextSearchResolution(0, 1024), 0);
}

TEST(ResolutionSearch, StepsGrowWithTheMaximum)
{
  using visfeat::searchSteps;
  EXPECT_EQ(searchSteps(visfeat::kMaxSearchResolution), visfeat::kMaxSearchSteps);
  EXPECT_EQ(searchSteps(512), visfeat::kMaxSearchSteps); // the cap stops it first
  EXPECT_EQ(searchSteps(1500), visfeat::kMaxSearchSteps + 1);
  EXPECT_EQ(searchSteps(2048), visfeat::kMaxSearchSteps + 1);
  EXPECT_EQ(searchSteps(8192), visfeat::kMaxSearchSteps + 3);
}

} // namespace
