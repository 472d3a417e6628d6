#pragma once

// Helpers shared by the estimator's fill tests (test_estimator_fill.cpp,
// test_estimator_holes.cpp): clouds of generated models and the region counts.

#include <support/cad_models.h>
#include <visfeat/point_types.h>
#include <visfeat/visibility_feature_estimation.h>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <array>
#include <cstdint>
#include <memory>

namespace visfeat_test {
namespace estimator {

namespace syn = visfeat::synthetic;
using Estimator =
  visfeat::VisibilityFeatureEstimation<pcl::PointXYZ, visfeat::PointVisibility>;
using Cloud = pcl::PointCloud<pcl::PointXYZ>;
using Output = pcl::PointCloud<visfeat::PointVisibility>;

/** count points of a generated model (already rotated). */
inline syn::CadSamples
samplesOf(const syn::CadModel& model, std::size_t count, std::uint64_t seed)
{
  syn::SamplingOptions options;
  options.count = count;
  options.seed = seed;
  return syn::sampleCadModel(model, options);
}

inline Cloud::Ptr
cloudOf(const syn::CadSamples& samples)
{
  auto cloud = std::make_shared<Cloud>();
  for (const Eigen::Vector3f& p : samples.points)
    cloud->push_back(pcl::PointXYZ(p.x(), p.y(), p.z()));
  return cloud;
}

inline Cloud::Ptr
sparseCloud(const syn::CadModel& model, std::size_t count, std::uint64_t seed)
{
  return cloudOf(samplesOf(model, count, seed));
}

/** Vertex, edge and face regions found, and a 0. */
inline std::array<std::size_t, 4>
counts(const Estimator& est)
{
  const auto c = est.getSegmentation().classCounts();
  return {c[1], c[2], c[3], 0};
}

} // namespace estimator
} // namespace visfeat_test
