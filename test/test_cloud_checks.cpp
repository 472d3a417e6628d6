// The PCL-free checks behind the estimator: GridSpec::cellOf (the one point-to-cell
// function), the shape of a cloud (collinear, thin, coplanar), the resolution from the
// point spacing, and the parameter ranges with their messages.

#include <visfeat/core/band/point_smoothing.h>
#include <visfeat/core/common/error.h>
#include <visfeat/core/common/parameters.h>
#include <visfeat/core/graph/topology_graph.h>
#include <visfeat/core/grid/cloud_shape.h>
#include <visfeat/core/grid/grid_spec.h>
#include <visfeat/core/grid/resolution.h>
#include <visfeat/core/segmentation/feature_segmentation.h>
#include <visfeat/core/visibility/visibility_map.h>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace {

using visfeat::CellCoord;
using visfeat::GridSpec;

/** The message visfeat::Error carries, or "" when f does not throw. */
std::string
errorOf(const std::function<void()>& f)
{
  try {
    f();
  } catch (const visfeat::Error& e) {
    return e.what();
  }
  return "";
}

// ---------------------------------------------------------------- cellOf

TEST(GridSpecCellOf, IsTheFloorOfCellUnitsInsideTheGrid)
{
  const GridSpec grid = GridSpec::fromBounds(Eigen::Vector3d(-1.0, 0.5, 2.0),
                                             Eigen::Vector3d(1.0, 1.5, 2.25), 40);
  std::mt19937_64 rng(91);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const Eigen::Vector3d size = grid.cell_size * grid.dims.cast<double>();
  for (int i = 0; i < 10000; ++i) {
    const Eigen::Vector3d p =
      grid.origin + Eigen::Vector3d(u(rng), u(rng), u(rng)).cwiseProduct(size);
    const CellCoord c = grid.cellOf(p);
    const Eigen::Vector3d q = grid.toCellUnits(p);
    ASSERT_EQ(c, q.array().floor().cast<int>().matrix()) << p.transpose();
    ASSERT_TRUE(grid.contains(c));
  }
  // Cell (i, j, k) holds its lower faces, not its upper ones.
  const CellCoord c(3, 4, 5);
  const Eigen::Vector3d corner = grid.origin + grid.cell_size * c.cast<double>();
  EXPECT_EQ(grid.cellOf(corner), c);
  EXPECT_EQ(grid.cellOf(grid.cellCenter(c)), c);
  EXPECT_TRUE(
    grid.toCellUnits(grid.cellCenter(c)).isApprox(Eigen::Vector3d(3.5, 4.5, 5.5)));
}

TEST(GridSpecCellOf, OutsideTheGridIsNotContained)
{
  GridSpec grid;
  grid.dims = Eigen::Vector3i(4, 5, 6);
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(grid.cellOf(Eigen::Vector3d(-0.25, 1.5, 2.5)), CellCoord(-1, 1, 2));
  EXPECT_EQ(grid.cellOf(Eigen::Vector3d(4.0, 5.0, 6.0)), CellCoord(4, 5, 6));
  EXPECT_EQ(grid.cellOf(Eigen::Vector3d(3.999, 4.999, 5.999)), CellCoord(3, 4, 5));
  EXPECT_EQ(grid.cellOf(Eigen::Vector3d(1e300, -1e300, nan)), CellCoord(4, -1, -1));
  EXPECT_EQ(grid.cellOf(Eigen::Vector3d(inf, -inf, 0.0)), CellCoord(4, -1, 0));
  for (const Eigen::Vector3d& p :
       {Eigen::Vector3d(-0.25, 1.5, 2.5), Eigen::Vector3d(1.0, 5.0, 1.0),
        Eigen::Vector3d(nan, 1.0, 1.0), Eigen::Vector3d(1.0, 1.0, 1e20)})
    EXPECT_FALSE(grid.contains(grid.cellOf(p))) << p.transpose();
}

// ---------------------------------------------------------------- shape

std::vector<Eigen::Vector3d>
randomPoints(std::size_t n, const Eigen::Vector3d& scale, std::uint64_t seed)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  std::vector<Eigen::Vector3d> points;
  for (std::size_t i = 0; i < n; ++i)
    points.push_back(Eigen::Vector3d(u(rng), u(rng), u(rng)).cwiseProduct(scale));
  return points;
}

