// VisibilityFeatureEstimation<pcl::PointXYZ, PointVisibility>: per-point output,
// NaN handling, indices, determinism (radii, labels, classes and the topology graph for
// any thread count and point order), agreement with the brute-force reference through
// the whole chain, and the exact message of each bad input.

#include "band_fixtures.h"
#include "reference/brute_force.h"
#include "shuffled_cloud.h"
#include <support/cad_models.h>
#include <support/portable_random.h>

#include <visfeat/point_types.h>
#include <visfeat/visibility_feature_estimation.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <functional>
#include <initializer_list>
#include <limits>
#include <memory>
#include <numeric>
#include <random>
#include <utility>

namespace {

namespace ref = visfeat_test::reference;
using Cloud = pcl::PointCloud<pcl::PointXYZ>;
using Estimator =
  visfeat::VisibilityFeatureEstimation<pcl::PointXYZ, visfeat::PointVisibility>;
using Output = pcl::PointCloud<visfeat::PointVisibility>;
using visfeat::CellId;
using visfeat::kNoCell;

const float kNaN = std::numeric_limits<float>::quiet_NaN();

std::string
lower(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

bool
finite(const pcl::PointXYZ& p)
{
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

bool
sameFloat(float a, float b)
{
  return (std::isnan(a) && std::isnan(b)) || std::memcmp(&a, &b, sizeof(float)) == 0;
}

Cloud::Ptr
cloudWithNaNs(std::uint64_t seed, int resolution)
{
  Cloud::Ptr cloud(
    new Cloud(visfeat_test::syntheticShapeCloud("cube", seed, resolution)));
  cloud->points.insert(cloud->points.begin() + 5, pcl::PointXYZ(kNaN, kNaN, kNaN));
  cloud->points.insert(cloud->points.begin() + 17, pcl::PointXYZ(0.1f, kNaN, 0.2f));
  cloud->push_back(pcl::PointXYZ(std::numeric_limits<float>::infinity(), 0.f, 0.f));
  cloud->width = static_cast<std::uint32_t>(cloud->points.size());
  cloud->height = 1;
  cloud->is_dense = false;
  return cloud;
}

/** Compute on `cloud` with a pre-filled output; expect failure and a message that
 * contains one of `words` (lower case). */
void
expectError(Estimator& est, std::initializer_list<const char*> words)
{
  Output out;
  out.push_back(visfeat::PointVisibility(1.f, 2.f, 3.f));
  est.compute(out);
  EXPECT_TRUE(out.empty()) << "output should be empty on error";
  EXPECT_EQ(out.width * out.height, 0u);
  const std::string msg = lower(est.getErrorMessage());
  ASSERT_FALSE(msg.empty()) << "no error message";
  bool found = false;
  std::string list;
  for (const char* w : words) {
    found = found || msg.find(w) != std::string::npos;
    list += std::string(" '") + w + "'";
  }
  EXPECT_TRUE(found) << "message \"" << est.getErrorMessage() << "\" mentions none of"
                     << list;
}

/** The same, and the message is exactly `message`. */
void
expectErrorMessage(Estimator& est, const std::string& message)
{
  Output out;
  out.push_back(visfeat::PointVisibility(1.f, 2.f, 3.f));
  est.compute(out);
  EXPECT_TRUE(out.empty()) << "output should be empty on error";
  EXPECT_EQ(out.width * out.height, 0u);
  EXPECT_EQ(est.getErrorMessage(), message);
}

/** Labels, classes and radii of two outputs, point j of `b` against point perm[j] of
 * `a`. */
void
expectSamePoints(const Output& a,
                 const Output& b,
                 const std::vector<std::size_t>& perm,
                 const std::string& what)
{
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t j = 0; j < b.size(); ++j) {
    const visfeat::PointVisibility& p = a.points[perm[j]];
    const visfeat::PointVisibility& q = b.points[j];
    ASSERT_TRUE(sameFloat(p.visibility_radius, q.visibility_radius))
      << what << ", point " << j;
    ASSERT_EQ(p.label, q.label) << what << ", point " << j;
    ASSERT_EQ(p.feature_class, q.feature_class) << what << ", point " << j;
  }
}

/** Same nodes (id, class, cells, points, bounds; centroid up to rounding: the points
 * are summed in input order) and same arcs. */
void
expectSameGraph(const visfeat::TopologyGraph& a,
                const visfeat::TopologyGraph& b,
                const std::string& what)
{
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::uint32_t id = 1; id <= a.size(); ++id) {
    const visfeat::GraphNode& p = a.node(id);
    const visfeat::GraphNode& q = b.node(id);
    EXPECT_EQ(p.id, q.id) << what;
    EXPECT_EQ(p.feature_class, q.feature_class) << what << ", node " << id;
    EXPECT_EQ(p.cells, q.cells) << what << ", node " << id;
    EXPECT_EQ(p.points, q.points) << what << ", node " << id;
    EXPECT_EQ(p.min, q.min) << what << ", node " << id;
    EXPECT_EQ(p.max, q.max) << what << ", node " << id;
    EXPECT_LT((p.centroid - q.centroid).norm(), 1e-9) << what << ", node " << id;
  }
  EXPECT_EQ(a.arcs(), b.arcs()) << what;
}

// ---------------------------------------------------------------- output

TEST(Estimator, PerPointOutputFollowsTheMap)
{
  const Cloud::Ptr cloud = cloudWithNaNs(61, 24);
  Estimator est;
  est.setInputCloud(cloud);
  est.setResolution(24);
  est.setMaxRadius(8);
  est.setMinRadius(8); // components need min_radius <= max_radius
  est.setNumberOfThreads(2);
  Output out;
  est.compute(out);
  ASSERT_EQ(est.getErrorMessage(), "");
  ASSERT_EQ(out.size(), cloud->size());
  EXPECT_FALSE(out.is_dense);
  const visfeat::VoxelBand& band = est.getVoxelBand();
  const visfeat::VisibilityMap& map = est.getVisibilityMap();
  ASSERT_EQ(band.pointCell().size(), cloud->size());
  ASSERT_EQ(map.radii().size(), band.size());
  EXPECT_EQ(map.parameters().max_radius, 8);
  std::size_t nan_points = 0;
  for (std::size_t i = 0; i < cloud->size(); ++i) {
    const pcl::PointXYZ& p = cloud->points[i];
    const visfeat::PointVisibility& q = out.points[i];
    EXPECT_TRUE(sameFloat(q.x, p.x) && sameFloat(q.y, p.y) && sameFloat(q.z, p.z))
      << "point " << i << " not copied";
    if (!finite(p)) {
      ++nan_points;
      EXPECT_TRUE(std::isnan(q.visibility_radius)) << "point " << i;
      EXPECT_EQ(q.label, 0u);
      EXPECT_EQ(q.feature_class, 0u);
      EXPECT_EQ(band.pointCell()[i], kNoCell);
      continue;
    }
    const CellId id = band.pointCell()[i];
    ASSERT_NE(id, kNoCell) << "point " << i;
    EXPECT_EQ(q.visibility_radius, static_cast<float>(map.radius(id))) << "point " << i;
  }
  EXPECT_EQ(nan_points, 3u);
  // Grid of DESIGN.md: cell = extent / resolution of the finite points.
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e30), hi = -lo;
  for (const pcl::PointXYZ& p : cloud->points)
    if (finite(p)) {
      lo = lo.cwiseMin(Eigen::Vector3d(p.x, p.y, p.z));
      hi = hi.cwiseMax(Eigen::Vector3d(p.x, p.y, p.z));
    }
  EXPECT_NEAR(est.getGrid().cell_size, (hi - lo).maxCoeff() / 24.0, 1e-9);
}

