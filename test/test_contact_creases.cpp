// locateContactCreases() on two planes meeting at a crease whose two face regions meet
// beside it (no edge region between them), cutOffFacePieces() and FeatureSegmentation's
// moveFaceCells() that give the strip a face spilled onto back to the other face.

#include "sheet_bands.h"

#include <visfeat/core/common/error.h>
#include <visfeat/core/graph/contact_creases.h>
#include <visfeat/core/graph/face_pieces.h>
#include <visfeat/core/segmentation/feature_segmentation.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <vector>

namespace {

using visfeat::CellCoord;
using visfeat::CellId;
using visfeat::ContactCrease;
using visfeat::FeatureClass;

constexpr double kPi = 3.14159265358979323846;

/** Two half-planes meeting along the y axis (cell units, cell size 1, the crease on
 * cell centres): face A is z = 0 for x <= 0, face B leaves the crease at `turn` degrees
 * from A. The regions meet up B's side (the watershed's boundary, not the crease): B's
 * points within `spill` (1.5 unless given) of the crease are labelled A. */
struct Crease
{
  visfeat::VoxelBand band;
  std::vector<std::uint32_t> cell_labels;
  std::vector<Eigen::Vector3d> points;
  std::vector<std::uint32_t> labels;
  std::vector<FeatureClass> classes{FeatureClass::kFace, FeatureClass::kFace};
};

/** c.band from the cells of c.points (no repair), and c.cell_labels: each cell the
 * label most of its points have (the smallest among equals). */
void
bandOfPoints(Crease& c, const visfeat::GridSpec& grid)
{
  std::vector<CellCoord> cells;
  for (const Eigen::Vector3d& p : c.points)
    cells.push_back(grid.cellOf(p));
  const auto before = [](const CellCoord& a, const CellCoord& b) {
    return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
  };
  std::sort(cells.begin(), cells.end(), before);
  cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  visfeat::VoxelBand::Options options;
  options.repair = false;
  c.band = visfeat::VoxelBand::fromCells(grid, cells, options);
  std::vector<std::vector<int>> votes(c.band.size(),
                                      std::vector<int>(c.classes.size() + 1, 0));
  for (std::size_t i = 0; i < c.points.size(); ++i)
    ++votes[static_cast<std::size_t>(c.band.find(grid.cellOf(c.points[i])))]
           [c.labels[i]];
  c.cell_labels.resize(c.band.size());
  for (std::size_t k = 0; k < votes.size(); ++k)
    c.cell_labels[k] = static_cast<std::uint32_t>(
      std::max_element(votes[k].begin() + 1, votes[k].end()) - votes[k].begin());
}

Crease
creaseOfTwoPlanes(double turn, double length = 40.0, double spill = 1.5)
{
  Crease c;
  visfeat::GridSpec grid;
  grid.dims = CellCoord(64, static_cast<int>(length) + 8, 64);
  grid.cell_size = 1.0;
  grid.origin = Eigen::Vector3d(-32.5, -4.0, -32.5); // x = 0, z = 0: cell centres
  const double t = turn * kPi / 180.0;
  const Eigen::Vector3d up(-std::cos(t), 0.0, std::sin(t)); // B's direction away
  for (double y = 0.125; y < length; y += 0.25)
    for (double s = 0.125; s < 20.0; s += 0.25) {
      c.points.emplace_back(-s, y, 0.0); // A
      c.labels.push_back(1);
      c.points.push_back(Eigen::Vector3d(0.0, y, 0.0) + s * up); // B
      c.labels.push_back(s <= spill ? 1 : 2);
    }
  bandOfPoints(c, grid);
  return c;
}

std::vector<ContactCrease>
locate(const Crease& c,
       const std::set<std::array<std::uint32_t, 2>>& excluded = {},
       int threads = 1)
{
  return visfeat::locateContactCreases(c.band, c.cell_labels, c.points, c.labels,
                                       c.classes, excluded, 4.0, 20.0, 1.0, threads);
}

/** Distance of a cell centre from the true crease (the y axis). */
double
offCrease(const Crease& c, CellId cell)
{
  const Eigen::Vector3d p = c.band.grid().cellCenter(c.band.coord(cell));
  return std::hypot(p.x(), p.z());
}

/** Every cell of the crease within 1.5 cells of the true crease, and the crease
 * covered along its length (rows y = 8..39, away from the sheet's ends). */
void
expectOnTheCrease(const Crease& c, const ContactCrease& crease)
{
  std::vector<char> row(48, 0);
  for (const CellId cell : crease.cells) {
    EXPECT_LE(offCrease(c, cell), 1.5) << "cell " << cell;
    row[static_cast<std::size_t>(c.band.coord(cell).y())] = 1;
  }
  for (int y = 8; y < 40; ++y)
    EXPECT_TRUE(row[static_cast<std::size_t>(y)]) << "row " << y;
}

TEST(ContactCreases, ARightAngleCreaseIsFoundOnTheCreaseNotOnTheBoundary)
{
  const Crease c = creaseOfTwoPlanes(90.0);
  const std::vector<ContactCrease> creases = locate(c);
  ASSERT_EQ(creases.size(), 1u);
  EXPECT_EQ(creases[0].faces[0], 1u);
  EXPECT_EQ(creases[0].faces[1], 2u);
  // the fitted sides turn less than the crease (face A's side holds the strip of B it
  // spilled onto) but well above the minimum crease angle
  EXPECT_GT(creases[0].degrees, 45.0);
  EXPECT_LE(creases[0].degrees, 90.5);
  EXPECT_GE(creases[0].samples, visfeat::kMinContactCreaseSamples);
  // on the crease, not on the boundary 1.5 cells up B
  expectOnTheCrease(c, creases[0]);
}

TEST(ContactCreases, ACreaseTheBoundarySpilledFarFromIsFoundWalkingAcross)
{
  // A's region holds B's surface up to 6 cells from the crease: at the contact, the
  // planes fitted by label are one plane (B's), and the crease lies beyond the window
  const Crease c = creaseOfTwoPlanes(90.0, 40.0, 6.0);
  const std::vector<ContactCrease> creases = locate(c);
  ASSERT_EQ(creases.size(), 1u);
  EXPECT_EQ(creases[0].faces[0], 1u);
  EXPECT_EQ(creases[0].faces[1], 2u);
  EXPECT_GT(creases[0].degrees, 70.0);
  EXPECT_LE(creases[0].degrees, 90.5);
  expectOnTheCrease(c, creases[0]);
}

TEST(ContactCreases, TheStripCutOffByTheCreasesEdgeGoesToTheOtherFace)
{
  Crease c = creaseOfTwoPlanes(90.0, 40.0, 6.0);
  const std::vector<ContactCrease> creases = locate(c);
  ASSERT_EQ(creases.size(), 1u);
  // the crease's cells an edge region (label 3): A's strip on B (z >= 2) is cut off
  c.classes.push_back(FeatureClass::kEdge);
  for (const CellId cell : creases[0].cells)
    c.cell_labels[static_cast<std::size_t>(cell)] = 3;
  const std::vector<visfeat::FacePiece> pieces =
    visfeat::cutOffFacePieces(c.band, c.cell_labels, c.classes, {{{1u, 2u}}});
  ASSERT_EQ(pieces.size(), 1u);
  EXPECT_EQ(pieces[0].into, 2u);
  std::size_t strip = 0; // A's cells up B's side
  for (std::size_t k = 0; k < c.band.size(); ++k)
    strip += c.cell_labels[k] == 1 && c.band.coord(static_cast<CellId>(k)).z() >= 34;
  EXPECT_EQ(pieces[0].cells.size(), strip);
  for (const CellId cell : pieces[0].cells)
    EXPECT_GE(c.band.coord(cell).z(), 34) << "cell " << cell; // z >= 1.5: B's side
  // a piece sharing more boundary with a third face than with the pair's other stays
  EXPECT_TRUE(
    visfeat::cutOffFacePieces(c.band, c.cell_labels, c.classes, {{{1u, 3u}}}).empty());
  // without the edge, A is one piece: nothing is cut off
  const Crease whole = creaseOfTwoPlanes(90.0, 40.0, 6.0);
  EXPECT_TRUE(visfeat::cutOffFacePieces(whole.band, whole.cell_labels, whole.classes,
                                        {{{1u, 2u}}})
                .empty());
}

TEST(ContactCreases, MovedFaceCellsTakeTheirNewFace)
{
  // raw mode: two face cores of 4 x 4 cells, a valley column between them
  const auto sheet =
    visfeat_test::paintSheet({"333313333", "333313333", "333313333", "333313333"}, 3);
  visfeat::FeatureSegmentation seg = visfeat_test::rawFaceCores(sheet);
  ASSERT_EQ(seg.regions().size(), 2u);
  ASSERT_EQ(seg.regions()[0].feature_class, FeatureClass::kFace);
  ASSERT_EQ(seg.regions()[1].feature_class, FeatureClass::kFace);
  // face 1's column x = 3 and the unlabelled valley cell (4, 0) go to face 2
  const std::vector<CellId> moved{sheet.at(3, 0), sheet.at(3, 1), sheet.at(3, 2),
                                  sheet.at(3, 3), sheet.at(4, 0)};
  const std::vector<std::uint32_t> renumbered = seg.moveFaceCells({moved}, {2u});
  ASSERT_EQ(renumbered.size(), 3u);
  EXPECT_EQ(renumbered[1], 1u);
  EXPECT_EQ(renumbered[2], 2u);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 9; ++x) {
      const std::uint32_t expected = x < 3 ? 1u : x == 4 ? 0u : 2u;
      EXPECT_EQ(seg.cellLabels()[static_cast<std::size_t>(sheet.at(x, y))], expected)
        << x << "," << y;
    }
  EXPECT_EQ(seg.regions()[0].cells, 12u);
  EXPECT_EQ(seg.regions()[1].cells, 20u);
  EXPECT_THROW(seg.moveFaceCells({moved}, {3u}), visfeat::Error); // no such face
  EXPECT_THROW(seg.moveFaceCells({moved}, {}), visfeat::Error);
}

