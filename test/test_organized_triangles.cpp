// The triangles of an organized cloud's pixel grid (organized_triangles.h): a wall
// tiled, depth jumps and shadow borders cut, the faces of a noisy cube view kept.

#include <support/cad_models.h>
#include <visfeat/core/band/organized_triangles.h>
#include <visfeat/core/common/error.h>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace {

namespace syn = visfeat::synthetic;
using visfeat::OrganizedTriangleParameters;
using visfeat::TriangleIndices;

constexpr double kPi = 3.14159265358979323846;

/** An organized cloud with its sensor. */
struct Organized
{
  int width = 0;
  int height = 0;
  std::vector<Eigen::Vector3d> points;
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
};

Organized
fromView(const syn::OrganizedView& view)
{
  Organized cloud;
  cloud.width = view.width;
  cloud.height = view.height;
  for (const Eigen::Vector3f& p : view.points)
    cloud.points.push_back(p.cast<double>());
  cloud.origin = view.camera_position;
  return cloud;
}

/** A pinhole camera at the origin looking along +z (image x = world x, image y =
 * world y), focal `focal` pixels, each pixel's depth (along z) from `depth`. */
Organized
pinhole(int width,
        int height,
        double focal,
        const std::function<double(int column, int row)>& depth)
{
  Organized cloud;
  cloud.width = width;
  cloud.height = height;
  for (int row = 0; row < height; ++row)
    for (int column = 0; column < width; ++column) {
      const double z = depth(column, row);
      cloud.points.emplace_back(z * (column + 0.5 - 0.5 * width) / focal,
                                z * (row + 0.5 - 0.5 * height) / focal, z);
    }
  return cloud;
}

std::vector<TriangleIndices>
triangulate(const Organized& cloud, const OrganizedTriangleParameters& parameters = {})
{
  return visfeat::organizedTriangles(cloud.points, cloud.width, cloud.height,
                                     cloud.origin, parameters);
}

double
area(const Organized& cloud, const TriangleIndices& t)
{
  const Eigen::Vector3d& a = cloud.points[t[0]];
  return 0.5 * (cloud.points[t[1]] - a).cross(cloud.points[t[2]] - a).norm();
}

/** The corner view of the cube (renderOrganizedView's defaults: 640 x 480 pixels)
 * with depth noise of sigma = noise_b * depth^2. */
syn::OrganizedView
cubeView(double noise_b)
{
  syn::OrganizedViewOptions options;
  options.noise_b = noise_b;
  options.seed = 5;
  return syn::renderOrganizedView(syn::cadModelByName("cube"), options);
}

/** Interior quads of a view (by their top-left pixel): all 4 pixels on one face. */
std::vector<std::size_t>
interiorQuads(const syn::OrganizedView& view)
{
  std::vector<std::size_t> quads;
  const std::size_t w = static_cast<std::size_t>(view.width);
  for (std::size_t row = 0; row + 1 < static_cast<std::size_t>(view.height); ++row)
    for (std::size_t column = 0; column + 1 < w; ++column) {
      const std::size_t a = row * w + column;
      const int f = view.face[a];
      if (f >= 0 && view.face[a + 1] == f && view.face[a + w] == f &&
          view.face[a + w + 1] == f)
        quads.push_back(a);
    }
  return quads;
}

/** Per quad (by its top-left pixel), how many triangles it gave; checks that every
 * triangle's corners are three distinct corners of one quad. */
std::vector<int>
trianglesPerQuad(const std::vector<TriangleIndices>& triangles, int width, int height)
{
  const std::uint32_t w = static_cast<std::uint32_t>(width);
  std::vector<int> count(static_cast<std::size_t>(width) * height, 0);
  for (const TriangleIndices& t : triangles) {
    const std::uint32_t row = std::min({t[0] / w, t[1] / w, t[2] / w});
    const std::uint32_t column = std::min({t[0] % w, t[1] % w, t[2] % w});
    for (std::uint32_t i : t) {
      EXPECT_LE(i / w - row, 1u);
      EXPECT_LE(i % w - column, 1u);
    }
    EXPECT_TRUE(t[0] != t[1] && t[1] != t[2] && t[0] != t[2]);
    ++count[row * w + column];
  }
  return count;
}

/** The fraction of `quads` that gave two triangles. */
double
fullFraction(const std::vector<std::size_t>& quads, const std::vector<int>& count)
{
  std::size_t full = 0;
  for (std::size_t q : quads)
    full += count[q] == 2 ? 1 : 0;
  return quads.empty() ? 0.0 : static_cast<double>(full) / quads.size();
}

