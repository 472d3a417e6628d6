// creasedFacePieces() on one face region that holds a crease (two half-planes, a roof)
// and on faces that hold none (a plane, a shallow turn, a cylinder);
// rejoinCreasedFacePieces(), and FeatureSegmentation's splitFaces().

#include "sheet_bands.h"

#include <visfeat/core/common/error.h>
#include <visfeat/core/graph/face_creases.h>
#include <visfeat/core/segmentation/feature_segmentation.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

namespace {

using visfeat::CellCoord;
using visfeat::CellId;
using visfeat::CreasedFacePiece;
using visfeat::FeatureClass;

constexpr double kPi = 3.14159265358979323846;

/** One face region (label 1) over the cells of `points` (cell units, cell size 1) and
 * the cells the band's repair adds. */
struct OneFace
{
  visfeat::VoxelBand band;
  std::vector<std::uint32_t> cell_labels;
  std::vector<Eigen::Vector3d> points;
  std::vector<CellId> point_cells;
  std::vector<FeatureClass> classes{FeatureClass::kFace};
};

/** Points 0.25 cells apart over (u, v) in [0, 48) x [0, 40), placed by `surface`; the
 * grid holds them with a margin of 8 cells. */
OneFace
faceOf(const std::function<Eigen::Vector3d(double, double)>& surface)
{
  OneFace f;
  for (double v = 0.125; v < 40.0; v += 0.25)
    for (double u = 0.125; u < 48.0; u += 0.25)
      f.points.push_back(surface(u, v));
  Eigen::Vector3d lo = f.points[0], hi = lo;
  for (const Eigen::Vector3d& p : f.points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  visfeat::GridSpec grid;
  grid.cell_size = 1.0;
  grid.origin = (lo.array() - 8.0).floor().matrix();
  grid.dims = ((hi - grid.origin).array() + 9.0).ceil().cast<int>().matrix();
  std::vector<CellCoord> cells;
  for (const Eigen::Vector3d& p : f.points)
    cells.push_back(grid.cellOf(p));
  const auto before = [](const CellCoord& a, const CellCoord& b) {
    return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
  };
  std::sort(cells.begin(), cells.end(), before);
  cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  // repaired, as the estimator's bands are: 6-connected across the stair steps
  f.band = visfeat::VoxelBand::fromCells(grid, cells, visfeat::VoxelBand::Options());
  f.cell_labels.assign(f.band.size(), 1u);
  for (const Eigen::Vector3d& p : f.points)
    f.point_cells.push_back(f.band.find(grid.cellOf(p)));
  return f;
}

/** A roof: flat for u < 24, then turning up by `turn` degrees about the line u = 24
 * (along v), tilted against the grid. */
OneFace
roof(double turn)
{
  const double t = turn * kPi / 180.0;
  const Eigen::Matrix3d tilt = (Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()) *
                                Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitX()))
                                 .toRotationMatrix();
  return faceOf([=](double u, double v) {
    const double s = u - 24.0;
    const Eigen::Vector3d p = s < 0.0
                                ? Eigen::Vector3d(s, v, 0.0)
                                : Eigen::Vector3d(s * std::cos(t), v, s * std::sin(t));
    return Eigen::Vector3d(tilt * p);
  });
}

std::vector<CreasedFacePiece>
piecesOf(const OneFace& f)
{
  visfeat::FaceCreaseParameters p;
  p.threads = 1;
  return visfeat::creasedFacePieces(f.band, f.cell_labels, f.points, f.point_cells,
                                    f.classes, p);
}

TEST(FaceCreases, ACreaseInsideAFaceCutsItAtTheCrease)
{
  for (const double turn : {25.0, 45.0, 90.0}) {
    const OneFace f = roof(turn);
    const std::vector<CreasedFacePiece> pieces = piecesOf(f);
    ASSERT_EQ(pieces.size(), 1u) << turn;
    EXPECT_EQ(pieces[0].face, 1u);
    // the piece is one side of the crease: every cell of it within 2 cells of that
    // side, every other cell within 2 cells of the other
    const Eigen::Matrix3d untilt = (Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()) *
                                    Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitX()))
                                     .toRotationMatrix()
                                     .transpose();
    const double t = turn * kPi / 180.0;
    // signed distance across the crease: from the flat side's direction (-1, 0, 0)
    // towards the turned side's (cos t, 0, sin t)
    const Eigen::Vector3d across =
      Eigen::Vector3d(1.0 + std::cos(t), 0.0, std::sin(t)).normalized();
    std::vector<char> in_piece(f.band.size(), 0);
    for (const CellId c : pieces[0].cells)
      in_piece[static_cast<std::size_t>(c)] = 1;
    double piece_side = 0.0;
    for (const CellId c : pieces[0].cells)
      piece_side += across.dot(untilt * f.band.grid().cellCenter(f.band.coord(c)));
    const double sign = piece_side >= 0.0 ? 1.0 : -1.0;
    for (std::size_t c = 0; c < f.band.size(); ++c) {
      const double s = sign * across.dot(untilt * f.band.grid().cellCenter(f.band.coord(
                                                    static_cast<CellId>(c))));
      if (in_piece[c])
        EXPECT_GE(s, -2.0) << turn << " cell " << c;
      else
        EXPECT_LE(s, 2.0) << turn << " cell " << c;
    }
    EXPECT_GT(pieces[0].cells.size(), f.band.size() / 3);
    EXPECT_LT(pieces[0].cells.size(), 2 * f.band.size() / 3);
  }
}

