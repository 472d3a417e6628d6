// The organized depth view of the CAD models (cad_depth_view.h): the faces a corner
// view sees, the pixel order, exact hits on the analytic faces, empty pixels for the
// background and for the projector's shadows, depth-dependent noise.

#include <support/cad_models.h>
#include <visfeat/core/common/error.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <vector>

namespace {

namespace syn = visfeat::synthetic;

bool
hit(const syn::OrganizedView& view, std::size_t i)
{
  return view.face[i] >= 0;
}

/** Depth along the optical axis of pixel i (world units). */
double
depth(const syn::OrganizedView& view, std::size_t i)
{
  return (view.points[i].cast<double>() - view.camera_position)
    .dot(view.camera_axes.col(2));
}

syn::OrganizedViewOptions
smallView()
{
  syn::OrganizedViewOptions options;
  options.width = 160;
  options.height = 120;
  return options;
}

TEST(CadDepthView, CornerOfTheCubeSeesThreeFaces)
{
  const syn::CadModel cube = syn::cadModelByName("cube");
  const syn::OrganizedViewOptions options = smallView();
  const syn::OrganizedView view = syn::renderOrganizedView(cube, options);
  ASSERT_EQ(view.width, 160);
  ASSERT_EQ(view.height, 120);
  ASSERT_EQ(view.points.size(), 160u * 120u);
  ASSERT_EQ(view.face.size(), view.points.size());
  ASSERT_EQ(view.curve_distance.size(), view.points.size());
  std::set<int> seen;
  std::size_t empty = 0;
  for (std::size_t i = 0; i < view.points.size(); ++i) {
    if (hit(view, i)) {
      seen.insert(view.face[i]);
      EXPECT_TRUE(view.points[i].allFinite());
      EXPECT_TRUE(std::isfinite(view.curve_distance[i]));
    } else {
      ++empty;
      EXPECT_TRUE(std::isnan(view.points[i].x()) && std::isnan(view.points[i].y()) &&
                  std::isnan(view.points[i].z()));
      EXPECT_TRUE(std::isnan(view.curve_distance[i]));
    }
  }
  // Exactly the three faces that face the camera, and background around them.
  std::set<int> facing;
  for (const syn::CadFace& f : cube.faces)
    if (f.normal.dot(options.camera_direction) > 0.0)
      facing.insert(f.id);
  EXPECT_EQ(facing.size(), 3u);
  EXPECT_EQ(seen, facing);
  EXPECT_GT(empty, 0u);
  EXPECT_LT(empty, view.points.size());
  // The vertex and the three edges between the faces are in view: some pixels lie
  // within a pixel's footprint of a curve.
  double nearest = 1e9;
  for (std::size_t i = 0; i < view.points.size(); ++i)
    if (hit(view, i))
      nearest = std::min(nearest, view.curve_distance[i]);
  EXPECT_LT(nearest, depth(view, 80 * 160 + 60) / view.focal);
}

TEST(CadDepthView, RowsAndColumns)
{
  const syn::OrganizedViewOptions options = smallView();
  const syn::OrganizedView view =
    syn::renderOrganizedView(syn::cadModelByName("u_prism"), options);
  // The world's up appears upwards (image y runs down), image x is horizontal.
  EXPECT_LT(view.camera_axes.col(1).dot(options.up), 0.0);
  EXPECT_NEAR(view.camera_axes.col(0).dot(options.up), 0.0, 1e-12);
  EXPECT_NEAR(view.camera_axes.determinant(), 1.0, 1e-12);
  std::size_t checked = 0;
  for (int row = 0; row < view.height; ++row)
    for (int column = 0; column < view.width; ++column) {
      const std::size_t i = static_cast<std::size_t>(row * view.width + column);
      if (!hit(view, i))
        continue;
      const Eigen::Vector3d c = view.camera_axes.transpose() *
                                (view.points[i].cast<double>() - view.camera_position);
      // The pixel's ray: x / z and y / z at the pixel's centre.
      EXPECT_NEAR(c.x() / c.z(), (column + 0.5 - 0.5 * view.width) / view.focal, 1e-5);
      EXPECT_NEAR(c.y() / c.z(), (row + 0.5 - 0.5 * view.height) / view.focal, 1e-5);
      // A pixel to the right is further along image x; one below, along image y.
      if (column + 1 < view.width && hit(view, i + 1)) {
        const Eigen::Vector3d r =
          view.camera_axes.transpose() *
          (view.points[i + 1].cast<double>() - view.camera_position);
        EXPECT_GT(r.x() / r.z(), c.x() / c.z());
        ++checked;
      }
      const std::size_t below = i + static_cast<std::size_t>(view.width);
      if (row + 1 < view.height && hit(view, below)) {
        const Eigen::Vector3d b =
          view.camera_axes.transpose() *
          (view.points[below].cast<double>() - view.camera_position);
        EXPECT_GT(b.y() / b.z(), c.y() / c.z());
      }
    }
  EXPECT_GT(checked, 1000u);
}

TEST(CadDepthView, HitsLieOnTheExactFaces)
{
  for (const std::string name :
       {"cylinder", "box_with_hole", "u_prism", "icosahedron"}) {
    SCOPED_TRACE(name);
    const syn::CadModel model =
      syn::rotated(syn::cadModelByName(name), syn::randomRotation(6));
    const syn::OrganizedView view = syn::renderOrganizedView(model, smallView());
    std::size_t hits = 0;
    for (std::size_t i = 0; i < view.points.size(); ++i) {
      if (!hit(view, i))
        continue;
      ++hits;
      const Eigen::Vector3d p = view.points[i].cast<double>();
      // On the analytic face (a chord polygon would be off by up to its tolerance).
      ASSERT_LT(syn::faceDistance(model, view.face[i], p), 2e-6) << "pixel " << i;
      EXPECT_NEAR(view.curve_distance[i], syn::curveDistance(model, p), 2e-6);
    }
    EXPECT_GT(hits, 1000u);
  }
}

TEST(CadDepthView, SeeThroughTheHole)
{
  const syn::CadModel box = syn::cadModelByName("box_with_hole");
  syn::OrganizedViewOptions options = smallView();
  options.camera_direction = Eigen::Vector3d::UnitZ(); // down the hole's axis
  options.up = Eigen::Vector3d::UnitY();
  const syn::OrganizedView view = syn::renderOrganizedView(box, options);
  const std::size_t centre = 60 * 160 + 80;
  EXPECT_FALSE(hit(view, centre)); // the background through the hole
  std::set<int> seen;
  for (std::size_t i = 0; i < view.points.size(); ++i)
    if (hit(view, i))
      seen.insert(view.face[i]);
  // The top face and, in perspective, the hole's wall; nothing of the bottom.
  EXPECT_EQ(seen, (std::set<int>{1, 6}));
  // A pixel halfway between the hole (radius 0.5) and the box's side (at 1) sees the
  // top face (z = 0.75); image x is world x here.
  EXPECT_NEAR(view.camera_axes.col(0).x(), 1.0, 1e-12);
  const double top_depth = view.camera_position.z() - 0.75;
  const int column =
    static_cast<int>(std::lround(80 - 0.5 + 0.75 * view.focal / top_depth));
  EXPECT_EQ(view.face[static_cast<std::size_t>(60 * 160 + column)], 1);
}

/** The u_prism seen into its notch. */
syn::OrganizedViewOptions
notchView(double baseline)
{
  syn::OrganizedViewOptions options = smallView();
  options.camera_direction = Eigen::Vector3d(0.4, 1.0, 0.6).normalized();
  options.baseline = baseline;
  return options;
}

TEST(CadDepthView, ProjectorShadows)
{
  const syn::CadModel u = syn::cadModelByName("u_prism");
  const syn::OrganizedView plain = syn::renderOrganizedView(u, notchView(0.0));
  // The depth step from pixel (row, a) to (row, b) when both lie on one face (a
  // plane: the local slope), else 0.
  auto slope = [&](int row, int a, int b) {
    if (b < 0 || b >= plain.width)
      return 0.0;
    const std::size_t i = static_cast<std::size_t>(row * plain.width + a);
    const std::size_t j = static_cast<std::size_t>(row * plain.width + b);
    return hit(plain, j) && plain.face[j] == plain.face[i]
             ? std::abs(depth(plain, j) - depth(plain, i))
             : 0.0;
  };
  for (double baseline : {-1.0, 1.0}) {
    SCOPED_TRACE("baseline " + std::to_string(baseline));
    const syn::OrganizedView lit = syn::renderOrganizedView(u, notchView(baseline));
    EXPECT_TRUE(lit.projector_position.isApprox(plain.camera_position +
                                                baseline * plain.camera_axes.col(0)));
    std::size_t shadows = 0, runs = 0, runs_at_jumps = 0;
    for (int row = 0; row < plain.height; ++row) {
      int run_start = -1;
      for (int column = 0; column <= plain.width; ++column) {
        const std::size_t i = static_cast<std::size_t>(row * plain.width + column);
        const bool shadow = column < plain.width && hit(plain, i) && !hit(lit, i);
        if (column < plain.width) {
          // A lit pixel is the same point as without the projector.
          ASSERT_TRUE(!hit(lit, i) ||
                      (hit(plain, i) && lit.points[i] == plain.points[i]));
          shadows += shadow ? 1 : 0;
        }
        if (shadow && run_start < 0)
          run_start = column;
        if (shadow || run_start < 0)
          continue;
        // A run of shadow [run_start, column): a depth jump (the occluding edge) at one
        // of its ends.
        ++runs;
        // Across the run's end the depth changes by more than 3 times the slope of
        // the faces on either side.
        auto jump = [&](int end, int outside) {
          if (outside < 0 || outside >= plain.width)
            return true;
          const std::size_t e = static_cast<std::size_t>(row * plain.width + end);
          const std::size_t o = static_cast<std::size_t>(row * plain.width + outside);
          if (!hit(plain, o))
            return true;
          const double slopes = std::max(slope(row, end, 2 * end - outside),
                                         slope(row, outside, 2 * outside - end));
          return std::abs(depth(plain, o) - depth(plain, e)) > 3.0 * slopes;
        };
        runs_at_jumps +=
          jump(run_start, run_start - 1) || jump(column - 1, column) ? 1 : 0;
        run_start = -1;
      }
    }
    EXPECT_GT(shadows, 100u);
    EXPECT_EQ(runs_at_jumps, runs);
  }
}

/** The measured and the predicted noise on the face with the most pixels: the root
 * mean square of the depth differences to the noise-free view, and of the sigmas. */
void
measureNoise(const syn::OrganizedView& clean,
             const syn::OrganizedView& noisy,
             const syn::OrganizedViewOptions& options,
             double& measured,
             double& predicted)
{
  std::vector<std::size_t> count(8, 0);
  for (int f : clean.face)
    if (f >= 0)
      ++count[static_cast<std::size_t>(f)];
  const int face =
    static_cast<int>(std::max_element(count.begin(), count.end()) - count.begin());
  double sum2 = 0.0, sigma2 = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < clean.points.size(); ++i) {
    if (clean.face[i] != face)
      continue;
    ASSERT_EQ(noisy.face[i], face); // the noise moves points along their rays only
    const double d = depth(clean, i);
    const double sigma = options.noise_a + options.noise_b * d * d;
    sum2 += std::pow(depth(noisy, i) - d, 2);
    sigma2 += sigma * sigma;
    ++n;
  }
  ASSERT_GT(n, 1000u);
  measured = std::sqrt(sum2 / n);
  predicted = std::sqrt(sigma2 / n);
}

