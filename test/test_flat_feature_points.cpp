// flatFeaturePoints(): edge and vertex points whose neighbourhood is one plane go to
// the nearest face; points near a crease, noisy ground and a region's last points
// stay. The points lie on two half-planes meeting at a crease along x (cell units).

#include <visfeat/core/common/error.h>
#include <visfeat/core/segmentation/flat_feature_points.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <set>
#include <vector>

namespace {

using visfeat::CellCoord;
using visfeat::CellId;
using visfeat::FeatureClass;
using visfeat::FlatPointMove;
using visfeat::FlatPointParameters;
using visfeat::VoxelBand;

constexpr double kPi = 3.14159265358979323846;
constexpr std::uint32_t kFaceA = 1;
constexpr std::uint32_t kFaceB = 2;
constexpr std::uint32_t kEdge = 3;
constexpr std::uint32_t kStray = 4; // a vertex region on flat ground

/** Two faces meeting at a crease along x that turns by `turn` degrees: face A is the
 * plane z = 20 for v < 0, face B rises from it for v >= 0 (v: signed distance from the
 * crease along the face, cells), points 0.3 cells apart. Edge: |v| <= 1. A stray strip
 * of edge points lies on face B at v in [5, 6]; with stray_vertex, a blob of vertex
 * points at v in [9, 10], x in [5, 6] is a region of its own. noise: Gaussian, cells,
 * along the face normal. */
struct Roof
{
  VoxelBand band;
  std::vector<Eigen::Vector3f> points;
  std::vector<CellId> cells;
  std::vector<std::uint32_t> cell_labels; // the side of the cell's first point
  std::vector<FeatureClass> region_classes{FeatureClass::kFace, FeatureClass::kFace,
                                           FeatureClass::kEdge, FeatureClass::kVertex};
  std::vector<std::uint32_t> labels;
  std::vector<FeatureClass> classes;
  std::vector<double> v; // per point, its v

  Roof(double turn, bool stray_vertex, double noise = 0.0, std::uint64_t seed = 1)
  {
    const double a = turn * kPi / 180.0;
    std::mt19937_64 random(seed);
    std::normal_distribution<double> gauss(0.0, noise > 0.0 ? noise : 1.0);
    for (double s = -10.0; s <= 14.0; s += 0.3)
      for (double x = 0.15; x <= 16.0; x += 0.3) {
        const Eigen::Vector3d along = s < 0
                                        ? Eigen::Vector3d(0, 1, 0)
                                        : Eigen::Vector3d(0, std::cos(a), std::sin(a));
        const Eigen::Vector3d normal =
          s < 0 ? Eigen::Vector3d(0, 0, 1)
                : Eigen::Vector3d(0, -std::sin(a), std::cos(a));
        Eigen::Vector3d p = Eigen::Vector3d(2.0 + x, 20.0, 20.0) + s * along;
        if (noise > 0.0)
          p += gauss(random) * normal;
        points.push_back(p.cast<float>());
        v.push_back(s);
        if (std::abs(s) <= 1.0 || (s >= 5.0 && s <= 6.0)) {
          labels.push_back(kEdge);
          classes.push_back(FeatureClass::kEdge);
        } else if (stray_vertex && s >= 9.0 && s <= 10.0 && x >= 5.0 && x <= 6.0) {
          labels.push_back(kStray);
          classes.push_back(FeatureClass::kVertex);
        } else {
          labels.push_back(s < 0 ? kFaceA : kFaceB);
          classes.push_back(FeatureClass::kFace);
        }
      }
    visfeat::GridSpec grid;
    grid.dims = Eigen::Vector3i(64, 64, 64);
    std::vector<CellCoord> coords;
    for (const Eigen::Vector3f& p : points)
      coords.push_back(p.array().floor().cast<int>().matrix());
    VoxelBand::Options no_repair;
    no_repair.repair = false;
    std::vector<CellCoord> unique(coords);
    std::sort(unique.begin(), unique.end(), [](const CellCoord& l, const CellCoord& r) {
      return std::lexicographical_compare(l.data(), l.data() + 3, r.data(),
                                          r.data() + 3);
    });
    unique.erase(std::unique(unique.begin(), unique.end()), unique.end());
    band = VoxelBand::fromCells(grid, unique, no_repair);
    for (const CellCoord& c : coords)
      cells.push_back(band.find(c));
    cell_labels.assign(band.size(), 0);
    for (std::size_t i = 0; i < points.size(); ++i)
      if (cell_labels[static_cast<std::size_t>(cells[i])] == 0)
        cell_labels[static_cast<std::size_t>(cells[i])] = v[i] < 0 ? kFaceA : kFaceB;
  }

