// Sharp versus smooth (crease_angles.h): the turn of two sides fitted by planes, on
// generated two-plane clouds at known turns and rotations, on a rounded crease
// (a fillet) of known radius, and the merge rule on a hand-labelled sheet of cells.

#include <support/synthetic_shapes.h>
#include <visfeat/core/band/voxel_band.h>
#include <visfeat/core/common/error.h>
#include <visfeat/core/graph/crease_angles.h>
#include <visfeat/core/graph/topology_graph.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace {

using visfeat::CreaseAngle;
using visfeat::FeatureClass;
namespace syn = visfeat::synthetic;

constexpr double kPi = 3.14159265358979323846;
constexpr double kCell = 0.25; // world units a cell
/** Noise-free planes: the fits are exact up to rounding. */
constexpr double kExactTolerance = 0.01;
/** Gaussian noise of 0.2 cell: the median over the samples stays within this. */
constexpr double kNoisyTolerance = 1.5;

struct LabelledCloud
{
  std::vector<Eigen::Vector3d> points;
  std::vector<std::uint32_t> labels;
};

/** Two half-planes meeting along the rotated x axis with the given turn (0 = flat),
 * sampled at random (`count` points) over along x across cells each side (default 40
 * x 12): points within edge_cells (default 1) of the crease are the edge (label 2),
 * the others face 1 or face 3; optional Gaussian noise. */
LabelledCloud
twoPlanes(double turn_degrees,
          const Eigen::Matrix3d& rotation,
          double noise_cells,
          std::uint64_t seed,
          double along_cells = 40.0,
          double across_cells = 12.0,
          int count = 20000,
          double edge_cells = 1.0)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> along(0.0, along_cells * kCell);
  std::uniform_real_distribution<double> across(0.0, across_cells * kCell);
  std::normal_distribution<double> noise(0.0, noise_cells * kCell);
  const double turn = turn_degrees * kPi / 180.0;
  // side A goes along -y; side B leaves the crease turned by `turn` from +y
  const Eigen::Vector3d dir_a(0.0, -1.0, 0.0);
  const Eigen::Vector3d dir_b(0.0, std::cos(turn), std::sin(turn));
  LabelledCloud cloud;
  for (int i = 0; i < count; ++i) {
    const bool side_b = i % 2 == 1;
    const double s = across(rng);
    Eigen::Vector3d p =
      Eigen::Vector3d(along(rng), 0.0, 0.0) + s * (side_b ? dir_b : dir_a);
    p += Eigen::Vector3d(noise(rng), noise(rng), noise(rng));
    cloud.points.push_back(rotation * p);
    cloud.labels.push_back(s < edge_cells * kCell ? 2u : (side_b ? 3u : 1u));
  }
  return cloud;
}

const std::vector<FeatureClass> kFaceEdgeFace = {
  FeatureClass::kFace, FeatureClass::kEdge, FeatureClass::kFace};

TEST(CreaseAngles, SideTurnOfTwoHalfPlanes)
{
  for (const double turn : {0.0, 10.0, 30.0, 41.81, 90.0, 109.47, 150.0}) {
    for (std::uint64_t r = 1; r <= 3; ++r) {
      const LabelledCloud cloud = twoPlanes(turn, syn::randomRotation(r), 0.0, r);
      std::vector<Eigen::Vector3d> a, b;
      for (std::size_t i = 0; i < cloud.points.size(); ++i)
        if (cloud.labels[i] != 2) // the sides without the edge's strip
          (cloud.labels[i] == 1 ? a : b).push_back(cloud.points[i]);
      const Eigen::Vector3d at = syn::randomRotation(r) * Eigen::Vector3d(0.1, 0, 0);
      EXPECT_NEAR(visfeat::sideTurnDegrees(a, b, at), turn, kExactTolerance)
        << "turn " << turn << " rotation " << r;
    }
  }
  EXPECT_TRUE(std::isnan(
    visfeat::sideTurnDegrees({}, {Eigen::Vector3d::Zero()}, Eigen::Vector3d::Zero())));
}

