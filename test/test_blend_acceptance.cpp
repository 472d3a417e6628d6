// Acceptance (ctest -L acceptance): sharp versus smooth on the blend models of
// blend_models.h at resolution 256, three rotations each. With the default minimum
// crease angle the fillets of the filleted box and the 10-degree facets of the faceted
// boss are faces, not edges: the counts and the arcs are the truth a CAD user expects,
// and every edge left measures the true 90-degree turn. With the rule off the same
// clouds keep spurious edges (the counts the rule removes are printed).

#include <support/blend_models.h>
#include <support/cad_models.h>
#include <support/synthetic_shapes.h>
#include <visfeat/point_types.h>
#include <visfeat/visibility_feature_estimation.h>

#include <gtest/gtest.h>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace {

namespace syn = visfeat::synthetic;
using visfeat::FeatureClass;
using Estimator =
  visfeat::VisibilityFeatureEstimation<pcl::PointXYZ, visfeat::PointVisibility>;

constexpr int kResolution = 256;
/** Sampling density of the other acceptance suites: 0.5 cells a point spacing. */
constexpr double kSpacingCells = 0.5;
/** A true crease turns 90 degrees; its measure (median of plane fits on noise-free
 * points) stays within this many degrees. */
constexpr double kCreaseTolerance = 3.0;
/** On a cloud sparser than the cells (a point spacing of 1.1 cells) a shallow
 * crease's measure, sometimes from a window twice as wide, stays within this many
 * degrees (measured: 24.0-35.3 for 27.7 on a 13-sided prism, rotations 1-4). */
constexpr double kSparseCreaseTolerance = 8.0;

struct Case
{
  const char* model;
  std::uint64_t rotation;
};

struct BlendRun
{
  std::array<std::size_t, 4> counts{};
  visfeat::TopologyGraph graph;
};

/** The estimator at kResolution with the given minimum crease angle on a cloud. */
void
computeAt256(Estimator& est,
             const pcl::PointCloud<pcl::PointXYZ>::Ptr& cloud,
             double min_angle)
{
  est.setInputCloud(cloud);
  est.setResolution(kResolution);
  est.setMinCreaseAngle(min_angle);
  pcl::PointCloud<visfeat::PointVisibility> out;
  est.compute(out);
  EXPECT_EQ(est.getErrorMessage(), "");
}

BlendRun
runModel(const syn::BlendModel& model, std::uint64_t rotation, double min_angle)
{
  const syn::TriangleMesh mesh =
    syn::rotated(model.mesh, syn::randomRotation(rotation));
  const std::size_t count = syn::samplesForSpacing(mesh, kResolution, kSpacingCells);
  auto cloud = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  for (const Eigen::Vector3f& p : syn::sampleSurface(mesh, count, rotation))
    cloud->push_back(pcl::PointXYZ(p.x(), p.y(), p.z()));
  Estimator est;
  computeAt256(est, cloud, min_angle);
  BlendRun run;
  run.counts = est.getSegmentation().classCounts();
  run.graph = est.getTopologyGraph();
  std::cout << model.name << " rotation " << rotation << " min_crease_angle "
            << min_angle << ": " << count << " points, V/E/F " << run.counts[1] << "/"
            << run.counts[2] << "/" << run.counts[3] << ", arcs "
            << run.graph.arcCount() << "; edge angles:";
  for (std::uint32_t id = 1; id <= run.graph.size(); ++id)
    if (run.graph.node(id).feature_class == FeatureClass::kEdge)
      std::cout << " " << run.graph.node(id).crease_angle;
  std::cout << std::endl;
  // the rule's promise: no edge it measured stays below the minimum (it measures again
  // after merging faces and merges again: the public rocker arm kept a 16.5-degree
  // edge under 20 with a single round)
  for (std::uint32_t id = 1; id <= run.graph.size(); ++id) {
    const double angle = run.graph.node(id).crease_angle;
    if (run.graph.node(id).feature_class == FeatureClass::kEdge &&
        std::isfinite(angle)) {
      EXPECT_GE(angle, min_angle) << model.name << " edge " << id;
    }
  }
  return run;
}

class BlendModels : public testing::TestWithParam<Case>
{};

TEST_P(BlendModels, BlendsAreFacesAndCreasesAreExact)
{
  const syn::BlendModel model = syn::blendModelByName(GetParam().model);
  const BlendRun run = runModel(model, GetParam().rotation,
                                visfeat::CreaseAngleParameters::kDefaultMinCreaseAngle);
  EXPECT_EQ(run.counts[1], std::size_t(model.vertices)) << model.truth;
  EXPECT_EQ(run.counts[2], std::size_t(model.curves)) << model.truth;
  EXPECT_EQ(run.counts[3], std::size_t(model.faces)) << model.truth;
  EXPECT_EQ(run.graph.arcCount(), std::size_t(model.arcs));
  for (std::uint32_t id = 1; id <= run.graph.size(); ++id) {
    const visfeat::GraphNode& node = run.graph.node(id);
    if (node.feature_class != FeatureClass::kEdge)
      continue;
    EXPECT_NEAR(node.crease_angle, model.crease_turn, kCreaseTolerance)
      << "edge " << id;
    EXPECT_EQ(run.graph.facesOfEdge(id).size(), 2u) << "edge " << id;
  }
}

std::string
caseName(const testing::TestParamInfo<Case>& info)
{
  return std::string(info.param.model) + "_rotation" +
         std::to_string(info.param.rotation);
}

INSTANTIATE_TEST_SUITE_P(Rotations,
                         BlendModels,
                         testing::Values(Case{"filleted_box", 1},
                                         Case{"filleted_box", 2},
                                         Case{"filleted_box", 3},
                                         Case{"faceted_boss", 1},
                                         Case{"faceted_boss", 2},
                                         Case{"faceted_boss", 3}),
                         caseName);

