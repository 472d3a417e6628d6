// Acceptance: the result does not depend on where the part is or how it is stored.
// - Every generated CAD model (20,000 points, automatic resolution: raised to 256 and
//   filled) under a reference rotation, which must give the model's true counts, then
//   under 20 further random rotations (fixed seeds) and with the reference sample moved
//   to survey coordinates (near (512345, 4312345, 120), double, recentred as the tool
//   does before the cast to float): the same vertex / edge / face counts.
// - Copies: an octahedron whose every point is stored three times, and two copies of it
//   a little apart (overlapping registered scans), give the clean cloud's resolution
//   and counts (6 / 12 / 8), dense (about 280 cells, the band of the points) and sparse
//   (20,000 points, filled at 256).
// Measured on 2026-12-01 (seeds 4000-4020): survey coordinates give the reference's
// counts on every model; the rotations did on the cube, the triangular prism and the
// cylinder (20 of 20) but not on the tetrahedron (19: an extra face), U-prism (19),
// box with hole (18) and icosahedron (10: extra vertices beside its edges). With the
// stray regions merged (strayRegionMerge) all are 20 of 20 but the U-prism (19:
// rotation 4004 has no region at one corner, whose three edges end short of it), so
// this test fails on the U-prism until the segmentation finds that corner.
// About 13 minutes on 2 busy cores (one test per model, 1.5-2.5 minutes each): label
// acceptance.

#include "band_fixtures.h"

#include "common/cloud_input.h"
#include "common/double_xyz_cloud.h"

#include <support/cad_models.h>
#include <support/synthetic_shapes.h>
#include <visfeat/point_types.h>
#include <visfeat/visibility_feature_estimation.h>

#include <gtest/gtest.h>

#include <pcl/PCLPointCloud2.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

