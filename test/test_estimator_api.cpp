// VisibilityFeatureEstimation as users call it: point types other than PointXYZ,
// setSearchSurface, parameters read at compute time (max_radius auto, the noise mode),
// a failed compute() keeping the previous results, the free-space mask released, the
// shape checks (collinear refused, coplanar noted). The automatic resolution
// (estimateResolution): test_resolution_estimation.cpp.

#include "band_fixtures.h"

#include <visfeat/point_types.h>
#include <visfeat/resolution_estimation.h>
#include <visfeat/visibility_feature_estimation.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <new>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace {

using Cloud = pcl::PointCloud<pcl::PointXYZ>;
using Output = pcl::PointCloud<visfeat::PointVisibility>;
template <typename PointT>
using EstimatorOf =
  visfeat::VisibilityFeatureEstimation<PointT, visfeat::PointVisibility>;
using Estimator = EstimatorOf<pcl::PointXYZ>;

const float kNaN = std::numeric_limits<float>::quiet_NaN();

bool
sameFloat(float a, float b)
{
  return (std::isnan(a) && std::isnan(b)) || std::memcmp(&a, &b, sizeof(float)) == 0;
}

/** Radius, label and class of b[j] equal those of a[index[j]]. */
void
expectSameFields(const Output& a,
                 const Output& b,
                 const std::vector<std::size_t>& index,
                 const std::string& what)
{
  ASSERT_EQ(b.size(), index.size()) << what;
  for (std::size_t j = 0; j < index.size(); ++j) {
    const visfeat::PointVisibility& p = a.points[index[j]];
    const visfeat::PointVisibility& q = b.points[j];
    ASSERT_TRUE(sameFloat(p.x, q.x) && sameFloat(p.y, q.y) && sameFloat(p.z, q.z))
      << what << ", point " << j;
    ASSERT_TRUE(sameFloat(p.visibility_radius, q.visibility_radius))
      << what << ", point " << j;
    ASSERT_EQ(p.label, q.label) << what << ", point " << j;
    ASSERT_EQ(p.feature_class, q.feature_class) << what << ", point " << j;
  }
}

std::vector<std::size_t>
allIndices(std::size_t n)
{
  std::vector<std::size_t> index(n);
  for (std::size_t i = 0; i < n; ++i)
    index[i] = i;
  return index;
}

/** A cube at resolution 40 with regions of every class (min_radius 8). */
Cloud::Ptr
cubeCloud()
{
  return Cloud::Ptr(new Cloud(visfeat_test::syntheticShapeCloud("cube", 81, 40)));
}

template <typename PointT>
void
configure(EstimatorOf<PointT>& est)
{
  est.setResolution(40);
  est.setMinRadius(8);
  est.setNumberOfThreads(2);
}

// ---------------------------------------------------------------- point types

template <typename PointT>
Output
runAs(const Cloud& xyz)
{
  typename pcl::PointCloud<PointT>::Ptr cloud(new pcl::PointCloud<PointT>);
  for (const pcl::PointXYZ& p : xyz.points) {
    PointT q;
    q.x = p.x;
    q.y = p.y;
    q.z = p.z;
    cloud->push_back(q);
  }
  EstimatorOf<PointT> est;
  est.setInputCloud(cloud);
  configure(est);
  Output out;
  est.compute(out);
  EXPECT_EQ(est.getErrorMessage(), "");
  return out;
}

// The library instantiates the estimator for PCL's XYZ point types (no
// PCL_NO_PRECOMPILE here, so these link against libvisfeat); only x y z matter.
TEST(EstimatorApi, PointXYZIAndPointNormalGiveTheSameOutput)
{
  const Cloud::Ptr cloud = cubeCloud();
  const Output xyz = runAs<pcl::PointXYZ>(*cloud);
  ASSERT_EQ(xyz.size(), cloud->size());
  const auto index = allIndices(cloud->size());
  expectSameFields(xyz, runAs<pcl::PointXYZI>(*cloud), index, "PointXYZI");
  expectSameFields(xyz, runAs<pcl::PointNormal>(*cloud), index, "PointNormal");
}

