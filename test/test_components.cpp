// ComponentSet on hand-painted sheets: the 6-connected flood of the cells at or above
// min_radius, the numbering by smallest cell id, the vertex / edge / face classes in
// the raw (paper) and default modes, the cores of faces too narrow to reach
// min_radius (narrow_face_persistence), and the parameter checks.

#include "sheet_bands.h"

#include <visfeat/core/common/error.h>
#include <visfeat/core/segmentation/components.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace {

using visfeat::ComponentParameters;
using visfeat::ComponentSet;
using visfeat::FeatureClass;
using visfeat_test::paintSheet;

ComponentParameters
smallParameters()
{
  ComponentParameters p;
  p.min_radius = 3;
  p.vertex_max_cells = 4;
  p.dimensionality = 3.0;
  p.face_min_depth = 3;
  p.flat_core_faces = false; // the painted sheets are flat: see the FlatCores tests
  return p;
}

TEST(ComponentSetFlood, SixConnectedPiecesNumberedBySmallestCellId)
{
  // Three pieces at or above 3: B (ids 7, 8) comes first in id order, then A, then C.
  // C's cells touch only by a corner: two components, not one.
  const auto sheet = paintSheet({"1111111331",  // y = 0: B at x = 7, 8
                                 "1111111111",  //
                                 "1111111111",  //
                                 "1331111111",  // y = 3: A
                                 "1411114111",  // y = 4: A, C1 (x = 6)
                                 "1111111411"}, // y = 5: C2 (x = 7), diagonal to C1
                                4);
  const ComponentSet set =
    ComponentSet::extract(sheet.band, sheet.map, smallParameters(), false);
  ASSERT_EQ(set.components().size(), 4u);
  const auto& labels = set.cellLabels();
  auto label = [&](int x, int y) { return labels[std::size_t(sheet.at(x, y))]; };
  EXPECT_EQ(label(7, 0), 1u);
  EXPECT_EQ(label(8, 0), 1u);
  EXPECT_EQ(label(1, 3), 2u);
  EXPECT_EQ(label(2, 3), 2u);
  EXPECT_EQ(label(1, 4), 2u); // radius 4 >= 3 joins too
  EXPECT_EQ(label(6, 4), 3u);
  EXPECT_EQ(label(7, 5), 4u); // diagonal to (6, 4): its own component
  EXPECT_EQ(label(0, 0), 0u); // below min_radius
  EXPECT_EQ(set.components()[0].cells, 2u);
  EXPECT_EQ(set.components()[1].cells, 3u);
  std::size_t labelled = 0;
  for (const auto l : labels)
    labelled += l != 0;
  EXPECT_EQ(labelled, 2u + 3u + 1u + 1u);
}

// A 7x7 square (depth 3: rings 0..3 from its border; 84 inner adjacencies, mean
// 168 / 49 = 3.43), a 2x10 strip (depth 0; mean 56 / 20 = 2.8), an 8x3 block (depth 1;
// mean 74 / 24 = 3.08) and a 2x2 blob, each inside a ring of radius-1 cells.
visfeat_test::Sheet
shapesSheet()
{
  return visfeat_test::sheetFromRadius(30, 14, 4, [](int x, int y) {
    const bool square = x >= 1 && x <= 7 && y >= 1 && y <= 7;
    const bool strip = x >= 10 && x <= 11 && y >= 1 && y <= 10;
    const bool block = x >= 14 && x <= 21 && y >= 1 && y <= 3;
    const bool blob = x >= 25 && x <= 26 && y >= 6 && y <= 7;
    return square || strip || block || blob ? 3 : 1;
  });
}

TEST(ComponentSetClasses, DefaultModeByDepth)
{
  const auto sheet = shapesSheet();
  const ComponentSet set =
    ComponentSet::extract(sheet.band, sheet.map, smallParameters(), false);
  ASSERT_EQ(set.components().size(), 4u);
  auto component = [&](int x, int y) {
    return set.components()[set.cellLabels()[std::size_t(sheet.at(x, y))] - 1];
  };
  EXPECT_EQ(component(4, 4).cells, 49u);
  EXPECT_EQ(component(4, 4).depth, 3u);
  EXPECT_FLOAT_EQ(component(4, 4).mean_neighbours, 168.f / 49.f);
  EXPECT_EQ(component(4, 4).feature_class, FeatureClass::kFace); // depth 3 >= 3
  EXPECT_EQ(component(10, 5).cells, 20u);
  EXPECT_EQ(component(10, 5).depth, 0u);
  EXPECT_FLOAT_EQ(component(10, 5).mean_neighbours, 56.f / 20.f);
  EXPECT_EQ(component(10, 5).feature_class, FeatureClass::kEdge);
  EXPECT_EQ(component(15, 2).depth, 1u);
  EXPECT_EQ(component(15, 2).feature_class, FeatureClass::kEdge); // depth 1 < 3
  EXPECT_EQ(component(25, 6).cells, 4u);
  EXPECT_EQ(component(25, 6).feature_class, FeatureClass::kVertex); // 4 <= 4 cells
}