// The rule is what makes them exact: off, the fillets and facets give edges (or
// corners) that the truth does not have.
TEST(BlendModelsWithoutTheRule, KeepSpuriousFeatures)
{
  for (const std::string& name : syn::blendModelNames()) {
    const syn::BlendModel model = syn::blendModelByName(name);
    const BlendRun run = runModel(model, 2, 0.0);
    EXPECT_GT(run.counts[1] + run.counts[2], std::size_t(model.vertices + model.curves))
      << name;
  }
}

/** Counts of a generated CAD model at 256 with the given minimum crease angle. */
std::array<std::size_t, 4>
cadCounts(const std::string& name, std::uint64_t rotation, double min_angle)
{
  const syn::CadModel model =
    syn::rotated(syn::cadModelByName(name), syn::randomRotation(rotation));
  syn::SamplingOptions options;
  options.count = syn::samplesForSpacing(model, kResolution, kSpacingCells);
  options.seed = rotation;
  auto cloud = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  for (const Eigen::Vector3f& p : syn::sampleCadModel(model, options).points)
    cloud->push_back(pcl::PointXYZ(p.x(), p.y(), p.z()));
  Estimator est;
  computeAt256(est, cloud, min_angle);
  return est.getSegmentation().classCounts();
}

// Sharp turns closer than the separation are not blends: the chamfers (45-degree
// creases 6-20 cells apart) and the three 30/60/30-degree creases 10 cells apart are
// split between faces like a fillet at 256, but the rule finds their sharp turns
// beside the contact and keeps what the segmentation found (measured before the walk
// across contacts and edges: the chamfered box lost 2 of 4 corners and 3 edges at
// rotation 1, the creases 2 edges and a face on all three rotations). With the rule
// the faces that still touch across a sharp turn also get an edge on it (contact
// creases), and a face whose own points turn is split there (creasedFacePieces()): no
// vertex, edge or face is lost, and none is added beyond the model's own (measured
// 2026-12-07 at rotation 1, rule against off: the chamfered box 8 vertices and 9 faces
// against 5 and 8, truth 16/24/10; the creases 11 and 9 against 8 and 7, truth
// 14/21/9; before the face split the rule added edges only).
TEST(BlendModelsWithTheRule, CreasesCloserThanTheSeparationAreKept)
{
  // rotation 1: where both merged wrongly (40 s for all three rotations on 2 loaded
  // cores; CI stays under 20 minutes)
  for (const char* name : {"chamfered_box", "parallel_creases"}) {
    const std::array<std::size_t, 4> rule = cadCounts(name, 1, 20.0);
    const std::array<std::size_t, 4> off = cadCounts(name, 1, 0.0);
    const syn::CadModel truth = syn::cadModelByName(name);
    const std::array<std::size_t, 4> most{
      {0, truth.vertices.size(), truth.curves.size(), truth.faces.size()}};
    for (const std::size_t c : {1u, 2u, 3u}) {
      EXPECT_GE(rule[c], off[c]) << name << ": class " << c;
      EXPECT_LE(rule[c], most[c]) << name << ": class " << c;
    }
  }
}

// A prism of 13 facets (27.7-degree creases) sampled at a point spacing of about 1.1
// cells at 256: the creases' edge regions are wider there than the crease angle's
// window, and contact creases between split facets overlap at their ends. Every edge
// between two faces carries its measured turn in the graph (before, on the rotations
// measured: 2-6 of 39 edges had none, null in the graph JSON, and one read 166 degrees
// from the one sample of 48 that saw two faces), the facet creases' near 27.7 degrees
// and the rims' near 90.
TEST(SparseFacetedPrism, EveryEdgeBetweenTwoFacesCarriesItsTurn)
{
  constexpr int kSides = 13;
  constexpr double kPi = 3.14159265358979323846;
  const double facet_turn = 360.0 / kSides;
  std::vector<Eigen::Vector3d> corners;
  for (const double z : {-1.0, 1.0})
    for (int k = 0; k < kSides; ++k)
      corners.emplace_back(std::cos(2.0 * kPi * k / kSides),
                           std::sin(2.0 * kPi * k / kSides), z);
  const syn::TriangleMesh prism = syn::fanTriangulation(syn::convexHull(corners));
  for (std::uint64_t rotation = 1; rotation <= 3; ++rotation) {
    const syn::TriangleMesh mesh =
      syn::rotated(prism, syn::randomRotation(70 + rotation));
    auto cloud = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
    for (const Eigen::Vector3f& p : syn::sampleSurface(mesh, 200000, rotation))
      cloud->push_back(pcl::PointXYZ(p.x(), p.y(), p.z()));
    Estimator est;
    computeAt256(est, cloud, visfeat::CreaseAngleParameters::kDefaultMinCreaseAngle);
    const visfeat::TopologyGraph& graph = est.getTopologyGraph();
    std::size_t two_sided = 0;
    for (std::uint32_t id = 1; id <= graph.size(); ++id) {
      if (graph.node(id).feature_class != FeatureClass::kEdge ||
          graph.facesOfEdge(id).size() != 2)
        continue;
      ++two_sided;
      const double angle = graph.node(id).crease_angle;
      ASSERT_TRUE(std::isfinite(angle)) << "rotation " << rotation << " edge " << id;
      EXPECT_LT(std::min(std::abs(angle - facet_turn), std::abs(angle - 90.0)),
                kSparseCreaseTolerance)
        << "rotation " << rotation << " edge " << id << ": " << angle;
    }
    EXPECT_GE(two_sided, std::size_t(2 * kSides)) << "rotation " << rotation;
  }
}

} // namespace