// ---------------------------------------------------------------- search surface

// The band comes from the surface; the input's points are labelled from the cells they
// fall in (GridSpec::cellOf), which are the cells the band put them in.
TEST(EstimatorApi, SearchSurfaceGivesTheFullRunsOutputAtTheInputPoints)
{
  const Cloud::Ptr surface = cubeCloud();
  Estimator full;
  full.setInputCloud(surface);
  configure(full);
  Output all;
  full.compute(all);
  ASSERT_EQ(all.size(), surface->size()) << full.getErrorMessage();

  Cloud::Ptr subset(new Cloud);
  std::vector<std::size_t> index;
  for (std::size_t i = 0; i < surface->size(); i += 3) {
    subset->push_back(surface->points[i]);
    index.push_back(i);
  }
  subset->push_back(pcl::PointXYZ(kNaN, kNaN, kNaN));
  subset->is_dense = false;
  Estimator part;
  part.setInputCloud(subset);
  part.setSearchSurface(surface);
  configure(part);
  Output some;
  part.compute(some);
  ASSERT_EQ(some.size(), subset->size()) << part.getErrorMessage();
  EXPECT_EQ(part.getVoxelBand().coords(), full.getVoxelBand().coords());
  EXPECT_EQ(part.getSegmentation().cellLabels(), full.getSegmentation().cellLabels());
  Output some_finite = some;
  some_finite.points.pop_back();
  // The same fields but at the corner points claimed by vertex regions that no point
  // falls in (claimCornerPoints: the nearest input point, which the subset may lack):
  // a point a vertex in one run only, at most one per vertex region.
  const auto vertex = static_cast<std::uint8_t>(visfeat::FeatureClass::kVertex);
  Output same = some_finite;
  std::size_t claimed = 0;
  for (std::size_t j = 0; j < index.size(); ++j) {
    const auto& p = all.points[index[j]];
    auto& q = same.points[j];
    if ((p.label != q.label || p.feature_class != q.feature_class) &&
        (p.feature_class == vertex || q.feature_class == vertex)) {
      ++claimed;
      q.label = p.label;
      q.feature_class = p.feature_class;
    }
  }
  EXPECT_LE(claimed, full.getSegmentation().classCounts()[1]);
  expectSameFields(all, same, index, "subset");
  EXPECT_TRUE(std::isnan(some.points.back().visibility_radius));
  EXPECT_EQ(some.points.back().label, 0u);
  // and a note says how many were skipped (none in the full run)
  const std::string skipped = "1 of " + std::to_string(subset->size()) +
                              " points have a NaN or infinite coordinate";
  EXPECT_TRUE(std::any_of(part.getNotes().begin(), part.getNotes().end(),
                          [&](const std::string& n) { return n.find(skipped) == 0; }))
    << "no note on the skipped point";
  for (const std::string& n : full.getNotes())
    EXPECT_EQ(n.find("NaN"), std::string::npos) << n;
  EXPECT_FALSE(some.is_dense);
  // Every point of the band's cloud is in the cell GridSpec::cellOf gives.
  const visfeat::GridSpec& grid = full.getGrid();
  for (std::size_t i = 0; i < surface->size(); ++i) {
    const pcl::PointXYZ& p = surface->points[i];
    ASSERT_EQ(full.getVoxelBand().coord(full.getVoxelBand().pointCell()[i]),
              grid.cellOf(Eigen::Vector3d(p.x, p.y, p.z)))
      << "point " << i;
  }
}

// ---------------------------------------------------------------- parameters

TEST(EstimatorApi, MinRadiusAloneWorks)
{
  Cloud::Ptr cloud(new Cloud(visfeat_test::syntheticShapeCloud("cube", 82, 64)));
  Estimator est;
  est.setInputCloud(cloud);
  est.setResolution(64);
  EXPECT_EQ(est.getMaxRadius(), visfeat::kDefaultMinRadius); // auto = min_radius
  est.setMinRadius(20);
  EXPECT_EQ(est.getMaxRadius(), 20);
  Output out;
  est.compute(out);
  EXPECT_EQ(est.getErrorMessage(), "");
  EXPECT_EQ(out.size(), cloud->size());
  EXPECT_EQ(est.getVisibilityMap().parameters().max_radius, 20);
  est.setMaxRadius(24);
  EXPECT_EQ(est.getMaxRadius(), 24);
  est.setMaxRadius(Estimator::kAutoMaxRadius);
  EXPECT_EQ(est.getMaxRadius(), 20);
}