/** Every triangle's normal points towards the sensor. */
void
expectFacingTheSensor(const Organized& cloud,
                      const std::vector<TriangleIndices>& triangles)
{
  for (const TriangleIndices& t : triangles) {
    const Eigen::Vector3d& a = cloud.points[t[0]];
    const Eigen::Vector3d normal =
      (cloud.points[t[1]] - a).cross(cloud.points[t[2]] - a);
    ASSERT_LT(normal.dot(a - cloud.origin), 0.0);
  }
}

TEST(OrganizedTriangles, FlatWallIsTiled)
{
  // Head-on: 320 x 240 pixels at depth 4, footprint 4 / 300.
  const double focal = 300.0, z = 4.0, step = z / focal;
  const Organized wall = pinhole(320, 240, focal, [&](int, int) { return z; });
  const std::vector<TriangleIndices> triangles = triangulate(wall);
  ASSERT_EQ(triangles.size(), 2u * 319u * 239u);
  const std::vector<int> count = trianglesPerQuad(triangles, 320, 240);
  for (int row = 0; row + 1 < 240; ++row)
    for (int column = 0; column + 1 < 320; ++column)
      ASSERT_EQ(count[row * 320 + column], 2) << row << " " << column;
  double sum = 0.0;
  for (const TriangleIndices& t : triangles)
    sum += area(wall, t);
  // The rectangle between the pixel centres exactly; the area the pixels see within
  // 1% (the half pixel around the border is left out).
  EXPECT_NEAR(sum / (319.0 * 239.0 * step * step), 1.0, 1e-9);
  EXPECT_NEAR(sum / (320.0 * 240.0 * step * step), 1.0, 0.01);
  expectFacingTheSensor(wall, triangles);

  // A wall at 60 degrees to the optical axis, seen at 45-75 degrees across the image
  // (edges up to 1 / cos 75 = 3.9 footprints along the slope): still every quad.
  const double slope = std::tan(kPi / 3.0);
  const Organized oblique = pinhole(160, 120, focal, [&](int column, int) {
    // plane z = 4 + slope * x, x = z * u: z = 4 / (1 - slope * u)
    return z / (1.0 - slope * (column + 0.5 - 80.0) / focal);
  });
  const std::vector<TriangleIndices> sloped = triangulate(oblique);
  EXPECT_EQ(sloped.size(), 2u * 159u * 119u);
  expectFacingTheSensor(oblique, sloped);
}

/** Triangles joining pixels of depth near to pixels of depth far; and the count of
 * triangles all on near and all on far. */
void
countAcross(const Organized& cloud,
            const std::vector<TriangleIndices>& triangles,
            double near,
            std::size_t& across,
            std::size_t& on_near,
            std::size_t& on_far)
{
  across = on_near = on_far = 0;
  for (const TriangleIndices& t : triangles) {
    int n = 0;
    for (std::uint32_t i : t)
      n += std::abs(cloud.points[i].z() - near) < 1e-9 ? 1 : 0;
    across += n == 1 || n == 2 ? 1 : 0;
    on_near += n == 3 ? 1 : 0;
    on_far += n == 0 ? 1 : 0;
  }
}

TEST(OrganizedTriangles, BoxInFrontOfAWallIsCutAtTheJump)
{
  // A box's front face (depth 3) over a wall behind it, seen head-on: two depth
  // levels, the box's sides unseen. Footprint at the box: 3 / 200.
  const double focal = 200.0, near = 3.0, step = near / focal;
  auto inBox = [](int column, int row) {
    return column >= 60 && column < 140 && row >= 40 && row < 110;
  };
  for (double jump : {7.5 * step, 2.0}) {
    SCOPED_TRACE("jump " + std::to_string(jump / step) + " footprints");
    const Organized scene = pinhole(200, 150, focal, [&](int column, int row) {
      return inBox(column, row) ? near : near + jump;
    });
    const std::vector<TriangleIndices> triangles = triangulate(scene);
    std::size_t across = 0, on_near = 0, on_far = 0;
    countAcross(scene, triangles, near, across, on_near, on_far);
    EXPECT_EQ(across, 0u);
    // Both surfaces whole: every quad inside one of them gives its two triangles
    // (and the 4 quads at the box's corners with 3 far pixels give one).
    EXPECT_EQ(on_near, 2u * 79u * 69u);
    EXPECT_EQ(on_far, 2u * (199u * 149u - 81u * 71u) + 4u);
    // No triangle has an edge across the jump.
    for (const TriangleIndices& t : triangles)
      for (int e = 0; e < 3; ++e)
        ASSERT_LT((scene.points[t[e]] - scene.points[t[(e + 1) % 3]]).norm(),
                  0.5 * jump);
    if (jump < 10.0 * step) {
      // The view angle limit alone lets this one through (seen at about 82.4
      // degrees): the edge limit cuts it.
      OrganizedTriangleParameters angle_only;
      angle_only.max_edge_ratio = 1000.0;
      countAcross(scene, triangulate(scene, angle_only), near, across, on_near, on_far);
      EXPECT_GT(across, 100u);
    }
  }
}