TEST(ComponentSetClasses, RawModeByMeanNeighbours)
{
  const auto sheet = shapesSheet();
  const ComponentSet set =
    ComponentSet::extract(sheet.band, sheet.map, smallParameters(), true);
  auto cls = [&](int x, int y) {
    return set.components()[set.cellLabels()[std::size_t(sheet.at(x, y))] - 1]
      .feature_class;
  };
  EXPECT_EQ(cls(4, 4), FeatureClass::kFace);    // 3.43 >= 3
  EXPECT_EQ(cls(10, 5), FeatureClass::kEdge);   // 2.8 < 3
  EXPECT_EQ(cls(15, 2), FeatureClass::kFace);   // 3.08 >= 3, unlike by depth
  EXPECT_EQ(cls(25, 6), FeatureClass::kVertex); // size decides first
}

TEST(ComponentSetClasses, AWholePieceOfTheBandIsAsDeepAsItIsLarge)
{
  // Every cell of the band reaches min_radius: no border, depth = cells (a face).
  const auto sheet = visfeat_test::sheetFromRadius(3, 3, 4, [](int, int) { return 4; });
  ComponentParameters p = smallParameters();
  p.face_min_depth = 9;
  const ComponentSet set = ComponentSet::extract(sheet.band, sheet.map, p, false);
  ASSERT_EQ(set.components().size(), 1u);
  EXPECT_EQ(set.components()[0].depth, 9u);
  EXPECT_EQ(set.components()[0].feature_class, FeatureClass::kFace);
}

std::string
validationMessage(const ComponentParameters& p, int max_radius)
{
  try {
    ComponentSet::validate(p, max_radius);
  } catch (const visfeat::Error& e) {
    return e.what();
  }
  return "";
}

/** Radius across a sheet whose creases run along y at x = 40 and x = 52: the distance
 * to the nearest crease plus `valley` (the radius at the creases), capped at 16: two
 * faces 40 cells wide with cores and one of 12 cells between the creases, whose
 * middle (x = 46) peaks at valley + 6. */
visfeat_test::Sheet
narrowFaceSheet(int valley)
{
  return visfeat_test::sheetFromRadius(92, 40, 16, [valley](int x, int) {
    return std::min(std::min(std::abs(x - 40), std::abs(x - 52)) + valley, 16);
  });
}

TEST(NarrowFaceCores, AFaceNarrowerThanACoreGetsOneBetweenItsCreases)
{
  const auto sheet = narrowFaceSheet(0);
  ComponentParameters p; // min_radius 16
  p.narrow_face_persistence = 0;
  EXPECT_EQ(ComponentSet::extract(sheet.band, sheet.map, p, false).components().size(),
            2u); // the paper's threshold: the two wide faces only
  p.narrow_face_persistence = 3;
  const ComponentSet set = ComponentSet::extract(sheet.band, sheet.map, p, false);
  ASSERT_EQ(set.components().size(), 3u);
  // peak 6, saddle 0: the core is the upper half, radius >= 3, x in 43..49
  const visfeat::Component& narrow = set.components()[2];
  EXPECT_EQ(narrow.feature_class, FeatureClass::kFace);
  EXPECT_EQ(narrow.cells, 7u * 40u);
  EXPECT_EQ(narrow.depth, 3u); // from its border x = 43 or 49 to its middle column
  for (int y = 0; y < 40; ++y)
    for (int x = 0; x < 92; ++x) {
      const std::uint32_t label = set.cellLabels()[std::size_t(sheet.at(x, y))];
      EXPECT_EQ(label == 3u, x >= 43 && x <= 49) << x << "," << y;
    }
  // the raw mode is the paper's: no narrow cores
  EXPECT_EQ(ComponentSet::extract(sheet.band, sheet.map, p, true).components().size(),
            2u);
}