TEST(EstimatorApi, DefaultsAreTheLibrarysConstants)
{
  Estimator est;
  EXPECT_EQ(est.getResolution(), visfeat::GridSpec::kDefaultResolution);
  EXPECT_EQ(est.getResolution(), 256);
  EXPECT_EQ(est.getMinRadius(), 16);
  EXPECT_EQ(visfeat::ComponentParameters{}.min_radius, visfeat::kDefaultMinRadius);
  // The cores with default parameters agree: the map's cap reaches min_radius.
  EXPECT_EQ(visfeat::VisibilityMap::Parameters{}.max_radius,
            visfeat::kDefaultMinRadius);
  EXPECT_NO_THROW(visfeat::SegmentationParameters{}.validate(
    visfeat::VisibilityMap::Parameters{}.max_radius));
  EXPECT_EQ(est.getVertexMaxCells(), 25);
  EXPECT_EQ(est.getDimensionality(), 3.5);
  EXPECT_EQ(est.getOpacity(), 0.0);
  EXPECT_EQ(est.getSmoothingRadius(), 0.0);
  EXPECT_EQ(est.getPointFeatureDistance(), 1.0);
  EXPECT_FALSE(est.getNoiseMode());
  EXPECT_FALSE(est.getKeepFreeSpace());
  EXPECT_TRUE(est.getFlatCoreFaces()); // on: see ComponentParameters::flat_core_faces
}

TEST(EstimatorApi, NoiseModeFillsWhatWasNotSetInAnyOrder)
{
  Estimator est;
  est.setNoiseMode(true);
  EXPECT_EQ(est.getSmoothingRadius(), Estimator::kNoiseSmoothingRadius);
  EXPECT_EQ(est.getSmoothingRadius(), 2.0);
  EXPECT_EQ(est.getPointFeatureDistance(), 1.25);
  EXPECT_EQ(est.getSegmentationParameters().point_feature_distance, 1.25);
  est.setNoiseMode(false);
  EXPECT_EQ(est.getSmoothingRadius(), 0.0);
  EXPECT_EQ(est.getPointFeatureDistance(), 1.0);

  Estimator before, after;
  before.setSmoothingRadius(3.0);
  before.setNoiseMode(true);
  after.setNoiseMode(true);
  after.setSmoothingRadius(3.0);
  for (Estimator* e : {&before, &after}) {
    EXPECT_EQ(e->getSmoothingRadius(), 3.0);
    EXPECT_EQ(e->getPointFeatureDistance(), 1.25);
  }
  after.setPointFeatureDistance(0.5);
  after.setNoiseMode(false);
  EXPECT_EQ(after.getSmoothingRadius(), 3.0);
  EXPECT_EQ(after.getPointFeatureDistance(), 0.5);

  // A get-change-set round trip of the segmentation parameters leaves
  // point_feature_distance to the mode; a different value sets it.
  Estimator trip;
  trip.setNoiseMode(true);
  visfeat::SegmentationParameters p = trip.getSegmentationParameters();
  p.join_distance = 20;
  trip.setSegmentationParameters(p);
  trip.setNoiseMode(false);
  EXPECT_EQ(trip.getPointFeatureDistance(), 1.0);
  EXPECT_EQ(trip.getSegmentationParameters().join_distance, 20);
  p.point_feature_distance = 2.0;
  trip.setSegmentationParameters(p);
  trip.setNoiseMode(true);
  EXPECT_EQ(trip.getPointFeatureDistance(), 2.0);
}