TEST(CadDepthView, NoiseGrowsWithDepth)
{
  const syn::CadModel cube = syn::cadModelByName("cube");
  std::vector<double> measured, predicted;
  for (double distance : {3.0, 6.0}) {
    syn::OrganizedViewOptions options = smallView();
    options.distance = distance;
    options.horizontal_fov = 40.0;
    const syn::OrganizedView clean = syn::renderOrganizedView(cube, options);
    options.noise_a = 0.002;
    options.noise_b = 0.004;
    options.seed = 12;
    const syn::OrganizedView noisy = syn::renderOrganizedView(cube, options);
    double m = 0.0, p = 0.0;
    measureNoise(clean, noisy, options, m, p);
    EXPECT_NEAR(m / p, 1.0, 0.2) << "distance " << distance;
    measured.push_back(m);
    predicted.push_back(p);
  }
  // About 4 times the sigma at twice the depth (a + b d^2), within 20%.
  EXPECT_GT(predicted[1] / predicted[0], 3.0);
  EXPECT_NEAR((measured[1] / measured[0]) / (predicted[1] / predicted[0]), 1.0, 0.2);
}

TEST(CadDepthView, Reproducible)
{
  const syn::CadModel cube = syn::cadModelByName("cube");
  syn::OrganizedViewOptions options = smallView();
  options.noise_a = 0.01;
  const syn::OrganizedView a = syn::renderOrganizedView(cube, options);
  const syn::OrganizedView b = syn::renderOrganizedView(cube, options);
  options.seed = 2;
  const syn::OrganizedView c = syn::renderOrganizedView(cube, options);
  std::size_t same = 0, hits = 0;
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    if (!hit(a, i))
      continue;
    ++hits;
    ASSERT_EQ(a.points[i], b.points[i]);
    same += a.points[i] == c.points[i] ? 1 : 0;
  }
  EXPECT_GT(hits, 0u);
  EXPECT_EQ(same, 0u); // another seed, other noise
}

TEST(CadDepthView, BadOptions)
{
  const syn::CadModel cube = syn::cadModelByName("cube");
  auto fails = [&](void (*change)(syn::OrganizedViewOptions&)) {
    syn::OrganizedViewOptions options = smallView();
    change(options);
    EXPECT_THROW(syn::renderOrganizedView(cube, options), visfeat::Error);
  };
  fails([](syn::OrganizedViewOptions& o) { o.width = 0; });
  fails([](syn::OrganizedViewOptions& o) { o.height = -3; });
  fails([](syn::OrganizedViewOptions& o) { o.horizontal_fov = 180.0; });
  fails([](syn::OrganizedViewOptions& o) { o.camera_direction.setZero(); });
  fails([](syn::OrganizedViewOptions& o) { o.distance = 0.5; }); // inside the cube
  fails([](syn::OrganizedViewOptions& o) { o.noise_b = -1.0; });
  fails([](syn::OrganizedViewOptions& o) { o.baseline = std::nan(""); });
}

} // namespace
