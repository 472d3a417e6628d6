// Acceptance (ctest -L acceptance): the whole pipeline on the generated CAD models at
// resolution 256, noise-free and noisy, under random rotations: exact numbers of
// vertex, edge and face regions, and per-point accuracy of the complete regions
// against each point's distance to the true sharp curves. The cases listed are the
// ones the current method gets exactly right; the closing notes of the components
// issue list those it does not (yet).

#include "band_fixtures.h"

#include <support/cad_models.h>
#include <support/evaluation.h>
#include <support/synthetic_shapes.h>
#include <visfeat/core/common/error.h>
#include <visfeat/core/graph/topology_graph.h>
#include <visfeat/core/mesh/mesh_sampling.h>
#include <visfeat/core/segmentation/feature_segmentation.h>
#include <visfeat/visibility_feature_estimation.h>

#include <gtest/gtest.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace {

using visfeat::FeatureClass;
namespace evaluation = visfeat::evaluation;
namespace synthetic = visfeat::synthetic;

struct PipelineRun
{
  synthetic::CadModel model; // rotated
  synthetic::CadSamples samples;
  pcl::PointCloud<visfeat::PointVisibility> output;
  std::array<std::size_t, 4> counts{};
  double cell = 0.0;
  visfeat::TopologyGraph graph;
};

PipelineRun
runPipeline(const std::string& name,
            std::uint64_t seed,
            int resolution = 256,
            double noise_cells = 0.0,
            std::uint64_t rotation = 0,
            int join_distance = -1)
{
  PipelineRun run;
  run.model = synthetic::rotated(
    synthetic::cadModelByName(name),
    synthetic::randomRotation(rotation != 0 ? rotation : seed * 101));
  visfeat_test::SampledCadModel sampled =
    visfeat_test::sampleCadCloud(run.model, resolution, seed, noise_cells);
  run.samples = std::move(sampled.samples);
  const auto cloud = sampled.cloud;
  visfeat::VisibilityFeatureEstimation<pcl::PointXYZ, visfeat::PointVisibility> est;
  est.setInputCloud(cloud);
  est.setResolution(resolution);
  est.setNoiseMode(noise_cells > 0.0);
  if (join_distance >= 0) {
    auto parameters = est.getSegmentationParameters();
    parameters.join_distance = join_distance;
    est.setSegmentationParameters(parameters);
  }
  est.compute(run.output);
  EXPECT_EQ(est.getErrorMessage(), "");
  run.counts = est.getSegmentation().classCounts();
  // The nominal cell the noise and the tolerances refer to (a noisy cloud's own grid
  // is slightly coarser).
  run.cell = noise_cells > 0.0 ? synthetic::cellSize(run.model, resolution)
                               : est.getGrid().cell_size;
  run.graph = est.getTopologyGraph();
  return run;
}

struct Case
{
  const char* model;
  std::uint64_t seed;
  /** Rotation seed; 0 = seed * 101. */
  std::uint64_t rotation = 0;
};

std::string
caseName(const testing::TestParamInfo<Case>& info)
{
  return std::string(info.param.model) + "_seed" + std::to_string(info.param.seed) +
         (info.param.rotation != 0 ? "_rotation" + std::to_string(info.param.rotation)
                                   : "");
}

// At least 95% of the points labeled edge or vertex lie within 2 cells of a true sharp
// curve; at least 90% of the points within 1 cell of one are labeled edge or vertex.
// Per point: edge/vertex labels against the distance to the true sharp curves.
evaluation::PointScores
featureScores(const PipelineRun& run)
{
  std::vector<std::uint8_t> feature(run.output.size());
  std::vector<double> distance(run.output.size());
  for (std::size_t i = 0; i < run.output.size(); ++i) {
    const auto cls = static_cast<FeatureClass>(run.output[i].feature_class);
    feature[i] = cls == FeatureClass::kEdge || cls == FeatureClass::kVertex;
    distance[i] = run.samples.curve_distance[i] / run.cell;
  }
  return evaluation::scoreFeaturePoints(feature, distance);
}