TEST(NarrowFaceCores, APeakLessPersistentThanTheParameterGetsNone)
{
  // creases whose valleys keep 4 rings: the narrow face peaks at 10, 6 above them
  const auto sheet = narrowFaceSheet(4);
  ComponentParameters p;
  p.narrow_face_persistence = 7;
  EXPECT_EQ(ComponentSet::extract(sheet.band, sheet.map, p, false).components().size(),
            2u);
  p.narrow_face_persistence = 6;
  const ComponentSet set = ComponentSet::extract(sheet.band, sheet.map, p, false);
  ASSERT_EQ(set.components().size(), 3u);
  // cut at 4 + 3 = 7: x in 43..49 again
  EXPECT_EQ(set.components()[2].cells, 7u * 40u);
}

TEST(NarrowFaceCores, ANestedPeakKeepsItsOwnCoreAndCoresNeverTouch)
{
  // no cell reaches min_radius: a peak of 12 at x = 15 (its part ends at 0) and, past
  // a valley of 7 at x = 20, a peak of 10 at x = 23 (persistence 3)
  const auto sheet = visfeat_test::sheetFromRadius(40, 80, 16, [](int x, int) {
    if (x <= 20)
      return std::max(0, 12 - std::abs(x - 15));
    if (x <= 23)
      return 7 + (x - 20);
    return std::max(0, 10 - (x - 23));
  });
  ComponentParameters p;
  p.narrow_face_persistence = 3;
  const ComponentSet set = ComponentSet::extract(sheet.band, sheet.map, p, false);
  ASSERT_EQ(set.components().size(), 2u);
  // the higher cut first: the nested peak's upper half, radius >= 7 + 2 = 9 (x 22..24);
  // then the wide peak's, radius >= 6 (x 9..27), less the cells next to the first
  // core (x 21) and what only they reach (x 25..27)
  const auto label = [&](int x) {
    return set.cellLabels()[std::size_t(sheet.at(x, 40))];
  };
  for (int x = 0; x < 40; ++x) {
    const std::uint32_t expected = x >= 22 && x <= 24  ? 1u
                                   : x >= 9 && x <= 20 ? 2u
                                                       : 0u;
    EXPECT_EQ(label(x), expected) << "x " << x;
  }
  EXPECT_EQ(set.components()[0].cells, 3u * 80u);
  EXPECT_EQ(set.components()[1].cells, 12u * 80u);
  for (std::size_t c = 0; c < sheet.band.size(); ++c) {
    const std::uint32_t a = set.cellLabels()[c];
    for (const visfeat::CellId n :
         sheet.band.neighbours(static_cast<visfeat::CellId>(c)))
      if (a != 0 && n != visfeat::kNoCell) {
        const std::uint32_t b = set.cellLabels()[static_cast<std::size_t>(n)];
        EXPECT_TRUE(b == 0 || b == a) << "cores " << a << " and " << b << " touch";
      }
  }
}

TEST(ComponentSetValidate, NamesTheParameterItsRangeAndUnit)
{
  EXPECT_EQ(validationMessage(smallParameters(), 3), "");
  ComponentParameters p = smallParameters();
  p.min_radius = 5;
  EXPECT_EQ(validationMessage(p, 4),
            "min_radius 5 is out of range [1, max_radius = 4] (rings; raise max_radius "
            "to at least min_radius)");
  p = smallParameters();
  p.min_radius = 0;
  EXPECT_EQ(validationMessage(p, 4),
            "min_radius 0 is out of range [1, max_radius = 4] (rings; raise max_radius "
            "to at least min_radius)");
  p = smallParameters();
  p.vertex_max_cells = -1;
  EXPECT_EQ(validationMessage(p, 4),
            "vertex_max_cells -1 is out of range [0, 100000] (cells)");
  p = smallParameters();
  p.dimensionality = 6.5;
  EXPECT_EQ(validationMessage(p, 4),
            "dimensionality 6.5 is out of range [0, 6] (mean same-component "
            "6-neighbours)");
  p.dimensionality = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(validationMessage(p, 4).find("dimensionality nan is out of range"),
            std::string::npos);
  p = smallParameters();
  p.face_min_depth = 0;
  EXPECT_EQ(validationMessage(p, 4),
            "face_min_depth 0 is out of range [1, 1000] (cells)");
  p = smallParameters();
  p.narrow_face_persistence = -1;
  EXPECT_EQ(validationMessage(p, 4),
            "narrow_face_persistence -1 is out of range [0, 64] (rings)");
}

TEST(ComponentSetValidate, ExtractChecksAgainstTheMapsCap)
{
  const auto sheet = shapesSheet(); // max_radius 4
  ComponentParameters p = smallParameters();
  p.min_radius = 5;
  EXPECT_THROW(ComponentSet::extract(sheet.band, sheet.map, p, false), visfeat::Error);
}

} // namespace
