// Acceptance: the estimator's last per-point step, feature points on flat ground go to
// their face (flatFeaturePoints, setFlatPointVariation). On clean dense clouds of the
// generated models precision rises and recall stays, the graph keeps its nodes, and
// the graph's point counts follow the labelled cloud. About 30 s on 2
// cores: label acceptance.

#include <support/cad_models.h>
#include <support/cad_queries.h>
#include <support/evaluation.h>
#include <visfeat/point_types.h>
#include <visfeat/visibility_feature_estimation.h>

#include "band_fixtures.h"

#include <gtest/gtest.h>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace {

namespace syn = visfeat::synthetic;
using visfeat::FeatureClass;
using Estimator =
  visfeat::VisibilityFeatureEstimation<pcl::PointXYZ, visfeat::PointVisibility>;
using Output = pcl::PointCloud<visfeat::PointVisibility>;

constexpr int kResolution = 256;
/** 0.5 cells a point spacing, as the other acceptance suites. */
constexpr double kSpacingCells = 0.5;

struct ModelCloud
{
  syn::CadModel model;
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud;
};

ModelCloud
modelCloud(const std::string& name, std::uint64_t rotation)
{
  ModelCloud m;
  m.model = syn::rotated(syn::cadModelByName(name), syn::randomRotation(rotation));
  syn::SamplingOptions options;
  options.count = syn::samplesForSpacing(m.model, kResolution, kSpacingCells);
  options.seed = rotation;
  m.cloud = visfeat_test::sampleCadCloud(m.model, options).cloud;
  return m;
}

Output
run(Estimator& est, const ModelCloud& m, double flat_variation)
{
  est.setInputCloud(m.cloud);
  est.setResolution(kResolution);
  est.setFlatPointVariation(flat_variation);
  Output out;
  est.compute(out);
  EXPECT_EQ(est.getErrorMessage(), "");
  return out;
}

bool
isFeature(std::uint8_t c)
{
  return c == static_cast<std::uint8_t>(FeatureClass::kEdge) ||
         c == static_cast<std::uint8_t>(FeatureClass::kVertex);
}

/** Every graph node's point count is the labelled cloud's, and none is 0. */
void
expectNodePointsFollowTheCloud(const Estimator& est, const Output& out)
{
  std::map<std::uint32_t, std::uint64_t> points;
  for (const auto& p : out.points)
    if (p.label != 0)
      ++points[p.label];
  const visfeat::TopologyGraph& graph = est.getTopologyGraph();
  for (std::uint32_t id = 1; id <= graph.size(); ++id) {
    EXPECT_EQ(graph.node(id).points, points[id]) << "node " << id;
    EXPECT_GT(graph.node(id).points, 0u) << "node " << id;
  }
}

TEST(FlatPointsOnModels, PrecisionRisesRecallStaysAndTheGraphStays)
{
  // the default bound against none, on models with wide faces and small features;
  // measured (rotation 1): precision 0.996 -> 1.000 (icosahedron), 0.919 -> 1.000
  // (chamfered box), 0.915 -> 1.000 (stepped block), recall unchanged but for 3
  // icosahedron points 0.95-0.98 cells from its 42-degree creases
  for (const char* name : {"cube", "icosahedron", "chamfered_box", "stepped_block"}) {
    SCOPED_TRACE(name);
    const ModelCloud m = modelCloud(name, 1);
    Estimator on, off;
    const Output labelled = run(on, m, Estimator().getFlatPointVariation());
    const Output plain = run(off, m, 0.0);
    ASSERT_EQ(labelled.size(), plain.size());
    EXPECT_EQ(on.getSegmentation().classCounts(), off.getSegmentation().classCounts());
    const double cell = on.getGrid().cell_size;
    std::vector<std::uint8_t> feature_on(plain.size()), feature_off(plain.size());
    std::vector<double> distance(plain.size());
    std::size_t moved = 0;
    for (std::size_t i = 0; i < plain.size(); ++i) {
      const Eigen::Vector3d p(plain[i].x, plain[i].y, plain[i].z);
      distance[i] = syn::curveDistance(m.model, p) / cell;
      feature_on[i] = isFeature(labelled[i].feature_class);
      feature_off[i] = isFeature(plain[i].feature_class);
      if (labelled[i].label == plain[i].label)
        continue;
      ++moved;
      // only feature points move, to a face, none of them on a crease's line
      EXPECT_TRUE(feature_off[i]) << "point " << i;
      EXPECT_EQ(labelled[i].feature_class,
                static_cast<std::uint8_t>(FeatureClass::kFace));
      EXPECT_GT(distance[i], 0.75) << "point " << i << " moved off a crease";
    }
    const auto with = visfeat::evaluation::scoreFeaturePoints(feature_on, distance);
    const auto without = visfeat::evaluation::scoreFeaturePoints(feature_off, distance);
    std::printf("%s: %zu points moved; precision %.4f -> %.4f, recall %.4f -> %.4f\n",
                name, moved, without.precision(), with.precision(), without.recall(),
                with.recall());
    EXPECT_GE(with.precision(), without.precision());
    EXPECT_GE(with.recall(), without.recall() - 1e-3);
    expectNodePointsFollowTheCloud(on, labelled);
    // a note gives the count (none where nothing moved)
    const std::string said = std::to_string(moved) + " of ";
    const auto& notes = on.getNotes();
    const bool noted =
      std::any_of(notes.begin(), notes.end(), [&](const std::string& n) {
        return n.find("feature points on flat ground: " + said) == 0 &&
               n.find("went to their faces") != std::string::npos;
      });
    EXPECT_EQ(noted, moved > 0);
  }
}

