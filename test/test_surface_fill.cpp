// The band from the surface: exact triangle rasterisation, the local Delaunay fill
// between sparse points, the band's fill cells, and the estimator's choice of fill.
// Creases rebuilt sharp and the faces' tangent planes: test_crease_fill.cpp.

#include "band_fixtures.h"
#include "fill_fixtures.h"

#include <visfeat/core/band/local_triangles.h>
#include <visfeat/core/band/triangle_cells.h>
#include <visfeat/core/band/voxel_band.h>
#include <visfeat/core/common/error.h>
#include <visfeat/surface_fill.h>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <set>
#include <vector>

namespace {

using namespace visfeat_test::fill;
using visfeat::CellCoord;

/** Reference: clip the triangle by the six planes of the closed box [lo, hi]
 * (Sutherland-Hodgman); it touches the box when something is left. */
bool
clippedTouches(const std::vector<Eigen::Vector3d>& triangle,
               const Eigen::Vector3d& lo,
               const Eigen::Vector3d& hi)
{
  std::vector<Eigen::Vector3d> poly = triangle;
  for (int axis = 0; axis < 3 && !poly.empty(); ++axis)
    for (int side = 0; side < 2 && !poly.empty(); ++side) {
      // keep s * (x[axis] - bound) <= 0
      const double bound = side == 0 ? hi[axis] : lo[axis];
      const double s = side == 0 ? 1.0 : -1.0;
      std::vector<Eigen::Vector3d> out;
      for (std::size_t i = 0; i < poly.size(); ++i) {
        const Eigen::Vector3d& a = poly[i];
        const Eigen::Vector3d& b = poly[(i + 1) % poly.size()];
        const double da = s * (a[axis] - bound), db = s * (b[axis] - bound);
        if (da <= 0.0)
          out.push_back(a);
        if ((da < 0.0 && db > 0.0) || (da > 0.0 && db < 0.0))
          out.push_back(a + (b - a) * (da / (da - db)));
      }
      poly = out;
    }
  return !poly.empty();
}

TEST(TriangleCells, EveryCellMatchesTheClippingReference)
{
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> at(1.0, 9.0);
  const Eigen::Vector3i dims(10, 10, 10);
  int touched = 0, borderline = 0;
  for (int t = 0; t < 60; ++t) {
    const Eigen::Vector3d a(at(rng), at(rng), at(rng)), b(at(rng), at(rng), at(rng)),
      c(at(rng), at(rng), at(rng));
    std::vector<CellCoord> cells;
    visfeat::appendTriangleCells(a, b, c, dims, cells);
    const std::set<Key> found([&] {
      std::set<Key> s;
      for (const CellCoord& x : cells)
        s.insert(key(x));
      return s;
    }());
    for (int z = 0; z < 10; ++z)
      for (int y = 0; y < 10; ++y)
        for (int x = 0; x < 10; ++x) {
          const Eigen::Vector3d lo(x, y, z);
          const bool inner =
            clippedTouches({a, b, c}, lo.array() + 1e-6, lo.array() + 1.0 - 1e-6);
          const bool outer =
            clippedTouches({a, b, c}, lo.array() - 1e-6, lo.array() + 1.0 + 1e-6);
          const bool got = found.count({x, y, z}) > 0;
          if (inner != outer) {
            ++borderline; // within 1e-6 of the box: either answer is right
            continue;
          }
          EXPECT_EQ(got, inner)
            << "triangle " << t << " cell " << x << " " << y << " " << z;
          touched += got;
        }
  }
  EXPECT_GT(touched, 1000);
  EXPECT_LT(borderline, touched / 100);
}

TEST(TriangleCells, APlaneOnACellBoundaryGivesOneLayer)
{
  // a square at z = 5 exactly, split in two triangles
  std::vector<CellCoord> cells;
  const Eigen::Vector3i dims(12, 12, 12);
  const Eigen::Vector3d p00(1, 1, 5), p10(9, 1, 5), p01(1, 9, 5), p11(9, 9, 5);
  visfeat::appendTriangleCells(p00, p10, p11, dims, cells);
  visfeat::appendTriangleCells(p00, p11, p01, dims, cells);
  std::set<Key> unique;
  for (const CellCoord& c : cells) {
    EXPECT_EQ(c.z(), 5);
    unique.insert(key(c));
  }
  // x and y from 1 to 9: the square's far sides x = 9 and y = 9 lie in cells 9, as a
  // point there would (cells are half-open)
  EXPECT_EQ(unique.size(), 81u);
}

TEST(TriangleCells, ALongSliverIsSplitAndStillExact)
{
  // a sliver across the grid, 60 cells long: split before its box is scanned
  const Eigen::Vector3d a(2.1, 2.2, 2.3), b(62.4, 61.7, 3.1), c(62.5, 61.9, 3.6);
  const Eigen::Vector3i dims(64, 64, 8);
  std::vector<CellCoord> cells;
  visfeat::appendTriangleCells(a, b, c, dims, cells);
  std::set<Key> found;
  for (const CellCoord& x : cells)
    found.insert(key(x));
  std::set<Key> brute;
  for (int z = 0; z < 8; ++z)
    for (int y = 0; y < 64; ++y)
      for (int x = 0; x < 64; ++x)
        if (visfeat::triangleTouchesCell(a, b, c, CellCoord(x, y, z)))
          brute.insert({x, y, z});
  EXPECT_EQ(found, brute);
  EXPECT_GT(brute.size(), 60u);
}

TEST(TriangleCells, RasterizeIsSortedUniqueAndThreadIndependent)
{
  visfeat::GridSpec grid;
  grid.origin = Eigen::Vector3d(-1, -1, -1);
  grid.cell_size = 0.1;
  grid.dims = Eigen::Vector3i(30, 30, 30);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> at(-0.8, 1.8);
  std::vector<Eigen::Vector3d> vertices;
  std::vector<visfeat::TriangleIndices> triangles;
  for (std::uint32_t t = 0; t < 300; ++t) {
    for (int k = 0; k < 3; ++k)
      vertices.emplace_back(at(rng), at(rng), at(rng));
    triangles.push_back({3 * t, 3 * t + 1, 3 * t + 2});
  }
  const auto one = visfeat::rasterizeTriangles(grid, vertices, triangles, 1);
  const auto two = visfeat::rasterizeTriangles(grid, vertices, triangles, 2);
  ASSERT_EQ(one.size(), two.size());
  for (std::size_t i = 0; i < one.size(); ++i)
    EXPECT_EQ(one[i], two[i]);
  for (std::size_t i = 1; i < one.size(); ++i)
    EXPECT_LT(grid.linearKey(one[i - 1]), grid.linearKey(one[i]));

  triangles.push_back({0, 1, static_cast<std::uint32_t>(vertices.size())});
  EXPECT_THROW(visfeat::rasterizeTriangles(grid, vertices, triangles, 1),
               visfeat::Error);
  triangles.pop_back();
  vertices[4].x() = std::nan("");
  EXPECT_THROW(visfeat::rasterizeTriangles(grid, vertices, triangles, 1),
               visfeat::Error);
}

/** Jittered grid points on a tilted plane, with a square hole in the middle. */
std::vector<Eigen::Vector3d>
planeWithHole(double hole_half, std::mt19937& rng)
{
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  const Eigen::Vector3d u = Eigen::Vector3d(1, 0.3, 0.2).normalized();
  const Eigen::Vector3d v = u.cross(Eigen::Vector3d(0.1, 0.2, 1)).normalized();
  std::vector<Eigen::Vector3d> points;
  for (int i = -15; i <= 15; ++i)
    for (int j = -15; j <= 15; ++j) {
      const double x = i + jitter(rng), y = j + jitter(rng);
      if (std::abs(x) < hole_half && std::abs(y) < hole_half)
        continue;
      points.push_back(x * u + y * v);
    }
  return points;
}

bool
covered(const Eigen::Vector3d& q,
        const std::vector<Eigen::Vector3d>& points,
        const std::vector<visfeat::TriangleIndices>& triangles)
{
  for (const auto& t : triangles) {
    const Eigen::Vector3d& a = points[t[0]];
    const Eigen::Vector3d& b = points[t[1]];
    const Eigen::Vector3d& c = points[t[2]];
    const Eigen::Vector3d n = (b - a).cross(c - a);
    const double area2 = n.squaredNorm();
    if (area2 <= 0.0)
      continue;
    const double l0 = (c - b).cross(q - b).dot(n) / area2;
    const double l1 = (a - c).cross(q - c).dot(n) / area2;
    const double l2 = 1.0 - l0 - l1;
    if (l0 >= -1e-9 && l1 >= -1e-9 && l2 >= -1e-9)
      return true;
  }
  return false;
}

TEST(PointsOnCells, EachPointJoinsItsCellOrTheNearestAndThreadsChangeNothing)
{
  // The cells of the plane z = 0.5 (cells of 0.1, z index 15) between x, y in [0, 1);
  // points on it, points a rounding off it, points far from it and a NaN.
  visfeat::GridSpec grid;
  grid.origin = Eigen::Vector3d(-1, -1, -1);
  grid.cell_size = 0.1;
  grid.dims = Eigen::Vector3i(30, 30, 30);
  std::vector<CellCoord> cells;
  for (int y = 10; y < 20; ++y)
    for (int x = 10; x < 20; ++x)
      cells.emplace_back(x, y, 15);
  pcl::PointCloud<pcl::PointXYZ> cloud;
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> at(0.0f, 0.999f), off(-0.02f, 0.02f);
  for (int i = 0; i < 50000; ++i) {
    const int kind = i % 10;
    const float z = kind == 0 ? -0.3f : kind == 1 ? 0.5f + off(rng) : 0.55f;
    cloud.push_back(pcl::PointXYZ(at(rng), at(rng), z));
  }
  cloud.push_back(pcl::PointXYZ(std::nanf(""), 0.0f, 0.0f));
  std::vector<visfeat::OccupiedCell> one, two;
  std::vector<std::int32_t> of_one, of_two;
  visfeat::pointsOnCells(cloud, grid, cells, one, of_one, 1);
  visfeat::pointsOnCells(cloud, grid, cells, two, of_two, 2);
  ASSERT_EQ(of_one, of_two);
  ASSERT_EQ(one.size(), two.size());
  for (std::size_t e = 0; e < one.size(); ++e) {
    EXPECT_EQ(one[e].coord, two[e].coord);
    EXPECT_EQ(one[e].offset_sum, two[e].offset_sum);
    EXPECT_EQ(one[e].point_count, two[e].point_count);
  }
  EXPECT_EQ(one.size(), cells.size());
  std::size_t counted = 0;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const pcl::PointXYZ& p = cloud[i];
    if (!std::isfinite(p.x) || p.z < 0.0f) { // NaN, or 0.8 from the plane: none
      EXPECT_EQ(of_one[i], -1) << i;
      continue;
    }
    ASSERT_GE(of_one[i], 0) << i;
    ++counted;
    const CellCoord c = one[static_cast<std::size_t>(of_one[i])].coord;
    // its own column of the plane (a point off it by a rounding takes its neighbour)
    EXPECT_EQ(c, CellCoord(grid.cellOf(Eigen::Vector3d(p.x, p.y, 0.55)))) << i;
  }
  std::size_t total = 0;
  for (const visfeat::OccupiedCell& o : one)
    total += o.point_count;
  EXPECT_EQ(total, counted);
}