TEST(CreaseAngles, AnEdgeWiderThanTheWindowIsMeasuredWithAWiderOne)
{
  // Edge strips 5 cells to each side of the crease: no window of 4 cells holds both
  // faces, one of 8 (kWideWindowFactor) does. 9 cells: beyond that too, unmeasured.
  const double window = visfeat::CreaseAngleParameters::kDefaultWindowCells;
  ASSERT_EQ(visfeat::CreaseAngleParameters::kWideWindowFactor, 2.0);
  for (const double turn : {25.0, 60.0, 90.0}) {
    for (std::uint64_t r = 1; r <= 3; ++r) {
      const LabelledCloud wide = twoPlanes(turn, syn::randomRotation(60 + r), 0.0, r,
                                           40.0, 16.0, 30000, window + 1.0);
      const std::vector<CreaseAngle> angles = visfeat::measureCreaseAngles(
        wide.points, wide.labels, kFaceEdgeFace, kCell, window);
      EXPECT_NEAR(angles[1].degrees, turn, 0.05)
        << "turn " << turn << " rotation " << r;
      EXPECT_EQ(angles[1].faces, (std::array<std::uint32_t, 2>{{1, 3}}));
      // a speck of such an edge (fewer than kMinWideEdgePoints) stays unmeasured
      LabelledCloud speck = wide;
      std::size_t kept = 0;
      for (std::uint32_t& label : speck.labels)
        if (label == 2 && ++kept >= visfeat::CreaseAngleParameters::kMinWideEdgePoints)
          label = 0;
      EXPECT_TRUE(
        std::isnan(visfeat::measureCreaseAngles(speck.points, speck.labels,
                                                kFaceEdgeFace, kCell, window)[1]
                     .degrees));
      const LabelledCloud wider = twoPlanes(turn, syn::randomRotation(60 + r), 0.0, r,
                                            40.0, 16.0, 30000, 2.0 * window + 1.0);
      EXPECT_TRUE(
        std::isnan(visfeat::measureCreaseAngles(wider.points, wider.labels,
                                                kFaceEdgeFace, kCell, window)[1]
                     .degrees))
        << "turn " << turn << " rotation " << r;
    }
  }
}

TEST(CreaseAngles, ACreaseWithOneFaceOnBothSidesIsMeasuredByGeometry)
{
  // The two planes' sides as one face (label 1): measureCreaseAngles() finds no two
  // faces, measureFadingCreases() splits the face's points across the edge's line.
  for (const double turn : {0.0, 15.0, 30.0, 90.0, 120.0}) {
    for (std::uint64_t r = 1; r <= 3; ++r) {
      LabelledCloud cloud = twoPlanes(turn, syn::randomRotation(80 + r), 0.0, r);
      for (std::uint32_t& label : cloud.labels)
        if (label == 3)
          label = 1;
      const double window = visfeat::CreaseAngleParameters::kDefaultWindowCells;
      EXPECT_TRUE(
        std::isnan(visfeat::measureCreaseAngles(cloud.points, cloud.labels,
                                                kFaceEdgeFace, kCell, window)[1]
                     .degrees));
      const std::vector<CreaseAngle> angles = visfeat::measureFadingCreases(
        cloud.points, cloud.labels, kFaceEdgeFace, {2}, kCell, window, 2);
      ASSERT_EQ(angles.size(), 3u);
      EXPECT_NEAR(angles[1].degrees, turn, 0.05)
        << "turn " << turn << " rotation " << r;
      EXPECT_EQ(angles[1].faces, (std::array<std::uint32_t, 2>{{1, 1}}));
      EXPECT_GT(angles[1].samples, 0u);
      EXPECT_TRUE(std::isnan(angles[0].degrees));
      EXPECT_TRUE(std::isnan(angles[2].degrees));
      // an edge not asked for, or no edge, is not measured
      EXPECT_TRUE(
        std::isnan(visfeat::measureFadingCreases(cloud.points, cloud.labels,
                                                 kFaceEdgeFace, {}, kCell, window)[1]
                     .degrees));
    }
  }
  const LabelledCloud cloud = twoPlanes(30.0, syn::randomRotation(80), 0.0, 1);
  EXPECT_THROW(visfeat::measureFadingCreases(cloud.points, cloud.labels, kFaceEdgeFace,
                                             {1}, kCell, 4.0),
               visfeat::Error); // a face
  EXPECT_THROW(visfeat::measureFadingCreases(cloud.points, cloud.labels, kFaceEdgeFace,
                                             {4}, kCell, 4.0),
               visfeat::Error); // no region
}