TEST(FlatPointsOnModels, NoiseModeReadsTheSmoothedPoints)
{
  // the step reads the points as the band saw them: in noise mode, smoothed, so a noisy
  // cloud's stray feature points move too (measured, the icosahedron at sigma 0.22
  // cells, rotation 3: precision 0.987 -> 0.994, 368 points), and recall stays
  const syn::CadModel model =
    syn::rotated(syn::cadModelByName("icosahedron"), syn::randomRotation(3));
  const auto sampled = visfeat_test::sampleCadCloud(model, kResolution, 3, 0.22);
  std::vector<double> distance;
  Output out[2];
  for (int k = 0; k < 2; ++k) {
    Estimator est;
    est.setInputCloud(sampled.cloud);
    est.setResolution(kResolution);
    est.setNoiseMode(true);
    est.setFlatPointVariation(k == 0 ? 0.0 : Estimator().getFlatPointVariation());
    est.compute(out[k]);
    ASSERT_EQ(est.getErrorMessage(), "");
    if (k == 0)
      for (const double d : sampled.samples.curve_distance)
        distance.push_back(d / est.getGrid().cell_size);
  }
  ASSERT_EQ(out[0].size(), distance.size());
  std::vector<std::uint8_t> without(distance.size()), with(distance.size());
  std::size_t moved = 0;
  for (std::size_t i = 0; i < distance.size(); ++i) {
    without[i] = isFeature(out[0][i].feature_class);
    with[i] = isFeature(out[1][i].feature_class);
    moved += without[i] && !with[i];
    EXPECT_FALSE(with[i] && !without[i]) << "point " << i << " became a feature point";
  }
  const auto a = visfeat::evaluation::scoreFeaturePoints(without, distance);
  const auto b = visfeat::evaluation::scoreFeaturePoints(with, distance);
  std::printf(
    "noisy icosahedron, noise mode: %zu points moved; precision %.4f -> %.4f, "
    "recall %.4f -> %.4f\n",
    moved, a.precision(), b.precision(), a.recall(), b.recall());
  EXPECT_GT(moved, 0u);
  EXPECT_GT(b.precision(), a.precision());
  EXPECT_GE(b.recall(), a.recall() - 1e-3);
}

TEST(FlatPointsOnModels, ALooseBoundMovesCreasePointsButNoNodeLosesItsPoints)
{
  // the loosest bound reads the points near the cube's 90-degree creases (about 0.06
  // within a 2-cell ball) as flat: most move, yet every node keeps a point (its least
  // flat), and the graph's counts follow the cloud
  const ModelCloud m = modelCloud("cube", 2);
  Estimator loose, plain_est;
  const Output moved =
    run(loose, m, visfeat::FlatPointParameters::kMaxSurfaceVariationRange.max);
  const Output plain = run(plain_est, m, 0.0);
  std::size_t before = 0, after = 0;
  for (std::size_t i = 0; i < plain.size(); ++i) {
    before += isFeature(plain[i].feature_class);
    after += isFeature(moved[i].feature_class);
  }
  EXPECT_LT(after, before / 2) << before << " feature points before";
  EXPECT_EQ(loose.getTopologyGraph().size(), plain_est.getTopologyGraph().size());
  expectNodePointsFollowTheCloud(loose, moved);
}

TEST(FlatPointsOnModels, ACloudTooSparseForTheStepSaysSo)
{
  // 60,000 points of the icosahedron at 256: about 0.5 points a cell squared, so no
  // ball holds 24 points; the labels stay and a note says why
  const syn::CadModel model =
    syn::rotated(syn::cadModelByName("icosahedron"), syn::randomRotation(1));
  syn::SamplingOptions options;
  options.count = 60000;
  options.seed = 1;
  const ModelCloud m{model, visfeat_test::sampleCadCloud(model, options).cloud};
  Estimator on, off;
  const Output labelled = run(on, m, Estimator().getFlatPointVariation());
  const Output plain = run(off, m, 0.0);
  ASSERT_EQ(labelled.size(), plain.size());
  for (std::size_t i = 0; i < plain.size(); ++i)
    ASSERT_EQ(labelled[i].label, plain[i].label) << "point " << i;
  const auto& notes = on.getNotes();
  EXPECT_TRUE(std::any_of(notes.begin(), notes.end(),
                          [](const std::string& n) {
                            return n.find("too few to tell flat ground") !=
                                   std::string::npos;
                          }))
    << "no note on the sparse cloud";
  for (const std::string& n : off.getNotes())
    EXPECT_EQ(n.find("flat ground"), std::string::npos) << n;
}

TEST(FlatPointsOnModels, OutOfRangeIsRefusedByName)
{
  const ModelCloud m = modelCloud("cube", 1);
  Estimator est;
  est.setInputCloud(m.cloud);
  est.setResolution(64);
  est.setFlatPointVariation(0.5);
  Output out;
  est.compute(out);
  EXPECT_NE(est.getErrorMessage().find("flat_point_variation 0.5 is out of range"),
            std::string::npos)
    << est.getErrorMessage();
  EXPECT_TRUE(out.empty());
}

} // namespace
