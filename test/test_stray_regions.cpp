// strayRegionMerge: vertex regions along an edge instead of at its ends join their
// edge or the face of their edges, a corner split in two is joined, face specks at a
// corner join the corner, pieces of a broken rim are one edge; ends of edges,
// T-junctions, corners (of a short crease, of a lens) and faces bounded by edges stay;
// cornerSpurMerge: an edge of too few points for a turn, dead ending at a corner,
// joins it; deadEndCornerMerge: a corner of one edge beside its faces' corner joins
// the edge.

#include "graph_sheet.h"

#include <visfeat/core/common/feature_class.h>
#include <visfeat/core/graph/stray_regions.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>

namespace {

using visfeat::FeatureClass;
using Labels = visfeat_test::Labels;

constexpr FeatureClass kV = FeatureClass::kVertex;
constexpr FeatureClass kE = FeatureClass::kEdge;
constexpr FeatureClass kF = FeatureClass::kFace;

/** The labelled sheet of graph_sheet.h, with strayRegionMerge. */
struct Sheet : visfeat_test::LabelledSheet
{
  using LabelledSheet::LabelledSheet;
  Labels strayMerge() const { return visfeat::strayRegionMerge(graph); }
};

using visfeat_test::identity;
using visfeat_test::in;

/** A crease y 19..20 from corner V4 (x <= 3) to corner V5 (x >= 36) between faces F1
 * (below) and F2 (above); a blob V6 beside it, in F1. */
std::uint32_t
blobBesideACrease(int x, int y)
{
  if (in(y, 19, 20))
    return x <= 3 ? 4 : x >= 36 ? 5 : 3;
  if (in(x, 17, 19) && in(y, 16, 18))
    return 6;
  return y < 19 ? 1 : 2;
}

/** A crease y 19..20 from corner V4 (x <= 3) to corner V5 (x >= 36) between faces F1
 * (below) and F2 (above); a blob V6 beside it, in F1. */
TEST(StrayRegions, ABlobBesideACreaseJoinsTheCrease)
{
  const std::vector<FeatureClass> classes{kF, kF, kE, kV, kV, kV};
  const Sheet sheet(classes, blobBesideACrease);
  ASSERT_EQ(sheet.graph.verticesOfEdge(3).size(),
            3u); // the blob is joined to the crease
  Labels expected = identity(6);
  expected[6] = 3;
  EXPECT_EQ(sheet.strayMerge(), expected);
}

/** Corner V4 (x, y <= 2) with creases E2 (along x, y 0..1) to V5 and E3 (along y,
 * x 0..1) to V6; face F1 fills the rest but for V7, a piece of its tip beside the
 * corner (smaller than it) touching both creases: it joins F1, the face of both. */
TEST(StrayRegions, ABrokenFaceTipBesideACornerJoinsItsFace)
{
  const std::vector<FeatureClass> classes{kF, kE, kE, kV, kV, kV, kV};
  const Sheet sheet(classes, [](int x, int y) -> std::uint32_t {
    if (x <= 2 && y <= 2)
      return 4;
    if (y <= 1)
      return x >= 36 ? 5 : 2;
    if (x <= 1)
      return y >= 36 ? 6 : 3;
    if (in(x, 3, 4) && in(y, 3, 4))
      return 7;
    return 1;
  });
  ASSERT_EQ(sheet.graph.verticesOfEdge(2).size(), 3u);
  ASSERT_EQ(sheet.graph.verticesOfEdge(3).size(), 3u);
  Labels expected = identity(7);
  expected[7] = 1;
  EXPECT_EQ(sheet.strayMerge(), expected);
}

/** Crease E3 (y 19..20) from V4 to V5 between F1 and the faces F2 | F7 above it;
 * crease E8 (x 19..20, y 23..35) between F2 and F7 ends at V6 on E3 and at V9 at the
 * sheet's border: V6 lies inside E3 but is an end of E8, so it stays, and so does
 * every other vertex: nothing joins. */
TEST(StrayRegions, TheEndOfACreaseMeetingAnotherStays)
{
  const std::vector<FeatureClass> classes{kF, kF, kE, kV, kV, kV, kF, kE, kV};
  const Sheet sheet(classes, [](int x, int y) -> std::uint32_t {
    if (in(y, 19, 20))
      return x <= 3 ? 4 : x >= 36 ? 5 : 3;
    if (y < 19)
      return 1;
    if (in(x, 19, 20))
      return y <= 22 ? 6 : y >= 36 ? 9 : 8;
    return x < 19 ? 2 : 7;
  });
  ASSERT_EQ(sheet.graph.verticesOfEdge(3).size(), 3u);
  ASSERT_EQ(sheet.graph.verticesOfEdge(8).size(), 2u);
  EXPECT_EQ(sheet.strayMerge(), identity(9));
}

/** Two blobs beside one crease: both join it; its ends are still the two corners. A
 * vertex joined to no edge is left alone. */
TEST(StrayRegions, SeveralBlobsOnOneCreaseAndVerticesWithoutEdges)
{
  const std::vector<FeatureClass> classes{kF, kF, kE, kV, kV, kV, kV, kV};
  const Sheet sheet(classes, [](int x, int y) -> std::uint32_t {
    if (in(y, 19, 20))
      return x <= 3 ? 4 : x >= 36 ? 5 : 3;
    if (in(x, 8, 10) && in(y, 21, 22))
      return 6;
    if (in(x, 28, 30) && in(y, 17, 18))
      return 7;
    if (in(x, 20, 22) && in(y, 5, 7))
      return 8; // far from every edge
    return y < 19 ? 1 : 2;
  });
  ASSERT_EQ(sheet.graph.verticesOfEdge(3).size(), 4u);
  Labels expected = identity(8);
  expected[6] = expected[7] = 3;
  EXPECT_EQ(sheet.strayMerge(), expected);
}

/** A hole's rim: the ring of cells at L-infinity distance 8..10 from (19.5, 19.5) is
 * edge E3 between the outer face F1 and the inner face F2, a closed loop with no
 * corner; V4, a piece of the ring, is its only vertex and joins it. */
TEST(StrayRegions, APieceOfALoopJoinsTheLoop)
{
  const std::vector<FeatureClass> classes{kF, kF, kE, kV};
  const Sheet sheet(classes, [](int x, int y) -> std::uint32_t {
    const double r = std::max(std::abs(x - 19.5), std::abs(y - 19.5));
    if (r < 8.0)
      return 2;
    if (r > 10.0)
      return 1;
    return in(x, 17, 22) && y < 19 ? 4 : 3;
  });
  ASSERT_EQ(sheet.graph.verticesOfEdge(3).size(), 1u);
  Labels expected = identity(4);
  expected[4] = 3;
  EXPECT_EQ(sheet.strayMerge(), expected);
}

/** A square rim (r 8-10 around the sheet's middle) between the outer face F1 and the
 * inner face F2 (F5 for x >= 20 when `split_inside`), broken where the band lost its
 * core: E3 for x <= 15, E4 for x >= 24, F1 between; no corners. */
std::uint32_t
brokenRim(int x, int y, bool split_inside)
{
  const double r = std::max(std::abs(x - 19.5), std::abs(y - 19.5));
  if (r < 8.0)
    return split_inside && x >= 20 ? 5 : 2;
  if (r > 10.0)
    return 1;
  return x <= 15 ? 3 : x >= 24 ? 4 : 1;
}

TEST(StrayRegions, PiecesOfABrokenRimAreOneEdge)
{
  const Sheet sheet({kF, kF, kE, kE},
                    [](int x, int y) { return brokenRim(x, y, false); });
  ASSERT_TRUE(sheet.graph.verticesOfEdge(3).empty());
  ASSERT_EQ(sheet.graph.facesOfEdge(3), Labels({1, 2}));
  ASSERT_EQ(sheet.graph.facesOfEdge(4), Labels({1, 2}));
  Labels expected = identity(4);
  expected[4] = 3;
  EXPECT_EQ(sheet.strayMerge(), expected);
  // Rims between different faces stay apart.
  const Sheet split({kF, kF, kE, kE, kF},
                    [](int x, int y) { return brokenRim(x, y, true); });
  ASSERT_EQ(split.graph.facesOfEdge(3), Labels({1, 2}));
  ASSERT_EQ(split.graph.facesOfEdge(4), Labels({1, 5}));
  EXPECT_EQ(split.strayMerge(), identity(5));
}

/** A crease that ends in the middle of the sheet (where its faces F1 | F2 meet
 * directly beyond it), with corners at both ends: both stay. A crease with one
 * corner that joins two creases: it stays too. */
TEST(StrayRegions, TheEndOfADanglingCreaseStays)
{
  const std::vector<FeatureClass> classes{kF, kF, kE, kV, kV};
  const Sheet sheet(classes, [](int x, int y) -> std::uint32_t {
    if (in(y, 19, 20) && x <= 25)
      return x <= 3 ? 5 : x >= 23 ? 4 : 3;
    return y < 19 || (y <= 20 && x <= 30) ? 1 : 2;
  });
  ASSERT_EQ(sheet.graph.verticesOfEdge(3).size(), 2u);
  EXPECT_EQ(sheet.strayMerge(), identity(5));

  // E3 along y 19..20 ending at V4 (x 23..25) where E5 (x 23..25, y <= 18) starts:
  // V4 is E3's only vertex but joins two edges
  const std::vector<FeatureClass> l_classes{kF, kF, kE, kV, kE};
  const Sheet l_shape(l_classes, [](int x, int y) -> std::uint32_t {
    if (in(y, 19, 20) && x <= 25)
      return x >= 23 ? 4 : 3;
    if (in(x, 23, 25) && y <= 18)
      return 5;
    return y > 20 || x > 25 ? 2 : 1;
  });
  ASSERT_EQ(l_shape.graph.verticesOfEdge(3).size(), 1u);
  ASSERT_EQ(l_shape.graph.neighbours(4, kE).size(), 2u);
  EXPECT_EQ(l_shape.strayMerge(), identity(5));
}

/** Corner V4 (x, y <= 3) ends creases E2 (y 0..1) and E3 (x 0..1) between face F1
 * and the faces beyond them; F5, a few cells at the corner's tip joined to V4 alone,
 * joins it. A face as large as the corner's faces, joined to V4 alone, stays. */
TEST(StrayRegions, AFaceSpeckAtACornerJoinsTheCorner)
{
  const auto layout = [](int speck_side) {
    return [speck_side](int x, int y) -> std::uint32_t {
      if (x <= 3 && y <= 3)
        return 4;
      if (in(x, 4, 3 + speck_side) && in(y, 4, 3 + speck_side))
        return 5; // beyond the corner's tip, diagonally: away from the creases
      if (y <= 1)
        return x >= 36 ? 6 : 2;
      if (x <= 1)
        return y >= 36 ? 7 : 3;
      return 1;
    };
  };
  const std::vector<FeatureClass> classes{kF, kE, kE, kV, kF, kV, kV};
  const Sheet speck(classes, layout(2));
  ASSERT_TRUE(speck.graph.neighbours(5, kE).empty());
  ASSERT_EQ(speck.graph.neighbours(5, kV), std::vector<std::uint32_t>{4});
  Labels expected = identity(7);
  expected[5] = 4;
  EXPECT_EQ(speck.strayMerge(), expected);

  // 34 x 34 cells: larger than F1 (the rest of the sheet, about 290 cells)
  const Sheet large(classes, layout(34));
  ASSERT_TRUE(large.graph.neighbours(5, kE).empty());
  EXPECT_EQ(large.strayMerge(), identity(7));
}

/** A cross of creases from corner V1 (x, y 39..40) to V2..V5 at the sides of an 80 x
 * 80 sheet, between the quadrant faces F10..F13; a one-cell blob V14 diagonally
 * beside V1, at (38, 38), is joined (dilation radius 4) to all four creases, which
 * have no face in common. Beyond V1 as seen from the far ends of the upper and right
 * creases, it lies 4% farther from them than V1 (a tie: V1, the larger region, is
 * their end): it joins V1, the vertex they all end at. */
TEST(StrayRegions, ABlobBesideACornersCreasesJoinsTheCorner)
{
  std::vector<FeatureClass> classes{kV, kV, kV, kV, kV, kE, kE,
                                    kE, kE, kF, kF, kF, kF, kV};
  const Sheet sheet(
    classes,
    [](int x, int y) -> std::uint32_t {
      const bool mid_x = in(x, 39, 40), mid_y = in(y, 39, 40);
      if (mid_x && mid_y)
        return 1;
      if (x == 38 && y == 38)
        return 14;
      if (mid_y) // left and right arms
        return x <= 3 ? 2 : x >= 76 ? 3 : x < 39 ? 6 : 7;
      if (mid_x) // lower and upper arms
        return y <= 3 ? 4 : y >= 76 ? 5 : y < 39 ? 8 : 9;
      return (x < 39 ? 10 : 11) + (y < 39 ? 0 : 2);
    },
    4, 80);
  ASSERT_EQ(sheet.graph.neighbours(14, kE).size(), 4u);
  Labels expected = identity(14);
  expected[14] = 1;
  EXPECT_EQ(sheet.strayMerge(), expected);
}

/** Corner V4 (x, y <= 2) with crease E3 up (x <= 1) to V7 and crease E2 along y <= 1
 * to V6; beside the corner, on E2's line, a corner piece V5 (x 4) and a crease piece
 * E8 (x 3) between the two; `face` elsewhere. With dilation radius 3 E2 reaches V4
 * across the pieces. */
std::uint32_t
splitCorner(int x, int y, std::uint32_t face)
{
  if (x <= 2 && y <= 2)
    return 4;
  if (y <= 1 && x == 3)
    return 8;
  if (y <= 1 && x == 4)
    return 5;
  if (y <= 1)
    return x >= 36 ? 6 : 2;
  if (x <= 1)
    return y >= 36 ? 7 : 3;
  return face;
}

/** splitCorner with face F1: V4 and V5 each end E8, and share it and E2 (which goes
 * on to V6), so they are one corner split in two: V5 and E8 join V4, the larger. */
TEST(StrayRegions, ACornerSplitInTwoIsOneCorner)
{
  const std::vector<FeatureClass> classes{kF, kE, kE, kV, kV, kV, kV, kE};
  const Sheet sheet(
    classes, [](int x, int y) { return splitCorner(x, y, 1); }, 3);
  const std::vector<std::uint32_t> v4 = sheet.graph.neighbours(4, kE);
  const std::vector<std::uint32_t> v5 = sheet.graph.neighbours(5, kE);
  ASSERT_NE(std::find(v4.begin(), v4.end(), 2u), v4.end());
  ASSERT_NE(std::find(v5.begin(), v5.end(), 2u), v5.end());
  ASSERT_EQ(sheet.graph.verticesOfEdge(8), (std::vector<std::uint32_t>{4, 5}));
  Labels expected = identity(8);
  expected[5] = 4;
  expected[8] = 4;
  EXPECT_EQ(sheet.strayMerge(), expected);
  EXPECT_EQ(visfeat::splitCornerMerge(sheet.graph), expected);
}

/** The same split corner, with the farthest a split corner's pieces may lie apart
 * below and above V4 and V5's distance: two corners farther apart are two corners,
 * whatever edge regions they share (a fragmented crease gave two corners a whole edge
 * apart two shared edge regions, one going on to a third corner). */
TEST(StrayRegions, SplitCornerPiecesLieWithinTheGivenDistance)
{
  const std::vector<FeatureClass> classes{kF, kE, kE, kV, kV, kV, kV, kE};
  const Sheet sheet(
    classes, [](int x, int y) { return splitCorner(x, y, 1); }, 3);
  const double apart =
    (sheet.graph.node(4).centroid - sheet.graph.node(5).centroid).norm();
  ASSERT_GT(apart, 0.0);
  Labels merged = identity(8);
  merged[5] = 4;
  merged[8] = 4;
  EXPECT_EQ(sheet.graph.size(), 8u);
  EXPECT_EQ(visfeat::strayRegionMerge(sheet.graph, 1.01 * apart), merged);
  EXPECT_EQ(visfeat::splitCornerMerge(sheet.graph, 1.01 * apart), merged);
  EXPECT_NE(visfeat::strayRegionMerge(sheet.graph, 0.99 * apart)[5], 4u);
  EXPECT_EQ(visfeat::splitCornerMerge(sheet.graph, 0.99 * apart), identity(8));
}

/** The split corner (splitCorner) with a crease E9 (x 6..7, y 2..14) leaving its
 * piece V5 between F1 (x < 6) and F11 (x >= 6), and further up the same line a crease
 * E10 (y 24..30) with no corner between the same faces. E9 ends at a corner (the
 * piece is part of V4), so it is no piece of a broken rim and E10 stays apart. */
TEST(StrayRegions, ACreaseEndingAtASplitCornerIsNoPieceOfABrokenRim)
{
  const std::vector<FeatureClass> classes{kF, kE, kE, kV, kV, kV, kV, kE, kE, kE, kF};
  const Sheet sheet(
    classes,
    [](int x, int y) -> std::uint32_t {
      if (in(x, 6, 7) && in(y, 2, 14))
        return 9;
      if (in(x, 6, 7) && in(y, 24, 30))
        return 10;
      return splitCorner(x, y, x < 6 ? 1 : 11);
    },
    3);
  ASSERT_EQ(sheet.graph.verticesOfEdge(8), Labels({4, 5}));
  ASSERT_EQ(sheet.graph.verticesOfEdge(9), Labels({5}));
  ASSERT_TRUE(sheet.graph.verticesOfEdge(10).empty());
  ASSERT_EQ(sheet.graph.facesOfEdge(9), Labels({1, 11}));
  ASSERT_EQ(sheet.graph.facesOfEdge(10), Labels({1, 11}));
  Labels expected = identity(11);
  expected[5] = 4;
  expected[8] = 4;
  EXPECT_EQ(sheet.strayMerge(), expected);
}

/** Corners V4 (x <= 2) and V5 (x 9..11) at the ends of a short crease E8 (y <= 1, x
 * 3..8), each with creases of its own (E3 up from V4 to V7, E9 up from V5 to V10, E2
 * on from V5 to V6): two corners that share one edge (a chamfer's) both stay. */
TEST(StrayRegions, TwoCornersOfAShortCreaseStay)
{
  const std::vector<FeatureClass> classes{kF, kE, kE, kV, kV, kV, kV, kE, kE, kV, kF};
  const Sheet sheet(classes, [](int x, int y) -> std::uint32_t {
    if (x <= 2 && y <= 2)
      return 4;
    if (in(x, 9, 11) && y <= 2)
      return 5;
    if (y <= 1)
      return x <= 8 ? 8 : x >= 36 ? 6 : 2;
    if (x <= 1)
      return y >= 36 ? 7 : 3;
    if (in(x, 9, 10))
      return y >= 36 ? 10 : 9;
    return x < 9 ? 1 : 11;
  });
  ASSERT_EQ(sheet.graph.verticesOfEdge(8), (std::vector<std::uint32_t>{4, 5}));
  EXPECT_EQ(sheet.strayMerge(), identity(11));
  EXPECT_EQ(visfeat::splitCornerMerge(sheet.graph), identity(11));
}

/** V4 (x <= 2) and V5 (x >= 30) joined by two creases, E2 (y 0..1) and E3 (y 10..11),
 * that go nowhere else: the ends of a lens, two corners; both stay. */
TEST(StrayRegions, TheTwoEndsOfALensStay)
{
  const std::vector<FeatureClass> classes{kF, kE, kE, kV, kV, kF};
  const Sheet sheet(classes, [](int x, int y) -> std::uint32_t {
    if (y <= 11 && (x <= 2 || x >= 30))
      return x <= 2 ? 4 : 5;
    if (y <= 1)
      return 2;
    if (in(y, 10, 11))
      return 3;
    return y < 10 ? 1 : 6;
  });
  ASSERT_EQ(sheet.graph.verticesOfEdge(2), (std::vector<std::uint32_t>{4, 5}));
  ASSERT_EQ(sheet.graph.verticesOfEdge(3), (std::vector<std::uint32_t>{4, 5}));
  EXPECT_EQ(sheet.strayMerge(), identity(6));
}

/** splitCornerMerge is the split-corner rule alone: a blob beside a crease (which
 * strayRegionMerge joins to the crease) stays. */
TEST(StrayRegions, TheSplitCornerRuleAloneLeavesStrayVertices)
{
  const std::vector<FeatureClass> classes{kF, kF, kE, kV, kV, kV};
  const Sheet sheet(classes, blobBesideACrease);
  ASSERT_NE(sheet.strayMerge(), identity(6));
  EXPECT_EQ(visfeat::splitCornerMerge(sheet.graph), identity(6));
}

/** A spur: E3 (y 19..20, x 4..7) between F1 (below) and F2 (above), dead ending at
 * corner V4 (x <= 3, y 17..22), with 8 points (one a cell) and no measured turn,
 * joins V4; with
 * a measured turn, with the points a side of a sample needs, or with a corner at
 * both ends (V5, x 9..11, y 17..22) it stays. */
TEST(StrayRegions, AnEdgeOfTooFewPointsForATurnDeadEndingAtACornerJoinsIt)
{
  const std::vector<FeatureClass> classes{kF, kF, kE, kV, kV};
  const auto layout = [](bool second_corner) {
    return [=](int x, int y) -> std::uint32_t {
      if (x <= 3 && in(y, 17, 22))
        return 4;
      if (second_corner && in(x, 9, 11) && in(y, 17, 22))
        return 5;
      if (in(y, 19, 20) && in(x, 4, 7))
        return 3;
      return y < 20 ? 1 : 2;
    };
  };
  Sheet spur(classes, layout(false));
  ASSERT_EQ(spur.graph.verticesOfEdge(3), std::vector<std::uint32_t>{4});
  ASSERT_EQ(spur.graph.node(3).points, 8u);
  Labels joined = identity(5);
  joined[3] = 4;
  EXPECT_EQ(visfeat::cornerSpurMerge(spur.graph, 10), joined);
  // few points, but a measured turn: a crease
  spur.graph.setCreaseAngle(3, 30.0);
  EXPECT_EQ(visfeat::cornerSpurMerge(spur.graph, 10), identity(5));
  // no measured turn, but the points of a sample's side
  Sheet with_points(classes, layout(false));
  with_points.graph.setPointGeometry(3, 10, Eigen::Vector3d::Zero(),
                                     Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
  EXPECT_EQ(visfeat::cornerSpurMerge(with_points.graph, 10), identity(5));
  EXPECT_EQ(visfeat::cornerSpurMerge(with_points.graph, 11), joined);
  // a corner at both ends: a short crease between two corners
  const Sheet both(classes, layout(true));
  ASSERT_EQ(both.graph.verticesOfEdge(3), (std::vector<std::uint32_t>{4, 5}));
  EXPECT_EQ(visfeat::cornerSpurMerge(both.graph, 10), identity(5));
}

/** A crease E3 (y 19-20, x 12-27) between F1 (below) and F2 (above) from the corner
 * V4 (x 8-11, y 17-22, where E11 below parts F1 from F12 and E13 above F2 from F14)
 * to V5 (x 28-30), which touches nothing else: the crease stopped short and its end
 * was drawn as a corner. With `corner`, the corner the crease runs to, V6 (x 35-39,
 * y 17-22), where E7 (x 37-38, above) parts F2 from F8 and E9 (below) F1 from F10;
 * without, those cells are F1 and F2. */
std::uint32_t
deadEnd(int x, int y, bool corner)
{
  if (in(x, 8, 11) && in(y, 17, 22))
    return 4;
  if (in(x, 9, 10))
    return y < 17 ? 11 : 13;
  if (x < 9)
    return y < 20 ? 12 : 14;
  if (in(x, 28, 30) && in(y, 19, 20))
    return 5;
  if (in(x, 12, 27) && in(y, 19, 20))
    return 3;
  if (corner) {
    if (in(x, 35, 39) && in(y, 17, 22))
      return 6;
    if (in(x, 37, 38))
      return y > 22 ? 7 : 9;
    if (x > 38)
      return y > 22 ? 8 : 10;
  }
  return y < 20 ? 1 : 2;
}

TEST(StrayRegions, ACornerAtTheEndOfOneEdgeBesideItsFacesCornerJoinsTheEdge)
{
  const std::vector<FeatureClass> classes{kF, kF, kE, kV, kV, kV, kE,
                                          kF, kE, kF, kE, kF, kE, kF};
  const Sheet sheet(classes, [](int x, int y) { return deadEnd(x, y, true); });
  ASSERT_EQ(sheet.graph.verticesOfEdge(3), Labels({4, 5}));
  ASSERT_EQ(sheet.graph.neighbours(4, kE), Labels({3, 11, 13}));
  ASSERT_EQ(sheet.graph.neighbours(5, kF), Labels({1, 2}));
  ASSERT_EQ(sheet.graph.neighbours(6, kE), Labels({7, 9}));
  ASSERT_EQ(sheet.graph.neighbours(6, kF), Labels({1, 2, 8, 10}));
  Labels joined = identity(14);
  joined[5] = 3;
  EXPECT_EQ(visfeat::deadEndCornerMerge(sheet.graph), joined);
  // no corner of F1 and F2 beyond it: the end stays
  const Sheet alone(classes, [](int x, int y) { return deadEnd(x, y, false); });
  ASSERT_EQ(alone.graph.verticesOfEdge(3), Labels({4, 5}));
  EXPECT_EQ(visfeat::deadEndCornerMerge(alone.graph), identity(14));
}

} // namespace
