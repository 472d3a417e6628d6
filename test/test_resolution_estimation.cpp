// The automatic resolution (estimateResolution, pcl::KdTreeFLANN): the resolution a
// cloud was sampled at, clamped and refused clouds, copies of the points, and the
// estimator using it with resolution 0.

#include "band_fixtures.h"

#include <support/cad_models.h>
#include <visfeat/point_types.h>
#include <visfeat/resolution_estimation.h>
#include <visfeat/visibility_feature_estimation.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace {

using Cloud = pcl::PointCloud<pcl::PointXYZ>;
using Output = pcl::PointCloud<visfeat::PointVisibility>;
using Estimator =
  visfeat::VisibilityFeatureEstimation<pcl::PointXYZ, visfeat::PointVisibility>;

const float kNaN = std::numeric_limits<float>::quiet_NaN();

// ---------------------------------------------------------------- resolution

// Clouds sampled at half a cell of resolution N come back at about N.
TEST(ResolutionEstimation, ReturnsTheResolutionTheCloudWasSampledAt)
{
  namespace syn = visfeat::synthetic;
  for (const int n : {32, 64, 128}) {
    for (const char* shape : {"cube", "tetrahedron", "icosahedron"}) {
      const Cloud cloud = visfeat_test::syntheticShapeCloud(shape, 83, n);
      const visfeat::ResolutionEstimate e = visfeat::estimateResolution(cloud);
      SCOPED_TRACE(std::string(shape) + " at " + std::to_string(n));
      EXPECT_NEAR(e.resolution, n, 0.08 * n) << e.reason;
      EXPECT_EQ(e.k, 8);
      EXPECT_EQ(e.queries, std::min<std::size_t>(cloud.size(), 10000));
      EXPECT_FALSE(e.clamped);
      EXPECT_EQ(e.resolution, visfeat::resolutionForSpacing(e.extent, e.spacing));
      EXPECT_EQ(e.reason.rfind("point spacing ", 0), 0u) << e.reason;
      EXPECT_NE(e.reason.find("(median distance to the 8th nearest neighbour over "),
                std::string::npos)
        << e.reason;
    }
    const syn::CadModel model = syn::cadModelByName("box_with_hole");
    syn::SamplingOptions options;
    options.count = syn::samplesForSpacing(model, n, 0.5);
    options.seed = 84;
    const syn::CadSamples samples = syn::sampleCadModel(model, options);
    Cloud cloud;
    for (const Eigen::Vector3f& p : samples.points)
      cloud.push_back(pcl::PointXYZ(p.x(), p.y(), p.z()));
    EXPECT_NEAR(visfeat::estimateResolution(cloud).resolution, n, 0.08 * n)
      << "box_with_hole at " << n;
  }
}

TEST(ResolutionEstimation, ClampedAndRefusedClouds)
{
  Cloud sparse;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j)
      sparse.push_back(pcl::PointXYZ(0.25f * i, 0.25f * j, 0.f));
  const visfeat::ResolutionEstimate e = visfeat::estimateResolution(sparse);
  EXPECT_EQ(e.resolution, visfeat::GridSpec::kMinResolution);
  EXPECT_TRUE(e.clamped);
  EXPECT_LT(e.unclamped, visfeat::GridSpec::kMinResolution);
  EXPECT_NE(e.reason.find(" (clamped from "), std::string::npos) << e.reason;

  Cloud one;
  one.push_back(pcl::PointXYZ(1.f, 2.f, 3.f));
  one.push_back(pcl::PointXYZ(kNaN, 0.f, 0.f));
  try {
    visfeat::estimateResolution(one);
    ADD_FAILURE() << "a single finite point has no spacing";
  } catch (const visfeat::Error& error) {
    EXPECT_STREQ(error.what(), "too few finite points to estimate the point spacing");
  }

  // Every point 64 times: the 64th neighbour, the farthest looked at, is a copy.
  const Cloud base = visfeat_test::syntheticShapeCloud("cube", 85, 16);
  Cloud::Ptr copies(new Cloud);
  for (const pcl::PointXYZ& p : base.points)
    for (int c = 0; c < 65; ++c)
      copies->push_back(p);
  Estimator est;
  est.setInputCloud(copies);
  est.setResolution(Estimator::kAutomaticResolution);
  Output out;
  est.compute(out);
  EXPECT_TRUE(out.empty());
  EXPECT_EQ(est.getErrorMessage(),
            "cannot estimate the point spacing: most points have 64 or more copies; "
            "set the resolution (setResolution())");
}