TEST(LocalTriangles, CoverThePlaneAndLeaveTheHoleOpen)
{
  std::mt19937 rng(3);
  const std::vector<Eigen::Vector3d> points = planeWithHole(4.0, rng);
  visfeat::LocalTriangleParameters parameters;
  const int k = parameters.neighbours + 1;
  const auto triangles =
    visfeat::umbrellaTriangles(points, nearest(points, k), k, parameters, 2);
  ASSERT_FALSE(triangles.empty());
  const Eigen::Vector3d u = Eigen::Vector3d(1, 0.3, 0.2).normalized();
  const Eigen::Vector3d v = u.cross(Eigen::Vector3d(0.1, 0.2, 1)).normalized();
  // every point of the sampled area away from the border and the hole is covered
  int tested = 0;
  for (double x = -12.5; x <= 12.5; x += 0.7)
    for (double y = -12.5; y <= 12.5; y += 0.7) {
      if (std::abs(x) < 6.0 && std::abs(y) < 6.0)
        continue;
      EXPECT_TRUE(covered(x * u + y * v, points, triangles)) << x << " " << y;
      ++tested;
    }
  EXPECT_GT(tested, 1000);
  // the hole, 8 spacings wide, is wider than max_edge_spacings local spacings
  EXPECT_FALSE(covered(Eigen::Vector3d::Zero(), points, triangles));
  // thread count changes nothing
  EXPECT_EQ(triangles,
            visfeat::umbrellaTriangles(points, nearest(points, k), k, parameters, 1));
}