TEST(FaceCreases, APlaneAShallowTurnAndACylinderHoldNone)
{
  EXPECT_TRUE(piecesOf(roof(0.0)).empty());
  EXPECT_TRUE(piecesOf(roof(10.0)).empty());
  // a cylinder of radius 30 cells, its axis along v
  EXPECT_TRUE(piecesOf(faceOf([](double u, double v) {
                const double a = u / 30.0;
                return Eigen::Vector3d(30.0 * std::sin(a), v,
                                       30.0 * (1.0 - std::cos(a)));
              }))
                .empty());
}

TEST(FaceCreases, TooFewPointsOrSmallPartsCutNothing)
{
  OneFace f = roof(45.0);
  visfeat::FaceCreaseParameters p;
  p.threads = 1;
  p.min_piece_cells = f.band.size(); // no part is that large
  EXPECT_TRUE(visfeat::creasedFacePieces(f.band, f.cell_labels, f.points, f.point_cells,
                                         f.classes, p)
                .empty());
  p = visfeat::FaceCreaseParameters();
  p.min_points = f.points.size() + 1;
  EXPECT_TRUE(visfeat::creasedFacePieces(f.band, f.cell_labels, f.points, f.point_cells,
                                         f.classes, p)
                .empty());
  // the points are an edge's: no face to split
  f.classes[0] = FeatureClass::kEdge;
  EXPECT_TRUE(piecesOf(f).empty());
  f.point_cells.pop_back();
  EXPECT_THROW(piecesOf(f), visfeat::Error);
  f.point_cells.push_back(static_cast<CellId>(f.band.size())); // not a band cell
  EXPECT_THROW(piecesOf(f), visfeat::Error);
}

TEST(FaceCreases, PiecesJoinAgainUnlessTheirContactIsACrease)
{
  // four columns of cells: regions 1 | 2 | 3 | 4; 1, 2 and 3 cut from face 1, 4 not
  const auto sheet = visfeat_test::paintSheet({"33333333", "33333333"}, 3);
  std::vector<std::uint32_t> cell_labels(sheet.band.size(), 0);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 8; ++x)
      cell_labels[static_cast<std::size_t>(sheet.at(x, y))] =
        static_cast<std::uint32_t>(1 + x / 2);
  const std::vector<std::uint32_t> origin{0, 1, 1, 1, 4};
  // no crease: 1, 2 and 3 are one face again; 4 was never cut from it
  std::vector<std::uint32_t> into =
    visfeat::rejoinCreasedFacePieces(sheet.band, cell_labels, origin, {});
  EXPECT_EQ(into, (std::vector<std::uint32_t>{0, 1, 1, 1, 4}));
  // the contact of 1 and 2 is a crease: 2 and 3 join, 1 stays
  into =
    visfeat::rejoinCreasedFacePieces(sheet.band, cell_labels, origin, {{{1u, 2u}}});
  EXPECT_EQ(into, (std::vector<std::uint32_t>{0, 1, 2, 2, 4}));
  into = visfeat::rejoinCreasedFacePieces(sheet.band, cell_labels, origin,
                                          {{{1u, 2u}}, {{2u, 3u}}});
  EXPECT_EQ(into, (std::vector<std::uint32_t>{0, 1, 2, 3, 4}));
}

TEST(FaceCreases, SplitFacesGivesEachListANewFace)
{
  // raw mode: two face cores of 4 x 4 cells, a valley column between them
  const auto sheet =
    visfeat_test::paintSheet({"333313333", "333313333", "333313333", "333313333"}, 3);
  visfeat::FeatureSegmentation seg = visfeat_test::rawFaceCores(sheet);
  ASSERT_EQ(seg.regions().size(), 2u);
  // face 2's columns x = 7, 8 a face of their own; the valley cell (4, 0) has none
  std::vector<CellId> piece{sheet.at(4, 0)};
  for (int y = 0; y < 4; ++y)
    for (int x = 7; x < 9; ++x)
      piece.push_back(sheet.at(x, y));
  const std::vector<std::uint32_t> renumbered = seg.splitFaces({piece});
  EXPECT_EQ(renumbered, (std::vector<std::uint32_t>{0, 1, 2}));
  ASSERT_EQ(seg.regions().size(), 3u);
  EXPECT_EQ(seg.regions()[2].feature_class, FeatureClass::kFace);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 9; ++x) {
      const std::uint32_t expected = x < 4 ? 1u : x == 4 ? 0u : x < 7 ? 2u : 3u;
      EXPECT_EQ(seg.cellLabels()[static_cast<std::size_t>(sheet.at(x, y))], expected)
        << x << "," << y;
    }
  EXPECT_EQ(seg.regions()[1].cells, 8u);
  EXPECT_EQ(seg.regions()[2].cells, 8u);
  EXPECT_THROW(seg.splitFaces({{CellId(sheet.band.size())}}), visfeat::Error);
}

} // namespace
