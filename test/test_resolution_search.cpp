// Acceptance: the automatic resolution's search for narrow faces. The stepped block's
// risers (21 cells at 256) have no core at 256 and merge with the treads; the search
// finds them and doubles the resolution, where every face is found. Models whose
// faces are all wide keep 256; where the search may not go finer, a warning says so.
// Clouds sampled all around a solid rise on their graph's gaps like closed meshes; open
// scans do not, and say why. About 3.5 minutes on 2 cores: label acceptance.

#include "band_fixtures.h"

#include <support/cad_models.h>
#include <visfeat/point_types.h>
#include <visfeat/visibility_feature_estimation.h>

#include <gtest/gtest.h>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>

namespace {

namespace syn = visfeat::synthetic;
using Estimator =
  visfeat::VisibilityFeatureEstimation<pcl::PointXYZ, visfeat::PointVisibility>;

/** The chord tolerance of the tessellation at 256 cells, in cells. */
constexpr double kChordCells = 0.05;

struct MeshRun
{
  int resolution = 0;
  std::string reason;
  std::vector<std::string> warnings;
  std::array<std::size_t, 4> counts{};
};

/** `name` under the rotation of `seed`, its mesh rasterised (20,000 points sampled for
 * the output), at `resolution` (0: automatic); drop_a_triangle: its last triangle left
 * out (an open mesh). */
MeshRun
runMesh(const std::string& name,
        std::uint64_t seed,
        int resolution,
        int narrow_face_persistence =
          visfeat::ComponentParameters::kDefaultNarrowFacePersistence,
        bool drop_a_triangle = false,
        int max_search_resolution = visfeat::kMaxSearchResolution)
{
  const syn::CadModel model =
    syn::rotated(syn::cadModelByName(name), syn::randomRotation(seed));
  auto mesh = std::make_shared<visfeat::SurfaceMesh>(
    syn::tessellateCadModel(model, kChordCells * syn::cellSize(model, 256)).mesh);
  if (drop_a_triangle) // an open mesh
    mesh->triangles.pop_back();
  syn::SamplingOptions options;
  options.count = 20000;
  options.seed = seed;
  Estimator est;
  est.setInputCloud(visfeat_test::sampleCadCloud(model, options).cloud);
  est.setInputMesh(mesh);
  est.setResolution(resolution);
  est.setNarrowFacePersistence(narrow_face_persistence);
  est.setMaxSearchResolution(max_search_resolution);
  pcl::PointCloud<visfeat::PointVisibility> out;
  est.compute(out);
  EXPECT_EQ(est.getErrorMessage(), "");
  MeshRun run;
  run.resolution = est.getResolutionEstimate().resolution;
  run.reason = est.getResolutionEstimate().reason;
  run.warnings = est.getWarnings();
  const auto counts = est.getSegmentation().classCounts();
  std::copy(counts.begin(), counts.end(), run.counts.begin());
  return run;
}

bool
mentions(const std::string& text, const std::string& what)
{
  return text.find(what) != std::string::npos;
}

class SteppedBlock : public testing::TestWithParam<std::uint64_t>
{};

TEST_P(SteppedBlock, SearchResolvesTheRisers)
{
  const syn::CadModel truth = syn::cadModelByName("stepped_block");
  // with the paper's single threshold, at 256 the risers merge with the treads
  const MeshRun paper = runMesh("stepped_block", GetParam(), 256, 0);
  EXPECT_LT(paper.counts[3], truth.faces.size());
  // the narrow-face cores give each riser a face of its own (measured 10, 10 and 11
  // faces, 8/17, 8/17 and 8/18 vertices/edges, against 7 faces and 6-8/11-12 without)
  const MeshRun coarse = runMesh("stepped_block", GetParam(), 256);
  std::printf("stepped block %d at 256: %zu/%zu/%zu without narrow-face cores, "
              "%zu/%zu/%zu with\n",
              static_cast<int>(GetParam()), paper.counts[1], paper.counts[2],
              paper.counts[3], coarse.counts[1], coarse.counts[2], coarse.counts[3]);
  EXPECT_GE(coarse.counts[3], truth.faces.size());
  const auto error = [&](const MeshRun& run) {
    const auto off = [](std::size_t a, std::size_t b) { return a > b ? a - b : b - a; };
    return off(run.counts[1], truth.vertices.size()) +
           off(run.counts[2], truth.curves.size()) +
           off(run.counts[3], truth.faces.size());
  };
  EXPECT_LT(error(coarse), error(paper));
  // the search finds them as narrow faces and doubles the resolution; where the
  // graph at 512 still has gaps (a corner not separated), it doubles once more
  // (kMaxSearchResolution 1024): measured rotation 21 16/24/10 at 1024, 22 16/24/10
  // at 512; 23 gave 14/22/10 at 512, a closed graph with two corners merged into one,
  // and stayed there until merged corners counted as a gap (2026-12-07, findGraphGaps:
  // two of their 4 edges leave 13 degrees apart); now 16/24/10 at 1024
  const MeshRun searched = runMesh("stepped_block", GetParam(), 0);
  EXPECT_TRUE(mentions(searched.reason, "narrow faces at resolution 256"))
    << searched.reason;
  if (mentions(searched.reason, "at resolution 512")) {
    EXPECT_EQ(searched.resolution, 1024) << searched.reason;
  } else {
    EXPECT_EQ(searched.resolution, 512) << searched.reason;
  }
  // every face has its core, and the counts are closer to the truth than at 256; the
  // corners where a riser's concave crease ends are not all separated at 512, and
  // which ones depends on the grid's offset (measured 14-16 of 16 vertices, 22-24 of
  // 24 edges at 512, against 8 / 17-18 at 256), so the search goes on where they are
  // not: measured exact on all three rotations
  EXPECT_EQ(searched.counts[3], truth.faces.size());
  EXPECT_EQ(searched.counts[1], truth.vertices.size());
  EXPECT_EQ(searched.counts[2], truth.curves.size());
  std::printf("searched: %zu/%zu/%zu at %d\n", searched.counts[1], searched.counts[2],
              searched.counts[3], searched.resolution);
  EXPECT_LT(error(searched), error(coarse))
    << searched.counts[1] << "/" << searched.counts[2] << " against "
    << coarse.counts[1] << "/" << coarse.counts[2] << " at 256";
  // no warning of the band or the map; the graph's own (findGraphGaps) only where the
  // corners are not all there
  const bool exact = searched.counts[1] == truth.vertices.size() &&
                     searched.counts[2] == truth.curves.size();
  for (const std::string& w : searched.warnings)
    EXPECT_TRUE(mentions(w, "the graph is not that of a closed part")) << w;
  if (exact) {
    EXPECT_TRUE(searched.warnings.empty()) << searched.warnings.front();
  }
}

INSTANTIATE_TEST_SUITE_P(Rotations, SteppedBlock, testing::Values(21u, 22u, 23u));

bool
hasGraphGaps(const MeshRun& run)
{
  return std::any_of(run.warnings.begin(), run.warnings.end(), [](const auto& w) {
    return mentions(w, "the graph is not that of a closed part");
  });
}

class ParallelCreases : public testing::TestWithParam<std::uint64_t>
{};

// Three creases 10 cells apart at 256 make no narrow face (their faces are too narrow
// for a peak of the map). Where they are not separated the graph of the closed mesh
// may have edges with one corner: then the search goes finer (kSearchOnGraphGaps).
// Where the graph looks whole, the creases' shallow valleys left inside the merged
// face make a valley line (mergedValleys(), kValleyLineRadius), and the search goes
// finer on that, for any input. Measured 2026-12-07 (these fixtures): rotation 21 has
// gaps at 256 (8/15/7), rotation 22 none (10/14/7, a closed graph with merged
// creases; before the valley lines it stayed there silently) but a line 106 cells
// long and 9 wide; truth 14/21/9. At 512 the creases are 20 cells apart: their ends'
// corners merge (10/16/8 and 10/17/9, corners of 4-5 edges, two of them 11-20 degrees
// apart), which the graph counts as a gap (findGraphGaps, kMergedCornerAngle), so the
// search goes on to 1024, where both are exact.
TEST_P(ParallelCreases, GraphGapsOrValleyLinesRaiseTheResolution)
{
  const MeshRun coarse = runMesh("parallel_creases", GetParam(), 256);
  const MeshRun searched = runMesh("parallel_creases", GetParam(), 0);
  const bool gaps = hasGraphGaps(coarse);
  std::printf("parallel creases %d: %zu/%zu/%zu at 256 (graph gaps: %s), %zu/%zu/%zu "
              "at %d\n",
              static_cast<int>(GetParam()), coarse.counts[1], coarse.counts[2],
              coarse.counts[3], gaps ? "yes" : "no", searched.counts[1],
              searched.counts[2], searched.counts[3], searched.resolution);
  if (GetParam() == 21u) {
    EXPECT_TRUE(gaps) << "the case that exercises the graph gaps";
  } else {
    EXPECT_FALSE(gaps) << "the case that exercises the valley line";
    EXPECT_TRUE(std::any_of(coarse.warnings.begin(), coarse.warnings.end(),
                            [](const std::string& w) {
                              return mentions(w, "a line of face cells in a valley");
                            }))
      << "the closed graph at 256 is not silent";
  }
  const bool on_gaps =
    mentions(searched.reason, "a closed mesh whose graph at resolution 256 is not that "
                              "of a closed part");
  EXPECT_EQ(on_gaps, gaps) << searched.reason;
  if (!gaps) {
    EXPECT_TRUE(
      mentions(searched.reason, "at resolution 256 (creases merged into faces)"))
      << searched.reason;
  }
  EXPECT_TRUE(mentions(searched.reason,
                       "a closed mesh whose graph at resolution 512 is "
                       "not that of a closed part"))
    << searched.reason;
  EXPECT_TRUE(mentions(searched.reason, "(corners merged into one)"))
    << searched.reason;
  EXPECT_EQ(searched.resolution, 1024) << searched.reason;
  EXPECT_EQ(searched.counts[1], 14u);
  EXPECT_EQ(searched.counts[2], 21u);
  EXPECT_EQ(searched.counts[3], 9u);
  // the same mesh with one triangle fewer is open: its gaps may be a border's, so they
  // do not raise the resolution; a valley line does
  const MeshRun open =
    runMesh("parallel_creases", GetParam(), 0,
            visfeat::ComponentParameters::kDefaultNarrowFacePersistence, true);
  EXPECT_FALSE(mentions(open.reason, "closed mesh")) << open.reason;
  EXPECT_EQ(open.resolution > 256, mentions(open.reason, "(creases merged into faces)"))
    << open.reason;
  std::printf("open: at %d\n", open.resolution);
}

INSTANTIATE_TEST_SUITE_P(Rotations, ParallelCreases, testing::Values(21u, 22u));

TEST(ResolutionSearch, WideFacesKeep256)
{
  for (const std::string name : {"cube", "box_with_hole"}) {
    const MeshRun run = runMesh(name, 21, 0);
    EXPECT_EQ(run.resolution, 256) << name;
    EXPECT_FALSE(mentions(run.reason, "narrow")) << run.reason;
    EXPECT_FALSE(mentions(run.reason, "closed mesh")) << run.reason;
  }
}

TEST(ResolutionSearch, StopsAtTheMaximumSet)
{
  // The stepped block's mesh searches from 256 to 512 by default (its risers are
  // narrow faces at 256; rotation 22 in SteppedBlock.SearchResolvesTheRisers); with
  // the search's maximum at 384 it stops there, and where narrow faces remain, the
  // warning names the maximum as a way on.
  const MeshRun capped =
    runMesh("stepped_block", 22, 0,
            visfeat::ComponentParameters::kDefaultNarrowFacePersistence, false, 384);
  EXPECT_EQ(capped.resolution, 384) << capped.reason;
  // (measured: at 384 its graph has gaps, 2 of 18 edges with one corner)
  bool named = false; // the narrow faces' or the graph's warning names the way on
  for (const std::string& w : capped.warnings)
    named = named || mentions(w, "setMaxSearchResolution(), now 384");
  EXPECT_TRUE(named) << (capped.warnings.empty() ? "no warning"
                                                 : capped.warnings.front());
  // out of range: refused, with the parameter's name
  Estimator est;
  est.setInputCloud(
    visfeat_test::sampleCadCloud(syn::cadModelByName("cube"), 64, 1).cloud);
  est.setResolution(Estimator::kAutomaticResolution);
  est.setMaxSearchResolution(2);
  pcl::PointCloud<visfeat::PointVisibility> out;
  est.compute(out);
  EXPECT_TRUE(
    mentions(est.getErrorMessage(), "max_search_resolution 2 is out of range"))
    << est.getErrorMessage();
  // with a resolution set there is no search: a note says the maximum does nothing
  est.setResolution(64);
  est.setMaxSearchResolution(2048);
  est.compute(out);
  ASSERT_EQ(est.getErrorMessage(), "");
  const auto& notes = est.getNotes();
  EXPECT_TRUE(std::any_of(notes.begin(), notes.end(), [](const std::string& n) {
    return mentions(n, "setMaxSearchResolution() (2048) has no effect");
  }));
}

TEST(ResolutionSearch, WarnsWhereThePointsAloneCannotGoFiner)
{
  // the band from the points only (fill 'points'): the dense cloud supports about 256
  // cells, so the narrow faces stay, and a warning says why
  const syn::CadModel model =
    syn::rotated(syn::cadModelByName("stepped_block"), syn::randomRotation(24));
  Estimator est;
  est.setInputCloud(visfeat_test::sampleCadCloud(model, 256, 24).cloud);
  est.setResolution(Estimator::kAutomaticResolution);
  est.setSurfaceFill(visfeat::SurfaceFill::kPoints);
  pcl::PointCloud<visfeat::PointVisibility> out;
  est.compute(out);
  ASSERT_EQ(est.getErrorMessage(), "");
  EXPECT_LT(est.getResolutionEstimate().resolution, 320);
  const auto& warnings = est.getWarnings();
  const auto narrow = std::find_if(warnings.begin(), warnings.end(), [](const auto& w) {
    return mentions(w, "narrow face") && mentions(w, "without a fill");
  });
  EXPECT_NE(narrow, warnings.end()) << (warnings.empty() ? "" : warnings.front());
}

/** The cloud of `model` sampled 0.5 cells apart at 256 (seed `seed`), without the
 * points of its largest face when `open` (an open scan). */
pcl::PointCloud<pcl::PointXYZ>::Ptr
modelCloud(const syn::CadModel& model, std::uint64_t seed, bool open)
{
  const visfeat_test::SampledCadModel sampled =
    visfeat_test::sampleCadCloud(model, 256, seed);
  if (!open)
    return sampled.cloud;
  std::vector<std::size_t> per_face(model.faces.size(), 0);
  for (const int f : sampled.samples.face)
    ++per_face[static_cast<std::size_t>(f)];
  const auto largest = static_cast<int>(
    std::max_element(per_face.begin(), per_face.end()) - per_face.begin());
  auto cloud = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  for (std::size_t i = 0; i < sampled.cloud->size(); ++i)
    if (sampled.samples.face[i] != largest)
      cloud->push_back((*sampled.cloud)[i]);
  return cloud;
}

TEST(ResolutionSearch, SaysWhyAnOpenScansGraphGapsDoNotRaiseIt)
{
  // The parallel creases as a dense cloud without its largest face (an open scan): at
  // 256 its graph has edges with one corner, and the automatic search, which rises on
  // such gaps for a closed surface only, says why it leaves them. It may rise on the
  // creases' valley line instead (any input), never on the gaps. (The whole cloud is
  // closed and rises on them: ClosedClouds.)
  const syn::CadModel model =
    syn::rotated(syn::cadModelByName("parallel_creases"), syn::randomRotation(21));
  const auto gapsWarning = [](const Estimator& est) {
    for (const std::string& w : est.getWarnings())
      if (mentions(w, "the graph is not that of a closed part"))
        return w;
    return std::string();
  };
  for (const int resolution : {Estimator::kAutomaticResolution, 256}) {
    Estimator est;
    est.setInputCloud(modelCloud(model, 21, true));
    est.setResolution(resolution);
    pcl::PointCloud<visfeat::PointVisibility> out;
    est.compute(out);
    ASSERT_EQ(est.getErrorMessage(), "");
    const visfeat::ResolutionEstimate& chosen = est.getResolutionEstimate();
    EXPECT_FALSE(mentions(chosen.reason, "closed")) << chosen.reason;
    // the reason says why the gaps did not raise it
    EXPECT_EQ(mentions(chosen.reason, "has gaps, not raised on them: the band encloses "
                                      "no volume"),
              resolution == 0)
      << chosen.reason;
    EXPECT_EQ(chosen.resolution > 320, mentions(chosen.reason, "(creases merged into "
                                                               "faces): raised to"))
      << chosen.reason;
    const std::string w = gapsWarning(est);
    ASSERT_FALSE(w.empty()) << "resolution " << resolution;
    EXPECT_EQ(mentions(w, "for a closed surface only"), resolution == 0) << w;
    // it names a resolution to try: the search's own step
    if (!mentions(w, "sample denser")) {
      EXPECT_TRUE(mentions(w, "raise the resolution, e.g. to " +
                                std::to_string(2 * chosen.resolution)))
        << w;
    }
    // the border first: no resolution closes its gaps
    EXPECT_TRUE(mentions(w, "The band encloses no volume (an open scan?): its border "
                            "leaves edges without their outer corner"))
      << w;
  }
}

struct ClosedCloud
{
  const char* model;
  std::uint64_t seed;
};

class ClosedClouds : public testing::TestWithParam<ClosedCloud>
{};

TEST_P(ClosedClouds, GraphGapsRaiseTheResolutionUntilTheCountsAreExact)
{
  // A cloud sampled all around a solid (no mesh) encloses a volume, so the search
  // rises on its graph's gaps as on a closed mesh's. The thin plate's 12-cell rims
  // (at 256) merge at 256 and 512, and separate at 1024 (measured 2026-12-07: 1/3/2
  // at 256, 5/6/4 at 510, where the search stopped before, and 8/14/7 at 1020); the
  // parallel creases 10 cells apart likewise (8/14/7, then 14/21/9 at 1020).
  const syn::CadModel truth = syn::cadModelByName(GetParam().model);
  const syn::CadModel model = syn::rotated(truth, syn::randomRotation(GetParam().seed));
  Estimator est;
  est.setInputCloud(modelCloud(model, GetParam().seed, false));
  est.setResolution(Estimator::kAutomaticResolution);
  pcl::PointCloud<visfeat::PointVisibility> out;
  est.compute(out);
  ASSERT_EQ(est.getErrorMessage(), "");
  const visfeat::ResolutionEstimate& chosen = est.getResolutionEstimate();
  std::printf("%s %d: %s\n", GetParam().model, static_cast<int>(GetParam().seed),
              chosen.reason.c_str());
  // it rises on the gaps, or on narrow faces where the map shows them (rotation 21 of
  // the plate: at 256 and at 512); the parallel creases show none
  EXPECT_TRUE(mentions(chosen.reason, "a closed surface (the band encloses a volume) "
                                      "whose graph at resolution") ||
              mentions(chosen.reason, "narrow faces at resolution 512"))
    << chosen.reason;
  EXPECT_GT(chosen.resolution, 1000) << chosen.reason;
  const auto counts = est.getSegmentation().classCounts();
  EXPECT_EQ(counts[1], truth.vertices.size());
  EXPECT_EQ(counts[2], truth.curves.size());
  EXPECT_EQ(counts[3], truth.faces.size());
  for (const std::string& w : est.getWarnings())
    EXPECT_FALSE(mentions(w, "the graph is not that of a closed part")) << w;
}

INSTANTIATE_TEST_SUITE_P(Models,
                         ClosedClouds,
                         testing::Values(ClosedCloud{"thin_plate_with_hole", 21},
                                         ClosedCloud{"thin_plate_with_hole", 22},
                                         ClosedCloud{"thin_plate_with_hole", 23},
                                         ClosedCloud{"parallel_creases", 21}),
                         [](const testing::TestParamInfo<ClosedCloud>& info) {
                           return std::string(info.param.model) + "_" +
                                  std::to_string(info.param.seed);
                         });

} // namespace