TEST(OrganizedTriangles, StepUnderTheLimitsIsKept)
{
  // A step of 6 footprints along a column: edges across it of about 6 footprints and
  // triangles seen at about 80.5 degrees, under both limits. The step is bridged: the
  // limits are no tighter than documented.
  const double focal = 200.0, near = 3.0, step = near / focal;
  const Organized scene = pinhole(120, 100, focal, [&](int column, int) {
    return column < 60 ? near : near + 6.0 * step;
  });
  std::size_t across = 0, on_near = 0, on_far = 0;
  countAcross(scene, triangulate(scene), near, across, on_near, on_far);
  EXPECT_EQ(across, 2u * 99u);
  EXPECT_EQ(on_near + on_far + across, 2u * 119u * 99u);
}

TEST(OrganizedTriangles, DiagonalStepIsCutByTheViewAngle)
{
  // A step of 6.2 footprints along the image diagonal: the edges across it are about
  // 6.3 footprints (under max_edge_ratio), the triangles across it are seen at
  // atan(6.2 sqrt 2) = 83.5 degrees, over max_view_angle_degrees.
  const double focal = 200.0, near = 3.0, step = near / focal;
  const Organized scene = pinhole(120, 100, focal, [&](int column, int row) {
    return column + row < 110 ? near : near + 6.2 * step;
  });
  std::size_t across = 0, on_near = 0, on_far = 0;
  countAcross(scene, triangulate(scene), near, across, on_near, on_far);
  EXPECT_EQ(across, 0u);
  EXPECT_GT(on_near, 5000u);
  EXPECT_GT(on_far, 5000u);
  // The edge limit alone keeps triangles across it.
  OrganizedTriangleParameters edges_only;
  edges_only.max_view_angle_degrees = 90.0;
  countAcross(scene, triangulate(scene, edges_only), near, across, on_near, on_far);
  EXPECT_GT(across, 50u);
}

/** Per pixel, the area of the face it sees (world units^2): depth^2 / (focal^2 |n .
 * d|), d the pixel's ray scaled to depth 1, n the unit normal of its face. */
double
visibleArea(const syn::CadModel& model, const syn::OrganizedView& view)
{
  double sum = 0.0;
  for (int row = 0; row < view.height; ++row)
    for (int column = 0; column < view.width; ++column) {
      const int f = view.face[static_cast<std::size_t>(row * view.width + column)];
      if (f < 0)
        continue;
      const Eigen::Vector3d d =
        view.camera_axes *
        Eigen::Vector3d((column + 0.5 - 0.5 * view.width) / view.focal,
                        (row + 0.5 - 0.5 * view.height) / view.focal, 1.0);
      const std::size_t i = static_cast<std::size_t>(row * view.width + column);
      const double depth = (view.points[i].cast<double>() - view.camera_position)
                             .dot(view.camera_axes.col(2));
      const Eigen::Vector3d n = model.faces[static_cast<std::size_t>(f)].normal;
      sum += depth * depth / (view.focal * view.focal * std::abs(n.dot(d)));
    }
  return sum;
}