TEST(ContactCreases, AShallowTurnPlacesNoCrease)
{
  // 10 degrees: below the minimum crease angle (20)
  EXPECT_TRUE(locate(creaseOfTwoPlanes(10.0)).empty());
  EXPECT_EQ(locate(creaseOfTwoPlanes(30.0)).size(), 1u);
}

TEST(ContactCreases, PairsAnEdgeSeparatesAreLeftAlone)
{
  const Crease c = creaseOfTwoPlanes(90.0);
  EXPECT_TRUE(locate(c, {{{1u, 2u}}}).empty());
  EXPECT_EQ(locate(c, {{{1u, 3u}}}).size(), 1u);
}

TEST(ContactCreases, EachNewEdgeTakesTheTurnOfTheCreaseHoldingMostOfIt)
{
  // Faces 1 and 2; crease A (30 degrees) over cells 0-9, crease B (50 degrees) over
  // cells 8-19: they overlap at 8-9, which went to A's edge (label 3); B's edge (4)
  // holds 10-19, and a corner (5) took A's first cell. Edge 6 is an old edge.
  ContactCrease a, b;
  a.degrees = 30.0;
  b.degrees = 50.0;
  for (CellId c = 0; c < 10; ++c)
    a.cells.push_back(c);
  for (CellId c = 8; c < 20; ++c)
    b.cells.push_back(c);
  std::vector<std::uint32_t> cell_labels(24, 1);
  for (CellId c = 0; c < 10; ++c)
    cell_labels[static_cast<std::size_t>(c)] = 3;
  for (CellId c = 10; c < 20; ++c)
    cell_labels[static_cast<std::size_t>(c)] = 4;
  cell_labels[0] = 5;
  cell_labels[20] = 6;
  const std::vector<FeatureClass> classes = {
    FeatureClass::kFace, FeatureClass::kFace,   FeatureClass::kEdge,
    FeatureClass::kEdge, FeatureClass::kVertex, FeatureClass::kEdge};
  const std::vector<char> is_new = {0, 0, 0, 1, 1, 1, 0};
  const std::vector<double> turns =
    visfeat::contactCreaseTurns({a, b}, cell_labels, classes, is_new);
  ASSERT_EQ(turns.size(), 7u);
  EXPECT_EQ(turns[3], 30.0); // A's 9 cells, not B's 2
  EXPECT_EQ(turns[4], 50.0); // B's first cells lie in A's edge: B still names 4
  for (const std::size_t other : {0, 1, 2, 5, 6})
    EXPECT_TRUE(std::isnan(turns[other])) << other;
  // the creases in the other order: the same
  const std::vector<double> swapped =
    visfeat::contactCreaseTurns({b, a}, cell_labels, classes, is_new);
  EXPECT_EQ(swapped[3], 30.0);
  EXPECT_EQ(swapped[4], 50.0);
  EXPECT_THROW(visfeat::contactCreaseTurns({a}, cell_labels, classes, {0, 1}),
               visfeat::Error);
  a.cells.push_back(99); // beyond the band
  EXPECT_THROW(visfeat::contactCreaseTurns({a}, cell_labels, classes, is_new),
               visfeat::Error);
}

} // namespace