TEST(CloudShape, WidthsAndExtent)
{
  const std::vector<Eigen::Vector3d> box =
    randomPoints(20000, Eigen::Vector3d(2.0, 1.0, 0.5), 92);
  const visfeat::CloudShape shape = visfeat::cloudShape(box);
  EXPECT_EQ(shape.finite, box.size());
  EXPECT_NEAR(shape.extent, 2.0, 0.01);
  EXPECT_NEAR(shape.widths[0], 2.0, 0.05);
  EXPECT_NEAR(shape.widths[1], 1.0, 0.05);
  EXPECT_NEAR(shape.widths[2], 0.5, 0.05);
  EXPECT_FALSE(visfeat::isCollinear(shape));
  EXPECT_FALSE(visfeat::isCoplanar(shape));
  EXPECT_EQ(visfeat::shapeProblem(shape, 256), "");
  EXPECT_EQ(visfeat::shapeNote(shape), "");
}

TEST(CloudShape, LinesArePlanesAreNotedTooFewPointsAreLeftToTheGrid)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<Eigen::Vector3d> line;
  for (int i = 0; i < 50; ++i)
    line.push_back(Eigen::Vector3d(1.0, 2.0, 3.0) +
                   i * Eigen::Vector3d(0.3, -0.1, 0.2));
  line.push_back(Eigen::Vector3d(nan, 0.0, 0.0));
  const visfeat::CloudShape l = visfeat::cloudShape(line);
  EXPECT_EQ(l.finite, 50u);
  EXPECT_TRUE(visfeat::isCollinear(l));
  const std::string collinear =
    "all 50 finite points lie on a line (collinear): there is no surface to label";
  EXPECT_EQ(visfeat::shapeProblem(l, 0), collinear);
  EXPECT_EQ(visfeat::shapeProblem(l, 256), collinear);

  std::vector<Eigen::Vector3d> plane = randomPoints(5000, Eigen::Vector3d(1, 1, 0), 93);
  const visfeat::CloudShape p = visfeat::cloudShape(plane);
  EXPECT_TRUE(visfeat::isCoplanar(p));
  EXPECT_FALSE(visfeat::isCollinear(p));
  EXPECT_EQ(visfeat::shapeProblem(p, 256), "");
  EXPECT_EQ(visfeat::shapeNote(p),
            "all points lie in a plane: expect one face and no edges or vertices (the "
            "outline of a flat patch is a boundary, not a crease)");

  // A bar 1 x 0.02 x 0.005: 1.28 cells across at 64, 2.56 at 128.
  const visfeat::CloudShape bar =
    visfeat::cloudShape(randomPoints(5000, Eigen::Vector3d(1.0, 0.02, 0.005), 94));
  const double across = bar.widths[1] / (bar.extent / 64);
  EXPECT_NEAR(across, 1.3, 0.03);
  EXPECT_EQ(visfeat::shapeProblem(bar, 0), ""); // no resolution: only the line test
  std::ostringstream thin;
  thin << "the points lie within " << across
       << " cells of a line at resolution 64: a surface needs at least 2 cells across; "
          "raise the resolution";
  EXPECT_EQ(visfeat::shapeProblem(bar, 64), thin.str());
  EXPECT_EQ(visfeat::shapeProblem(bar, 128), "");

  for (const std::vector<Eigen::Vector3d>& few :
       {std::vector<Eigen::Vector3d>{}, std::vector<Eigen::Vector3d>{{1, 2, 3}},
        std::vector<Eigen::Vector3d>{{1, 2, 3}, {1, 2, 3}, {nan, 0, 0}}}) {
    const visfeat::CloudShape s = visfeat::cloudShape(few);
    EXPECT_FALSE(visfeat::hasExtent(s));
    EXPECT_FALSE(visfeat::isCollinear(s));
    EXPECT_EQ(visfeat::shapeProblem(s, 64), "");
    EXPECT_EQ(visfeat::shapeNote(s), "");
  }
}

// ---------------------------------------------------------------- resolution

TEST(ResolutionArithmetic, SpacingAndResolution)
{
  // k neighbours cover pi r^2 = (k - 1/3) spacing^2.
  EXPECT_NEAR(visfeat::spacingFromNeighbourDistance(1.0, 8),
              std::sqrt(3.14159265358979323846 / (23.0 / 3.0)), 1e-15);
  EXPECT_EQ(visfeat::resolutionForSpacing(2.0, 2.0 / 512.0), 256);
  EXPECT_EQ(visfeat::resolutionForSpacing(1.0, 1.0), GridSpec::kMinResolution);
  EXPECT_EQ(visfeat::resolutionForSpacing(1.0, 1e-9), GridSpec::kMaxResolution);
  EXPECT_EQ(visfeat::resolutionForSpacing(1.0, std::nan("")), GridSpec::kMinResolution);
}

