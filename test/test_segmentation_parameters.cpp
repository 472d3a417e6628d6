// Segmentation modes and parameters, fast: the paper's raw mode on a small cube keeps
// exactly its cores, out-of-range parameters are refused by name, and the result does
// not depend on the number of threads.

#include <support/cad_models.h>
#include <support/synthetic_shapes.h>
#include <visfeat/core/common/error.h>
#include <visfeat/core/segmentation/feature_segmentation.h>
#include <visfeat/visibility_feature_estimation.h>

#include <gtest/gtest.h>
#include <pcl/point_types.h>

#include <memory>
#include <string>

namespace {

namespace synthetic = visfeat::synthetic;

TEST(RawMode, KeepsThePapersLiteralComponents)
{
  // Raw mode labels only cells at or above min_radius and leaves the rest 0.
  const synthetic::CadModel model =
    synthetic::rotated(synthetic::cadModelByName("cube"), synthetic::randomRotation(7));
  synthetic::SamplingOptions options;
  options.count = synthetic::samplesForSpacing(model, 96, 0.5);
  const synthetic::CadSamples samples = synthetic::sampleCadModel(model, options);
  auto cloud = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  for (const auto& p : samples.points)
    cloud->push_back(pcl::PointXYZ(p.x(), p.y(), p.z()));
  visfeat::VisibilityFeatureEstimation<pcl::PointXYZ, visfeat::PointVisibility> est;
  est.setInputCloud(cloud);
  est.setResolution(96);
  est.setMinRadius(11);
  est.setMaxRadius(11);
  est.setRawMode(true);
  pcl::PointCloud<visfeat::PointVisibility> out;
  est.compute(out);
  ASSERT_EQ(out.size(), cloud->size());
  const auto& map = est.getVisibilityMap();
  const auto& band = est.getVoxelBand();
  const auto& seg = est.getSegmentation();
  std::size_t unlabeled = 0;
  for (std::size_t c = 0; c < band.size(); ++c) {
    const bool core = map.radii()[c] >= 11;
    EXPECT_EQ(seg.cellLabels()[c] != 0, core) << "cell " << c;
    unlabeled += !core;
  }
  EXPECT_GT(unlabeled, 0u);
  // Its components are exactly the cores.
  EXPECT_EQ(seg.regions().size(), seg.cores().components().size());
}

TEST(SegmentationParameters, OutOfRangeIsRejectedByName)
{
  const auto rejects = [](visfeat::SegmentationParameters p, const std::string& name) {
    try {
      visfeat::FeatureSegmentation::validate(p, 16);
    } catch (const visfeat::Error& e) {
      return std::string(e.what()).find(name) != std::string::npos;
    }
    return false;
  };
  visfeat::SegmentationParameters p;
  EXPECT_NO_THROW(visfeat::FeatureSegmentation::validate(p, 16));
  p.vertex_reach = 0;
  EXPECT_TRUE(rejects(p, "vertex_reach"));
  p = {};
  p.vertex_reach = -5;
  EXPECT_TRUE(rejects(p, "vertex_reach"));
  p = {};
  p.feature_width = -1;
  EXPECT_TRUE(rejects(p, "feature_width"));
  p = {};
  p.join_distance = -1;
  EXPECT_TRUE(rejects(p, "join_distance"));
  p.join_distance = 1001;
  EXPECT_TRUE(rejects(p, "join_distance"));
  p = {};
  p.point_feature_distance = -0.5;
  EXPECT_TRUE(rejects(p, "point_feature_distance"));
  p = {};
  p.min_piece_cells = -1;
  EXPECT_TRUE(rejects(p, "min_piece_cells"));
  p = {};
  p.components.min_radius = 17; // above the cap of 16
  EXPECT_TRUE(rejects(p, "min_radius"));
  p = {};
  p.threads = -1;
  EXPECT_TRUE(rejects(p, "threads -1 is out of range [0, 1024] (0 = all available)"));
  p.threads = 1025;
  EXPECT_TRUE(rejects(p, "threads 1025 is out of range"));
}

/** The generated cube (seed 3) at 128 cells through the estimator, `threads`
 * threads. */
pcl::PointCloud<visfeat::PointVisibility>
cubeLabels(
  int threads,
  visfeat::VisibilityFeatureEstimation<pcl::PointXYZ, visfeat::PointVisibility>& est)
{
  const synthetic::CadModel model =
    synthetic::rotated(synthetic::cadModelByName("cube"), synthetic::randomRotation(3));
  synthetic::SamplingOptions options;
  options.count = synthetic::samplesForSpacing(model, 128, 0.5);
  const synthetic::CadSamples samples = synthetic::sampleCadModel(model, options);
  auto cloud = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  for (const auto& p : samples.points)
    cloud->push_back(pcl::PointXYZ(p.x(), p.y(), p.z()));
  est.setInputCloud(cloud);
  est.setResolution(128);
  est.setNumberOfThreads(static_cast<unsigned int>(threads));
  pcl::PointCloud<visfeat::PointVisibility> out;
  est.compute(out);
  return out;
}

TEST(SegmentationThreads, ResultIsTheSameForAnyCount)
{
  // The per-core dilations (vertex test, edge joining) run on threads: the labels must
  // not depend on how many.
  visfeat::VisibilityFeatureEstimation<pcl::PointXYZ, visfeat::PointVisibility> one,
    two;
  const auto a = cubeLabels(1, one);
  const auto b = cubeLabels(2, two);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a[i].label, b[i].label) << "point " << i;
    ASSERT_EQ(a[i].feature_class, b[i].feature_class) << "point " << i;
  }
  const auto& band = one.getVoxelBand();
  const auto& map = one.getVisibilityMap();
  visfeat::SegmentationParameters p = one.getSegmentationParameters();
  p.threads = 1;
  const auto serial = visfeat::FeatureSegmentation::compute(band, map, p);
  ASSERT_EQ(serial.classCounts()[1], 8u); // vertices: the dilations ran
  for (const int threads : {2, 3, 0}) {
    p.threads = threads;
    const auto parallel = visfeat::FeatureSegmentation::compute(band, map, p);
    EXPECT_EQ(parallel.cellLabels(), serial.cellLabels()) << threads << " threads";
    EXPECT_EQ(parallel.skeleton(), serial.skeleton()) << threads << " threads";
    ASSERT_EQ(parallel.regions().size(), serial.regions().size());
    for (std::size_t r = 0; r < serial.regions().size(); ++r)
      EXPECT_EQ(parallel.regions()[r].cells, serial.regions()[r].cells);
  }
}

} // namespace