TEST(CreaseAngles, MeasuredOnLabelledCloudsAtKnownTurns)
{
  for (const double turn : {10.0, 30.0, 41.81, 90.0, 120.0}) {
    for (std::uint64_t r = 1; r <= 3; ++r) {
      for (const double noise : {0.0, 0.2}) {
        const LabelledCloud cloud =
          twoPlanes(turn, syn::randomRotation(10 + r), noise, r);
        const std::vector<CreaseAngle> angles = visfeat::measureCreaseAngles(
          cloud.points, cloud.labels, kFaceEdgeFace, kCell,
          visfeat::CreaseAngleParameters::kDefaultWindowCells);
        ASSERT_EQ(angles.size(), 3u);
        EXPECT_TRUE(std::isnan(angles[0].degrees)); // faces have none
        EXPECT_TRUE(std::isnan(angles[2].degrees));
        EXPECT_NEAR(angles[1].degrees, turn, noise > 0.0 ? kNoisyTolerance : 0.05)
          << "turn " << turn << " rotation " << r << " noise " << noise;
        EXPECT_EQ(angles[1].faces[0], 1u);
        EXPECT_EQ(angles[1].faces[1], 3u);
        EXPECT_GT(angles[1].samples, 0u);
      }
    }
  }
}

TEST(CreaseAngles, TheSameForAnyThreadCount)
{
  // Six creases far apart (labels 3 k + 1, 3 k + 2, 3 k + 3), noisy.
  LabelledCloud all;
  std::vector<FeatureClass> classes;
  const double turns[] = {15.0, 30.0, 60.0, 90.0, 100.0, 135.0};
  for (std::uint32_t k = 0; k < 6; ++k) {
    const LabelledCloud one = twoPlanes(turns[k], syn::randomRotation(40 + k), 0.2, k);
    for (std::size_t i = 0; i < one.points.size(); ++i) {
      all.points.push_back(one.points[i] + Eigen::Vector3d(200.0 * kCell * k, 0, 0));
      all.labels.push_back(one.labels[i] + 3 * k);
    }
    classes.insert(classes.end(), kFaceEdgeFace.begin(), kFaceEdgeFace.end());
  }
  const auto measure = [&](int threads) {
    return visfeat::measureCreaseAngles(
      all.points, all.labels, classes, kCell,
      visfeat::CreaseAngleParameters::kDefaultWindowCells, 180.0, threads);
  };
  const std::vector<CreaseAngle> one = measure(1), two = measure(2),
                                 all_threads = measure(0);
  ASSERT_EQ(one.size(), 18u);
  for (std::size_t r = 0; r < one.size(); ++r) {
    for (const std::vector<CreaseAngle>* other : {&two, &all_threads}) {
      const CreaseAngle& b = (*other)[r];
      EXPECT_EQ(std::isnan(one[r].degrees), std::isnan(b.degrees)) << r;
      if (!std::isnan(one[r].degrees)) {
        EXPECT_EQ(one[r].degrees, b.degrees) << r;
      }
      EXPECT_EQ(one[r].faces, b.faces) << r;
      EXPECT_EQ(one[r].samples, b.samples) << r;
    }
    if (r % 3 == 1) {
      EXPECT_NEAR(one[r].degrees, turns[r / 3], kNoisyTolerance) << r;
    }
  }
}

