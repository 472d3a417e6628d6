// Non-uniform sampling of the CAD models (SamplingOptions::face_density): points per
// unit area in proportion to the faces' multipliers, the total count unchanged, the
// uniform path untouched.

#include <support/cad_models.h>
#include <support/synthetic_shapes.h>
#include <visfeat/core/common/error.h>

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace {

namespace syn = visfeat::synthetic;

/** Points per unit area on each face. */
std::vector<double>
pointsPerArea(const syn::CadModel& model, const syn::CadSamples& samples)
{
  std::vector<double> density(model.faces.size(), 0.0);
  for (int f : samples.face)
    density[static_cast<std::size_t>(f)] += 1.0;
  for (std::size_t f = 0; f < density.size(); ++f)
    density[f] /= syn::faceArea(model, static_cast<int>(f));
  return density;
}

TEST(CadDensity, DenseFaceRatio)
{
  const double ratio = 5.0;
  for (const std::string name : {"cube", "box_with_hole"})
    for (int dense : {0, 2}) {
      SCOPED_TRACE(name + " dense face " + std::to_string(dense));
      const syn::CadModel model =
        syn::rotated(syn::cadModelByName(name), syn::randomRotation(4));
      syn::SamplingOptions options;
      options.count = 200000;
      options.seed = 8;
      options.face_density = syn::denseFace(model, dense, ratio);
      const syn::CadSamples samples = syn::sampleCadModel(model, options);
      ASSERT_EQ(samples.points.size(), options.count); // the count as asked
      const std::vector<double> density = pointsPerArea(model, samples);
      for (std::size_t f = 0; f < model.faces.size(); ++f) {
        if (static_cast<int>(f) == dense)
          continue;
        const double measured = density[static_cast<std::size_t>(dense)] / density[f];
        EXPECT_NEAR(measured, ratio, 0.1 * ratio) << "face " << f;
      }
      // Every point still lies on the face it is labelled with.
      for (std::size_t i = 0; i < samples.points.size(); i += 97)
        EXPECT_LT(
          syn::faceDistance(model, samples.face[i], samples.points[i].cast<double>()),
          1e-5);
    }
}

TEST(CadDensity, UniformPathUnchanged)
{
  const syn::CadModel model = syn::cadModelByName("box_with_hole");
  syn::SamplingOptions options;
  options.count = 5000;
  options.seed = 3;
  const syn::CadSamples uniform = syn::sampleCadModel(model, options);
  options.face_density.assign(model.faces.size(), 1.0);
  const syn::CadSamples ones = syn::sampleCadModel(model, options);
  ASSERT_EQ(uniform.points.size(), ones.points.size());
  for (std::size_t i = 0; i < uniform.points.size(); ++i) {
    ASSERT_EQ(uniform.points[i], ones.points[i]) << i;
    ASSERT_EQ(uniform.face[i], ones.face[i]) << i;
  }
  // A uniform cloud has about the same points per area on every face.
  options.count = 100000;
  options.face_density.clear();
  const std::vector<double> density =
    pointsPerArea(model, syn::sampleCadModel(model, options));
  for (std::size_t f = 1; f < density.size(); ++f)
    EXPECT_NEAR(density[f] / density[0], 1.0, 0.1) << "face " << f;
}

TEST(CadDensity, SpacingCountFromTheTrueArea)
{
  const syn::CadModel model = syn::cadModelByName("cube");
  syn::SamplingOptions options;
  options.spacing = 0.05;
  const std::size_t uniform = syn::sampleCadModel(model, options).points.size();
  EXPECT_EQ(uniform, static_cast<std::size_t>(std::ceil(model.area() / (0.05 * 0.05))));
  options.face_density = syn::denseFace(model, 1, 3.0);
  EXPECT_EQ(syn::sampleCadModel(model, options).points.size(), uniform);
  // A face of multiplier 0 gets no point.
  options.face_density[3] = 0.0;
  for (int f : syn::sampleCadModel(model, options).face)
    ASSERT_NE(f, 3);
}

TEST(CadDensity, BadMultipliers)
{
  const syn::CadModel model = syn::cadModelByName("cube");
  syn::SamplingOptions options;
  options.count = 10;
  options.face_density = {1.0, 2.0}; // not one per face
  EXPECT_THROW(syn::sampleCadModel(model, options), visfeat::Error);
  options.face_density.assign(model.faces.size(), 0.0);
  EXPECT_THROW(syn::sampleCadModel(model, options), visfeat::Error);
  options.face_density[0] = -1.0;
  EXPECT_THROW(syn::sampleCadModel(model, options), visfeat::Error);
  options.face_density[0] = std::nan("");
  EXPECT_THROW(syn::sampleCadModel(model, options), visfeat::Error);
  EXPECT_THROW(syn::denseFace(model, 6, 2.0), visfeat::Error);
  EXPECT_THROW(syn::denseFace(model, -1, 2.0), visfeat::Error);
  EXPECT_THROW(syn::denseFace(model, 0, 0.0), visfeat::Error);
}

} // namespace
