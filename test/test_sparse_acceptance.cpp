// Acceptance: sparse clouds with default options. Every generated model at 10,000,
// 20,000 and 40,000 points under three rotations (fresh seeds, none used while tuning
// the fill): the per-point bars of the components issue on every case (precision >=
// 0.95 within 2, recall >= 0.90 within 1, in point spacings where the cells are finer
// than the spacing), and exact counts and arcs on a guarded share of the cases. One
// ctest case per model and point count (17-24 s each on 2 cores): the 10,000-point
// cases are label acceptance, the 20,000 and 40,000 label extended (test/CMakeLists).

#include "band_fixtures.h"

#include <support/cad_models.h>
#include <support/evaluation.h>
#include <visfeat/point_types.h>
#include <visfeat/visibility_feature_estimation.h>

#include <gtest/gtest.h>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace {

namespace syn = visfeat::synthetic;
namespace ev = visfeat::evaluation;
using Estimator =
  visfeat::VisibilityFeatureEstimation<pcl::PointXYZ, visfeat::PointVisibility>;

/** A (model, point count) pair and the rotations of it, of 3, that must give exact
 * counts and arcs: all of them, as the issue asks, since 2026-12-04 (53 of 63 before
 * the stray regions were merged, 56 before the cut's gaps between an edge and its
 * corner were rejoined, 57 before an edge kept at most two faces, 58 before a corner
 * split in two was joined, 59 before edges were bridged to their corners, 60 before a
 * corner at the end of one edge only joined it, 61 before a face sliver along one
 * crease joined its face, 62 before a corner took the point where its creases meet:
 * the tetrahedron at 10,000 points, seed 31, whose vertex cores lie 21 cells down
 * the spike from its tip). The run is deterministic (any thread count). */
struct SparseCase
{
  const char* model;
  std::size_t count;
  int min_exact;
};

const SparseCase kCases[] = {
  {"cube", 10000, 3},
  {"cube", 20000, 3},
  {"cube", 40000, 3},
  {"tetrahedron", 10000, 3},
  {"tetrahedron", 20000, 3},
  {"tetrahedron", 40000, 3},
  {"icosahedron", 10000, 3},
  {"icosahedron", 20000, 3},
  {"icosahedron", 40000, 3},
  {"triangular_prism", 10000, 3},
  {"triangular_prism", 20000, 3},
  {"triangular_prism", 40000, 3},
  {"u_prism", 10000, 3},
  {"u_prism", 20000, 3},
  {"u_prism", 40000, 3},
  {"box_with_hole", 10000, 3},
  {"box_with_hole", 20000, 3},
  {"box_with_hole", 40000, 3},
  {"cylinder", 10000, 3},
  {"cylinder", 20000, 3},
  {"cylinder", 40000, 3},
};

const std::uint64_t kSeeds[] = {31, 32, 33};

/** For gtest's names of the cases (ctest lists them). */
void
PrintTo(const SparseCase& c, std::ostream* out)
{
  *out << c.model << " at " << c.count << " points";
}

struct Outcome
{
  std::string name;
  bool exact = false;
  double precision = 0.0, recall = 0.0;
  std::string found;
};