TEST(EstimatorApi, NoiseModeResultsDoNotDependOnCallOrder)
{
  const Cloud::Ptr cloud = cubeCloud();
  Estimator a, b;
  a.setSmoothingRadius(1.5);
  a.setNoiseMode(true);
  b.setNoiseMode(true);
  b.setSmoothingRadius(1.5);
  Output out_a, out_b;
  for (auto [est, out] : {std::pair{&a, &out_a}, std::pair{&b, &out_b}}) {
    est->setInputCloud(cloud);
    configure(*est);
    est->compute(*out);
    ASSERT_EQ(est->getErrorMessage(), "");
    EXPECT_GT(est->getPhaseTimes().smoothing_ms, 0.0);
  }
  expectSameFields(out_a, out_b, allIndices(cloud->size()), "call order");
}

// ---------------------------------------------------------------- failure

struct Snapshot
{
  std::vector<visfeat::CellCoord> coords;
  std::vector<std::uint8_t> radii;
  std::vector<std::uint32_t> labels;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> arcs;
  double total_ms = 0.0;
  int resolution = 0;
  double cell_size = 0.0;

  explicit Snapshot(const Estimator& est)
      : coords(est.getVoxelBand().coords())
      , radii(est.getVisibilityMap().radii())
      , labels(est.getSegmentation().cellLabels())
      , arcs(est.getTopologyGraph().arcs())
      , total_ms(est.getPhaseTimes().total())
      , resolution(est.getResolutionEstimate().resolution)
      , cell_size(est.getGrid().cell_size)
  {}

  bool operator==(const Snapshot& o) const
  {
    return coords == o.coords && radii == o.radii && labels == o.labels &&
           arcs == o.arcs && total_ms == o.total_ms && resolution == o.resolution &&
           cell_size == o.cell_size;
  }
};

TEST(EstimatorApi, AFailedComputeKeepsThePreviousResults)
{
  const Cloud::Ptr cloud = cubeCloud();
  Estimator est;
  est.setInputCloud(cloud);
  configure(est);
  est.setNumberOfThreads(1); // progress: one call inside the map's loop at the end
  Output out;
  est.compute(out);
  ASSERT_EQ(est.getErrorMessage(), "");
  const Snapshot good(est);
  ASSERT_FALSE(good.coords.empty());
  ASSERT_FALSE(good.arcs.empty());

  // Refused before the work (initCompute).
  est.setResolution(-3);
  est.compute(out);
  EXPECT_TRUE(out.empty());
  EXPECT_NE(est.getErrorMessage(), "");
  EXPECT_TRUE(Snapshot(est) == good);
  est.setResolution(40);

  // Thrown during the work: std::exception, visfeat::Error, std::bad_alloc. The last
  // progress call (done == total) comes after the map's parallel loop.
  const auto throwAtTheEnd = [&est](auto make) {
    auto calls = std::make_shared<int>(0);
    est.setProgressCallback([calls, make](std::size_t done, std::size_t total) {
      if (done == total && ++*calls == 2)
        make();
    });
  };
  throwAtTheEnd([] { throw std::runtime_error("stopped\nby the caller"); });
  est.compute(out);
  EXPECT_TRUE(out.empty());
  EXPECT_EQ(est.getErrorMessage(), "unexpected error: stopped by the caller");
  EXPECT_TRUE(Snapshot(est) == good);
  throwAtTheEnd([] { throw visfeat::Error("cancelled"); });
  est.compute(out);
  EXPECT_EQ(est.getErrorMessage(), "cancelled");
  EXPECT_TRUE(Snapshot(est) == good);
  throwAtTheEnd([] { throw std::bad_alloc(); });
  est.compute(out);
  EXPECT_EQ(est.getErrorMessage(), "out of memory: lower the resolution");
  EXPECT_TRUE(Snapshot(est) == good);

  // Success replaces them.
  est.setProgressCallback({});
  est.setResolution(36);
  est.compute(out);
  EXPECT_EQ(est.getErrorMessage(), "");
  EXPECT_EQ(out.size(), cloud->size());
  EXPECT_FALSE(Snapshot(est) == good);
  EXPECT_EQ(est.getResolutionEstimate().resolution, 36);
}