  std::vector<FlatPointMove> moves(const FlatPointParameters& parameters = {}) const
  {
    return visfeat::flatFeaturePoints(band, points, cells, points, labels, classes,
                                      cell_labels, region_classes, parameters);
  }
};

TEST(FlatFeaturePoints, StrayEdgePointsOnAFlatFaceGoToIt)
{
  for (const double turn : {30.0, 60.0, 90.0}) {
    SCOPED_TRACE(turn);
    const Roof roof(turn, false);
    std::set<std::size_t> moved;
    for (const FlatPointMove& m : roof.moves()) {
      moved.insert(m.point);
      EXPECT_EQ(m.label, kFaceB) << "v " << roof.v[m.point];
    }
    std::size_t strays = 0;
    for (std::size_t i = 0; i < roof.points.size(); ++i) {
      const bool stray = roof.v[i] >= 5.0 && roof.v[i] <= 6.0;
      strays += stray;
      // the strip is more than 1.5 cells from the crease and the ends of the roof
      const bool inner = roof.points[i].x() > 3.6 && roof.points[i].x() < 16.4;
      if (stray && inner) {
        EXPECT_EQ(moved.count(i), 1u) << "stray point at v " << roof.v[i];
      }
      if (std::abs(roof.v[i]) <= 1.0) { // within point_feature_distance of the crease
        EXPECT_EQ(moved.count(i), 0u) << "edge point at v " << roof.v[i];
      }
    }
    EXPECT_GT(strays, 0u);
    EXPECT_GE(moved.size(), strays / 2);
  }
}

TEST(FlatFeaturePoints, ARegionAllOnFlatGroundKeepsItsLeastFlatPoint)
{
  const Roof roof(90.0, true, 0.002, 3); // a trace of noise: no two balls alike
  std::vector<std::size_t> vertex_points;
  for (std::size_t i = 0; i < roof.points.size(); ++i)
    if (roof.labels[i] == kStray)
      vertex_points.push_back(i);
  ASSERT_GT(vertex_points.size(), 8u);
  std::set<std::size_t> moved;
  bool edge_moved = false;
  for (const FlatPointMove& m : roof.moves()) {
    moved.insert(m.point);
    edge_moved = edge_moved || roof.labels[m.point] == kEdge;
  }
  EXPECT_TRUE(edge_moved); // the stray strip moves: the edge keeps its crease points
  // of the vertex region all on flat ground, exactly one point stays: the least flat
  std::size_t stays = vertex_points.size(), least_flat = vertex_points.front();
  double most = -1.0;
  for (const std::size_t i : vertex_points) {
    if (moved.count(i) == 0)
      stays = i;
    std::vector<Eigen::Vector3d> ball;
    for (const Eigen::Vector3f& p : roof.points)
      if ((p - roof.points[i]).norm() <= 2.0f)
        ball.push_back(p.cast<double>());
    const double v = visfeat::surfaceVariation(ball);
    if (v > most) {
      most = v;
      least_flat = i;
    }
  }
  std::size_t kept = 0;
  for (const std::size_t i : vertex_points)
    kept += moved.count(i) == 0;
  EXPECT_EQ(kept, 1u);
  EXPECT_EQ(stays, least_flat);
}

TEST(FlatFeaturePoints, NoisyGroundKeepsItsLabels)
{
  // noise of a tenth of a cell reads above the default bound (about 9e-3 over a
  // 1.5-cell ball)
  const Roof roof(90.0, false, 0.1);
  EXPECT_TRUE(roof.moves().empty());
  // a bound above the noise's variation moves the stray strip again
  FlatPointParameters loose;
  loose.max_surface_variation = 0.02;
  EXPECT_FALSE(roof.moves(loose).empty());
}

TEST(FlatFeaturePoints, OffOrSparseMovesNothing)
{
  const Roof roof(90.0, false);
  FlatPointParameters off;
  off.max_surface_variation = 0.0;
  EXPECT_TRUE(roof.moves(off).empty());
  FlatPointParameters sparse; // more points than a 1.5-cell ball holds at 0.3 apart
  sparse.min_points = 200;
  EXPECT_TRUE(roof.moves(sparse).empty());
}

TEST(FlatFeaturePoints, TheSameForAnyThreadCount)
{
  const Roof roof(60.0, true, 0.01, 7);
  FlatPointParameters one;
  one.threads = 1;
  FlatPointParameters two;
  two.threads = 2;
  const std::vector<FlatPointMove> a = roof.moves(one);
  const std::vector<FlatPointMove> b = roof.moves(two);
  ASSERT_EQ(a.size(), b.size());
  ASSERT_FALSE(a.empty());
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k].point, b[k].point);
    EXPECT_EQ(a[k].label, b[k].label);
  }
}

TEST(FlatFeaturePoints, BadParametersAndSizesAreRefused)
{
  const Roof roof(90.0, false);
  FlatPointParameters bad;
  bad.max_surface_variation = 0.5;
  EXPECT_THROW(roof.moves(bad), visfeat::Error);
  bad = FlatPointParameters();
  bad.radius = 0.0;
  EXPECT_THROW(roof.moves(bad), visfeat::Error);
  bad = FlatPointParameters();
  bad.min_points = 2;
  EXPECT_THROW(roof.moves(bad), visfeat::Error);
  Roof wrong = roof;
  wrong.labels.pop_back();
  EXPECT_THROW(wrong.moves(), visfeat::Error);
  wrong = roof;
  wrong.cells[0] = static_cast<CellId>(roof.band.size());
  EXPECT_THROW(wrong.moves(), visfeat::Error);
  wrong = roof;
  wrong.cell_labels.pop_back();
  EXPECT_THROW(wrong.moves(), visfeat::Error);
  wrong = roof;
  wrong.region_classes.resize(1); // face B's cells name a region that is not there
  EXPECT_THROW(wrong.moves(), visfeat::Error);
}

TEST(FlatFeaturePoints, SurfaceVariationOfAPlaneAndOfACube)
{
  std::vector<Eigen::Vector3d> plane;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j)
      plane.emplace_back(i, j, 0.5 * i - 0.25 * j); // a tilted plane
  EXPECT_NEAR(visfeat::surfaceVariation(plane), 0.0, 1e-12);
  std::vector<Eigen::Vector3d> cube;
  for (int k = 0; k < 8; ++k)
    cube.emplace_back(k & 1, (k >> 1) & 1, (k >> 2) & 1);
  EXPECT_NEAR(visfeat::surfaceVariation(cube), 1.0 / 3.0, 1e-12);
  EXPECT_TRUE(std::isnan(visfeat::surfaceVariation({{0, 0, 0}, {1, 0, 0}})));
  EXPECT_TRUE(std::isnan(
    visfeat::surfaceVariation({{1, 1, 1}, {1, 1, 1}, {1, 1, 1}}))); // no spread
}

} // namespace