TEST(Estimator, WholeChainMatchesReference)
{
  Cloud::Ptr cloud(new Cloud(visfeat_test::syntheticShapeCloud("tetrahedron", 62, 16)));
  for (double opacity : {0.0, 3.0}) {
    Estimator est;
    est.setInputCloud(cloud);
    est.setResolution(16);
    est.setMaxRadius(6);
    est.setMinRadius(6); // components need min_radius <= max_radius
    est.setOpacity(opacity);
    Output out;
    est.compute(out);
    ASSERT_EQ(out.size(), cloud->size()) << est.getErrorMessage();
    const visfeat::VoxelBand& band = est.getVoxelBand();
    const ref::FreeSubcells rfs(band.grid(), band.coords());
    const std::vector<int> expected = ref::radii(band.coords(), rfs, 6, opacity);
    std::size_t mismatches = 0;
    for (std::size_t i = 0; i < cloud->size(); ++i) {
      const CellId id = band.pointCell()[i];
      ASSERT_NE(id, kNoCell);
      mismatches += out.points[i].visibility_radius !=
                    static_cast<float>(expected[static_cast<std::size_t>(id)]);
    }
    EXPECT_EQ(mismatches, 0u) << "opacity " << opacity;
  }
}

TEST(Estimator, IndicesSelectTheOutputPoints)
{
  const Cloud::Ptr cloud = cloudWithNaNs(63, 20);
  pcl::IndicesPtr indices(new pcl::Indices);
  for (std::size_t i = 0; i < cloud->size(); i += 7)
    indices->push_back(static_cast<pcl::index_t>(i));
  indices->push_back(5); // the NaN point
  Estimator full, part;
  for (Estimator* e : {&full, &part}) {
    e->setInputCloud(cloud);
    e->setResolution(20);
    e->setMaxRadius(6);
    e->setMinRadius(6); // components need min_radius <= max_radius
  }
  part.setIndices(indices);
  Output all, some;
  full.compute(all);
  part.compute(some);
  ASSERT_EQ(all.size(), cloud->size());
  ASSERT_EQ(some.size(), indices->size());
  for (std::size_t k = 0; k < indices->size(); ++k) {
    const visfeat::PointVisibility& a =
      all.points[static_cast<std::size_t>((*indices)[k])];
    const visfeat::PointVisibility& b = some.points[k];
    EXPECT_TRUE(sameFloat(a.x, b.x) && sameFloat(a.y, b.y) && sameFloat(a.z, b.z));
    EXPECT_TRUE(sameFloat(a.visibility_radius, b.visibility_radius)) << "index " << k;
  }
  EXPECT_FALSE(some.is_dense);
}

