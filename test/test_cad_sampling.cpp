// The generated CAD models' sampling: samples on their face at their curve distance,
// uniform by area and within faces, exact curve distances, rotation invariance, the
// requested noise, spacing and reproducibility.

#include "cad_fixtures.h"
#include <support/cad_models.h>
#include <support/portable_random.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <string>
#include <vector>

namespace {

namespace syn = visfeat::synthetic;
using namespace visfeat_test::cad;

TEST(CadModels, SamplesLieOnTheirFaceWithTheirCurveDistance)
{
  for (const std::string& name : syn::cadModelNames()) {
    SCOPED_TRACE(name);
    const syn::CadModel model =
      syn::rotated(syn::cadModelByName(name), syn::randomRotation(5));
    const syn::CadSamples s = sample(model, 3000, 11);
    ASSERT_EQ(s.points.size(), 3000u);
    ASSERT_EQ(s.face.size(), 3000u);
    ASSERT_EQ(s.curve_distance.size(), 3000u);
    for (std::size_t i = 0; i < s.points.size(); ++i) {
      const Eigen::Vector3d p = s.points[i].cast<double>();
      ASSERT_GE(s.face[i], 0);
      ASSERT_LT(s.face[i], static_cast<int>(model.faces.size()));
      EXPECT_LT(syn::faceDistance(model, s.face[i], p), 1e-5);
      EXPECT_NEAR(s.curve_distance[i], syn::curveDistance(model, p), 1e-5);
    }
  }
}

TEST(CadModels, SamplingIsUniformByArea)
{
  const std::size_t n = 60000;
  for (const char* name :
       {"triangular_prism", "u_prism", "box_with_hole", "cylinder"}) {
    SCOPED_TRACE(name);
    const syn::CadModel model = syn::cadModelByName(name);
    const syn::CadSamples s = sample(model, n, 21);
    std::vector<double> share(model.faces.size(), 0.0);
    for (int f : s.face)
      share[static_cast<std::size_t>(f)] += 1.0 / static_cast<double>(n);
    for (std::size_t f = 0; f < model.faces.size(); ++f) {
      const double p = syn::faceArea(model, static_cast<int>(f)) / model.area();
      // Binomial: 5 standard deviations (a few percent of the share at most).
      EXPECT_NEAR(share[f], p, 5.0 * std::sqrt(p * (1 - p) / static_cast<double>(n)))
        << "face " << f;
    }
  }
}

TEST(CadModels, SamplingIsUniformWithinFaces)
{
  // Cube: on a face of side s, the points within d of the face's boundary are
  // 1 - (1 - 2d/s)^2 of it, and that boundary is the nearest sharp curve.
  const std::size_t n = 60000;
  // share of the samples within d of a sharp curve, against the share of the area
  const auto expectShareWithin = [n](const syn::CadSamples& samples, double d,
                                     double expected) {
    const double got = static_cast<double>(std::count_if(
                         samples.curve_distance.begin(), samples.curve_distance.end(),
                         [&](double x) { return x < d; })) /
                       static_cast<double>(n);
    EXPECT_NEAR(got, expected, 5.0 * std::sqrt(expected * (1 - expected) / n))
      << "d = " << d;
  };
  const syn::CadModel cube = syn::cadModelByName("cube");
  const double side = 2.0 / std::sqrt(3.0);
  const syn::CadSamples s = sample(cube, n, 31);
  for (double d : {0.05, 0.15, 0.3}) {
    expectShareWithin(s, d, 1.0 - std::pow(1.0 - 2.0 * d / side, 2));
  }
  // Cylinder (r 1, h 2): within d of a rim: the ring 1 - (1 - d)^2 of each disc and
  // 2d/h of the lateral face.
  const syn::CadModel cyl = syn::cadModelByName("cylinder");
  const syn::CadSamples c = sample(cyl, n, 32);
  for (double d : {0.05, 0.2, 0.5}) {
    const double near_area =
      2 * kPi * (1.0 - std::pow(1.0 - d, 2)) + 2 * kPi * 2.0 * (2.0 * d / 2.0);
    expectShareWithin(c, d, near_area / cyl.area());
  }
}

TEST(CadModels, CurveDistanceIsExact)
{
  const syn::CadModel cube = syn::cadModelByName("cube");
  const double a = 1.0 / std::sqrt(3.0); // half side
  const int edge = segmentBetween(cube, {-a, -a, -a}, {a, -a, -a});
  ASSERT_GE(edge, 0);
  const Eigen::Vector3d mid(0, -a, -a);
  EXPECT_NEAR(syn::curveDistance(cube, edge, mid), 0.0, 1e-15);
  EXPECT_NEAR(syn::curveDistance(cube, mid), 0.0, 1e-15);
  // Outwards from the edge midpoint, perpendicular to it: 0.3-0.4-0.5.
  EXPECT_NEAR(syn::curveDistance(cube, mid + Eigen::Vector3d(0, -0.3, -0.4)), 0.5,
              1e-14);
  EXPECT_NEAR(syn::curveDistance(cube, edge, mid + Eigen::Vector3d(0, -0.3, -0.4)), 0.5,
              1e-14);
  // Along the edge: still on it; beyond its end: the distance to the corner.
  EXPECT_NEAR(syn::curveDistance(cube, edge, mid + Eigen::Vector3d(0.5, 0, 0)), 0.0,
              1e-15);
  EXPECT_NEAR(syn::curveDistance(cube, edge, Eigen::Vector3d(a + 0.3, -a - 0.4, -a)),
              0.5, 1e-14);
  EXPECT_NEAR(syn::curveDistance(cube, Eigen::Vector3d(a + 0.3, -a, -a)), 0.3, 1e-14);
  // Face centre: a from its four edges; cube centre: a * sqrt(2).
  EXPECT_NEAR(syn::curveDistance(cube, Eigen::Vector3d(0, -a, 0)), a, 1e-14);
  EXPECT_NEAR(syn::curveDistance(cube, Eigen::Vector3d::Zero()), a * std::sqrt(2.0),
              1e-14);

  // Cylinder (r 1, circles at z = -1 and 1).
  const syn::CadModel cyl = syn::cadModelByName("cylinder");
  EXPECT_NEAR(syn::curveDistance(cyl, Eigen::Vector3d(0, 0, 0)), std::sqrt(2.0), 1e-14);
  EXPECT_NEAR(syn::curveDistance(cyl, Eigen::Vector3d(0, 0, 1)), 1.0, 1e-14);
  EXPECT_NEAR(syn::curveDistance(cyl, Eigen::Vector3d(0, 0, 3)), std::sqrt(5.0), 1e-14);
  EXPECT_NEAR(syn::curveDistance(cyl, Eigen::Vector3d(2, 0, 1)), 1.0, 1e-14);
  EXPECT_NEAR(syn::curveDistance(cyl, Eigen::Vector3d(0.3, 0.4, 1.2)),
              std::hypot(0.2, 0.5), 1e-14);
  EXPECT_NEAR(syn::curveDistance(cyl, Eigen::Vector3d(0.6, 0.8, 1.0)), 0.0, 1e-14);
  EXPECT_NEAR(syn::curveDistance(cyl, 0, Eigen::Vector3d(0.6, 0.8, 1.0)), 2.0, 1e-14);

  // Box with a hole of radius 0.5 along z (circles at z = -0.75 and 0.75): from the
  // centre the circles are nearer than the straight edges (1.25 and sqrt 2).
  const syn::CadModel box = syn::cadModelByName("box_with_hole");
  EXPECT_NEAR(syn::curveDistance(box, Eigen::Vector3d::Zero()), std::hypot(0.5, 0.75),
              1e-14);
  EXPECT_NEAR(syn::curveDistance(box, Eigen::Vector3d(1.0, 1.0, 0.0)), 0.0, 1e-14);
  // On the top face halfway between the hole and an edge.
  EXPECT_NEAR(syn::curveDistance(box, Eigen::Vector3d(0.75, 0.0, 0.75)), 0.25, 1e-14);

  // Face distances: in the face's plane outside it, above it, and on the wall.
  EXPECT_NEAR(syn::faceDistance(box, 1, Eigen::Vector3d(0, 0, 0.75)), 0.5, 1e-14);
  EXPECT_NEAR(syn::faceDistance(box, 1, Eigen::Vector3d(0.75, 0, 1.0)), 0.25, 1e-14);
  EXPECT_NEAR(syn::faceDistance(box, 6, Eigen::Vector3d(0.2, 0, 0.1)), 0.3, 1e-14);
  EXPECT_NEAR(syn::faceDistance(box, 6, Eigen::Vector3d(0.5, 0, 1.75)), 1.0, 1e-14);
}

TEST(CadModels, RotationInvariance)
{
  std::mt19937_64 rng(8);
  visfeat::synthetic::UniformReal coord(-2.0, 2.0);
  for (const std::string& name : syn::cadModelNames()) {
    SCOPED_TRACE(name);
    const syn::CadModel model = syn::cadModelByName(name);
    const Eigen::Matrix3d r = syn::randomRotation(99);
    const syn::CadModel turned = syn::rotated(model, r);
    EXPECT_NO_THROW(syn::checkCadModel(turned));
    EXPECT_NEAR(turned.area(), model.area(), 1e-9);
    EXPECT_EQ(syn::eulerCharacteristic(turned), syn::eulerCharacteristic(model));
    for (int i = 0; i < 200; ++i) {
      const Eigen::Vector3d p(coord(rng), coord(rng), coord(rng));
      EXPECT_NEAR(syn::curveDistance(turned, r * p), syn::curveDistance(model, p),
                  1e-12);
      const int f = i % static_cast<int>(model.faces.size());
      EXPECT_NEAR(syn::faceDistance(turned, f, r * p), syn::faceDistance(model, f, p),
                  1e-12);
    }
    // Sampling under a rotation = rotating the samples; truth unchanged.
    syn::SamplingOptions options;
    options.count = 500;
    options.seed = 4;
    const syn::CadSamples plain = syn::sampleCadModel(model, options);
    options.rotation = r;
    const syn::CadSamples spun = syn::sampleCadModel(model, options);
    ASSERT_EQ(plain.points.size(), spun.points.size());
    for (std::size_t i = 0; i < plain.points.size(); ++i) {
      EXPECT_LT(
        (spun.points[i].cast<double>() - r * plain.points[i].cast<double>()).norm(),
        1e-5);
      EXPECT_EQ(spun.face[i], plain.face[i]);
      EXPECT_EQ(spun.curve_distance[i], plain.curve_distance[i]);
    }
  }
}

TEST(CadModels, NoiseHasTheRequestedSigma)
{
  const syn::CadModel model = syn::cadModelByName("box_with_hole");
  const double sigma = 0.01;
  const std::size_t n = 30000;
  const syn::CadSamples clean = sample(model, n, 77);
  const syn::CadSamples noisy = sample(model, n, 77, sigma);
  ASSERT_EQ(noisy.points.size(), n);
  Eigen::Vector3d sum = Eigen::Vector3d::Zero(), sum2 = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < n; ++i) {
    // Same noise-free samples (the noise comes from its own stream), same truth.
    EXPECT_EQ(noisy.face[i], clean.face[i]);
    EXPECT_EQ(noisy.curve_distance[i], clean.curve_distance[i]);
    const Eigen::Vector3d d =
      noisy.points[i].cast<double>() - clean.points[i].cast<double>();
    sum += d;
    sum2 += d.cwiseProduct(d);
  }
  const Eigen::Vector3d mean = sum / static_cast<double>(n);
  const Eigen::Vector3d sd = (sum2 / static_cast<double>(n)).cwiseSqrt();
  for (int k = 0; k < 3; ++k) {
    EXPECT_LT(std::abs(mean[k]), 5.0 * sigma / std::sqrt(static_cast<double>(n)));
    EXPECT_NEAR(sd[k], sigma, 0.03 * sigma); // sd of the sd: sigma / sqrt(2n) ~ 0.4%
  }
}

TEST(CadModels, SpacingAndReproducibility)
{
  const syn::CadModel model =
    syn::rotated(syn::cadModelByName("u_prism"), syn::randomRotation(3));
  const double cell = syn::cellSize(model, 64);
  EXPECT_NEAR(cell, model.bounds().sizes().maxCoeff() / 64, 1e-15);
  const std::size_t count = syn::samplesForSpacing(model, 64, 0.5);
  EXPECT_EQ(
    count, static_cast<std::size_t>(std::ceil(model.area() / std::pow(0.5 * cell, 2))));
  syn::SamplingOptions options;
  options.spacing = 0.5 * cell;
  options.seed = 12;
  const syn::CadSamples a = syn::sampleCadModel(model, options);
  EXPECT_EQ(a.points.size(), count);
  const syn::CadSamples b = syn::sampleCadModel(model, options);
  EXPECT_EQ(a.points, b.points);
  EXPECT_EQ(a.face, b.face);
  options.seed = 13;
  EXPECT_NE(syn::sampleCadModel(model, options).points, a.points);
}

} // namespace