TEST(ResolutionArithmetic, FromNeighbourDistances)
{
  const visfeat::ResolutionEstimate e =
    visfeat::resolutionFromNeighbourDistances({3.0, 1.0, 2.0}, 8, 1000.0);
  EXPECT_EQ(e.k, 8);
  EXPECT_EQ(e.queries, 3u);
  EXPECT_EQ(e.extent, 1000.0);
  EXPECT_DOUBLE_EQ(e.spacing, visfeat::spacingFromNeighbourDistance(2.0, 8)); // median
  EXPECT_EQ(e.resolution, 391); // 1000 / (2 * 1.28028) = 390.5
  EXPECT_FALSE(e.clamped);
  EXPECT_EQ(e.reason, "point spacing 1.28027 (median distance to the 8th nearest "
                      "neighbour over 3 points), 2 spacings per cell, extent 1000");

  const visfeat::ResolutionEstimate small =
    visfeat::resolutionFromNeighbourDistances({1.0}, 2, 3.0);
  EXPECT_EQ(small.resolution, GridSpec::kMinResolution);
  EXPECT_TRUE(small.clamped);
  EXPECT_EQ(small.unclamped, 1.0);
  EXPECT_EQ(small.reason, "point spacing 1.37294 (median distance to the 2nd nearest "
                          "neighbour over 1 points), 2 spacings per cell, extent 3 "
                          "(clamped from 1)");

  EXPECT_EQ(errorOf([] { visfeat::resolutionFromNeighbourDistances({}, 8, 1.0); }),
            "the nearest-neighbour search found no neighbours");
  EXPECT_EQ(errorOf([] {
              visfeat::resolutionFromNeighbourDistances({0.0, 0.0, 1.0}, 8, 1.0);
            }),
            "cannot estimate the point spacing: most points have 8 or more duplicates");
}

// Rows of a table: each query's distances to its neighbours, ranks 1..per_query.
visfeat::NeighbourDistanceTable
tableOf(const std::vector<std::vector<double>>& rows)
{
  visfeat::NeighbourDistanceTable table;
  table.per_query = rows.front().size();
  for (const auto& row : rows)
    table.values.insert(table.values.end(), row.begin(), row.end());
  return table;
}

TEST(ResolutionArithmetic, CopiesAreCountedAsOneSite)
{
  // Clean: neighbour j at sqrt(j) (a uniform density); the 2nd is the estimate.
  std::vector<double> clean;
  for (int j = 1; j <= 16; ++j)
    clean.push_back(std::sqrt(double(j)));
  const visfeat::ResolutionEstimate plain =
    visfeat::resolutionFromNeighbourTable(tableOf({clean, clean, clean}), 2, 100.0);
  EXPECT_EQ(plain.copies, 1);
  EXPECT_DOUBLE_EQ(plain.spacing,
                   visfeat::spacingFromNeighbourDistance(std::sqrt(2.0), 2));
  EXPECT_EQ(plain.reason.find("copies"), std::string::npos) << plain.reason;
  // The same sites, each point three times: 2 copies at 0, then each site 3 times.
  std::vector<double> tripled{0.0, 0.0};
  for (int j = 1; j <= 5; ++j)
    for (int c = 0; c < 3; ++c)
      tripled.push_back(std::sqrt(double(j)));
  tripled.resize(16);
  const visfeat::ResolutionEstimate three =
    visfeat::resolutionFromNeighbourTable(tableOf({tripled, tripled, clean}), 2, 100.0);
  EXPECT_EQ(three.copies, 3);
  EXPECT_DOUBLE_EQ(three.spacing, plain.spacing); // the 6th point is the 2nd site
  EXPECT_GT(three.copy_radius, 0.0);
  EXPECT_NE(three.reason.find("; 3 copies of most points (points within "),
            std::string::npos)
    << three.reason;
  EXPECT_NE(three.reason.find("the 2nd neighbour is the 6th point"), std::string::npos)
    << three.reason;
  // Two copies a little apart (0.05): the partner first, then each site twice.
  std::vector<double> pairs{0.05};
  for (int j = 1; j <= 8; ++j)
    for (int c = 0; c < 2; ++c)
      pairs.push_back(std::sqrt(double(j)) + 0.01 * c);
  pairs.resize(16);
  const visfeat::ResolutionEstimate two =
    visfeat::resolutionFromNeighbourTable(tableOf({pairs, pairs, clean}), 2, 100.0);
  EXPECT_EQ(two.copies, 2);
  EXPECT_DOUBLE_EQ(two.spacing, plain.spacing);
  // A minority with copies does not change the estimate.
  const visfeat::ResolutionEstimate few =
    visfeat::resolutionFromNeighbourTable(tableOf({tripled, clean, clean}), 2, 100.0);
  EXPECT_EQ(few.copies, 1);

  EXPECT_EQ(errorOf([] {
              visfeat::resolutionFromNeighbourTable(visfeat::NeighbourDistanceTable{},
                                                    2, 1.0);
            }),
            "the nearest-neighbour search found no neighbours");
  EXPECT_EQ(
    errorOf([&] { visfeat::resolutionFromNeighbourTable(tableOf({clean}), 17, 1.0); }),
    "neighbour rank 17 is outside [1, 16]");
  // more copies than the table can hold: every distance 0
  EXPECT_EQ(errorOf([] {
              visfeat::resolutionFromNeighbourTable(
                tableOf({std::vector<double>(16, 0.0)}), 2, 1.0);
            }),
            "cannot estimate the point spacing: most points have 16 or more copies");
}