namespace {

namespace syn = visfeat::synthetic;
using Cloud = pcl::PointCloud<pcl::PointXYZ>;
using Estimator =
  visfeat::VisibilityFeatureEstimation<pcl::PointXYZ, visfeat::PointVisibility>;
using Counts = std::array<std::size_t, 3>; // vertices, edges, faces

/** Points per model: the automatic resolution raises these to 256 cells and fills the
 * band between the points (the sparse path, the tool's default for such clouds, about
 * 2-3 s a run on 2 cores). Measured on 2026-12-01: fixed resolutions of 128 and 192
 * with points 0.5 cells apart are cheaper but not exact on the reference rotation
 * (icosahedron 8/30/20, U-prism 7/19/11, box with hole 7/18/12 at 128), and dense
 * clouds at 256 cost ~10 s a run (25 minutes for the 154 runs). */
constexpr std::size_t kPoints = 20000;
constexpr int kRotations = 20;
/** The reference rotation's seed; the others follow it. Unrotated (axis-aligned)
 * models are not the reference: at 20,000 points their faces lie on cell boundaries
 * and the cube gives 18/26/14 (a separate problem of axis-aligned faces). */
constexpr std::uint64_t kReferenceSeed = 4000;
/** The octahedron sampled densely enough for about 290 cells (the band of the points
 * alone, as in the measurement), and sparse (kPoints, filled at 256). */
constexpr std::size_t kOctahedronDense = 560000;
const Eigen::Vector3d kSurvey(512345.678, 4312345.123, 120.456);

[[maybe_unused]] std::string
toString(const Counts& c)
{
  return std::to_string(c[0]) + "/" + std::to_string(c[1]) + "/" + std::to_string(c[2]);
}

struct Result
{
  Counts counts{};
  visfeat::ResolutionEstimate resolution;
  std::string error;
};

/** The pipeline with default options and the automatic resolution, as the tool's
 * default. */
[[maybe_unused]] Result
run(const Cloud::Ptr& cloud)
{
  Estimator est;
  est.setInputCloud(cloud);
  est.setResolution(0);
  pcl::PointCloud<visfeat::PointVisibility> out;
  est.compute(out);
  Result r;
  r.error = est.getErrorMessage();
  const auto counts = est.getSegmentation().classCounts();
  r.counts = {counts[1], counts[2], counts[3]};
  r.resolution = est.getResolutionEstimate();
  return r;
}

[[maybe_unused]] Counts
truthCounts(const syn::CadModel& model)
{
  return {model.vertices.size(), model.curves.size(), model.faces.size()};
}

/** The points in double, moved to `shift`, stored as FLOAT64 x y z and read back as
 * the tool reads a file: recentred in double, then cast to float. */
[[maybe_unused]] Cloud::Ptr
throughSurveyCoordinates(const std::vector<Eigen::Vector3f>& points,
                         const Eigen::Vector3d& shift,
                         Eigen::Vector3d& offset)
{
  std::vector<Eigen::Vector3d> in_double(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    in_double[i] = points[i].cast<double>();
  const pcl::PCLPointCloud2 c = visfeat_tools::doubleXYZCloud(in_double, shift);
  offset = visfeat_tools::recentringOffset(c);
  auto cloud = std::make_shared<Cloud>();
  visfeat_tools::toXYZ(c, *cloud, offset);
  return cloud;
}

[[maybe_unused]] Cloud::Ptr
sampled(const syn::CadModel& model, std::uint64_t seed, std::size_t count)
{
  syn::SamplingOptions options;
  options.count = count;
  options.seed = seed;
  return visfeat_test::sampleCadCloud(model, options).cloud;
}

[[maybe_unused]] double
secondsSince(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
    .count();
}

/** One generated model: a reference rotation must give the true counts; 20 further
 * rotations and the reference sample moved to survey coordinates give the same. */
#ifndef VISFEAT_COPIES_ONLY // the rotations: label invariance, test.sh --full
class Invariance : public ::testing::TestWithParam<std::string>
{};

TEST_P(Invariance, TopologyUnderRotationsAndSurveyTranslation)
{
  const std::string name = GetParam();
  const auto start = std::chrono::steady_clock::now();
  const syn::CadModel upright = syn::cadModelByName(name);
  const auto sample = [&](std::uint64_t seed) {
    const syn::CadModel model = syn::rotated(upright, syn::randomRotation(seed));
    syn::SamplingOptions options;
    options.count = kPoints;
    options.seed = seed;
    return visfeat_test::sampleCadCloud(model, options);
  };
  const visfeat_test::SampledCadModel reference = sample(kReferenceSeed);
  const Result base = run(reference.cloud);
  ASSERT_EQ(base.error, "");
  ASSERT_EQ(toString(base.counts), toString(truthCounts(upright)))
    << "reference rotation: " << base.resolution.reason;
  int same = 0;
  for (int r = 1; r <= kRotations; ++r) {
    const std::uint64_t seed = kReferenceSeed + static_cast<std::uint64_t>(r);
    const Result turned = run(sample(seed).cloud);
    EXPECT_EQ(toString(turned.counts), toString(base.counts))
      << "rotation seed " << seed << ": " << turned.error << " "
      << turned.resolution.reason;
    same += turned.counts == base.counts;
  }
  Eigen::Vector3d offset;
  const Result survey =
    run(throughSurveyCoordinates(reference.samples.points, kSurvey, offset));
  EXPECT_FALSE(offset.isZero());
  EXPECT_LT((kSurvey - offset).norm(), 20.0);
  EXPECT_EQ(toString(survey.counts), toString(base.counts))
    << "survey coordinates: " << survey.error;
  std::printf("%s: %s at %d cells, %d of %d rotations the same, survey %s (%.1f s)\n",
              name.c_str(), toString(base.counts).c_str(), base.resolution.resolution,
              same, kRotations, toString(survey.counts).c_str(), secondsSince(start));
}

INSTANTIATE_TEST_SUITE_P(GeneratedModels,
                         Invariance,
                         ::testing::ValuesIn(syn::cadModelNames()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           return info.param;
                         });
#endif

/** `base` `times` times, the c-th copy moved by c `shift`. */
[[maybe_unused]] Cloud::Ptr
copiesOf(const Cloud& base, int times, const Eigen::Vector3f& shift)
{
  auto out = std::make_shared<Cloud>();
  for (int c = 0; c < times; ++c)
    for (const pcl::PointXYZ& p : base.points)
      out->push_back(
        pcl::PointXYZ(p.x + c * shift.x(), p.y + c * shift.y(), p.z + c * shift.z()));
  return out;
}

#ifndef VISFEAT_INVARIANCE_ONLY // the copies: label acceptance
TEST(Copies, DuplicatedAndOverlappingOctahedronGiveTheCleanCounts)
{
  const syn::CadModel model =
    syn::rotated(syn::polyhedralModel("octahedron", syn::platonicSolid("octahedron")),
                 syn::randomRotation(15));
  for (const std::size_t count : {kOctahedronDense, kPoints}) {
    const Cloud::Ptr clean = sampled(model, 15, count);
    const Result base = run(clean);
    ASSERT_EQ(base.error, "");
    EXPECT_EQ(toString(base.counts), "6/12/8") << base.resolution.reason;
    EXPECT_EQ(base.resolution.copies, 1);
    // registered scans a little apart: a tenth of the spacing, no symmetric direction
    const Eigen::Vector3f shift = Eigen::Vector3f(0.6f, -0.48f, 0.64f) *
                                  static_cast<float>(0.1 * base.resolution.spacing);
    const std::pair<const char*, Cloud::Ptr> cases[] = {
      {"every point three times", copiesOf(*clean, 3, Eigen::Vector3f::Zero())},
      {"two copies a little apart", copiesOf(*clean, 2, shift)}};
    for (const auto& [what, cloud] : cases) {
      const Result r = run(cloud);
      SCOPED_TRACE(std::to_string(count) + " points, " + what);
      EXPECT_EQ(r.error, "");
      EXPECT_EQ(r.resolution.copies, what[0] == 'e' ? 3 : 2) << r.resolution.reason;
      EXPECT_NEAR(r.resolution.resolution, base.resolution.resolution,
                  0.03 * base.resolution.resolution)
        << r.resolution.reason;
      EXPECT_EQ(toString(r.counts), "6/12/8") << r.resolution.reason;
      std::printf("octahedron %zu points, %s: resolution %d (clean %d), %s\n", count,
                  what, r.resolution.resolution, base.resolution.resolution,
                  toString(r.counts).c_str());
    }
  }
}

#endif

} // namespace