Outcome
runCase(const std::string& name, std::size_t count, std::uint64_t seed)
{
  const syn::CadModel model =
    syn::rotated(syn::cadModelByName(name), syn::randomRotation(seed));
  syn::SamplingOptions options;
  options.count = count;
  options.seed = seed;
  const visfeat_test::SampledCadModel sampled =
    visfeat_test::sampleCadCloud(model, options);
  const syn::CadSamples& samples = sampled.samples;
  Estimator est;
  est.setInputCloud(sampled.cloud);
  est.setResolution(0); // automatic, as the tool's default
  pcl::PointCloud<visfeat::PointVisibility> out;
  est.compute(out);
  Outcome outcome;
  outcome.name = name + " " + std::to_string(count) + " seed " + std::to_string(seed);
  EXPECT_EQ(est.getErrorMessage(), "") << outcome.name;
  if (out.size() != samples.points.size())
    return outcome;
  // distances in point spacings where the cells are finer than the spacing
  const double unit = std::max(est.getGrid().cell_size,
                               std::sqrt(model.area() / static_cast<double>(count)));
  std::vector<double> distance(out.size());
  std::vector<std::uint32_t> labels(out.size());
  std::vector<std::uint8_t> classes(out.size()), feature(out.size());
  for (std::size_t i = 0; i < out.size(); ++i) {
    distance[i] = samples.curve_distance[i] / unit;
    labels[i] = out[i].label;
    classes[i] = out[i].feature_class;
    const auto cls = static_cast<visfeat::FeatureClass>(out[i].feature_class);
    feature[i] =
      cls == visfeat::FeatureClass::kEdge || cls == visfeat::FeatureClass::kVertex;
  }
  const ev::PointScores scores = ev::scoreFeaturePoints(feature, distance);
  const ev::TopologyComparison topology = ev::compareTopology(
    model, samples.points, samples.face, labels, classes, est.getTopologyGraph(), unit);
  // every vertex of the graph is on a point of the labelled cloud (a sparse cloud may
  // have no sample near a corner: the vertex claims the nearest, claimCornerPoints)
  const visfeat::TopologyGraph& graph = est.getTopologyGraph();
  for (std::uint32_t id = 1; id <= graph.size(); ++id) {
    const visfeat::GraphNode& node = graph.node(id);
    EXPECT_TRUE(node.feature_class != visfeat::FeatureClass::kVertex || node.points > 0)
      << outcome.name << ": vertex " << id << " (" << node.cells
      << " cells) has no point";
  }
  outcome.exact = topology.exact();
  outcome.precision = scores.precision();
  outcome.recall = scores.recall();
  outcome.found =
    std::to_string(topology.found[0]) + "/" + std::to_string(topology.found[1]) + "/" +
    std::to_string(topology.found[2]) + " for " + std::to_string(topology.truth[0]) +
    "/" + std::to_string(topology.truth[1]) + "/" + std::to_string(topology.truth[2]) +
    (topology.arcsCorrect() ? "" : ", arcs wrong");
  for (std::size_t i = 0; i < std::min<std::size_t>(3, topology.problems.size()); ++i)
    outcome.found += "; " + topology.problems[i];
  return outcome;
}

class SparseClouds : public ::testing::TestWithParam<SparseCase>
{};

// One test per model and point count (21, ~10-40 s each), so that ctest -j spreads
// them over the cores.
TEST_P(SparseClouds, DefaultOptionsFindTheTopology)
{
  const SparseCase& c = GetParam();
  int exact = 0;
  for (const std::uint64_t seed : kSeeds) {
    const Outcome o = runCase(c.model, c.count, seed);
    exact += o.exact;
    EXPECT_GE(o.precision, 0.95) << o.name;
    EXPECT_GE(o.recall, 0.90) << o.name;
    if (!o.exact)
      std::printf("not exact: %s: %s\n", o.name.c_str(), o.found.c_str());
  }
  std::printf("%s %zu: exact counts and arcs in %d of %zu rotations\n", c.model,
              c.count, exact, std::size(kSeeds));
  EXPECT_GE(exact, c.min_exact);
}

TEST(SparseCloudsCatalogue, EveryModelAtEveryCount)
{
  for (const std::string& name : syn::cadModelNames())
    for (const std::size_t count : {10000u, 20000u, 40000u})
      EXPECT_TRUE(std::any_of(
        std::begin(kCases), std::end(kCases),
        [&](const SparseCase& c) { return c.model == name && c.count == count; }))
        << name << " " << count;
}

INSTANTIATE_TEST_SUITE_P(Models,
                         SparseClouds,
                         ::testing::ValuesIn(kCases),
                         [](const ::testing::TestParamInfo<SparseCase>& info) {
                           return std::string(info.param.model) + "_" +
                                  std::to_string(info.param.count);
                         });

} // namespace