TEST(LocalTriangles, BadInputIsRefused)
{
  const std::vector<Eigen::Vector3d> points(3, Eigen::Vector3d::Zero());
  visfeat::LocalTriangleParameters parameters;
  EXPECT_THROW(visfeat::umbrellaTriangles(points, {0, 1}, 2, parameters, 1),
               visfeat::Error);
  parameters.neighbours = 1;
  EXPECT_THROW(visfeat::umbrellaTriangles(points, {}, 0, parameters, 1),
               visfeat::Error);
  // coincident points make no triangle
  parameters = visfeat::LocalTriangleParameters{};
  EXPECT_TRUE(
    visfeat::umbrellaTriangles(points, {0, 1, 2, 1, 0, 2, 2, 0, 1}, 3, parameters, 1)
      .empty());
}

TEST(VoxelBandFill, FillCellsJoinWithoutPoints)
{
  visfeat::GridSpec grid;
  grid.origin = Eigen::Vector3d::Zero();
  grid.cell_size = 1.0;
  grid.dims = Eigen::Vector3i(10, 10, 10);
  std::vector<visfeat::OccupiedCell> occupied(2);
  occupied[0].coord = CellCoord(2, 2, 2);
  occupied[0].point_count = 3;
  occupied[1].coord = CellCoord(6, 2, 2);
  occupied[1].point_count = 1;
  const std::vector<std::int32_t> point_occupied{0, 0, 1, 0};
  // the fill repeats an occupied cell and itself
  const std::vector<CellCoord> fill{
    {3, 2, 2}, {4, 2, 2}, {5, 2, 2}, {4, 2, 2}, {6, 2, 2}};
  visfeat::VoxelBand::Options options;
  const visfeat::VoxelBand band =
    visfeat::VoxelBand::build(grid, occupied, point_occupied, options, fill);
  EXPECT_EQ(band.size(), 5u);
  EXPECT_EQ(band.fillCellCount(), 3u);
  EXPECT_EQ(band.repairCellCount(), 0u);
  EXPECT_EQ(band.pointCount(band.find(CellCoord(4, 2, 2))), 0u);
  EXPECT_EQ(band.pointCount(band.find(CellCoord(6, 2, 2))), 1u);
  EXPECT_EQ(band.pointCell()[2], band.find(CellCoord(6, 2, 2)));
  EXPECT_NE(band.neighbours(band.find(CellCoord(4, 2, 2)))[1], visfeat::kNoCell);
  EXPECT_THROW(visfeat::VoxelBand::build(grid, occupied, point_occupied, options,
                                         {CellCoord(10, 0, 0)}),
               visfeat::Error);
}

TEST(SurfaceFillNames, RoundTrip)
{
  for (const auto fill :
       {visfeat::SurfaceFill::kAuto, visfeat::SurfaceFill::kPoints,
        visfeat::SurfaceFill::kLocalTriangles, visfeat::SurfaceFill::kMesh}) {
    visfeat::SurfaceFill parsed = visfeat::SurfaceFill::kAuto;
    ASSERT_TRUE(visfeat::parseSurfaceFill(visfeat::surfaceFillName(fill), parsed));
    EXPECT_EQ(parsed, fill);
  }
  visfeat::SurfaceFill parsed = visfeat::SurfaceFill::kPoints;
  EXPECT_FALSE(visfeat::parseSurfaceFill("splats", parsed));
  EXPECT_EQ(parsed, visfeat::SurfaceFill::kPoints);
}

} // namespace