// The run's regions and graph matched against the model's truth (evaluation.h).
evaluation::TopologyComparison
compareWithTruth(const PipelineRun& run)
{
  std::vector<std::uint32_t> labels(run.output.size());
  std::vector<std::uint8_t> classes(run.output.size());
  for (std::size_t i = 0; i < run.output.size(); ++i) {
    labels[i] = run.output[i].label;
    classes[i] = run.output[i].feature_class;
  }
  return evaluation::compareTopology(run.model, run.samples.points, run.samples.face,
                                     labels, classes, run.graph, run.cell);
}

void
expectFeaturePointsHugTheTrueCurves(const PipelineRun& run)
{
  const evaluation::PointScores scores = featureScores(run);
  ASSERT_GT(scores.labeled, 0u);
  ASSERT_GT(scores.near, 0u);
  EXPECT_GE(scores.precision(), 0.95) << "precision (2 cells)";
  EXPECT_GE(scores.recall(), 0.90) << "recall (1 cell)";
}

std::string
joinLines(const std::vector<std::string>& lines)
{
  std::string text;
  for (const auto& line : lines)
    text += "\n  " + line;
  return text;
}

class ExactTopology : public testing::TestWithParam<Case>
{};

TEST_P(ExactTopology, CountsMatchTheTruth)
{
  const PipelineRun run =
    runPipeline(GetParam().model, GetParam().seed, 256, 0.0, GetParam().rotation);
  ASSERT_EQ(run.output.size(), run.samples.points.size());
  EXPECT_EQ(run.counts[1], run.model.vertices.size()) << "vertex regions";
  EXPECT_EQ(run.counts[2], run.model.curves.size()) << "edge regions";
  EXPECT_EQ(run.counts[3], run.model.faces.size()) << "face regions";
  EXPECT_EQ(run.counts[0], 0u);
  // Complete regions: every point has a region.
  for (const auto& p : run.output.points)
    ASSERT_NE(p.label, 0u);

  // Regions matched to the true curves, vertices and faces (evaluation.h says how);
  // every curve's region links exactly the regions of its two faces and of its end
  // vertices (none for a circle).
  const evaluation::TopologyComparison comparison = compareWithTruth(run);
  EXPECT_TRUE(comparison.countsExact()) << joinLines(comparison.problems);
  EXPECT_EQ(comparison.curves_matched, run.model.curves.size());
  EXPECT_EQ(comparison.vertices_matched, run.model.vertices.size());
  EXPECT_EQ(comparison.faces_matched, run.model.faces.size());
  EXPECT_EQ(comparison.curves_linked, run.model.curves.size());
  EXPECT_EQ(comparison.vertices_linked, run.model.vertices.size())
    << "every corner links exactly its faces";
  EXPECT_TRUE(comparison.exact()) << joinLines(comparison.problems);

  // Complete regions hug the curves.
  expectFeaturePointsHugTheTrueCurves(run);
}

// Every generated model under three random rotations: exact counts, every straight
// edge linked to exactly its two vertices (circles to none) and every edge to exactly
// its two faces, a vertex region within 3 cells of every true corner, and the
// per-point bars.
INSTANTIATE_TEST_SUITE_P(Models,
                         ExactTopology,
                         testing::Values(Case{"cube", 1},
                                         Case{"cube", 2},
                                         Case{"cube", 3},
                                         Case{"tetrahedron", 1},
                                         Case{"tetrahedron", 2},
                                         Case{"tetrahedron", 3},
                                         Case{"icosahedron", 1},
                                         Case{"icosahedron", 2},
                                         Case{"icosahedron", 3},
                                         Case{"triangular_prism", 1},
                                         Case{"triangular_prism", 2},
                                         Case{"triangular_prism", 3},
                                         Case{"u_prism", 1},
                                         Case{"u_prism", 2},
                                         Case{"u_prism", 3},
                                         Case{"box_with_hole", 1},
                                         Case{"box_with_hole", 2},
                                         Case{"box_with_hole", 3},
                                         Case{"cylinder", 1},
                                         Case{"cylinder", 2},
                                         Case{"cylinder", 3},
                                         // visfeat_generate icosahedron -seed 1: the
                                         // README's picture (edges of one corner
                                         // crossing near it once lost an arc)
                                         Case{"icosahedron", 1, 1}),
                         caseName);

