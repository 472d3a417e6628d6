// The scoring shared by the tests and visfeat_eval: per-point precision / recall / F1
// on hand-built examples whose answers are known by construction, the threshold sweep
// on scores whose best threshold is known, and the topology comparison on a real run
// and on a deliberately broken copy of it.

#include <support/cad_models.h>
#include <support/evaluation.h>
#include <support/synthetic_shapes.h>
#include <visfeat/core/common/error.h>
#include <visfeat/core/common/feature_class.h>
#include <visfeat/visibility_feature_estimation.h>

#include <gtest/gtest.h>
#include <pcl/point_types.h>

#include <cmath>
#include <limits>
#include <vector>

namespace {

namespace ev = visfeat::evaluation;
namespace syn = visfeat::synthetic;
using visfeat::FeatureClass;

const double kNaN = std::numeric_limits<double>::quiet_NaN();

TEST(PointScores, HandBuiltExample)
{
  // distance (cells):    0    0.5  1.0  1.5  2.0  3.0  5.0  NaN  0.9  10
  // feature:             y    y    n    y    y    y    n    y    n    n
  // Labeled: 6 (indices 0,1,3,4,5,7); within 2 cells: 0,1,3,4 -> 4 (NaN never near).
  // Near (<= 1 cell): 0,1,2,8 -> 4; of which labeled: 0,1 -> 2.
  const std::vector<std::uint8_t> feature{1, 1, 0, 1, 1, 1, 0, 1, 0, 0};
  const std::vector<double> distance{0, 0.5, 1.0, 1.5, 2.0, 3.0, 5.0, kNaN, 0.9, 10};
  const ev::PointScores s = ev::scoreFeaturePoints(feature, distance);
  EXPECT_EQ(s.labeled, 6u);
  EXPECT_EQ(s.labeled_near, 4u);
  EXPECT_EQ(s.near, 4u);
  EXPECT_EQ(s.near_labeled, 2u);
  EXPECT_DOUBLE_EQ(s.precision(), 4.0 / 6.0);
  EXPECT_DOUBLE_EQ(s.recall(), 0.5);
  EXPECT_DOUBLE_EQ(s.f1(), 2.0 * (4.0 / 6.0) * 0.5 / (4.0 / 6.0 + 0.5)); // 4/7
  EXPECT_NEAR(s.f1(), 4.0 / 7.0, 1e-12);

  // Other tolerances move the boundaries: recall within 1.5, precision within 1.
  const ev::PointScores t = ev::scoreFeaturePoints(feature, distance, {1.5, 1.0});
  EXPECT_EQ(t.labeled_near, 2u); // 0, 1
  EXPECT_EQ(t.near, 5u);         // 0, 1, 2, 3, 8
  EXPECT_EQ(t.near_labeled, 3u); // 0, 1, 3
}

TEST(PointScores, DegenerateCasesAreZeroNotNaN)
{
  const ev::PointScores none = ev::scoreFeaturePoints({0, 0}, {0.0, 5.0});
  EXPECT_EQ(none.precision(), 0.0);
  EXPECT_EQ(none.recall(), 0.0);
  EXPECT_EQ(none.f1(), 0.0);
  const ev::PointScores perfect = ev::scoreFeaturePoints({1, 0}, {0.0, 5.0});
  EXPECT_EQ(perfect.f1(), 1.0);
  EXPECT_THROW(ev::scoreFeaturePoints({1, 0, 1}, {0.0, 5.0}), visfeat::Error);
}

// 40 points on a curve (distance 0) with scores 0.60..0.99, 160 far ones (distance 10)
// with scores 0.00..0.59, and one far outlier scored 0.995. Any threshold in
// (0.59, 0.60] labels the 40 + the outlier: P = 40/41, R = 1, F1 = 80/81, and no other
// threshold does better (higher ones lose recall faster than they gain precision:
// dropping the lowest curve point costs 1/40 of recall; lower ones add far points).
struct Constructed
{
  std::vector<float> score;
  std::vector<double> distance;
};

Constructed
constructed()
{
  Constructed c;
  for (int i = 0; i < 40; ++i) {
    c.score.push_back(0.60f + 0.01f * static_cast<float>(i));
    c.distance.push_back(0.0);
  }
  for (int i = 0; i < 160; ++i) {
    c.score.push_back(0.59f * static_cast<float>(i) / 159.0f);
    c.distance.push_back(10.0);
  }
  c.score.push_back(0.995f);
  c.distance.push_back(10.0);
  return c;
}

TEST(ThresholdSweep, FindsTheBestThresholdExactly)
{
  const Constructed c = constructed();
  const ev::ThresholdSweep best = ev::sweepThreshold(c.score, c.distance);
  EXPECT_FLOAT_EQ(static_cast<float>(best.threshold), 0.60f);
  EXPECT_EQ(best.scores.labeled, 41u);
  EXPECT_EQ(best.scores.labeled_near, 40u);
  EXPECT_EQ(best.scores.near, 40u);
  EXPECT_EQ(best.scores.near_labeled, 40u);
  EXPECT_NEAR(best.scores.f1(), 80.0 / 81.0, 1e-12);
  EXPECT_EQ(best.candidates, 201u); // every distinct value

  // The sweep agrees with scoring the labels of its threshold directly.
  std::vector<std::uint8_t> feature(c.score.size());
  for (std::size_t i = 0; i < c.score.size(); ++i)
    feature[i] = c.score[i] >= best.threshold;
  const ev::PointScores direct = ev::scoreFeaturePoints(feature, c.distance);
  EXPECT_EQ(direct.labeled, best.scores.labeled);
  EXPECT_EQ(direct.near_labeled, best.scores.near_labeled);
}

TEST(ThresholdSweep, QuantilesTryOnlyTheirValues)
{
  const Constructed c = constructed();
  // 201 scores, 4 quantiles: indices 0, 50, 100, 150 of the ascending order; the 161st
  // value (index 160) is 0.60, not among them, so the best of these is index 150
  // (0.59 * 150/159 ...) -- 11 far points + 40 near: P = 40/51, R = 1.
  const ev::ThresholdSweep q = ev::sweepThreshold(c.score, c.distance, 4);
  EXPECT_EQ(q.candidates, 4u);
  EXPECT_EQ(q.scores.labeled, 51u);
  EXPECT_NEAR(q.scores.f1(), 2.0 * (40.0 / 51.0) / (40.0 / 51.0 + 1.0), 1e-12);
  EXPECT_LT(q.scores.f1(), ev::sweepThreshold(c.score, c.distance).scores.f1());
}

TEST(ThresholdSweep, TiesNaNsAndEmptyInput)
{
  // All equal: one candidate, everything labeled.
  const ev::ThresholdSweep tie =
    ev::sweepThreshold({0.5f, 0.5f, 0.5f}, {0.0, 0.0, 10.0});
  EXPECT_EQ(tie.candidates, 1u);
  EXPECT_EQ(tie.scores.labeled, 3u);
  EXPECT_FLOAT_EQ(static_cast<float>(tie.threshold), 0.5f);

  // A NaN score is never a feature, but its point still counts for recall.
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const ev::ThresholdSweep with_nan =
    ev::sweepThreshold({nan, 0.9f, 0.1f}, {0.0, 0.0, 10.0});
  EXPECT_EQ(with_nan.scores.near, 2u);
  EXPECT_EQ(with_nan.scores.near_labeled, 1u);
  EXPECT_EQ(with_nan.scores.labeled, 1u);
  EXPECT_NEAR(with_nan.scores.f1(), 2.0 / 3.0, 1e-12);

  const ev::ThresholdSweep empty = ev::sweepThreshold({nan}, {0.0});
  EXPECT_EQ(empty.candidates, 0u);
  EXPECT_TRUE(std::isnan(empty.threshold));
  EXPECT_EQ(empty.scores.f1(), 0.0);
  EXPECT_THROW(ev::sweepThreshold({0.5f}, {0.0, 1.0}), visfeat::Error);
}

// A cube at resolution 96 comes out exact; relabeling one edge region's points with
// another edge region's id must be caught.
TEST(TopologyComparison, ExactCubeAndABrokenCopy)
{
  const syn::CadModel model =
    syn::rotated(syn::cadModelByName("cube"), syn::randomRotation(1));
  syn::SamplingOptions options;
  options.count = syn::samplesForSpacing(model, 96, 0.5);
  options.seed = 1;
  const syn::CadSamples samples = syn::sampleCadModel(model, options);
  auto cloud = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  for (const auto& p : samples.points)
    cloud->push_back(pcl::PointXYZ(p.x(), p.y(), p.z()));
  visfeat::VisibilityFeatureEstimation<pcl::PointXYZ, visfeat::PointVisibility> est;
  est.setInputCloud(cloud);
  est.setResolution(96);
  pcl::PointCloud<visfeat::PointVisibility> out;
  est.compute(out);
  ASSERT_EQ(out.size(), samples.points.size()) << est.getErrorMessage();

  std::vector<std::uint32_t> labels(out.size());
  std::vector<std::uint8_t> classes(out.size());
  for (std::size_t i = 0; i < out.size(); ++i) {
    labels[i] = out[i].label;
    classes[i] = out[i].feature_class;
  }
  const double cell = est.getGrid().cell_size;
  const ev::TopologyComparison good = ev::compareTopology(
    model, samples.points, samples.face, labels, classes, est.getTopologyGraph(), cell);
  EXPECT_EQ(good.truth, (std::array<std::size_t, 3>{8, 12, 6}));
  ASSERT_TRUE(good.exact()) << (good.problems.empty() ? "" : good.problems[0]);
  EXPECT_EQ(good.curves_linked, 12u);

  // Two edge regions made one (in the labels only; the graph keeps both).
  std::uint32_t first = 0, second = 0;
  for (std::size_t i = 0; i < out.size(); ++i)
    if (classes[i] == static_cast<std::uint8_t>(FeatureClass::kEdge)) {
      if (first == 0)
        first = labels[i];
      else if (labels[i] != first && second == 0)
        second = labels[i];
    }
  ASSERT_NE(second, 0u);
  for (auto& label : labels)
    if (label == second)
      label = first;
  const ev::TopologyComparison broken = ev::compareTopology(
    model, samples.points, samples.face, labels, classes, est.getTopologyGraph(), cell);
  EXPECT_TRUE(broken.countsExact()); // the graph's counts did not change
  EXPECT_EQ(broken.curves_matched, 11u);
  EXPECT_FALSE(broken.arcsCorrect());
  EXPECT_FALSE(broken.exact());
  EXPECT_FALSE(broken.problems.empty());

  // Vertex points moved to face class: the vertices are not found.
  std::vector<std::uint8_t> no_vertices = classes;
  for (auto& c : no_vertices)
    if (c == static_cast<std::uint8_t>(FeatureClass::kVertex))
      c = static_cast<std::uint8_t>(FeatureClass::kFace);
  const ev::TopologyComparison lost =
    ev::compareTopology(model, samples.points, samples.face, labels, no_vertices,
                        est.getTopologyGraph(), cell);
  EXPECT_EQ(lost.vertices_matched, 0u);
  EXPECT_FALSE(lost.arcsCorrect());

  EXPECT_THROW(ev::compareTopology(model, samples.points, {}, labels, classes,
                                   est.getTopologyGraph(), cell),
               visfeat::Error);
}

} // namespace