TEST(Estimator, SameOutputForShuffledPointsAndThreadCounts)
{
  const Cloud::Ptr cloud = cloudWithNaNs(64, 24);
  visfeat_test::ShuffledCloud<pcl::PointXYZ> shuffled_points =
    visfeat_test::shuffledCloud(*cloud, 9);
  const std::vector<std::size_t>& perm = shuffled_points.order;
  const Cloud::Ptr shuffled(new Cloud(std::move(shuffled_points.cloud)));

  Output a, b, c, d;
  Estimator ea, eb, ec, ed;
  ea.setInputCloud(cloud);
  eb.setInputCloud(shuffled);
  ec.setInputCloud(cloud);
  ed.setInputCloud(shuffled);
  for (Estimator* e : {&ea, &eb, &ec, &ed}) {
    e->setResolution(24);
    e->setMaxRadius(9);
    e->setMinRadius(9); // components need min_radius <= max_radius
    e->setOpacity(1.5);
  }
  ea.setNumberOfThreads(1);
  eb.setNumberOfThreads(2);
  ec.setNumberOfThreads(2);
  ed.setNumberOfThreads(4);
  ea.compute(a);
  eb.compute(b);
  ec.compute(c);
  ed.compute(d);
  ASSERT_EQ(a.size(), cloud->size());
  ASSERT_EQ(b.size(), cloud->size());
  ASSERT_EQ(c.size(), cloud->size());
  ASSERT_EQ(ea.getVoxelBand().coords(), eb.getVoxelBand().coords());
  for (std::size_t j = 0; j < perm.size(); ++j) {
    ASSERT_TRUE(
      sameFloat(b.points[j].visibility_radius, a.points[perm[j]].visibility_radius))
      << "shuffled point " << j;
    ASSERT_TRUE(sameFloat(c.points[j].visibility_radius, a.points[j].visibility_radius))
      << "2 threads, point " << j;
  }
  std::vector<std::size_t> identity(perm.size());
  std::iota(identity.begin(), identity.end(), 0);
  expectSamePoints(a, b, perm, "shuffled, 2 threads");
  expectSamePoints(a, c, identity, "2 threads");
  expectSamePoints(a, d, perm, "shuffled, 4 threads");
  EXPECT_EQ(ea.getSegmentation().cellLabels(), eb.getSegmentation().cellLabels());
  EXPECT_EQ(ea.getSegmentation().cellLabels(), ed.getSegmentation().cellLabels());
  expectSameGraph(ea.getTopologyGraph(), eb.getTopologyGraph(), "shuffled, 2 threads");
  expectSameGraph(ea.getTopologyGraph(), ec.getTopologyGraph(), "2 threads");
  expectSameGraph(ea.getTopologyGraph(), ed.getTopologyGraph(), "shuffled, 4 threads");
}