/** Two perpendicular planes joined by a quarter cylinder of radius r cells, sampled
 * densely; the edge is the points within 1 cell (of arc) of the fillet's middle. */
LabelledCloud
fillet(double radius_cells, const Eigen::Matrix3d& rotation)
{
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double r = radius_cells * kCell, arc = 0.5 * kPi * r, flat = 20.0 * kCell;
  const double length = 40.0 * kCell;
  LabelledCloud cloud;
  for (int i = 0; i < 60000; ++i) {
    // s: arc length from the fillet's middle, negative on side A
    const double s = (unit(rng) * 2.0 - 1.0) * (0.5 * arc + flat);
    const double x = unit(rng) * length;
    Eigen::Vector3d p;
    if (std::abs(s) <= 0.5 * arc) {
      const double a = s / r; // -45..45 degrees; the tangent turns with a
      p = Eigen::Vector3d(x, r * std::sin(a), r - r * std::cos(a));
    } else {
      const double sign = s < 0 ? -1.0 : 1.0, beyond = std::abs(s) - 0.5 * arc;
      const double a = sign * 0.25 * kPi;
      const Eigen::Vector3d end(x, r * std::sin(a), r - r * std::cos(a));
      p = end + beyond * sign * Eigen::Vector3d(0.0, std::cos(a), std::sin(a));
    }
    cloud.points.push_back(rotation * p);
    cloud.labels.push_back(std::abs(s) < kCell ? 2u : (s < 0 ? 1u : 3u));
  }
  return cloud;
}

// The rule of README "Sharp versus smooth": over the default window a fillet of radius
// r cells reads about 2 d / r radians (d about 2.3 cells), so radii above about 13
// cells read below 20 degrees, and a tight blend of 6 cells stays a crease.
TEST(CreaseAngles, FilletsReadByTheirRadius)
{
  const auto measure = [](double radius_cells) {
    const LabelledCloud cloud = fillet(radius_cells, syn::randomRotation(5));
    return visfeat::measureCreaseAngles(
             cloud.points, cloud.labels, kFaceEdgeFace, kCell,
             visfeat::CreaseAngleParameters::kDefaultWindowCells)[1]
      .degrees;
  };
  const double wide = measure(19.2), tight = measure(6.0), sharp = measure(0.01);
  std::cout << "fillet radius 19.2 cells: " << wide << " degrees, 6 cells: " << tight
            << ", 0.01 cells: " << sharp << std::endl;
  EXPECT_LT(wide, visfeat::CreaseAngleParameters::kDefaultMinCreaseAngle);
  EXPECT_GT(wide, 5.0); // the bend is measured, not zero
  EXPECT_GT(tight, visfeat::CreaseAngleParameters::kDefaultMinCreaseAngle);
  EXPECT_NEAR(sharp, 90.0, 1.0);
  EXPECT_GT(tight, wide);
}

/** Half a cylinder (radius and length in cells, axis along the rotated x) sampled at
 * random, one point a cell squared, cut across by an edge region along its middle
 * line: points within edge_cells of arc from it are the edge (label 2), the others
 * face 1 or face 3, as where a sparse cloud's watershed cut a hole's wall. */