TEST(OrganizedTriangles, CornerOfTheCubeGivesItsThreeFaces)
{
  const syn::CadModel cube = syn::cadModelByName("cube");
  const syn::OrganizedView view = cubeView(0.0);
  const Organized cloud = fromView(view);
  const std::vector<TriangleIndices> triangles = triangulate(cloud);
  std::vector<bool> facing(cube.faces.size(), false);
  for (const syn::CadFace& f : cube.faces)
    facing[static_cast<std::size_t>(f.id)] = f.normal.dot(view.camera_position) > 0.0;
  double sum = 0.0;
  std::size_t creases = 0;
  for (const TriangleIndices& t : triangles) {
    std::vector<int> faces;
    for (std::uint32_t i : t) {
      ASSERT_GE(view.face[i], 0); // no corner on the background
      ASSERT_TRUE(facing[static_cast<std::size_t>(view.face[i])]);
      faces.push_back(view.face[i]);
    }
    if (std::count(faces.begin(), faces.end(), faces[0]) < 3) {
      // across a crease: every corner within two pixel footprints of the crease
      ++creases;
      for (std::uint32_t i : t)
        EXPECT_LT(view.curve_distance[i],
                  2.0 * (cloud.points[i] - cloud.origin).norm() / view.focal);
    }
    sum += area(cloud, t);
  }
  EXPECT_GT(creases, 100u);
  // The three faces covered: the triangles' area is the area the pixels see, less
  // the half pixel along the outline.
  const double seen = visibleArea(cube, view);
  EXPECT_NEAR(sum / seen, 1.0, 0.05);
  EXPECT_LT(sum, seen);
  const std::vector<std::size_t> quads = interiorQuads(view);
  EXPECT_EQ(fullFraction(quads, trianglesPerQuad(triangles, view.width, view.height)),
            1.0);
  expectFacingTheSensor(cloud, triangles);
}

TEST(OrganizedTriangles, NoisyFacesStayWhole)
{
  // Depth noise of about one pixel footprint: sigma = noise_b depth^2 and the
  // footprint is depth / focal, equal at depth 2.2 (the cube spans depths 1.8-3.1:
  // sigma is 0.8-1.4 footprints). Measured: 99.4% of the quads are kept; an edge
  // limit of 5 footprints keeps 92%, a view angle limit of 80 degrees 91%.
  const double focal = cubeView(0.0).focal;
  const syn::OrganizedView view = cubeView(1.0 / (2.2 * focal));
  const Organized cloud = fromView(view);
  const std::vector<TriangleIndices> triangles = triangulate(cloud);
  const std::vector<std::size_t> quads = interiorQuads(view);
  ASSERT_GT(quads.size(), 50000u);
  EXPECT_GE(fullFraction(quads, trianglesPerQuad(triangles, view.width, view.height)),
            0.97);
}

TEST(OrganizedTriangles, EmptyPixelsMakeNoTriangle)
{
  // A wall with 15% of its pixels empty (NaN, infinite, or at the sensor itself).
  Organized wall = pinhole(100, 80, 100.0, [](int, int) { return 2.0; });
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<bool> empty(wall.points.size(), false);
  for (std::size_t i = 0; i < wall.points.size(); ++i) {
    const double x = u(rng);
    if (x < 0.05)
      wall.points[i] = Eigen::Vector3d(nan, 0.0, 2.0);
    else if (x < 0.10)
      wall.points[i].z() = std::numeric_limits<double>::infinity();
    else if (x < 0.15)
      wall.points[i] = wall.origin;
    empty[i] = x < 0.15;
  }
  const std::vector<TriangleIndices> triangles = triangulate(wall);
  const std::vector<int> count = trianglesPerQuad(triangles, 100, 80);
  for (const TriangleIndices& t : triangles)
    for (std::uint32_t i : t)
      ASSERT_FALSE(empty[i]);
  // A quad with 4 returns gives 2 triangles, with 3 one, with fewer none.
  for (std::size_t row = 0; row + 1 < 80; ++row)
    for (std::size_t column = 0; column + 1 < 100; ++column) {
      const std::size_t a = row * 100 + column;
      const int returns = 4 - empty[a] - empty[a + 1] - empty[a + 100] - empty[a + 101];
      ASSERT_EQ(count[a], std::max(returns - 2, 0)) << a;
    }
}

/** The distance from p to the model's surface. */
double
surfaceDistance(const syn::CadModel& model, const Eigen::Vector3d& p)
{
  double d = std::numeric_limits<double>::infinity();
  for (const syn::CadFace& f : model.faces)
    d = std::min(d, syn::faceDistance(model, f.id, p));
  return d;
}