// Complete regions with edges, vertices and faces, in the noise mode (smoothing is
// multithreaded too): labels, classes and graph for 1, 2 and 4 threads and shuffled
// points.
TEST(Estimator, SameRegionsAndGraphForShuffledPointsAndThreadCounts)
{
  Cloud::Ptr cloud(new Cloud(visfeat_test::syntheticShapeCloud("cube", 70, 56)));
  std::vector<std::size_t> perm(cloud->size());
  std::iota(perm.begin(), perm.end(), 0);
  std::mt19937_64 rng(10);
  std::shuffle(perm.begin(), perm.end(), rng);
  Cloud::Ptr shuffled(new Cloud);
  for (std::size_t i : perm)
    shuffled->push_back(cloud->points[i]);
  std::vector<std::size_t> identity(perm.size());
  std::iota(identity.begin(), identity.end(), 0);

  const auto run = [](const Cloud::Ptr& input, unsigned threads, Output& out) {
    auto est = std::make_unique<Estimator>();
    est->setInputCloud(input);
    est->setResolution(56);
    est->setMinRadius(8);
    est->setNoiseMode(true);
    est->setNumberOfThreads(threads);
    est->compute(out);
    EXPECT_EQ(est->getErrorMessage(), "");
    return est;
  };
  Output a, b, c, d;
  const auto ea = run(cloud, 1, a);
  const auto eb = run(shuffled, 2, b);
  const auto ec = run(cloud, 4, c);
  const auto ed = run(shuffled, 4, d);
  // The case is not trivial: vertices, edges and faces, and arcs between them.
  const visfeat::TopologyGraph& graph = ea->getTopologyGraph();
  ASSERT_GT(graph.classCount(visfeat::FeatureClass::kVertex), 0u);
  ASSERT_GT(graph.classCount(visfeat::FeatureClass::kEdge), 0u);
  ASSERT_GT(graph.classCount(visfeat::FeatureClass::kFace), 0u);
  ASSERT_GT(graph.arcCount(), 0u);
  expectSamePoints(a, b, perm, "shuffled, 2 threads");
  expectSamePoints(a, c, identity, "4 threads");
  expectSamePoints(a, d, perm, "shuffled, 4 threads");
  expectSameGraph(graph, eb->getTopologyGraph(), "shuffled, 2 threads");
  expectSameGraph(graph, ec->getTopologyGraph(), "4 threads");
  expectSameGraph(graph, ed->getTopologyGraph(), "shuffled, 4 threads");
}

TEST(Estimator, ErrorMessageClearedAfterSuccess)
{
  Cloud::Ptr cloud(new Cloud(visfeat_test::syntheticShapeCloud("cube", 65, 12)));
  Estimator est;
  est.setInputCloud(cloud);
  est.setResolution(-1); // 0 is the automatic resolution
  expectError(est, {"resolution"});
  est.setResolution(12);
  est.setMaxRadius(4);
  est.setMinRadius(4); // components need min_radius <= max_radius
  Output out;
  est.compute(out);
  EXPECT_EQ(out.size(), cloud->size());
  EXPECT_EQ(est.getErrorMessage(), "");
}

// ---------------------------------------------------------------- bad input

TEST(EstimatorBadInput, EmptyCloud)
{
  Estimator est;
  est.setInputCloud(Cloud::Ptr(new Cloud));
  est.setResolution(32);
  expectError(est, {"empty", "no point"});
  expectErrorMessage(est, "the input cloud is empty");
}

TEST(EstimatorBadInput, NoInputCloud)
{
  Estimator est;
  expectError(est, {"input", "cloud"});
  expectErrorMessage(est, "no input cloud: call setInputCloud() first");
}

TEST(EstimatorBadInput, AllNaNCloud)
{
  Cloud::Ptr cloud(new Cloud);
  for (int i = 0; i < 10; ++i)
    cloud->push_back(pcl::PointXYZ(kNaN, static_cast<float>(i), kNaN));
  cloud->push_back(pcl::PointXYZ(std::numeric_limits<float>::infinity(), 1.f, 1.f));
  cloud->is_dense = false;
  Estimator est;
  est.setInputCloud(cloud);
  est.setResolution(32);
  expectError(est, {"finite", "nan"});
  expectErrorMessage(
    est,
    "the cloud has no finite point: all 11 points have a NaN or infinite coordinate");
  est.setResolution(0); // automatic: the same message
  expectErrorMessage(
    est,
    "the cloud has no finite point: all 11 points have a NaN or infinite coordinate");
}