LabelledCloud
cutCylinder(double radius_cells,
            double length_cells,
            double edge_cells,
            const Eigen::Matrix3d& rotation,
            std::uint64_t seed)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double r = radius_cells * kCell;
  const int count = static_cast<int>(kPi * radius_cells * length_cells);
  LabelledCloud cloud;
  for (int i = 0; i < count; ++i) {
    const double angle = (unit(rng) - 0.5) * kPi; // -90..90 degrees
    const Eigen::Vector3d p(unit(rng) * length_cells * kCell, r * std::sin(angle),
                            r - r * std::cos(angle));
    cloud.points.push_back(rotation * p);
    const double arc = angle * r;
    cloud.labels.push_back(std::abs(arc) < edge_cells * kCell ? 2u
                                                              : (arc < 0 ? 1u : 3u));
  }
  return cloud;
}

// The turn that a crease concentrates, not one the surface repeats beside it: the box
// with hole at 10,000 points (4 cells a point spacing, so a window of 16 cells) had
// its hole's wall (radius 42 cells) cut by the watershed into pieces whose edges read
// 20-23 degrees, over the minimum; beside them the wall turns as much. A crease of 25
// degrees between flat faces, measured the same way, keeps its turn.
TEST(CreaseAngles, ACylinderCutAcrossIsABlend)
{
  constexpr double kWindow = 16.0, kEdgeCells = 4.0;
  const double min_angle = visfeat::CreaseAngleParameters::kDefaultMinCreaseAngle;
  for (std::uint64_t r = 1; r <= 3; ++r) {
    const Eigen::Matrix3d rotation = syn::randomRotation(60 + r);
    const LabelledCloud wall = cutCylinder(42.0, 120.0, kEdgeCells, rotation, r);
    const double blend =
      visfeat::measureCreaseAngles(wall.points, wall.labels, kFaceEdgeFace, kCell,
                                   kWindow, min_angle)[1]
        .degrees;
    EXPECT_LT(blend, 0.5 * min_angle) << "rotation " << r;
    const LabelledCloud crease =
      twoPlanes(25.0, rotation, 0.0, r, 120.0, 48.0, 12000, kEdgeCells);
    const double sharp =
      visfeat::measureCreaseAngles(crease.points, crease.labels, kFaceEdgeFace, kCell,
                                   kWindow, min_angle)[1]
        .degrees;
    EXPECT_NEAR(sharp, 25.0, 1.0) << "rotation " << r;
    std::cout << "rotation " << r << ": wall " << blend << " degrees, crease " << sharp
              << std::endl;
  }
}

// --- The merge rule on a sheet of cells ----------------------------------------------

/** A width x height sheet of cells (z = 0, cell size 1, no repair). */
visfeat::VoxelBand
sheetBand(int width, int height)
{
  visfeat::GridSpec grid;
  grid.origin = Eigen::Vector3d::Zero();
  grid.cell_size = 1.0;
  grid.dims = Eigen::Vector3i(width, height, 1);
  std::vector<visfeat::CellCoord> cells;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      cells.emplace_back(x, y, 0);
  visfeat::VoxelBand::Options options;
  options.repair = false;
  return visfeat::VoxelBand::fromCells(grid, cells, options);
}

/** A 40 x 20 sheet of cells (z = 0): F1 x < 18; E2 x 18-19, y < 9; V4 x 18-19,
 * y 9-10; E5 x 18-19, y > 10; F3 x >= 20, y < 9; E7 x >= 20, y 9-10; F6 x >= 20,
 * y > 10. V4 is the corner where E2 (F1 | F3), E5 (F1 | F6) and E7 (F3 | F6) meet. */
visfeat::TopologyGraph
sheetGraph()
{
  const visfeat::VoxelBand band = sheetBand(40, 20);
  std::vector<std::uint32_t> labels(band.size());
  for (std::size_t i = 0; i < band.size(); ++i) {
    const visfeat::CellCoord& c = band.coord(static_cast<visfeat::CellId>(i));
    const int x = c.x(), y = c.y();
    const int band_y = y < 9 ? 0 : (y <= 10 ? 1 : 2);
    if (x < 18)
      labels[i] = 1;
    else if (x < 20)
      labels[i] = band_y == 0 ? 2 : (band_y == 1 ? 4 : 5);
    else
      labels[i] = band_y == 0 ? 3 : (band_y == 1 ? 7 : 6);
  }
  const std::vector<FeatureClass> classes = {FeatureClass::kFace, FeatureClass::kEdge,
                                             FeatureClass::kFace, FeatureClass::kVertex,
                                             FeatureClass::kEdge, FeatureClass::kFace,
                                             FeatureClass::kEdge};
  return visfeat::TopologyGraph::build(band, labels, classes, {});
}