// Noise mode (smoothing 2 cells, feature points within 1.25 cells) on noisy clouds,
// every model under three random rotations at sigma 0.22 and 0.32 cell: exact counts,
// arcs and everything compareTopology() checks, and per-point F1 >= 0.95.
// The U prism at sigma 0.22, seed 1 once linked one 60-cell edge to only one corner:
// stray core cells near the corner were taken for the end of the edge's body.
struct NoisyCase
{
  const char* model;
  double sigma;
  std::uint64_t seed;
};

class NoiseMode : public testing::TestWithParam<NoisyCase>
{};

TEST_P(NoiseMode, RecoversTheTopology)
{
  const NoisyCase& c = GetParam();
  const PipelineRun run = runPipeline(c.model, c.seed, 256, c.sigma);
  const evaluation::TopologyComparison comparison = compareWithTruth(run);
  EXPECT_TRUE(comparison.exact()) << joinLines(comparison.problems);
  const evaluation::PointScores scores = featureScores(run);
  EXPECT_GE(scores.f1(), 0.95)
    << "precision " << scores.precision() << ", recall " << scores.recall();
}

std::string
noisyCaseName(const testing::TestParamInfo<NoisyCase>& info)
{
  return std::string(info.param.model) + "_sigma" +
         std::to_string(static_cast<int>(std::lround(info.param.sigma * 100))) +
         "_seed" + std::to_string(info.param.seed);
}

std::vector<NoisyCase>
noisyCases()
{
  std::vector<NoisyCase> cases;
  for (const char* model : {"cube", "tetrahedron", "icosahedron", "triangular_prism",
                            "u_prism", "box_with_hole", "cylinder"})
    for (const double sigma : {0.22, 0.32})
      for (const std::uint64_t seed : {1, 2, 3})
        cases.push_back(NoisyCase{model, sigma, seed});
  return cases;
}

INSTANTIATE_TEST_SUITE_P(Models,
                         NoiseMode,
                         testing::ValuesIn(noisyCases()),
                         noisyCaseName);

// At sigma 0.45 cell, at least 90% of the true vertices and edges found (a region of
// their own).
class HeavyNoise : public testing::TestWithParam<const char*>
{};

TEST_P(HeavyNoise, FindsNineTenthsOfTheFeatures)
{
  const PipelineRun run = runPipeline(GetParam(), 1, 256, 0.45);
  const evaluation::TopologyComparison comparison = compareWithTruth(run);
  EXPECT_GE(static_cast<double>(comparison.vertices_matched),
            0.9 * static_cast<double>(run.model.vertices.size()))
    << joinLines(comparison.problems);
  EXPECT_GE(static_cast<double>(comparison.curves_matched),
            0.9 * static_cast<double>(run.model.curves.size()))
    << joinLines(comparison.problems);
}

INSTANTIATE_TEST_SUITE_P(Models,
                         HeavyNoise,
                         testing::Values("cube",
                                         "tetrahedron",
                                         "icosahedron",
                                         "triangular_prism",
                                         "u_prism",
                                         "box_with_hole",
                                         "cylinder"),
                         [](const testing::TestParamInfo<const char*>& info) {
                           return std::string(info.param);
                         });