TEST(ContactCreases, TheSameForAnyThreadCount)
{
  const Crease c = creaseOfTwoPlanes(90.0, 200.0); // 9,000 cells: three chunks
  ASSERT_GT(c.band.size(), 8192u);
  const std::vector<ContactCrease> one = locate(c, {}, 1);
  ASSERT_EQ(one.size(), 1u);
  for (const int threads : {2, 0}) {
    const std::vector<ContactCrease> other = locate(c, {}, threads);
    ASSERT_EQ(other.size(), 1u);
    EXPECT_EQ(other[0].faces, one[0].faces);
    EXPECT_EQ(other[0].degrees, one[0].degrees);
    EXPECT_EQ(other[0].samples, one[0].samples);
    EXPECT_EQ(other[0].cells, one[0].cells);
  }
}

/** The corner of a cube: three quarter-planes x = 0, y = 0, z = 0 (cell units, cell
 * size 1, the planes on cell centres) of `size` cells, each a face region, with no
 * edge or vertex region between them. */
Crease
cornerOfThreePlanes(double size)
{
  Crease c;
  c.classes = {FeatureClass::kFace, FeatureClass::kFace, FeatureClass::kFace};
  visfeat::GridSpec grid;
  grid.dims = CellCoord(40, 40, 40);
  grid.cell_size = 1.0;
  grid.origin = Eigen::Vector3d(-4.5, -4.5, -4.5);
  for (double u = 0.125; u < size; u += 0.25)
    for (double v = 0.125; v < size; v += 0.25) {
      c.points.emplace_back(u, v, 0.0); // label 1: z = 0
      c.labels.push_back(1);
      c.points.emplace_back(0.0, u, v); // label 2: x = 0
      c.labels.push_back(2);
      c.points.emplace_back(v, 0.0, u); // label 3: y = 0
      c.labels.push_back(3);
    }
  bandOfPoints(c, grid);
  return c;
}

