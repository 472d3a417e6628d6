// The whole pipeline on the generated CAD models at resolution 256, noise-free, under
// random rotations: exact numbers of vertex, edge and face regions, and per-point
// accuracy of the complete regions against each point's distance to the true sharp
// curves. The cases listed are the ones the current method gets exactly right; the
// closing notes of the components issue list those it does not (yet).

#include <visfeat/cad_models.h>
#include <visfeat/error.h>
#include <visfeat/feature_segmentation.h>
#include <visfeat/synthetic_shapes.h>
#include <visfeat/topology_graph.h>
#include <visfeat/visibility_feature_estimation.h>

#include <gtest/gtest.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <limits>
#include <map>
#include <string>

namespace {

using visfeat::FeatureClass;
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
runPipeline(const std::string& name, std::uint64_t seed, int resolution = 256)
{
  PipelineRun run;
  run.model = synthetic::rotated(synthetic::cadModelByName(name),
                                 synthetic::randomRotation(seed * 101));
  synthetic::SamplingOptions options;
  options.count = synthetic::samplesForSpacing(run.model, resolution, 0.5);
  options.seed = seed;
  run.samples = synthetic::sampleCadModel(run.model, options);
  auto cloud = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  for (const auto& p : run.samples.points)
    cloud->push_back(pcl::PointXYZ(p.x(), p.y(), p.z()));
  visfeat::VisibilityFeatureEstimation<pcl::PointXYZ, visfeat::PointVisibility> est;
  est.setInputCloud(cloud);
  est.setResolution(resolution);
  est.compute(run.output);
  EXPECT_EQ(est.getErrorMessage(), "");
  run.counts = est.getSegmentation().classCounts();
  run.cell = est.getGrid().cell_size;
  run.graph = est.getTopologyGraph();
  return run;
}

struct Case
{
  const char* model;
  std::uint64_t seed;
};

std::string
caseName(const testing::TestParamInfo<Case>& info)
{
  return std::string(info.param.model) + "_seed" + std::to_string(info.param.seed);
}

// At least 95% of the points labeled edge or vertex lie within 2 cells of a true sharp
// curve; at least 90% of the points within 1 cell of one are labeled edge or vertex.
void
expectFeaturePointsHugTheTrueCurves(const PipelineRun& run)
{
  std::size_t labeled = 0, labeled_near = 0, near = 0, near_labeled = 0;
  for (std::size_t i = 0; i < run.output.size(); ++i) {
    const auto cls = static_cast<FeatureClass>(run.output[i].feature_class);
    const bool feature = cls == FeatureClass::kEdge || cls == FeatureClass::kVertex;
    const double d = run.samples.curve_distance[i] / run.cell;
    labeled += feature;
    labeled_near += feature && d <= 2.0;
    near += d <= 1.0;
    near_labeled += feature && d <= 1.0;
  }
  ASSERT_GT(labeled, 0u);
  ASSERT_GT(near, 0u);
  EXPECT_GE(double(labeled_near) / double(labeled), 0.95) << "precision (2 cells)";
  EXPECT_GE(double(near_labeled) / double(near), 0.90) << "recall (1 cell)";
}

class ExactTopology : public testing::TestWithParam<Case>
{};

TEST_P(ExactTopology, CountsMatchTheTruth)
{
  const PipelineRun run = runPipeline(GetParam().model, GetParam().seed);
  ASSERT_EQ(run.output.size(), run.samples.points.size());
  EXPECT_EQ(run.counts[1], run.model.vertices.size()) << "vertex regions";
  EXPECT_EQ(run.counts[2], run.model.curves.size()) << "edge regions";
  EXPECT_EQ(run.counts[3], run.model.faces.size()) << "face regions";
  EXPECT_EQ(run.counts[0], 0u);
  // Complete regions: every point has a region.
  for (const auto& p : run.output.points)
    ASSERT_NE(p.label, 0u);

  // Which region is which true curve: the majority of the nearest-curve votes of its
  // edge points; which region is which true vertex: the vertex region holding most
  // points within 3 cells of it.
  const synthetic::CadModel& model = run.model;
  std::map<std::uint32_t, std::map<int, std::size_t>> curve_votes;
  std::vector<std::map<std::uint32_t, std::size_t>> vertex_votes(model.vertices.size());
  for (std::size_t i = 0; i < run.output.size(); ++i) {
    const auto& q = run.output[i];
    const Eigen::Vector3d p = run.samples.points[i].cast<double>();
    if (q.feature_class == static_cast<std::uint8_t>(FeatureClass::kEdge)) {
      int nearest = -1;
      double best = std::numeric_limits<double>::infinity();
      for (std::size_t c = 0; c < model.curves.size(); ++c) {
        const double d = synthetic::curveDistance(model, static_cast<int>(c), p);
        if (d < best) {
          best = d;
          nearest = static_cast<int>(c);
        }
      }
      ++curve_votes[q.label][nearest];
    }
    if (q.feature_class == static_cast<std::uint8_t>(FeatureClass::kVertex))
      for (std::size_t v = 0; v < model.vertices.size(); ++v)
        if ((p - model.vertices[v]).norm() <= 3.0 * run.cell)
          ++vertex_votes[v][q.label];
  }
  auto majority = [](const auto& votes) {
    auto best = votes.begin();
    for (auto it = votes.begin(); it != votes.end(); ++it)
      if (it->second > best->second)
        best = it;
    return best->first;
  };
  std::map<int, std::uint32_t> region_of_curve;
  for (const auto& [region, votes] : curve_votes) {
    const int curve = majority(votes);
    EXPECT_EQ(region_of_curve.count(curve), 0u)
      << "two edge regions claim curve " << curve;
    region_of_curve[curve] = region;
  }
  ASSERT_EQ(region_of_curve.size(), model.curves.size())
    << "every true curve has a region";
  std::vector<std::uint32_t> region_of_vertex(model.vertices.size(), 0);
  for (std::size_t v = 0; v < model.vertices.size(); ++v) {
    ASSERT_FALSE(vertex_votes[v].empty()) << "no vertex region at true vertex " << v;
    region_of_vertex[v] = majority(vertex_votes[v]);
  }
  // Which region is which true face: the majority region of the face-labeled points
  // sampled from it.
  std::vector<std::map<std::uint32_t, std::size_t>> face_votes(model.faces.size());
  for (std::size_t i = 0; i < run.output.size(); ++i)
    if (run.output[i].feature_class == static_cast<std::uint8_t>(FeatureClass::kFace))
      ++face_votes[static_cast<std::size_t>(run.samples.face[i])][run.output[i].label];
  std::vector<std::uint32_t> region_of_face(model.faces.size(), 0);
  for (std::size_t f = 0; f < model.faces.size(); ++f) {
    ASSERT_FALSE(face_votes[f].empty()) << "no face region on true face " << f;
    region_of_face[f] = majority(face_votes[f]);
  }
  for (std::size_t c = 0; c < model.curves.size(); ++c) {
    std::vector<std::uint32_t> faces{
      region_of_face[static_cast<std::size_t>(model.curves[c].faces[0])],
      region_of_face[static_cast<std::size_t>(model.curves[c].faces[1])]};
    std::sort(faces.begin(), faces.end());
    EXPECT_EQ(run.graph.facesOfEdge(region_of_curve[static_cast<int>(c)]), faces)
      << "faces of the region of true curve " << c;
  }

  for (std::size_t c = 0; c < model.curves.size(); ++c) {
    const auto& curve = model.curves[c];
    std::vector<std::uint32_t> expected;
    if (curve.kind == synthetic::CadCurve::Kind::kSegment)
      expected = {region_of_vertex[static_cast<std::size_t>(curve.vertices[0])],
                  region_of_vertex[static_cast<std::size_t>(curve.vertices[1])]};
    std::sort(expected.begin(), expected.end());
    EXPECT_EQ(run.graph.verticesOfEdge(region_of_curve[static_cast<int>(c)]), expected)
      << "vertices of the region of true curve " << c;
  }
  // Every corner is linked to exactly the faces it lies on.
  const std::vector<std::vector<int>> faces_of_vertex = synthetic::vertexFaces(model);
  for (std::size_t v = 0; v < model.vertices.size(); ++v) {
    std::vector<std::uint32_t> expected;
    for (const int f : faces_of_vertex[v])
      expected.push_back(region_of_face[static_cast<std::size_t>(f)]);
    std::sort(expected.begin(), expected.end());
    EXPECT_EQ(run.graph.neighbours(region_of_vertex[v], FeatureClass::kFace), expected)
      << "faces of the region of true vertex " << v;
  }

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
                                         Case{"cylinder", 3}),
                         caseName);

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
  p.point_feature_distance = -0.5;
  EXPECT_TRUE(rejects(p, "point_feature_distance"));
  p = {};
  p.min_piece_cells = -1;
  EXPECT_TRUE(rejects(p, "min_piece_cells"));
  p = {};
  p.components.min_radius = 17; // above the cap of 16
  EXPECT_TRUE(rejects(p, "min_radius"));
}

} // namespace
