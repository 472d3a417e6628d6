// openFaceMerge: a face sliver bounded by one crease between two corners joins the
// face it was cut from; a face bounded by a closed rim stays. creaseInnerVertexMerge:
// a vertex between two creases of the same two faces joins the larger crease; the
// ends of a lens and corners of three faces stay.

#include "graph_sheet.h"

#include <visfeat/core/common/error.h>
#include <visfeat/core/common/feature_class.h>
#include <visfeat/core/graph/open_faces.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace {

using visfeat::FeatureClass;
using visfeat_test::identity;
using visfeat_test::in;
using visfeat_test::LabelledSheet;
using visfeat_test::Labels;

constexpr FeatureClass kV = FeatureClass::kVertex;
constexpr FeatureClass kE = FeatureClass::kEdge;
constexpr FeatureClass kF = FeatureClass::kFace;

/** A crease along y 19..20 between F1 (below) and F2 (above): E3 from corner V4 (x <=
 * 3, y 17..22) to V5 (x 20..22, y 17..22), then E7 on to V6 (x >= 36). With
 * `sliver`, F8 (y 21..23, x 4..19) lies between E3 and F2: a piece of F2 cut off
 * along E3. */
std::uint32_t
creaseWithSliver(int x, int y, bool sliver)
{
  if (in(y, 17, 22) && (x <= 3 || in(x, 20, 22) || x >= 36))
    return x <= 3 ? 4 : x >= 36 ? 6 : 5;
  if (in(y, 19, 20))
    return x < 20 ? 3 : 7;
  if (sliver && in(y, 21, 23) && in(x, 4, 19))
    return 8;
  return y < 19 ? 1 : 2;
}

const std::vector<FeatureClass> kSliverClasses{kF, kF, kE, kV, kV, kV, kE, kF};

TEST(OpenFaces, AFaceSliverAlongOneCreaseJoinsTheFaceItWasCutFrom)
{
  const LabelledSheet sheet(kSliverClasses,
                            [](int x, int y) { return creaseWithSliver(x, y, true); });
  ASSERT_EQ(sheet.graph.neighbours(8, kE), Labels({3}));
  ASSERT_EQ(sheet.graph.verticesOfEdge(3), Labels({4, 5}));
  ASSERT_EQ(sheet.graph.facesOfEdge(3), Labels({1, 8}));
  ASSERT_EQ(sheet.graph.neighbours(8, kV), Labels({4, 5}));
  Labels expected = identity(8);
  expected[8] = 2;
  EXPECT_EQ(visfeat::openFaceMerge(sheet.graph), expected);
}

TEST(OpenFaces, AFaceBoundedByAClosedRimStays)
{
  // F2 (r < 8) inside the rim E3 (r 8..10), F1 outside; no vertex
  const LabelledSheet disc({kF, kF, kE}, [](int x, int y) -> std::uint32_t {
    const double r = std::max(std::abs(x - 19.5), std::abs(y - 19.5));
    return r < 8.0 ? 2 : r > 10.0 ? 1 : 3;
  });
  ASSERT_EQ(disc.graph.neighbours(2, kE), Labels({3}));
  EXPECT_EQ(visfeat::openFaceMerge(disc.graph), identity(3));
  // and a face between two creases (F1 and F2 of the crease with no sliver) stays
  const LabelledSheet plain(kSliverClasses,
                            [](int x, int y) { return creaseWithSliver(x, y, false); });
  EXPECT_EQ(visfeat::openFaceMerge(plain.graph), identity(8));
}

TEST(OpenFaces, SliversOnBothSidesJoinTheFaceEachSharesMostBoundaryWith)
{
  // F8 (y 21..23) between E3 and F2, and F9 (y 16..18) between F1 and E3: E3's faces
  // are the two slivers, and F1 and F2 both touch both of its corners
  const auto label = [](int x, int y) -> std::uint32_t {
    if (in(y, 16, 18) && in(x, 4, 19))
      return 9;
    return creaseWithSliver(x, y, true);
  };
  std::vector<FeatureClass> classes = kSliverClasses;
  classes.push_back(kF);
  const LabelledSheet sheet(classes, label);
  ASSERT_EQ(sheet.graph.facesOfEdge(3), Labels({8, 9}));
  ASSERT_EQ(sheet.graph.neighbours(4, kF), Labels({1, 2, 8, 9}));
  ASSERT_EQ(sheet.graph.neighbours(5, kF), Labels({1, 2, 8, 9}));
  // the graph alone cannot tell which face each was cut from
  EXPECT_EQ(visfeat::openFaceMerge(sheet.graph), identity(9));
  Labels expected = identity(9);
  expected[8] = 2;
  expected[9] = 1;
  EXPECT_EQ(visfeat::openFaceMerge(sheet.graph, sheet.band, sheet.labels), expected);
  EXPECT_THROW(visfeat::openFaceMerge(sheet.graph, sheet.band, Labels(3, 1)),
               visfeat::Error);
}

TEST(OpenFaces, AVertexInsideOneCreaseJoinsTheLargerCrease)
{
  // the crease with no sliver: V5 between E3 (16 x 2 cells) and E7 (13 x 2 cells)
  const LabelledSheet sheet(kSliverClasses,
                            [](int x, int y) { return creaseWithSliver(x, y, false); });
  ASSERT_EQ(sheet.graph.neighbours(5, kE), Labels({3, 7}));
  ASSERT_EQ(sheet.graph.facesOfEdge(7), Labels({1, 2}));
  Labels expected = identity(8);
  expected[5] = 3;
  expected[7] = 3;
  EXPECT_EQ(visfeat::creaseInnerVertexMerge(sheet.graph), expected);
  // with the sliver V5 touches three faces: a corner, kept
  const LabelledSheet sliver(kSliverClasses,
                             [](int x, int y) { return creaseWithSliver(x, y, true); });
  EXPECT_EQ(visfeat::creaseInnerVertexMerge(sliver.graph), identity(8));
}

TEST(OpenFaces, TheTwoEndsOfALensStay)
{
  // V4 (x <= 2) and V5 (x >= 30), y 6..23, joined by E2 (y 8..9) and E3 (y 20..21),
  // both between F1 (between them) and F6 (outside)
  const LabelledSheet sheet({kF, kE, kE, kV, kV, kF},
                            [](int x, int y) -> std::uint32_t {
                              if (in(y, 6, 23) && (x <= 2 || x >= 30))
                                return x <= 2 ? 4 : 5;
                              if (in(y, 8, 9))
                                return 2;
                              if (in(y, 20, 21))
                                return 3;
                              return in(y, 10, 19) ? 1 : 6;
                            });
  ASSERT_EQ(sheet.graph.verticesOfEdge(2), Labels({4, 5}));
  ASSERT_EQ(sheet.graph.verticesOfEdge(3), Labels({4, 5}));
  ASSERT_EQ(sheet.graph.facesOfEdge(2), Labels({1, 6}));
  ASSERT_EQ(sheet.graph.facesOfEdge(3), Labels({1, 6}));
  ASSERT_EQ(sheet.graph.neighbours(4, kF), Labels({1, 6}));
  EXPECT_EQ(visfeat::creaseInnerVertexMerge(sheet.graph), identity(6));
}

} // namespace