TEST(ContactCreases, ThreeCreasesOfACornerMeetAtOneVertex)
{
  const Crease c = cornerOfThreePlanes(24.0);
  const std::vector<ContactCrease> creases = locate(c);
  ASSERT_EQ(creases.size(), 3u);
  // both ends of each leave the band (past the corner, and at the sheet's border)
  for (const ContactCrease& crease : creases) {
    ASSERT_EQ(crease.open_ends.size(), 2u) << crease.faces[0] << crease.faces[1];
    EXPECT_FALSE(crease.open_ends[0].meets_edge);
    EXPECT_FALSE(crease.open_ends[1].meets_edge);
    EXPECT_LT(std::min(crease.open_ends[0].at.norm(), crease.open_ends[1].at.norm()),
              3.0);
  }
  const std::vector<std::vector<CellId>> corners =
    visfeat::contactCorners(c.band, c.cell_labels, c.classes, creases);
  ASSERT_EQ(corners.size(), 1u);
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  bool has_origin = false;
  for (const CellId cell : corners[0]) {
    const Eigen::Vector3d centre = c.band.grid().cellCenter(c.band.coord(cell));
    mean += centre;
    has_origin = has_origin || centre.norm() < 0.5;
    EXPECT_LE(centre.norm(), visfeat::kContactCornerMaxRadiusCells + 1e-9);
  }
  mean /= static_cast<double>(corners[0].size());
  EXPECT_TRUE(has_origin);
  EXPECT_LT(mean.norm(), 1.5);

  // two of the three creases alone still meet there; one alone makes no corner
  const std::vector<ContactCrease> two(creases.begin(), creases.begin() + 2);
  EXPECT_EQ(visfeat::contactCorners(c.band, c.cell_labels, c.classes, two).size(), 1u);
  const std::vector<ContactCrease> one(creases.begin(), creases.begin() + 1);
  EXPECT_TRUE(visfeat::contactCorners(c.band, c.cell_labels, c.classes, one).empty());
}

TEST(ContactCreases, ACreaseThatRunsIntoAnEdgeGetsACornerThere)
{
  // the corner's third face (label 3, y = 0) made an edge region: the crease between
  // faces 1 and 2 runs into it and ends there
  Crease c = cornerOfThreePlanes(24.0);
  c.classes[2] = FeatureClass::kEdge;
  for (std::size_t k = 0; k < c.band.size(); ++k) // the whole layer y = 0 is the edge's
    if (c.band.grid().cellCenter(c.band.coord(static_cast<CellId>(k))).y() < 0.5)
      c.cell_labels[k] = 3;
  const std::vector<ContactCrease> creases = locate(c);
  ASSERT_EQ(creases.size(), 1u);
  EXPECT_EQ(creases[0].faces[0], 1u);
  EXPECT_EQ(creases[0].faces[1], 2u);
  // the end at the corner meets the edge; the other leaves the sheet's border
  ASSERT_EQ(creases[0].open_ends.size(), 2u);
  const auto& ends = creases[0].open_ends;
  const auto& inner = ends[0].at.norm() < ends[1].at.norm() ? ends[0] : ends[1];
  const auto& outer = &inner == &ends[0] ? ends[1] : ends[0];
  EXPECT_TRUE(inner.meets_edge);
  EXPECT_FALSE(outer.meets_edge);
  EXPECT_LT(inner.at.norm(), 3.0);
  const std::vector<std::vector<CellId>> corners =
    visfeat::contactCorners(c.band, c.cell_labels, c.classes, creases);
  ASSERT_EQ(corners.size(), 1u);
  for (const CellId cell : corners[0]) {
    EXPECT_NE(c.cell_labels[static_cast<std::size_t>(cell)], 3u); // faces' cells only
    EXPECT_LT(c.band.grid().cellCenter(c.band.coord(cell)).norm(), 12.0);
  }
}
