#pragma once

// Helpers shared by the generated CAD models' tests (test_cad_models.cpp: the models
// and their truth; test_cad_sampling.cpp: the sampling and the distances).

#include <support/cad_models.h>

#include <Eigen/Core>

#include <cstdint>
#include <set>

namespace visfeat_test {
namespace cad {

namespace syn = visfeat::synthetic;

inline constexpr double kPi = 3.14159265358979323846;

inline syn::CadSamples
sample(const syn::CadModel& model,
       std::size_t count,
       std::uint64_t seed,
       double noise = 0.0)
{
  syn::SamplingOptions options;
  options.count = count;
  options.seed = seed;
  options.noise_sigma = noise;
  return syn::sampleCadModel(model, options);
}

/** The id of the segment between the vertices nearest to a and b. */
inline int
segmentBetween(const syn::CadModel& model,
               const Eigen::Vector3d& a,
               const Eigen::Vector3d& b)
{
  const auto nearest = [&](const Eigen::Vector3d& p) {
    int best = -1;
    for (std::size_t v = 0; v < model.vertices.size(); ++v)
      if (best < 0 || (model.vertices[v] - p).norm() <
                        (model.vertices[static_cast<std::size_t>(best)] - p).norm())
        best = static_cast<int>(v);
    return best;
  };
  const int va = nearest(a), vb = nearest(b);
  for (const syn::CadCurve& c : model.curves)
    if (c.kind == syn::CadCurve::Kind::kSegment &&
        std::set<int>{c.vertices[0], c.vertices[1]} == std::set<int>{va, vb})
      return c.id;
  return -1;
}

} // namespace cad
} // namespace visfeat_test