TEST(EstimatorApi, FreeSpaceIsReleasedUnlessKept)
{
  const Cloud::Ptr cloud = cubeCloud();
  Estimator est;
  est.setInputCloud(cloud);
  configure(est);
  Output out;
  est.compute(out);
  ASSERT_EQ(est.getErrorMessage(), "");
  EXPECT_EQ(est.getFreeSpace().dims(), Eigen::Vector3i::Zero());
  EXPECT_EQ(est.getFreeSpace().memoryBytes(), 0u);
  const Output released = out;
  est.setKeepFreeSpace(true);
  est.compute(out);
  EXPECT_EQ(est.getFreeSpace().dims(), 2 * est.getGrid().dims);
  EXPECT_GT(est.getFreeSpace().memoryBytes(), 0u);
  expectSameFields(released, out, allIndices(cloud->size()), "kept");
}

// ---------------------------------------------------------------- shape

TEST(EstimatorShape, CollinearCloudsAreRefused)
{
  Cloud::Ptr line(new Cloud);
  for (int i = 0; i < 100; ++i)
    line->push_back(pcl::PointXYZ(0.01f * i, 0.02f * i, -0.01f * i));
  line->push_back(pcl::PointXYZ(kNaN, kNaN, kNaN));
  line->is_dense = false;
  for (const int resolution : {0, 64}) {
    Estimator est;
    est.setInputCloud(line);
    est.setResolution(resolution);
    Output out;
    est.compute(out);
    EXPECT_TRUE(out.empty());
    EXPECT_EQ(est.getErrorMessage(),
              "all 100 finite points lie on a line (collinear): there is no surface to "
              "label");
  }
}

TEST(EstimatorShape, ThinCloudsAreRefusedAtTheirResolution)
{
  // A strip 2 long and 0.02 wide: 0.64 cells across at resolution 64.
  Cloud::Ptr strip(new Cloud);
  for (int i = 0; i <= 200; ++i)
    for (int j = 0; j <= 2; ++j)
      strip->push_back(pcl::PointXYZ(0.01f * i, 0.01f * j, 0.f));
  const visfeat::CloudShape shape = visfeat::cloudShapeOf(*strip);
  std::ostringstream expected;
  expected << "the points lie within " << shape.widths[1] / (shape.extent / 64)
           << " cells of a line at resolution 64: a surface needs at least 2 cells "
              "across; raise the resolution";
  EXPECT_NEAR(shape.widths[1] / (shape.extent / 64), 0.64, 1e-3);
  Estimator est;
  est.setInputCloud(strip);
  est.setResolution(64);
  Output out;
  est.compute(out);
  EXPECT_TRUE(out.empty());
  EXPECT_EQ(est.getErrorMessage(), expected.str());
  est.setResolution(256); // 2.56 cells across: processed
  est.setMinRadius(2);
  est.compute(out);
  EXPECT_EQ(est.getErrorMessage(), "");
  EXPECT_EQ(out.size(), strip->size());
}

TEST(EstimatorShape, CoplanarCloudsAreProcessedWithANote)
{
  std::mt19937_64 rng(87);
  Cloud::Ptr square(new Cloud(visfeat_test::squareCloud(
    Eigen::Vector3d(0.6, 0.8, 0.0), Eigen::Vector3d(0.0, 0.0, 1.0), 20000, rng)));
  Estimator est;
  est.setInputCloud(square);
  est.setResolution(48);
  est.setMinRadius(8);
  Output out;
  est.compute(out);
  ASSERT_EQ(est.getErrorMessage(), "");
  EXPECT_EQ(out.size(), square->size());
  ASSERT_EQ(est.getNotes().size(), 1u);
  EXPECT_EQ(est.getNotes()[0],
            "all points lie in a plane: expect one face and no edges or vertices (the "
            "outline of a flat patch is a boundary, not a crease)");
  // A solid has no such note (it may have others: this cube is too sparse at 40 for
  // the flat-ground step, which says so).
  est.setInputCloud(cubeCloud());
  est.setResolution(40);
  est.compute(out);
  ASSERT_EQ(est.getErrorMessage(), "");
  for (const std::string& note : est.getNotes())
    EXPECT_EQ(note.find("lie in a plane"), std::string::npos) << note;
}

} // namespace
