// The steps of FeatureSegmentation (src/core/segmentation/segmentation_steps.h) on
// hand-painted sheets: flat bands one cell thick whose visibility radii draw faces,
// edges and corners. Radius 3 = a core (min_radius 3), lower values the valleys
// between cores; the classes come from the regions' contacts, not from the geometry,
// so a flat sheet is enough.

#include "sheet_bands.h"

#include <core/segmentation/segmentation_steps.h>
#include <visfeat/core/common/error.h>
#include <visfeat/core/segmentation/feature_segmentation.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <memory>
#include <vector>

namespace {

using visfeat::CellId;
using visfeat::ComponentSet;
using visfeat::FeatureClass;
using visfeat::FeatureSegmentation;
using visfeat::SegmentationParameters;
using visfeat_test::Sheet;
namespace seg = visfeat::segmentation;

constexpr int kCap = 3; // max_radius of the painted maps

SegmentationParameters
smallParameters()
{
  SegmentationParameters p;
  p.components.min_radius = 3;
  p.components.vertex_max_cells = 4;
  p.components.dimensionality = 3.0;
  p.components.face_min_depth = 2;
  // The painted maps lie on a flat sheet: their edges are flat, and flatCore() would
  // call the long ones faces (whatever the default); these tests are about the steps
  // after the cores.
  p.components.flat_core_faces = false;
  p.vertex_reach = 5;
  p.join_distance = 4;
  p.feature_width = 1;
  return p;
}

/** An axis-aligned segment of picture cells, ends included. */
struct Line
{
  int x0, y0, x1, y1;
};

/** Chebyshev distance from (x, y) to the nearest line. */
int
lineDistance(const std::vector<Line>& lines, int x, int y)
{
  int best = 1 << 20;
  for (const Line& l : lines) {
    const int dx = x < l.x0 ? l.x0 - x : (x > l.x1 ? x - l.x1 : 0);
    const int dy = y < l.y0 ? l.y0 - y : (y > l.y1 ? y - l.y1 : 0);
    best = std::min(best, std::max(dx, dy));
  }
  return best;
}

/** A drawing of creases: cells of `cores` (segments too) have radius 3; the rest of a
 * line's cells and cells within 2 of a line 2; 3 away 1; farther, 3 (face cores). */
Sheet
creaseSheet(int width,
            int height,
            const std::vector<Line>& lines,
            const std::vector<Line>& cores)
{
  return visfeat_test::sheetFromRadius(width, height, kCap, [&](int x, int y) {
    if (lineDistance(cores, x, y) == 0)
      return 3;
    const int d = lineDistance(lines, x, y);
    return d <= 2 ? 2 : (d == 3 ? 1 : 3);
  });
}

/** Face A (x 0..5), an edge core (x = 10) and face B (x 15..20), 12 rows; between
 * them radii rise towards the edge (1 2 2 2 | 3 | 2 2 2 1), so the edge's watershed
 * region is x 7..13. */
const char* const kEdgeRow = "333333122232221333333";

Sheet
edgeSheet(bool speck = false)
{
  std::vector<std::string> rows(12, kEdgeRow);
  if (speck) // a pocket in A (x 1..4, y 4..6) holding a 2-cell core at (2..3, 5)
    for (int y = 4; y <= 6; ++y)
      for (int x = 1; x <= 4; ++x)
        rows[std::size_t(y)][std::size_t(x)] = y == 5 && (x == 2 || x == 3) ? '3' : '1';
  return visfeat_test::paintSheet(rows, kCap);
}

/** The cores of a sheet and the state of the steps over them (the state keeps
 * references: the parameters live here). */
struct Steps
{
  Steps(const Sheet& sheet, const SegmentationParameters& p)
      : parameters(p)
      , cores(
          ComponentSet::extract(sheet.band, sheet.map, parameters.components, false))
      , state(sheet.band, sheet.map, parameters, cores)
  {}
  SegmentationParameters parameters;
  ComponentSet cores;
  seg::SegmentationState state;
};

std::uint32_t
coreAt(const Sheet& sheet, const ComponentSet& cores, int x, int y)
{
  return cores.cellLabels()[std::size_t(sheet.at(x, y))];
}

FeatureClass
classAt(const Sheet& sheet, const FeatureSegmentation& s, int x, int y)
{
  return s.cellClass(sheet.at(x, y));
}

TEST(SegmentationSteps, TheWatershedGivesTheEdgeTheRisingValleys)
{
  const Sheet sheet = edgeSheet();
  Steps steps(sheet, smallParameters());
  // Cores numbered by smallest cell id: A (0, 0), the edge (10, 0), B (15, 0).
  ASSERT_EQ(steps.cores.components().size(), 3u);
  seg::growCoresIntoRegions(steps.state);
  for (int y = 0; y < 12; ++y)
    for (int x = 0; x < 21; ++x) {
      const std::uint32_t expected = x <= 6 ? 1 : (x <= 13 ? 2 : 3);
      EXPECT_EQ(steps.state.labels[std::size_t(sheet.at(x, y))], expected)
        << x << "," << y;
    }
  // 12 rows of contact on each side, both ways.
  const seg::Contacts expected{{{1, 2}, 12}, {{2, 1}, 12}, {{2, 3}, 12}, {{3, 2}, 12}};
  EXPECT_EQ(steps.state.contacts.byLabel(), expected);
}

TEST(SegmentationSteps, ContactsOfSetsAreTheLabelContactsSummedByRoot)
{
  const Sheet sheet = edgeSheet();
  Steps steps(sheet, smallParameters());
  seg::growCoresIntoRegions(steps.state);
  // The two faces in one set (root 1): their contacts with the edge add up.
  steps.state.sets.join(3, 1);
  const seg::Contacts faces{{{1, 2}, 24}, {{2, 1}, 24}};
  EXPECT_EQ(steps.state.contacts.through(steps.state.sets), faces);
  // All in one set: no contact left.
  steps.state.sets.join(1, 2);
  EXPECT_TRUE(steps.state.contacts.through(steps.state.sets).empty());
}

TEST(SegmentationSteps, AnEdgeIsNamedByTheTwoFacesItSeparates)
{
  const Sheet sheet = edgeSheet();
  Steps steps(sheet, smallParameters());
  seg::growCoresIntoRegions(steps.state);
  seg::classifyByFaces(steps.state);
  EXPECT_EQ(steps.state.cls[1], FeatureClass::kFace);
  EXPECT_EQ(steps.state.cls[2], FeatureClass::kEdge);
  EXPECT_EQ(steps.state.cls[3], FeatureClass::kFace);
  ASSERT_EQ(steps.state.signature.count(2), 1u);
  EXPECT_EQ(steps.state.signature.at(2), seg::FacePair(1, 3));
  EXPECT_EQ(steps.state.face_count[2], 2u);
}

TEST(SegmentationSteps, ASpeckMergesIntoTheFaceAroundIt)
{
  const Sheet sheet = edgeSheet(true);
  Steps steps(sheet, smallParameters());
  // A = 1, the edge = 2, B = 3, the speck (2, 5) = 4.
  ASSERT_EQ(steps.cores.components().size(), 4u);
  ASSERT_EQ(coreAt(sheet, steps.cores, 3, 5), 4u);
  seg::growCoresIntoRegions(steps.state);
  seg::classifyByFaces(steps.state);
  EXPECT_EQ(steps.state.cls[4], FeatureClass::kNone); // touches one face only
  EXPECT_EQ(steps.state.face_count[4], 1u);
  EXPECT_EQ(steps.state.speck_into[4], 1u);
  seg::findVertices(steps.state); // within 5 steps: face A only
  EXPECT_TRUE(steps.state.vertices.empty());
  seg::mergeSpecks(steps.state);
  EXPECT_EQ(steps.state.sets.find(4), 1u);
  EXPECT_EQ(steps.state.speck[4], 1);

  const auto whole =
    FeatureSegmentation::compute(sheet.band, sheet.map, smallParameters());
  EXPECT_EQ(whole.classCounts(), (std::array<std::size_t, 4>{0, 0, 1, 2}));
  EXPECT_EQ(classAt(sheet, whole, 2, 5), FeatureClass::kFace);
  EXPECT_EQ(whole.cellLabels()[std::size_t(sheet.at(2, 5))],
            whole.cellLabels()[std::size_t(sheet.at(0, 0))]);
  // The paper's literal method keeps it: a 2-cell vertex component.
  SegmentationParameters raw = smallParameters();
  raw.raw = true;
  const auto literal = FeatureSegmentation::compute(sheet.band, sheet.map, raw);
  EXPECT_EQ(literal.classCounts(), (std::array<std::size_t, 4>{0, 1, 1, 2}));
  EXPECT_EQ(classAt(sheet, literal, 2, 5), FeatureClass::kVertex);
}

// A T: faces A (top left), B (top right), C (bottom); edges AB (x = 10, y 0..6), AC
// (y = 10, x 0..6) and BC (y = 10, x 14..20) stop 4 cells short of the corner (10, 10),
// whose core is one cell.
Sheet
tSheet()
{
  return creaseSheet(
    21, 21, {{10, 0, 10, 10}, {0, 10, 20, 10}},
    {{10, 0, 10, 6}, {0, 10, 6, 10}, {14, 10, 20, 10}, {10, 10, 10, 10}});
}

TEST(SegmentationSteps, ACornerCoreReachingEdgesOfThreeFacePairsIsAVertex)
{
  const Sheet sheet = tSheet();
  Steps steps(sheet, smallParameters());
  // By smallest cell id: A, AB, B (row 0), AC, the corner, BC (row 10), C (row 14).
  ASSERT_EQ(steps.cores.components().size(), 7u);
  ASSERT_EQ(coreAt(sheet, steps.cores, 10, 10), 5u);
  seg::growCoresIntoRegions(steps.state);
  seg::classifyByFaces(steps.state);
  EXPECT_EQ(steps.state.signature.at(2), seg::FacePair(1, 3)); // AB
  EXPECT_EQ(steps.state.signature.at(4), seg::FacePair(1, 7)); // AC
  EXPECT_EQ(steps.state.signature.at(6), seg::FacePair(3, 7)); // BC
  seg::findVertices(steps.state);
  // The edges' ends are 4 steps away (vertex_reach 5), the faces' cores farther except
  // C's (4 steps): AB, AC, BC and C.
  EXPECT_EQ(steps.state.reached.at(5), (std::set<std::uint32_t>{2, 4, 6, 7}));
  EXPECT_EQ(steps.state.vertices, (std::vector<std::uint32_t>{5}));
  EXPECT_EQ(steps.state.cls[5], FeatureClass::kVertex);
  EXPECT_EQ(steps.state.signature.count(5), 0u);

  // Within 3 steps the corner core reaches no other core: it is no vertex.
  SegmentationParameters near = smallParameters();
  near.vertex_reach = 3;
  Steps short_reach(sheet, near);
  seg::growCoresIntoRegions(short_reach.state);
  seg::classifyByFaces(short_reach.state);
  seg::findVertices(short_reach.state);
  EXPECT_TRUE(short_reach.state.reached.at(5).empty());
  EXPECT_TRUE(short_reach.state.vertices.empty());
}

TEST(SegmentationSteps, TheCornerIsWhereTheEdgeLinesMeet)
{
  const Sheet sheet = tSheet();
  const auto s = FeatureSegmentation::compute(sheet.band, sheet.map, smallParameters());
  EXPECT_EQ(s.classCounts(), (std::array<std::size_t, 4>{0, 1, 3, 3}));
  // The edges are drawn from their cores' ends to the corner (10, 10); the cells
  // within 1.5 cells of it join the vertex.
  EXPECT_EQ(classAt(sheet, s, 10, 10), FeatureClass::kVertex);
  EXPECT_EQ(classAt(sheet, s, 10, 9), FeatureClass::kVertex);
  EXPECT_EQ(classAt(sheet, s, 9, 10), FeatureClass::kVertex);
  EXPECT_EQ(classAt(sheet, s, 10, 8), FeatureClass::kEdge);
  EXPECT_EQ(classAt(sheet, s, 8, 10), FeatureClass::kEdge);
  EXPECT_EQ(classAt(sheet, s, 12, 10), FeatureClass::kEdge);
  const CellId drawn = sheet.at(10, 8);
  EXPECT_TRUE(s.skeleton()[std::size_t(drawn)]);
  // Its centre lies on the segment (grid cell (11, 9, 1), centre + 0.5).
  EXPECT_EQ(s.skeletonCentres()[std::size_t(drawn)],
            Eigen::Vector3f(11.5f, 9.5f, 1.5f));
  EXPECT_FLOAT_EQ(std::abs(s.skeletonTangents()[std::size_t(drawn)].y()), 1.f);
}

// The T of tSheet without its corner core: three edges whose cores stop 3 cells short
// of (10, 10), where nothing else marks the corner.
TEST(SegmentationSteps, ACornerWithoutACoreIsWhereThreeFreeEdgeEndsMeet)
{
  const auto tWithoutCorner = [](int gap) {
    return creaseSheet(
      21, 21, {{10, 0, 10, 10}, {0, 10, 20, 10}},
      {{10, 0, 10, 10 - gap}, {0, 10, 10 - gap, 10}, {10 + gap, 10, 20, 10}});
  };
  const Sheet sheet = tWithoutCorner(3);
  const auto s = FeatureSegmentation::compute(sheet.band, sheet.map, smallParameters());
  EXPECT_EQ(s.classCounts(), (std::array<std::size_t, 4>{0, 1, 3, 3}));
  EXPECT_EQ(classAt(sheet, s, 10, 10), FeatureClass::kVertex);
  EXPECT_EQ(classAt(sheet, s, 10, 8), FeatureClass::kEdge); // drawn to the corner
  EXPECT_EQ(classAt(sheet, s, 12, 10), FeatureClass::kEdge);

  // Ends farther apart than vertex_reach (5) are not grouped: no corner.
  const Sheet far = tWithoutCorner(5);
  const auto f = FeatureSegmentation::compute(far.band, far.map, smallParameters());
  EXPECT_EQ(f.classCounts()[1], 0u);
  EXPECT_EQ(f.classCounts()[2], 3u);
}

// The T without its corner core, and without the band around the corner: the cells
// within `hole` (Chebyshev) of (10, 10) are missing, as where a sparse cloud's samples
// stop short of a sharp tip. The edges' lines meet off the band; the corner is the
// band cell nearest to their meeting point within 4 cells, or none.
TEST(SegmentationSteps, ACornerBeyondTheBandIsTheNearestBandCell)
{
  const auto tWithoutTip = [](int hole, int gap) {
    const std::vector<Line> lines{{10, 0, 10, 10}, {0, 10, 20, 10}};
    const std::vector<Line> cores{
      {10, 0, 10, 10 - gap}, {0, 10, 10 - gap, 10}, {10 + gap, 10, 20, 10}};
    return visfeat_test::sheetFromRadius(21, 21, kCap, [&](int x, int y) {
      if (std::abs(x - 10) <= hole && std::abs(y - 10) <= hole)
        return -1;
      if (lineDistance(cores, x, y) == 0)
        return 3;
      const int d = lineDistance(lines, x, y);
      return d <= 2 ? 2 : (d == 3 ? 1 : 3);
    });
  };
  SegmentationParameters p = smallParameters();
  p.vertex_reach = 8;
  const auto vertexNear = [](const Sheet& sheet, const FeatureSegmentation& s) {
    for (int y = 6; y <= 14; ++y)
      for (int x = 6; x <= 14; ++x)
        if (sheet.at(x, y) != visfeat::kNoCell &&
            classAt(sheet, s, x, y) == FeatureClass::kVertex)
          return true;
    return false;
  };
  // the nearest band cells 3 cells from the meeting point
  const Sheet cut = tWithoutTip(2, 3);
  ASSERT_EQ(cut.at(10, 10), visfeat::kNoCell);
  const auto s = FeatureSegmentation::compute(cut.band, cut.map, p);
  EXPECT_EQ(s.classCounts()[1], 1u);
  EXPECT_EQ(s.classCounts()[2], 3u);
  EXPECT_TRUE(vertexNear(cut, s));
  // 5 cells away: no corner
  const Sheet far = tWithoutTip(4, 5);
  const auto f = FeatureSegmentation::compute(far.band, far.map, p);
  EXPECT_EQ(f.classCounts()[1], 0u);
  EXPECT_EQ(f.classCounts()[2], 3u);
}

// An edge A|C (y = 20) in three pieces: x 0..16, a one-cell core at (20, 20), x
// 24..40. Above, face A holds an island B, bounded by the edge loop x in {2, 14}, y in
// {0, 12}, 14 steps from the middle core.
Sheet
edgeWithIslandSheet()
{
  const std::vector<Line> loop{
    {2, 0, 14, 0}, {2, 12, 14, 12}, {2, 0, 2, 12}, {14, 0, 14, 12}};
  std::vector<Line> lines = loop;
  lines.push_back({0, 20, 40, 20});
  std::vector<Line> cores = loop;
  cores.push_back({0, 20, 16, 20});
  cores.push_back({20, 20, 20, 20});
  cores.push_back({24, 20, 40, 20});
  return creaseSheet(41, 29, lines, cores);
}

TEST(SegmentationSteps, ASmallCoreInsideAnEdgeIsNeverAVertex)
{
  const Sheet sheet = edgeWithIslandSheet();
  SegmentationParameters p = smallParameters();
  p.vertex_reach = 14;
  Steps steps(sheet, p);
  seg::growCoresIntoRegions(steps.state);
  seg::classifyByFaces(steps.state);
  const std::uint32_t middle = coreAt(sheet, steps.cores, 20, 20);
  const std::uint32_t loop = coreAt(sheet, steps.cores, 2, 0);
  const std::uint32_t left = coreAt(sheet, steps.cores, 0, 20);
  const std::uint32_t right = coreAt(sheet, steps.cores, 40, 20);
  ASSERT_EQ(steps.cores.components()[middle - 1].cells, 1u);
  // The middle core separates the same faces as the pieces beside it; the loop
  // another pair: the vertex test alone would take it.
  ASSERT_EQ(steps.state.signature.count(middle), 1u);
  EXPECT_EQ(steps.state.signature.at(middle), steps.state.signature.at(left));
  EXPECT_EQ(steps.state.signature.at(middle), steps.state.signature.at(right));
  EXPECT_NE(steps.state.signature.at(middle), steps.state.signature.at(loop));
  seg::findVertices(steps.state);
  EXPECT_EQ(steps.state.reached.at(middle).count(loop), 1u);
  EXPECT_EQ(steps.state.reached.at(middle).count(left), 1u);
  EXPECT_EQ(steps.state.reached.at(middle).count(right), 1u);
  EXPECT_TRUE(steps.state.vertices.empty());
  EXPECT_EQ(steps.state.cls[middle], FeatureClass::kEdge);

  // In the end one edge A|C, the loop, and faces A, B, C.
  const auto s = FeatureSegmentation::compute(sheet.band, sheet.map, p);
  EXPECT_EQ(s.classCounts(), (std::array<std::size_t, 4>{0, 0, 2, 3}));
  EXPECT_EQ(s.cellLabels()[std::size_t(sheet.at(0, 20))],
            s.cellLabels()[std::size_t(sheet.at(40, 20))]);
}

// One vertical edge between A (left) and B (right), x = 10, whose ridge is lost in rows
// 10..19: cores at rows 0..9 and 20..29; in rows 12..17 the faces' cores reach x = 9
// and x = 11 and take the line, so the two pieces' regions do not touch.
Sheet
brokenEdgeSheet(int second_piece_end = 29)
{
  return visfeat_test::sheetFromRadius(21, 30, kCap, [&](int x, int y) {
    if (y >= 12 && y <= 17)
      return x == 10 ? 1 : 3;
    if (x == 10 && (y <= 9 || (y >= 20 && y <= second_piece_end)))
      return 3;
    const int d = std::abs(x - 10);
    return d <= 2 ? 2 : (d == 3 ? 1 : 3);
  });
}

TEST(SegmentationSteps, TwoPiecesOfOneStraightEdgeAreJoinedAcrossALongGap)
{
  const Sheet sheet = brokenEdgeSheet();
  Steps steps(sheet, smallParameters()); // join_distance 4, the gap is 11 cells
  ASSERT_EQ(steps.cores.components().size(), 4u); // A, piece 1, B, piece 2
  seg::growCoresIntoRegions(steps.state);
  EXPECT_EQ(steps.state.contacts.byLabel().count({2, 4}), 0u); // apart
  seg::classifyByFaces(steps.state);
  EXPECT_EQ(steps.state.signature.at(2), seg::FacePair(1, 3));
  EXPECT_EQ(steps.state.signature.at(4), seg::FacePair(1, 3));
  seg::findVertices(steps.state);
  seg::mergeSpecks(steps.state);
  seg::joinEdgeFragments(steps.state);
  EXPECT_EQ(steps.state.sets.find(4), 2u); // on one line, both 10 cells long

  const auto s = FeatureSegmentation::compute(sheet.band, sheet.map, smallParameters());
  EXPECT_EQ(s.classCounts(), (std::array<std::size_t, 4>{0, 0, 1, 2}));
}

TEST(SegmentationSteps, PiecesStayApartWithoutJoiningOrWhenTooShortForALine)
{
  SegmentationParameters off = smallParameters();
  off.join_distance = 0;
  const Sheet sheet = brokenEdgeSheet();
  EXPECT_EQ(FeatureSegmentation::compute(sheet.band, sheet.map, off).classCounts(),
            (std::array<std::size_t, 4>{0, 0, 2, 2}));
  // A second piece of 6 cells (length 5 < 8) gives no direction to join along.
  const Sheet short_piece = brokenEdgeSheet(25);
  EXPECT_EQ(
    FeatureSegmentation::compute(short_piece.band, short_piece.map, smallParameters())
      .classCounts(),
    (std::array<std::size_t, 4>{0, 0, 2, 2}));
}

TEST(SegmentationSteps, ThinningKeepsFeatureWidthCellsEachSideOfTheSkeleton)
{
  const Sheet sheet = edgeSheet();
  for (const int width : {0, 1, 2, 3, 5}) {
    SegmentationParameters p = smallParameters();
    p.feature_width = width;
    const auto s = FeatureSegmentation::compute(sheet.band, sheet.map, p);
    EXPECT_EQ(s.classCounts(), (std::array<std::size_t, 4>{0, 0, 1, 2})) << width;
    for (int y = 0; y < 12; ++y)
      for (int x = 0; x < 21; ++x) {
        // The edge's region is x 7..13; the cut keeps x 10 +- width of it.
        const bool edge = x >= 7 && x <= 13 && std::abs(x - 10) <= width;
        EXPECT_EQ(classAt(sheet, s, x, y),
                  edge ? FeatureClass::kEdge : FeatureClass::kFace)
          << "width " << width << " at " << x << "," << y;
      }
    // The rest went to the nearer face: x 7 to A, x 13 to B.
    if (width < 3) {
      EXPECT_EQ(s.cellLabels()[std::size_t(sheet.at(7, 0))],
                s.cellLabels()[std::size_t(sheet.at(0, 0))]);
      EXPECT_EQ(s.cellLabels()[std::size_t(sheet.at(13, 0))],
                s.cellLabels()[std::size_t(sheet.at(20, 0))]);
    }
  }
}

TEST(SegmentationSteps, AnEdgeCutOffItsCornerIsRejoinedAcrossAShortGap)
{
  // Hand-painted regions on the edge sheet: a face (1) everywhere, an edge (2) at
  // x = 10, y 0..5, and its corner (3) `gap` cells beyond its end, paired.
  const Sheet sheet = edgeSheet();
  const auto paint = [&](int gap, bool blocked) {
    auto steps = std::make_unique<Steps>(sheet, smallParameters());
    seg::SegmentationState& state = steps->state;
    state.cls.assign(5, FeatureClass::kNone);
    state.cls[1] = FeatureClass::kFace;
    state.cls[2] = FeatureClass::kEdge;
    state.cls[3] = FeatureClass::kVertex;
    state.cls[4] = FeatureClass::kEdge;
    state.labels.assign(sheet.band.size(), 1);
    for (int y = 0; y <= 5; ++y)
      state.labels[std::size_t(sheet.at(10, y))] = 2;
    state.labels[std::size_t(sheet.at(10, 6 + gap))] = 3;
    if (blocked) // another edge across the gap, cell (10, 6) and its sides
      for (int x = 8; x <= 12; ++x)
        state.labels[std::size_t(sheet.at(x, 6))] = 4;
    return steps;
  };
  const auto rejoined = [&](int gap, bool blocked) {
    const auto steps = paint(gap, blocked);
    seg::ThinningState thinning(steps->state);
    thinning.pairs.emplace(3u, 2u);
    std::vector<std::uint32_t> before = thinning.labels;
    seg::rejoinCutPairs(thinning);
    int changed = 0;
    for (std::size_t c = 0; c < before.size(); ++c)
      if (thinning.labels[c] != before[c]) {
        EXPECT_EQ(thinning.labels[c], 2u) << "gap " << gap;
        ++changed;
      }
    return changed;
  };
  EXPECT_EQ(rejoined(1, false), 1); // (10, 6)
  EXPECT_EQ(rejoined(2, false), 2); // (10, 6), (10, 7)
  EXPECT_EQ(rejoined(3, false), 0) << "beyond kMaxRejoinSteps";
  EXPECT_EQ(rejoined(0, false), 0) << "touching already";
  EXPECT_EQ(rejoined(1, true), 0) << "never through another feature";
}

TEST(LabelUnion, JoinKeepsTheSmallerRootAttachKeepsTheFirst)
{
  seg::LabelUnion sets(5);
  sets.join(4, 2);
  EXPECT_EQ(sets.find(4), 2u);
  sets.attach(5, 2); // 2's set merges into 5, which keeps its root (and class)
  EXPECT_EQ(sets.find(2), 5u);
  EXPECT_EQ(sets.find(4), 5u);
  sets.join(5, 1);
  EXPECT_EQ(sets.find(4), 1u);
  EXPECT_EQ(sets.find(3), 3u);
}

TEST(CoreLine, FitsAStraightRunOfCells)
{
  const Sheet sheet = edgeSheet();
  std::vector<CellId> column;
  for (int y = 0; y < 12; ++y)
    column.push_back(sheet.at(10, y));
  const seg::CoreLine line = seg::fitCoreLine(sheet.band, column);
  EXPECT_DOUBLE_EQ(line.length, 11.0);
  EXPECT_NEAR(line.width, 0.0, 1e-12);
  EXPECT_NEAR(std::abs(line.direction.y()), 1.0, 1e-12);
  EXPECT_TRUE(line.straight());
  // The lower half continues it; a parallel run 4 cells aside (> kStraightTolerance)
  // does not.
  const seg::CoreLine half = seg::fitCoreLine(
    sheet.band, std::vector<CellId>(column.begin(), column.begin() + 9));
  EXPECT_TRUE(line.onLine(half));
  std::vector<CellId> aside;
  for (int y = 0; y < 12; ++y)
    aside.push_back(sheet.at(14, y));
  EXPECT_FALSE(line.onLine(seg::fitCoreLine(sheet.band, aside)));
  // Under 8 cells long: not straight, joins nothing.
  const seg::CoreLine stub = seg::fitCoreLine(
    sheet.band, std::vector<CellId>(column.begin(), column.begin() + 8));
  EXPECT_DOUBLE_EQ(stub.length, 7.0);
  EXPECT_FALSE(stub.straight());
  EXPECT_FALSE(line.onLine(stub));
}

// addEdgeRegions (the contact creases): the listed face cells become a new edge
// region, other cells keep their labels, labels are renumbered by smallest cell id.
TEST(AddEdgeRegions, FaceCellsOfTheListBecomeAnEdgeRegion)
{
  // one face of 10 x 4 cells and a row below it without a core (raw mode: the cores
  // only); a crease two cells wide down its middle
  const auto sheet = visfeat_test::paintSheet(
    {"3333333333", "3333333333", "3333333333", "3333333333", "1111111111"}, kCap);
  SegmentationParameters p = smallParameters();
  p.raw = true;
  p.components.dimensionality = 2.0;
  FeatureSegmentation seg = FeatureSegmentation::compute(sheet.band, sheet.map, p);
  ASSERT_EQ(seg.regions().size(), 1u);
  ASSERT_EQ(seg.regions()[0].feature_class, visfeat::FeatureClass::kFace);
  std::vector<visfeat::CellId> crease, stray;
  for (int y = 0; y < 5; ++y) {
    crease.push_back(sheet.at(4, y)); // y = 4: unlabelled (radius 1), stays so
    crease.push_back(sheet.at(5, y));
  }
  const std::vector<std::uint32_t> renumbered = seg.addEdgeRegions({crease, stray});
  ASSERT_EQ(seg.regions().size(), 2u); // the empty list adds no region
  ASSERT_EQ(renumbered.size(), 2u);
  EXPECT_EQ(renumbered[1], 1u); // the face keeps label 1 (its smallest cell id, x = 0)
  for (int y = 0; y < 5; ++y)
    for (int x = 0; x < 10; ++x) {
      const std::uint32_t label = seg.cellLabels()[std::size_t(sheet.at(x, y))];
      const std::uint32_t expected = y == 4 ? 0u : (x == 4 || x == 5) ? 2u : 1u;
      EXPECT_EQ(label, expected) << x << "," << y;
    }
  EXPECT_EQ(seg.regions()[1].feature_class, visfeat::FeatureClass::kEdge);
  EXPECT_EQ(seg.regions()[1].cells, 8u);
  EXPECT_EQ(seg.regions()[0].cells, 32u);
  EXPECT_THROW(seg.addEdgeRegions({{static_cast<visfeat::CellId>(1000)}}),
               visfeat::Error);
}

} // namespace
