// The tessellation of the CAD models (cad_tessellation.h) and the polygon
// triangulation behind it (polygon_triangulation.h): areas within the chord error,
// watertight and consistently oriented meshes, normals that agree with the faces.

#include <support/cad_models.h>
#include <support/polygon_triangulation.h>
#include <support/synthetic_shapes.h>
#include <visfeat/core/common/error.h>
#include <visfeat/core/mesh/mesh_sampling.h>

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace {

namespace syn = visfeat::synthetic;

constexpr double kPi = 3.14159265358979323846;

/** The named model under the rotation of a seed (seed 0: not rotated). */
syn::CadModel
model(const std::string& name, std::uint64_t seed)
{
  const syn::CadModel m = syn::cadModelByName(name);
  return seed == 0 ? m : syn::rotated(m, syn::randomRotation(seed));
}

Eigen::Vector3d
corner(const syn::CadMesh& mesh, std::size_t t, int k)
{
  return mesh.mesh.vertices[mesh.mesh.triangles[t][static_cast<std::size_t>(k)]];
}

/** The (not normalised) normal of triangle t: twice its area along its normal. */
Eigen::Vector3d
normal(const syn::CadMesh& mesh, std::size_t t)
{
  return (corner(mesh, t, 1) - corner(mesh, t, 0))
    .cross(corner(mesh, t, 2) - corner(mesh, t, 0));
}

/** The chord error budget of a face (world units^2), as documented. */
double
areaBudget(const syn::CadModel& m, int face, double tolerance)
{
  const syn::CadFace& f = m.faces[static_cast<std::size_t>(face)];
  if (f.kind == syn::CadFace::Kind::kCylindrical) {
    const auto& c0 = m.curves[static_cast<std::size_t>(f.circles[0])];
    const auto& c1 = m.curves[static_cast<std::size_t>(f.circles[1])];
    return 2.0 * kPi * (c1.centre - c0.centre).norm() * tolerance;
  }
  double budget = 0.0;
  for (int c : f.circles)
    budget += 2.0 * kPi * m.curves[static_cast<std::size_t>(c)].radius * tolerance;
  return budget;
}

TEST(PolygonTriangulation, SquareWithThreeHoles)
{
  syn::Polygon2 outer{{0, 0}, {4, 0}, {4, 3}, {0, 3}};
  std::vector<syn::Polygon2> holes;
  double hole_area = 0.0;
  // Holes of both orientations, one with its rightmost point level with another's.
  const double centres[3][2] = {{1, 1}, {3, 1}, {2, 2.2}};
  for (int h = 0; h < 3; ++h) {
    syn::Polygon2 hole;
    const int n = 7 + 3 * h;
    for (int k = 0; k < n; ++k) {
      const double a = (h == 1 ? -1.0 : 1.0) * 2.0 * kPi * k / n;
      hole.emplace_back(centres[h][0] + 0.4 * std::cos(a),
                        centres[h][1] + 0.4 * std::sin(a));
    }
    hole_area += 0.5 * std::abs(syn::twiceSignedArea(hole));
    holes.push_back(hole);
  }
  std::vector<Eigen::Vector2d> points(outer);
  for (const auto& h : holes)
    points.insert(points.end(), h.begin(), h.end());
  const auto triangles = syn::triangulatePolygon(outer, holes);
  ASSERT_EQ(triangles.size(), points.size() + 2 * holes.size() - 2);
  double area = 0.0;
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  for (const auto& t : triangles) {
    syn::Polygon2 tri{points[t[0]], points[t[1]], points[t[2]]};
    const double twice = syn::twiceSignedArea(tri);
    EXPECT_GT(twice, 0.0); // counter-clockwise, not degenerate
    area += 0.5 * twice;
    for (int k = 0; k < 3; ++k)
      ++directed[{t[static_cast<std::size_t>(k)],
                  t[static_cast<std::size_t>((k + 1) % 3)]}];
  }
  // No overlap: the counter-clockwise areas add up to the region's area.
  EXPECT_NEAR(area, 12.0 - hole_area, 1e-12);
  // Every directed edge once; interior edges also reversed, boundary edges not.
  std::size_t boundary = 0;
  for (const auto& e : directed) {
    EXPECT_EQ(e.second, 1);
    boundary += directed.count({e.first.second, e.first.first}) ? 0 : 1;
  }
  EXPECT_EQ(boundary, points.size());
}

TEST(PolygonTriangulation, NonConvexAndErrors)
{
  // The u_prism's profile: 8 points, 6 triangles, area 9 - 2.
  const syn::Polygon2 u{{0, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}};
  const auto triangles = syn::triangulatePolygon(u, {});
  ASSERT_EQ(triangles.size(), 6u);
  double area = 0.0;
  for (const auto& t : triangles)
    area += 0.5 * syn::twiceSignedArea({u[t[0]], u[t[1]], u[t[2]]});
  EXPECT_NEAR(area, 7.0, 1e-12);
  syn::Polygon2 clockwise(u.rbegin(), u.rend());
  EXPECT_THROW(syn::triangulatePolygon(clockwise, {}), visfeat::Error);
  EXPECT_THROW(syn::triangulatePolygon({{0, 0}, {1, 0}}, {}), visfeat::Error);
  const syn::Polygon2 outside{{5, 5}, {6, 5}, {6, 6}};
  EXPECT_THROW(syn::triangulatePolygon(u, {outside}), visfeat::Error);
}

TEST(CadTessellation, CircleSegments)
{
  EXPECT_EQ(syn::circleSegments(1.0, 10.0), 8);
  for (double radius : {0.1, 0.5, 1.0, 7.0})
    for (double tolerance : {1e-1, 1e-2, 1e-3, 1e-4}) {
      const int n = syn::circleSegments(radius, tolerance);
      EXPECT_GE(n, 8);
      // The chord's sagitta is within the tolerance, and one segment fewer is not.
      EXPECT_LE(radius * (1.0 - std::cos(kPi / n)), tolerance * (1.0 + 1e-12));
      if (n > 8) {
        EXPECT_GT(radius * (1.0 - std::cos(kPi / (n - 1))), tolerance);
      }
    }
  EXPECT_THROW(syn::circleSegments(1.0, 0.0), visfeat::Error);
  EXPECT_THROW(syn::circleSegments(1.0, -1.0), visfeat::Error);
  EXPECT_THROW(syn::circleSegments(1.0, std::nan("")), visfeat::Error);
  EXPECT_THROW(syn::circleSegments(1.0, 1e-15), visfeat::Error);
}

TEST(CadTessellation, AreaWithinTheChordBudget)
{
  for (const std::string& name : syn::cadModelNames())
    for (std::uint64_t seed : {0u, 3u})
      for (double tolerance : {0.02, 0.002}) {
        SCOPED_TRACE(name + " seed " + std::to_string(seed) + " tolerance " +
                     std::to_string(tolerance));
        const syn::CadModel m = model(name, seed);
        const syn::CadMesh mesh = syn::tessellateCadModel(m, tolerance);
        ASSERT_EQ(mesh.face.size(), mesh.mesh.triangles.size());
        std::vector<double> area(m.faces.size(), 0.0);
        for (std::size_t t = 0; t < mesh.face.size(); ++t) {
          ASSERT_GE(mesh.face[t], 0);
          ASSERT_LT(mesh.face[t], static_cast<int>(m.faces.size()));
          area[static_cast<std::size_t>(mesh.face[t])] += 0.5 * normal(mesh, t).norm();
        }
        double budget = 0.0;
        for (std::size_t f = 0; f < m.faces.size(); ++f) {
          const double face_budget = areaBudget(m, static_cast<int>(f), tolerance);
          budget += face_budget;
          EXPECT_NEAR(area[f], syn::faceArea(m, static_cast<int>(f)),
                      face_budget + 1e-12 * m.area())
            << "face " << f;
        }
        EXPECT_NEAR(visfeat::meshArea(mesh.mesh), m.area(), budget + 1e-12 * m.area());
      }
}

TEST(CadTessellation, FinerToleranceSmallerError)
{
  for (const std::string name : {"cylinder", "box_with_hole"}) {
    SCOPED_TRACE(name);
    const syn::CadModel m = model(name, 5);
    double previous = 0.0;
    for (double tolerance : {0.05, 0.01, 0.002}) {
      const double error = std::abs(
        visfeat::meshArea(syn::tessellateCadModel(m, tolerance).mesh) - m.area());
      EXPECT_GT(error, 0.0); // the circles are polygons
      if (previous > 0.0) {
        EXPECT_LT(error, 0.5 * previous);
      }
      previous = error;
    }
  }
}

/** Every edge in exactly two triangles, once in each direction; every vertex used; the
 * mesh's Euler characteristic is the model's. */
void
expectWatertight(const syn::CadModel& m, const syn::CadMesh& mesh)
{
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  std::set<std::pair<std::uint32_t, std::uint32_t>> undirected;
  for (const auto& t : mesh.mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = t[static_cast<std::size_t>(k)];
      const std::uint32_t b = t[static_cast<std::size_t>((k + 1) % 3)];
      ASSERT_NE(a, b);
      ++directed[{a, b}];
      undirected.insert({std::min(a, b), std::max(a, b)});
    }
  for (const auto& e : directed) {
    EXPECT_EQ(e.second, 1) << e.first.first << "-" << e.first.second;
    EXPECT_EQ(directed.count({e.first.second, e.first.first}), 1u)
      << e.first.first << "-" << e.first.second << " has one triangle";
  }
  std::set<std::uint32_t> used;
  for (const auto& t : mesh.mesh.triangles)
    used.insert(t.begin(), t.end());
  EXPECT_EQ(used.size(), mesh.mesh.vertices.size());
  const long chi = static_cast<long>(mesh.mesh.vertices.size()) -
                   static_cast<long>(undirected.size()) +
                   static_cast<long>(mesh.mesh.triangles.size());
  EXPECT_EQ(chi, syn::eulerCharacteristic(m));
}

TEST(CadTessellation, WatertightAndConsistentlyOriented)
{
  for (const std::string& name : syn::cadModelNames())
    for (std::uint64_t seed : {0u, 7u, 11u}) {
      SCOPED_TRACE(name + " seed " + std::to_string(seed));
      const syn::CadModel m = model(name, seed);
      expectWatertight(m, syn::tessellateCadModel(m, 0.01));
    }
}

TEST(CadTessellation, CircleAxesOfEitherSign)
{
  // The cylinder with its circles' axes flipped, one or both: the rings run the other
  // way and start half a turn away, the strip between them must still close.
  for (int flip : {1, 2, 3}) {
    SCOPED_TRACE("flip " + std::to_string(flip));
    syn::CadModel m = model("cylinder", 2);
    for (int c = 0; c < 2; ++c)
      if (flip & (1 << c))
        m.curves[static_cast<std::size_t>(c)].axis *= -1.0;
    ASSERT_NO_THROW(syn::checkCadModel(m));
    const syn::CadMesh mesh = syn::tessellateCadModel(m, 0.003);
    expectWatertight(m, mesh);
    EXPECT_NEAR(visfeat::meshArea(mesh.mesh), m.area(),
                areaBudget(m, 0, 0.003) + areaBudget(m, 1, 0.003) +
                  areaBudget(m, 2, 0.003));
    for (std::size_t t = 0; t < mesh.face.size(); ++t)
      if (mesh.face[t] == 2) { // the lateral face: normals away from the axis
        const Eigen::Vector3d centroid =
          (corner(mesh, t, 0) + corner(mesh, t, 1) + corner(mesh, t, 2)) / 3.0;
        const Eigen::Vector3d axis = m.curves[0].axis;
        const Eigen::Vector3d radial = centroid - centroid.dot(axis) * axis;
        EXPECT_GT(normal(mesh, t).normalized().dot(radial.normalized()), 0.99);
      }
  }
}

TEST(CadTessellation, NormalsAgreeWithTheFaces)
{
  for (const std::string& name : syn::cadModelNames())
    for (std::uint64_t seed : {0u, 9u}) {
      SCOPED_TRACE(name + " seed " + std::to_string(seed));
      const syn::CadModel m = model(name, seed);
      const syn::CadMesh mesh = syn::tessellateCadModel(m, 0.01);
      for (std::size_t t = 0; t < mesh.face.size(); ++t) {
        const syn::CadFace& f = m.faces[static_cast<std::size_t>(mesh.face[t])];
        const Eigen::Vector3d n = normal(mesh, t);
        ASSERT_GT(n.norm(), 0.0) << "triangle " << t << " is degenerate";
        const Eigen::Vector3d unit = n.normalized();
        for (int k = 0; k < 3; ++k) // every vertex on the exact face
          EXPECT_LT(syn::faceDistance(m, f.id, corner(mesh, t, k)), 1e-9);
        if (f.kind == syn::CadFace::Kind::kPlanar) {
          EXPECT_GT(unit.dot(f.normal), 1.0 - 1e-9) << "triangle " << t;
          continue;
        }
        // Away from the axis (a solid cylinder) or towards it (a hole's wall).
        const auto& c0 = m.curves[static_cast<std::size_t>(f.circles[0])];
        const Eigen::Vector3d axis = c0.axis.normalized();
        const Eigen::Vector3d centroid =
          (corner(mesh, t, 0) + corner(mesh, t, 1) + corner(mesh, t, 2)) / 3.0;
        Eigen::Vector3d radial = centroid - c0.centre;
        radial = (radial - radial.dot(axis) * axis).normalized();
        EXPECT_GT((f.hole ? -1.0 : 1.0) * unit.dot(radial), 0.99) << "triangle " << t;
        EXPECT_LT(std::abs(unit.dot(axis)), 1e-9);
      }
    }
}

TEST(CadTessellation, SharedCircleVerticesAndErrors)
{
  const syn::CadModel m = model("box_with_hole", 0);
  const double tolerance = 0.001;
  const syn::CadMesh mesh = syn::tessellateCadModel(m, tolerance);
  // The model's vertices first, then each circle's points once.
  std::size_t expected = m.vertices.size();
  for (const auto& c : m.curves)
    if (c.kind == syn::CadCurve::Kind::kCircle)
      expected += static_cast<std::size_t>(syn::circleSegments(c.radius, tolerance));
  ASSERT_EQ(mesh.mesh.vertices.size(), expected);
  for (std::size_t v = 0; v < m.vertices.size(); ++v)
    EXPECT_EQ(mesh.mesh.vertices[v], m.vertices[v]);
  EXPECT_THROW(syn::tessellateCadModel(m, 0.0), visfeat::Error);
  EXPECT_THROW(syn::tessellateCadModel(m, -0.1), visfeat::Error);
}

} // namespace