std::vector<CreaseAngle>
sheetAngles(double e2, double e5, double e7)
{
  std::vector<CreaseAngle> angles(7);
  angles[1].degrees = e2;
  angles[1].faces = {{1, 3}};
  angles[4].degrees = e5;
  angles[4].faces = {{1, 6}};
  angles[6].degrees = e7;
  angles[6].faces = {{3, 6}};
  return angles;
}

TEST(CreaseAngles, MergeRuleOnASheet)
{
  const visfeat::TopologyGraph graph = sheetGraph();
  ASSERT_EQ(graph.verticesOfEdge(2), std::vector<std::uint32_t>({4}));
  using Into = std::vector<std::uint32_t>;
  const Into kept = {0, 1, 2, 3, 4, 5, 6, 7};
  // Every edge steep enough, or the rule off: nothing changes.
  EXPECT_EQ(visfeat::shallowCreaseMerge(graph, sheetAngles(90, 90, 90), {}, 20.0),
            kept);
  EXPECT_EQ(visfeat::shallowCreaseMerge(graph, sheetAngles(10, 10, 10), {}, 0.0), kept);
  // Unmeasured edges stay.
  EXPECT_EQ(visfeat::shallowCreaseMerge(graph, sheetAngles(NAN, 90, 90), {}, 20.0),
            kept);
  // E2 shallow: F1 and F3 are one face; the corner then ends only E5 and E7, which
  // separate the same pair (F1+F3 | F6): V4 and E7 join E5, one straight crease.
  EXPECT_EQ(visfeat::shallowCreaseMerge(graph, sheetAngles(19.9, 90, 90), {}, 20.0),
            Into({0, 1, 1, 1, 5, 5, 6, 5}));
  // At exactly the minimum the edge stays a crease.
  EXPECT_EQ(visfeat::shallowCreaseMerge(graph, sheetAngles(20.0, 90, 90), {}, 20.0),
            kept);
  // Two shallow edges: F1, F3 and F6 are one face, E5 a crease that fades into it;
  // V4 no longer joins two different pairs of faces and becomes part of E5.
  EXPECT_EQ(visfeat::shallowCreaseMerge(graph, sheetAngles(10, 90, 10), {}, 20.0),
            Into({0, 1, 1, 1, 5, 5, 1, 1}));
  // Faces touching without an edge: a shallow contact of F3 and F6 is a spill of the
  // watershed while E7, a crease kept, separates them: nothing changes.
  visfeat::CreaseAngle contact;
  contact.faces = {{3, 6}};
  contact.degrees = 12.0;
  EXPECT_EQ(
    visfeat::shallowCreaseMerge(graph, sheetAngles(90, 90, 90), {contact}, 20.0), kept);
  // With E7 unmeasured the contact makes F3 and F6 one face; E7, inside it, joins
  // it; V4 then ends E2 and E5 only, which separate the same two faces: V4 and E5
  // join E2.
  EXPECT_EQ(
    visfeat::shallowCreaseMerge(graph, sheetAngles(90, 90, NAN), {contact}, 20.0),
    Into({0, 1, 2, 3, 2, 2, 3, 3}));
  contact.degrees = 25.0;
  EXPECT_EQ(
    visfeat::shallowCreaseMerge(graph, sheetAngles(90, 90, NAN), {contact}, 20.0),
    kept);
}