TEST(EstimatorBadInput, OnePoint)
{
  Cloud::Ptr cloud(new Cloud);
  cloud->push_back(pcl::PointXYZ(1.f, 2.f, 3.f));
  Estimator est;
  est.setInputCloud(cloud);
  est.setResolution(32);
  expectError(est, {"coincide", "single", "one point", "1 point", "extent",
                    "degenerate", "identical", "same"});
  expectErrorMessage(
    est, "the cloud has a single finite point: there is no surface to analyse");
  // Same with repeated copies of one point and NaNs around it.
  cloud->push_back(pcl::PointXYZ(1.f, 2.f, 3.f));
  cloud->push_back(pcl::PointXYZ(kNaN, kNaN, kNaN));
  cloud->is_dense = false;
  expectError(est, {"coincide", "single", "one point", "1 point", "extent",
                    "degenerate", "identical", "same"});
  const std::string coincide =
    "all finite points coincide: the bounding box is a "
    "single point, so there is no extent to divide into cells";
  expectErrorMessage(est, coincide);
  est.setResolution(0); // automatic: the same message
  expectErrorMessage(est, coincide);
}

TEST(EstimatorBadInput, TooFewPointsForOneFace)
{
  // A face spans 2 min_radius cells each way and the fill bridges at most 4 cells a
  // point spacing: fewer than (2 * 16 / 4)^2 = 64 points hold no face at any
  // resolution (3 points gave an empty result and advice to sample denser at 4).
  namespace syn = visfeat::synthetic;
  const syn::CadModel cube = syn::cadModelByName("cube");
  const auto sample = [&](std::size_t count) {
    syn::SamplingOptions options;
    options.count = count;
    options.seed = 5;
    Cloud::Ptr cloud(new Cloud);
    for (const Eigen::Vector3f& p : syn::sampleCadModel(cube, options).points)
      cloud->push_back(pcl::PointXYZ(p.x(), p.y(), p.z()));
    return cloud;
  };
  ASSERT_EQ(visfeat::minimumCloudPoints(16), 64u);
  const Cloud::Ptr few = sample(63);
  for (const int resolution : {Estimator::kAutomaticResolution, 64}) {
    Estimator est;
    est.setInputCloud(few);
    est.setResolution(resolution);
    expectErrorMessage(
      est,
      "only 63 finite points: too few for one face (a face spans 2 min_radius = 32 "
      "cells each way, and the band is filled over at most 4 cells a point "
      "spacing: at least 64 points); sample denser, or give the surface as a mesh "
      "(setInputMesh())");
  }
  // NaNs do not count
  Cloud::Ptr with_nan(new Cloud(*sample(64)));
  with_nan->points[7].x = kNaN;
  with_nan->is_dense = false;
  Estimator est;
  est.setInputCloud(with_nan);
  expectError(est, {"only 63 finite points"});
  // 64 points pass the check (the result is another matter)
  Estimator enough;
  enough.setInputCloud(sample(64));
  enough.setResolution(64);
  Output out;
  enough.compute(out);
  EXPECT_EQ(enough.getErrorMessage(), "");
  EXPECT_EQ(out.size(), 64u);
  // the floor follows min_radius: at 8, 16 points
  EXPECT_EQ(visfeat::minimumCloudPoints(8), 16u);
  Estimator smaller;
  smaller.setInputCloud(few);
  smaller.setResolution(64);
  smaller.setMinRadius(8);
  smaller.compute(out);
  EXPECT_EQ(smaller.getErrorMessage(), "");
  // a mesh gives the band: few output points on it are fine
  auto mesh =
    std::make_shared<visfeat::SurfaceMesh>(syn::tessellateCadModel(cube, 0.01).mesh);
  Estimator meshed;
  meshed.setInputCloud(few);
  meshed.setInputMesh(mesh);
  meshed.setResolution(64);
  meshed.compute(out);
  EXPECT_EQ(meshed.getErrorMessage(), "");
  EXPECT_EQ(meshed.getSegmentation().classCounts()[3], 6u) << "the cube's faces";
}

TEST(EstimatorBadInput, ResolutionOutOfRange)
{
  Cloud::Ptr cloud(new Cloud(visfeat_test::syntheticShapeCloud("cube", 66, 12)));
  // 0 is the automatic resolution (see test_estimator_api.cpp), not out of range.
  for (int resolution : {-1, -5, visfeat::GridSpec::kMinResolution - 1, 100000}) {
    Estimator est;
    est.setInputCloud(cloud);
    est.setResolution(resolution);
    SCOPED_TRACE("resolution " + std::to_string(resolution));
    expectError(est, {"resolution"});
    expectErrorMessage(est, "resolution " + std::to_string(resolution) +
                              " is out of range: 0 (automatic) or [4, 8192] (cells "
                              "along the longest side of the bounding box)");
  }
}