// Joining: at sigma 0.32 noise breaks edges of the box with hole into pieces that the
// default join_distance (24 cells) joins (NoiseMode checks 14 edges); without joining
// (0: only touching pieces) some edges come out in pieces.
// The icosahedron as the public lapy file has it: a corner on each end of the z axis,
// the rings of five at z = +-2/sqrt(5), a mirror plane (y = 0) on a plane of the grid.
// In that orientation its shallow creases (138 degrees) break into several edge
// regions, and the split-corner rule took two corners a whole edge apart that shared
// two of them for one corner split in two: 12 corners became 2 at 300 cells and 1 at
// 400 (the file's 1,000,000-point cloud: 2 vertices, 23 edges at its automatic 323).
visfeat::SurfaceMesh
poleIcosahedron()
{
  const double pi = std::acos(-1.0), r = 4.0 / std::sqrt(5.0), h = 2.0 / std::sqrt(5.0);
  visfeat::SurfaceMesh mesh;
  mesh.vertices.emplace_back(0.0, 0.0, 2.0); // 0: north; 1-5 upper ring; 6-10 lower
  for (int k = 0; k < 5; ++k)
    mesh.vertices.emplace_back(r * std::cos(2 * pi * k / 5),
                               r * std::sin(2 * pi * k / 5), h);
  for (int k = 0; k < 5; ++k)
    mesh.vertices.emplace_back(r * std::cos(2 * pi * k / 5 + pi / 5),
                               r * std::sin(2 * pi * k / 5 + pi / 5), -h);
  mesh.vertices.emplace_back(0.0, 0.0, -2.0); // 11: south
  for (std::uint32_t k = 0; k < 5; ++k) {
    const std::uint32_t u = 1 + k, u1 = 1 + (k + 1) % 5, l = 6 + k,
                        l1 = 6 + (k + 1) % 5;
    mesh.triangles.push_back({0, u, u1});
    mesh.triangles.push_back({u, l, u1});
    mesh.triangles.push_back({l, l1, u1});
    mesh.triangles.push_back({11, l1, l});
  }
  return mesh;
}

TEST(SymmetricOrientation, EveryCornerOfThePoleIcosahedronIsItsOwnVertex)
{
  const auto mesh = std::make_shared<visfeat::SurfaceMesh>(poleIcosahedron());
  auto cloud = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  for (const visfeat::MeshSample& s : visfeat::sampleMesh(*mesh, 100000, 7))
    cloud->push_back(pcl::PointXYZ(s.position.x(), s.position.y(), s.position.z()));
  for (const int resolution : {300, 400}) {
    visfeat::VisibilityFeatureEstimation<pcl::PointXYZ, visfeat::PointVisibility> est;
    est.setInputCloud(cloud);
    est.setInputMesh(mesh);
    est.setResolution(resolution);
    pcl::PointCloud<visfeat::PointVisibility> out;
    est.compute(out);
    ASSERT_EQ(est.getErrorMessage(), "");
    const double cell = est.getGrid().cell_size;
    // per vertex region, the true corners its points lie near (within 2 min_radius)
    std::map<std::uint32_t, std::set<std::size_t>> corners_of;
    for (const visfeat::PointVisibility& p : out.points) {
      if (p.feature_class != static_cast<std::uint8_t>(FeatureClass::kVertex))
        continue;
      const Eigen::Vector3d at = p.getVector3fMap().cast<double>();
      for (std::size_t v = 0; v < mesh->vertices.size(); ++v)
        if ((at - mesh->vertices[v]).norm() < 2.0 * est.getMinRadius() * cell)
          corners_of[p.label].insert(v);
    }
    std::set<std::size_t> found;
    for (const auto& [label, corners] : corners_of) {
      EXPECT_EQ(corners.size(), 1u)
        << "resolution " << resolution << ": vertex region " << label << " holds "
        << corners.size() << " corners";
      found.insert(corners.begin(), corners.end());
    }
    EXPECT_EQ(found.size(), 12u) << "resolution " << resolution;
    EXPECT_EQ(est.getSegmentation().classCounts()[1], 12u)
      << "resolution " << resolution;
  }
}

TEST(Joining, NoiseSplitEdgesAreJoined)
{
  const PipelineRun run = runPipeline("box_with_hole", 1, 256, 0.32, 0, 0);
  EXPECT_GT(run.counts[2], run.model.curves.size());
}

} // namespace