// ---------------------------------------------------------------- parameters

TEST(ParameterRanges, MessagesNameParameterValueRangeAndUnit)
{
  EXPECT_EQ(
    visfeat::outOfRangeMessage("x", 5, visfeat::ParameterRange<int>{0, 3}, "cells"),
    "x 5 is out of range [0, 3] (cells)");
  EXPECT_FALSE((visfeat::ParameterRange<double>{0.0, 1.0}.contains(std::nan(""))));

  visfeat::ComponentParameters c;
  EXPECT_NO_THROW(c.validate(visfeat::kDefaultMinRadius));
  c.vertex_max_cells = 100001;
  EXPECT_EQ(errorOf([&] { c.validate(16); }),
            "vertex_max_cells 100001 is out of range [0, 100000] (cells)");
  c = {};
  EXPECT_EQ(
    errorOf([&] { c.validate(15); }),
    "min_radius 16 is out of range [1, max_radius = 15] (rings; raise max_radius "
    "to at least min_radius)");

  visfeat::SegmentationParameters s;
  EXPECT_NO_THROW(s.validate(16));
  s.vertex_reach = 0;
  EXPECT_EQ(errorOf([&] { s.validate(16); }),
            "vertex_reach 0 is out of range [1, 1000] (cells)");
  s = {};
  s.min_piece_cells = -1;
  EXPECT_EQ(errorOf([&] { s.validate(16); }),
            "min_piece_cells -1 is out of range [0, 1000000] (cells)");
  s = {};
  s.feature_width = 1001;
  EXPECT_EQ(errorOf([&] { s.validate(16); }),
            "feature_width 1001 is out of range [0, 1000] (cells)");
  // The core's own check agrees with the struct's.
  EXPECT_THROW(visfeat::FeatureSegmentation::validate(s, 16), visfeat::Error);

  visfeat::SmoothingParameters m;
  EXPECT_NO_THROW(m.validate());
  m.radius = 0.0; // the estimator's "off"
  EXPECT_NO_THROW(m.validate());
  m.min_neighbours = -2;
  EXPECT_EQ(errorOf([&] { m.validate(); }),
            "smoothing min_neighbours -2 is out of range [0, 100000] (points)");

  visfeat::VisibilityMap::Parameters v;
  v.opacity = 65.0;
  EXPECT_EQ(errorOf([&] { visfeat::VisibilityMap::validate(v); }),
            "opacity 65 is out of range [0, 64] (cell edges)");

  visfeat::TopologyGraphParameters g;
  g.min_face_contact = 1.5;
  EXPECT_EQ(
    errorOf([&] { visfeat::TopologyGraph::validate(g); }),
    "min_face_contact 1.5 is out of range [0, 1] (fraction of the strongest face "
    "contact)");

  // The ranges the tools read.
  EXPECT_EQ(GridSpec::kResolutionRange.min, 4);
  EXPECT_EQ(GridSpec::kResolutionRange.max, 8192);
  EXPECT_EQ(visfeat::ComponentParameters::kVertexMaxCellsRange.max, 100000);
  EXPECT_EQ(visfeat::ComponentParameters::kDimensionalityRange.max, 6.0);
  EXPECT_EQ(visfeat::SmoothingParameters::kRadiusRange.max, 8.0);
  EXPECT_EQ(visfeat::VisibilityMap::Parameters::kMaxRadiusRange.max, 64);
}

} // namespace