/** A 40 x 30 sheet like a box side between two fillets, cut open: the top face T1
 * (y < 9), the top rim (y 9-10: E2 x < 18, E5 x >= 22), the side (y 11-18: S3
 * x < 18, S6 x >= 22), the bottom rim (y 19-20: E7 x < 18, E8 x >= 22) and the bottom
 * face B9 (y >= 21); V4 (x 18-21, y 9-20) is a vertex region across the side from rim
 * to rim, as on a fillet: T1-S3, S3-B9, B9-S6 and S6-T1 close around it. */
visfeat::TopologyGraph
filletSheetGraph()
{
  const visfeat::VoxelBand band = sheetBand(40, 30);
  std::vector<std::uint32_t> labels(band.size());
  for (std::size_t i = 0; i < band.size(); ++i) {
    const visfeat::CellCoord& c = band.coord(static_cast<visfeat::CellId>(i));
    const int x = c.x(), y = c.y();
    const int side = x < 18 ? 0 : (x < 22 ? 1 : 2); // left, the vertex, right
    if (y < 9)
      labels[i] = 1;
    else if (y >= 21)
      labels[i] = 9;
    else if (side == 1)
      labels[i] = 4;
    else if (y <= 10)
      labels[i] = side == 0 ? 2 : 5;
    else if (y <= 18)
      labels[i] = side == 0 ? 3 : 6;
    else
      labels[i] = side == 0 ? 7 : 8;
  }
  const std::vector<FeatureClass> classes = {
    FeatureClass::kFace,   FeatureClass::kEdge, FeatureClass::kFace,
    FeatureClass::kVertex, FeatureClass::kEdge, FeatureClass::kFace,
    FeatureClass::kEdge,   FeatureClass::kEdge, FeatureClass::kFace};
  return visfeat::TopologyGraph::build(band, labels, classes, {});
}

TEST(CreaseAngles, AVertexTheCreasesPassByJoinsTheirFace)
{
  const visfeat::TopologyGraph graph = filletSheetGraph();
  ASSERT_EQ(graph.neighbours(4, FeatureClass::kEdge),
            std::vector<std::uint32_t>({2, 5, 7, 8}));
  std::vector<CreaseAngle> angles(9);
  const std::array<std::pair<std::uint32_t, std::array<std::uint32_t, 2>>, 4> edges = {
    {{2, {1, 3}}, {5, {1, 6}}, {7, {3, 9}}, {8, {6, 9}}}};
  for (const auto& [e, faces] : edges) {
    angles[e - 1].degrees = 90.0;
    angles[e - 1].faces = faces;
  }
  using Into = std::vector<std::uint32_t>;
  const Into kept = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9};
  // The two side faces apart: V4 is a corner of four faces and four creases.
  EXPECT_EQ(visfeat::shallowCreaseMerge(graph, angles, {}, 20.0), kept);
  // A shallow contact makes S3 and S6 one side: the rims pass V4 by (top-side and
  // side-bottom, the top and the bottom in one pair each), so V4 joins the side, and
  // each rim's two pieces become one edge.
  visfeat::CreaseAngle contact;
  contact.faces = {{3, 6}};
  contact.degrees = 10.0;
  EXPECT_EQ(visfeat::shallowCreaseMerge(graph, angles, {contact}, 20.0),
            Into({0, 1, 2, 3, 3, 2, 3, 7, 7, 9}));
}

/** A 40 x 20 sheet of cells: F1 x < 18, F3 x >= 22, between them (x 18-21) E2 for
 * y < 8, V4 for y 12-15 (touching F1 and F3, no edge: a speck on a cylinder's wall cut
 * by the watershed), F1 elsewhere; V5 (x 5-6, y 15-16) lies inside F1 (a cone's apex
 * touches one face). */