/** The cloud with every point `times` times, each copy moved by `shift` more. */
Cloud
withCopies(const Cloud& base, int times, const Eigen::Vector3f& shift)
{
  Cloud out;
  for (int c = 0; c < times; ++c)
    for (const pcl::PointXYZ& p : base.points)
      out.push_back(
        pcl::PointXYZ(p.x + c * shift.x(), p.y + c * shift.y(), p.z + c * shift.z()));
  return out;
}

// Duplicates (merged or re-exported scans) and two copies a little apart (overlapping
// registered scans) give the clean cloud's spacing, and say how many copies they saw.
TEST(ResolutionEstimation, CopiesDoNotShrinkTheSpacing)
{
  for (const char* shape : {"cube", "octahedron"}) {
    SCOPED_TRACE(shape);
    const Cloud clean = visfeat_test::syntheticShapeCloud(shape, 87, 64);
    const visfeat::ResolutionEstimate e = visfeat::estimateResolution(clean);
    EXPECT_EQ(e.copies, 1);
    EXPECT_EQ(e.reason.find("copies"), std::string::npos) << e.reason;
    // the shift of the overlap: a tenth of the spacing, in a direction of no symmetry
    const Eigen::Vector3f shift =
      Eigen::Vector3f(0.6f, -0.48f, 0.64f) * static_cast<float>(0.1 * e.spacing);
    for (const int times : {2, 3, 5}) {
      const visfeat::ResolutionEstimate d =
        visfeat::estimateResolution(withCopies(clean, times, Eigen::Vector3f::Zero()));
      EXPECT_EQ(d.copies, times);
      EXPECT_NEAR(d.resolution, e.resolution, 0.03 * e.resolution)
        << times << " copies: " << d.reason;
      EXPECT_NE(d.reason.find(std::to_string(times) + " copies of most points"),
                std::string::npos)
        << d.reason;
    }
    const visfeat::ResolutionEstimate o =
      visfeat::estimateResolution(withCopies(clean, 2, shift));
    EXPECT_EQ(o.copies, 2);
    EXPECT_NEAR(o.resolution, e.resolution, 0.03 * e.resolution) << o.reason;
  }
}

TEST(ResolutionEstimation, EstimatorUsesItWithResolutionZero)
{
  const Cloud::Ptr cloud(new Cloud(visfeat_test::syntheticShapeCloud("cube", 86, 48)));
  const visfeat::ResolutionEstimate expected = visfeat::estimateResolution(*cloud);
  Estimator est;
  est.setInputCloud(cloud);
  est.setResolution(0);
  est.setMinRadius(8);
  // the band from the points alone: the resolution is the density's (with a fill it
  // is raised, see SparseCloudsAreFilledAtTheTopologyResolution)
  est.setSurfaceFill(visfeat::SurfaceFill::kPoints);
  Output out;
  est.compute(out);
  ASSERT_EQ(est.getErrorMessage(), "");
  EXPECT_EQ(est.getResolution(), 0);
  const visfeat::ResolutionEstimate& used = est.getResolutionEstimate();
  EXPECT_EQ(used.resolution, expected.resolution);
  EXPECT_EQ(used.spacing, expected.spacing);
  EXPECT_EQ(used.reason, expected.reason);
  EXPECT_NEAR(est.getGrid().cell_size, used.extent / used.resolution, 1e-12);

  est.setResolution(40);
  est.compute(out);
  ASSERT_EQ(est.getErrorMessage(), "");
  EXPECT_EQ(est.getResolutionEstimate().resolution, 40);
  EXPECT_EQ(est.getResolutionEstimate().queries, 0u);
  EXPECT_EQ(est.getResolutionEstimate().reason, "set by setResolution()");
}

} // namespace
