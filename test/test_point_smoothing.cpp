// smoothPoints: noise goes down on planes, exact planes stay, creases keep their sides
// beyond the radius, results do not depend on the thread count, bad input is refused.
#include <support/portable_random.h>
#include <visfeat/core/band/point_smoothing.h>
#include <visfeat/core/common/error.h>
#include <visfeat/core/grid/grid_spec.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

using visfeat::GridSpec;
using visfeat::SmoothingParameters;
using visfeat::smoothPoints;

namespace {

// A 64-cell grid over [-1, 1]^3 (cell ~0.034).
GridSpec
unitGrid()
{
  return GridSpec::fromBounds(Eigen::Vector3d::Constant(-1.0),
                              Eigen::Vector3d::Constant(1.0), 64);
}

// Points on the plane z = 0 (|x|, |y| < 0.8), spacing about half a cell, with Gaussian
// noise of sigma cells along z.
std::vector<Eigen::Vector3f>
noisyPlane(const GridSpec& grid, double sigma_cells, unsigned seed)
{
  visfeat::synthetic::RandomEngine rng(seed);
  visfeat::synthetic::UniformReal along(-0.8, 0.8);
  visfeat::synthetic::Normal noise(0.0, sigma_cells * grid.cell_size);
  const double area = 1.6 * 1.6;
  const auto count = static_cast<std::size_t>(area / std::pow(0.5 * grid.cell_size, 2));
  std::vector<Eigen::Vector3f> points;
  for (std::size_t i = 0; i < count; ++i)
    points.emplace_back(along(rng), along(rng), sigma_cells > 0.0 ? noise(rng) : 0.0);
  return points;
}

double
rmsZ(const std::vector<Eigen::Vector3f>& points)
{
  double sum = 0.0;
  for (const auto& p : points)
    sum += double(p.z()) * p.z();
  return std::sqrt(sum / static_cast<double>(points.size()));
}

} // namespace

TEST(PointSmoothing, NoiseOnAPlaneGoesDown)
{
  const GridSpec grid = unitGrid();
  const auto points = noisyPlane(grid, 0.32, 7);
  const auto smoothed = smoothPoints(points, grid, SmoothingParameters{});
  ASSERT_EQ(smoothed.size(), points.size());
  const double before = rmsZ(points) / grid.cell_size;
  const double after = rmsZ(smoothed) / grid.cell_size;
  EXPECT_NEAR(before, 0.32, 0.02);
  // About 50 neighbours within 2 cells: the plane's own error is ~sigma / 7.
  EXPECT_LT(after, before / 3.0) << before << " -> " << after;
  // Points move along the fitted normal, which tilts from z by the plane's small
  // random error (a few degrees): sideways moves are that tilt times the move.
  double lateral = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i)
    lateral += (smoothed[i] - points[i]).head<2>().squaredNorm();
  lateral = std::sqrt(lateral / static_cast<double>(points.size())) / grid.cell_size;
  EXPECT_LT(lateral, 0.05) << "RMS sideways move, cells";
}

TEST(PointSmoothing, ExactPlaneStays)
{
  const GridSpec grid = unitGrid();
  auto points = noisyPlane(grid, 0.0, 3);
  for (auto& p : points) // a tilted plane: x + 2y + 3z = 0.1
    p.z() = static_cast<float>((0.1 - p.x() - 2.0 * p.y()) / 3.0 * 0.5);
  for (auto& p : points)
    p *= 0.8f;
  const auto smoothed = smoothPoints(points, grid, SmoothingParameters{});
  for (std::size_t i = 0; i < points.size(); ++i)
    ASSERT_LT((smoothed[i] - points[i]).norm(), 1e-3 * grid.cell_size) << i;
}

TEST(PointSmoothing, CreaseSidesBeyondTheRadiusStay)
{
  // Two exact half-planes meeting at a right angle along the y axis: z = |x| (x in
  // [-0.6, 0.6]). Beyond the radius every neighbourhood is one plane: no point moves.
  // Within it, points are pulled inside the crease by less than the radius.
  const GridSpec grid = unitGrid();
  visfeat::synthetic::RandomEngine rng(11);
  visfeat::synthetic::UniformReal u(-0.6, 0.6);
  std::vector<Eigen::Vector3f> points;
  for (int i = 0; i < 40000; ++i) {
    const double x = u(rng), y = u(rng);
    points.emplace_back(x, y, std::abs(x));
  }
  SmoothingParameters parameters;
  parameters.radius = 2.0;
  const auto smoothed = smoothPoints(points, grid, parameters);
  std::size_t moved_far = 0, moved_near = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double from_crease =
      std::abs(points[i].x()) * std::sqrt(2.0) / grid.cell_size;
    const double moved = (smoothed[i] - points[i]).norm() / grid.cell_size;
    if (from_crease > parameters.radius + 0.1 && std::abs(points[i].y()) < 0.5)
      moved_far += moved > 1e-3;
    if (from_crease < 0.5 && std::abs(points[i].y()) < 0.5) {
      moved_near += moved > 0.05;
      EXPECT_LT(moved, parameters.radius) << i;
    }
  }
  EXPECT_EQ(moved_far, 0u);
  EXPECT_GT(moved_near, 0u); // the crease itself is rounded (the documented cost)
}

TEST(PointSmoothing, SameResultForAnyThreadCount)
{
  const GridSpec grid = unitGrid();
  const auto points = noisyPlane(grid, 0.45, 5);
  SmoothingParameters one, two;
  one.threads = 1;
  two.threads = 2;
  const auto a = smoothPoints(points, grid, one);
  const auto b = smoothPoints(points, grid, two);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i)
    ASSERT_EQ(a[i], b[i]) << i;
}

TEST(PointSmoothing, NonFinitePointsAndLonersStay)
{
  const GridSpec grid = unitGrid();
  auto points = noisyPlane(grid, 0.3, 9);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  points.emplace_back(nan, 0.0f, 0.0f);
  points.emplace_back(0.0f, 0.0f, 0.5f); // far above the plane: no neighbours
  const auto smoothed = smoothPoints(points, grid, SmoothingParameters{});
  EXPECT_TRUE(std::isnan(smoothed[points.size() - 2].x()));
  EXPECT_EQ(smoothed.back(), points.back());
}

TEST(PointSmoothing, BadInputIsRefused)
{
  const GridSpec grid = unitGrid();
  const std::vector<Eigen::Vector3f> inside{{0.0f, 0.0f, 0.0f}};
  SmoothingParameters bad;
  for (const double radius : {0.0, -1.0, 8.5, std::nan("")}) {
    bad.radius = radius;
    EXPECT_THROW(smoothPoints(inside, grid, bad), visfeat::Error) << radius;
  }
  bad = SmoothingParameters{};
  bad.threads = -1;
  EXPECT_THROW(smoothPoints(inside, grid, bad), visfeat::Error);
  const std::vector<Eigen::Vector3f> outside{{5.0f, 0.0f, 0.0f}};
  EXPECT_THROW(smoothPoints(outside, grid, SmoothingParameters{}), visfeat::Error);
}