visfeat::TopologyGraph
speckSheetGraph()
{
  const visfeat::VoxelBand band = sheetBand(40, 20);
  std::vector<std::uint32_t> labels(band.size());
  for (std::size_t i = 0; i < band.size(); ++i) {
    const visfeat::CellCoord& c = band.coord(static_cast<visfeat::CellId>(i));
    const int x = c.x(), y = c.y();
    if (x >= 5 && x <= 6 && y >= 15 && y <= 16)
      labels[i] = 5;
    else if (x < 18)
      labels[i] = 1;
    else if (x >= 22)
      labels[i] = 3;
    else if (y < 8)
      labels[i] = 2;
    else if (y >= 12 && y <= 15)
      labels[i] = 4;
    else
      labels[i] = 1;
  }
  const std::vector<FeatureClass> classes = {FeatureClass::kFace, FeatureClass::kEdge,
                                             FeatureClass::kFace, FeatureClass::kVertex,
                                             FeatureClass::kVertex};
  return visfeat::TopologyGraph::build(band, labels, classes, {});
}

TEST(CreaseAngles, AVertexWithoutEdgesBetweenMergedFacesJoinsThem)
{
  const visfeat::TopologyGraph graph = speckSheetGraph();
  ASSERT_TRUE(graph.neighbours(4, FeatureClass::kEdge).empty());
  ASSERT_EQ(graph.neighbours(4, FeatureClass::kFace),
            std::vector<std::uint32_t>({1, 3}));
  ASSERT_EQ(graph.neighbours(5, FeatureClass::kFace), std::vector<std::uint32_t>({1}));
  std::vector<CreaseAngle> angles(5);
  angles[1].faces = {{1, 3}};
  using Into = std::vector<std::uint32_t>;
  // E2 a crease: nothing merges, both vertices stay.
  angles[1].degrees = 60.0;
  EXPECT_EQ(visfeat::shallowCreaseMerge(graph, angles, {}, 20.0),
            Into({0, 1, 2, 3, 4, 5}));
  // E2 shallow: F1 and F3 become one, E2 and V4 join it; V5, on one face, stays.
  angles[1].degrees = 10.0;
  EXPECT_EQ(visfeat::shallowCreaseMerge(graph, angles, {}, 20.0),
            Into({0, 1, 1, 1, 1, 5}));
}

TEST(CreaseAngles, WrittenInTheGraphJsonForEdges)
{
  visfeat::TopologyGraph graph = sheetGraph();
  graph.setCreaseAngle(2, 33.5);
  EXPECT_EQ(graph.node(2).crease_angle, 33.5);
  EXPECT_TRUE(std::isnan(graph.node(5).crease_angle));
  EXPECT_THROW(graph.setCreaseAngle(8, 1.0), visfeat::Error);
  std::ostringstream out;
  graph.writeJson(out, {});
  const std::string json = out.str();
  // three edges: one measured, two null; no other node has the field
  EXPECT_NE(json.find("\"crease_angle\": 33.5"), std::string::npos) << json;
  std::size_t fields = 0, nulls = 0;
  for (std::size_t at = json.find("crease_angle"); at != std::string::npos;
       at = json.find("crease_angle", at + 1)) {
    ++fields;
    nulls += json.compare(at, 19, "crease_angle\": null") == 0;
  }
  EXPECT_EQ(fields, 3u);
  EXPECT_EQ(nulls, 2u);
}

TEST(CreaseAngles, ParametersValidate)
{
  visfeat::CreaseAngleParameters p;
  EXPECT_NO_THROW(p.validate());
  EXPECT_EQ(p.min_crease_angle, 20.0);
  p.min_crease_angle = -1.0;
  EXPECT_THROW(p.validate(), visfeat::Error);
  p.min_crease_angle = 180.5;
  EXPECT_THROW(p.validate(), visfeat::Error);
  p = visfeat::CreaseAngleParameters{};
  p.window_cells = 0.5;
  EXPECT_THROW(p.validate(), visfeat::Error);
}

} // namespace
