// locateContactCreases() on two planes meeting at a crease whose two face regions meet
// a cell beside it (no edge region between them), and FeatureSegmentation's
// addEdgeRegions() that turns the crease's cells into an edge.

#include <visfeat/core/graph/contact_creases.h>

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
 * cell centres): face A is z = 0 for x <= 0, face B turns up from it by `turn`
 * degrees. The regions meet one cell up B's side (the watershed's boundary, not the
 * crease): B's points within 1.5 of the crease are labelled A. */
struct Crease
{
  visfeat::VoxelBand band;
  std::vector<std::uint32_t> cell_labels;
  std::vector<Eigen::Vector3d> points;
  std::vector<std::uint32_t> labels;
  std::vector<FeatureClass> classes{FeatureClass::kFace, FeatureClass::kFace};
};

Crease
creaseOfTwoPlanes(double turn, double length = 40.0)
{
  Crease c;
  visfeat::GridSpec grid;
  grid.dims = CellCoord(64, static_cast<int>(length) + 8, 64);
  grid.cell_size = 1.0;
  grid.origin = Eigen::Vector3d(-32.5, -4.0, -32.5); // x = 0, z = 0: cell centres
  const double t = turn * kPi / 180.0;
  const Eigen::Vector3d up(-std::cos(t), 0.0, std::sin(t)); // B's direction away
  std::vector<CellCoord> cells;
  for (double y = 0.125; y < length; y += 0.25)
    for (double s = 0.125; s < 20.0; s += 0.25) {
      c.points.emplace_back(-s, y, 0.0); // A
      c.labels.push_back(1);
      c.points.push_back(Eigen::Vector3d(0.0, y, 0.0) + s * up); // B
      c.labels.push_back(s <= 1.5 ? 1 : 2);
    }
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
  // a cell takes the label of most of its points
  std::vector<std::array<int, 3>> votes(c.band.size(), {0, 0, 0});
  for (std::size_t i = 0; i < c.points.size(); ++i)
    ++votes[static_cast<std::size_t>(c.band.find(grid.cellOf(c.points[i])))]
           [c.labels[i]];
  c.cell_labels.resize(c.band.size());
  for (std::size_t k = 0; k < votes.size(); ++k)
    c.cell_labels[k] = votes[k][2] > votes[k][1] ? 2u : 1u;
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
  // every cell within 1.5 cells of the crease (the boundary is 1.5 up B), and the
  // crease covered along its length (rows y = 4..35, away from the sheet's ends)
  std::vector<char> row(48, 0);
  for (const CellId cell : creases[0].cells) {
    EXPECT_LE(offCrease(c, cell), 1.5) << "cell " << cell;
    row[static_cast<std::size_t>(c.band.coord(cell).y())] = 1;
  }
  for (int y = 8; y < 40; ++y)
    EXPECT_TRUE(row[static_cast<std::size_t>(y)]) << "row " << y;
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