TEST(EstimatorBadInput, VisibilityParametersOutOfRange)
{
  Cloud::Ptr cloud(new Cloud(visfeat_test::syntheticShapeCloud("cube", 67, 12)));
  {
    Estimator est;
    est.setInputCloud(cloud);
    est.setResolution(12);
    est.setOpacity(-1.0);
    expectError(est, {"opacity"});
    expectErrorMessage(est, "opacity -1 is out of range [0, 64] (cell edges)");
  }
  {
    Estimator est;
    est.setInputCloud(cloud);
    est.setResolution(12);
    est.setMaxRadius(-1); // 0 is "auto": min_radius
    expectError(est, {"radius"});
    expectErrorMessage(est, "max_radius -1 is out of range [1, 64] (rings)");
  }
  {
    Estimator est;
    est.setInputCloud(cloud);
    est.setResolution(12);
    est.setMaxRadius(visfeat::VisibilityMap::kMaxRadius + 1);
    expectError(est, {"radius"});
    expectErrorMessage(est, "max_radius 65 is out of range [1, 64] (rings)");
  }
}

TEST(EstimatorBadInput, EveryParameterIsNamedWithValueRangeAndUnit)
{
  Cloud::Ptr cloud(new Cloud(visfeat_test::syntheticShapeCloud("cube", 69, 12)));
  const auto check = [&](const std::function<void(Estimator&)>& set,
                         const std::string& message) {
    Estimator est;
    est.setInputCloud(cloud);
    est.setResolution(12);
    set(est);
    SCOPED_TRACE(message);
    expectErrorMessage(est, message);
  };
  check([](Estimator& e) { e.setMinRadius(0); },
        "min_radius 0 is out of range [1, 64] (rings)");
  check([](Estimator& e) { e.setMinRadius(65); },
        "min_radius 65 is out of range [1, 64] (rings)");
  check(
    [](Estimator& e) {
      e.setMaxRadius(8);
      e.setMinRadius(9);
    },
    "min_radius 9 is out of range [1, max_radius = 8] (rings; raise max_radius to at "
    "least min_radius)");
  check([](Estimator& e) { e.setVertexMaxCells(-1); },
        "vertex_max_cells -1 is out of range [0, 100000] (cells)");
  check([](Estimator& e) { e.setDimensionality(6.5); },
        "dimensionality 6.5 is out of range [0, 6] (mean same-component 6-neighbours)");
  check([](Estimator& e) { e.setSmoothingRadius(8.5); },
        "smoothing radius 8.5 is out of range [0, 8] (cells; 0 = off)");
  check([](Estimator& e) { e.setPointFeatureDistance(-0.5); },
        "point_feature_distance -0.5 is out of range [0, 10] (cells)");
  check([](Estimator& e) { e.setNumberOfThreads(5000); },
        "threads 5000 is out of range [0, 1024] (0 = all available)");
  check([](Estimator& e) { e.setGraphDilation(1001); },
        "dilation_radius 1001 is out of range [0, 1000] (cells)");
  check(
    [](Estimator& e) {
      visfeat::SegmentationParameters p = e.getSegmentationParameters();
      p.join_distance = 1001;
      e.setSegmentationParameters(p);
    },
    "join_distance 1001 is out of range [0, 1000] (cells)");
  check(
    [](Estimator& e) {
      visfeat::SegmentationParameters p = e.getSegmentationParameters();
      p.components.face_min_depth = 0;
      e.setSegmentationParameters(p);
    },
    "face_min_depth 0 is out of range [1, 1000] (cells)");
}

TEST(EstimatorBadInput, MemoryLimitIsEnforced)
{
  Cloud::Ptr cloud(new Cloud(visfeat_test::syntheticShapeCloud("cube", 68, 32)));
  Estimator est;
  est.setInputCloud(cloud);
  est.setResolution(32);
  est.setMemoryLimit(1024); // 1 KiB: nothing fits
  expectError(est, {"memory", "mib"});
  const std::string& message = est.getErrorMessage();
  EXPECT_EQ(message.rfind("a grid of ", 0), 0u) << message;
  EXPECT_NE(message.find(" cells needs about "), std::string::npos) << message;
  EXPECT_NE(message.find(", more than the limit of 0.0 MiB: lower the resolution or "
                         "raise the memory limit"),
            std::string::npos)
    << message;
}

} // namespace