TEST(OrganizedTriangles, OcclusionsAndShadowBordersAreCut)
{
  // The U-prism seen into its notch: the arms occlude the notch; with a projector
  // beside the camera they also cast shadows into it.
  const syn::CadModel u = syn::cadModelByName("u_prism");
  syn::OrganizedViewOptions options;
  options.width = 320;
  options.height = 240;
  options.camera_direction = Eigen::Vector3d(0.4, 1.0, 0.6).normalized();
  const syn::OrganizedView plain = syn::renderOrganizedView(u, options);
  for (double baseline : {0.0, 1.0}) {
    SCOPED_TRACE("baseline " + std::to_string(baseline));
    options.baseline = baseline;
    const syn::OrganizedView view = syn::renderOrganizedView(u, options);
    std::size_t shadows = 0;
    for (std::size_t i = 0; i < view.face.size(); ++i)
      shadows += plain.face[i] >= 0 && view.face[i] < 0 ? 1 : 0;
    EXPECT_EQ(shadows > 300, baseline != 0.0);
    const Organized cloud = fromView(view);
    // Every triangle lies on the surface: its centroid and edge midpoints within two
    // pixel footprints of a face. A triangle across a jump or a shadow hangs in the
    // air, up to the jump; where an occluding edge meets the face behind it the jump
    // shrinks to nothing, and is bridged where it is under the limits (measured: about
    // 1.1 footprints off).
    auto offSurface = [&](const std::vector<TriangleIndices>& triangles) {
      std::size_t off = 0;
      for (const TriangleIndices& t : triangles) {
        const Eigen::Vector3d& a = cloud.points[t[0]];
        const Eigen::Vector3d& b = cloud.points[t[1]];
        const Eigen::Vector3d& c = cloud.points[t[2]];
        const double footprint = (a - cloud.origin).norm() / view.focal;
        const double d = std::max(
          {surfaceDistance(u, (a + b + c) / 3.0), surfaceDistance(u, 0.5 * (a + b)),
           surfaceDistance(u, 0.5 * (b + c)), surfaceDistance(u, 0.5 * (c + a))});
        off += d > 2.0 * footprint ? 1 : 0;
      }
      return off;
    };
    const std::vector<TriangleIndices> triangles = triangulate(cloud);
    for (const TriangleIndices& t : triangles)
      for (std::uint32_t i : t)
        ASSERT_GE(view.face[i], 0); // no shadow or background pixel
    EXPECT_EQ(offSurface(triangles), 0u);
    EXPECT_GT(triangles.size(), 20000u);
    // The view has jumps to cut: without the limits, triangles hang across them.
    OrganizedTriangleParameters uncut;
    uncut.max_edge_ratio = 1000.0;
    uncut.max_view_angle_degrees = 90.0;
    EXPECT_GT(offSurface(triangulate(cloud, uncut)), 50u);
  }
}

TEST(OrganizedTriangles, BadInputThrows)
{
  const Organized wall = pinhole(4, 3, 10.0, [](int, int) { return 1.0; });
  auto throwsOneLine = [&](const std::vector<Eigen::Vector3d>& points, int width,
                           int height, const Eigen::Vector3d& origin,
                           const OrganizedTriangleParameters& parameters) {
    try {
      visfeat::organizedTriangles(points, width, height, origin, parameters);
      ADD_FAILURE() << "no throw for " << width << "x" << height;
    } catch (const visfeat::Error& e) {
      EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
    }
  };
  const OrganizedTriangleParameters good;
  const Eigen::Vector3d o = Eigen::Vector3d::Zero();
  throwsOneLine(wall.points, 0, 3, o, good);
  throwsOneLine(wall.points, 4, -1, o, good);
  throwsOneLine(wall.points, 3, 5, o, good); // 15 pixels for 12 points
  throwsOneLine(wall.points, 6, 3, o, good);
  throwsOneLine({}, 1, 1, o, good);
  throwsOneLine(wall.points, 4, 3, Eigen::Vector3d(0.0, std::nan(""), 0.0), good);
  for (double ratio : {0.5, std::nan(""), 2000.0}) {
    OrganizedTriangleParameters p;
    p.max_edge_ratio = ratio;
    throwsOneLine(wall.points, 4, 3, o, p);
  }
  for (double angle : {0.0, 91.0, std::nan("")}) {
    OrganizedTriangleParameters p;
    p.max_view_angle_degrees = angle;
    throwsOneLine(wall.points, 4, 3, o, p);
  }
  EXPECT_EQ(triangulate(wall).size(), 2u * 3u * 2u);
  // One row or one column: no quad, no triangle, no error.
  EXPECT_TRUE(visfeat::organizedTriangles(wall.points, 12, 1, o, good).empty());
  EXPECT_TRUE(visfeat::organizedTriangles(wall.points, 1, 12, o, good).empty());
}

} // namespace
