// Mesh input (mesh_sampling.h): area-weighted uniform sampling of triangles and the
// strict OFF reader.

#include <visfeat/core/common/error.h>
#include <visfeat/core/mesh/mesh_sampling.h>

#include <Eigen/Geometry>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace {

using visfeat::SurfaceMesh;

/** Three triangles of areas 0.5, 2 and 0 (degenerate), and a fourth of area 4.5. */
SurfaceMesh
unequalTriangles()
{
  SurfaceMesh mesh;
  mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0},  // area 0.5
                   {0, 0, 1}, {2, 0, 1}, {0, 2, 1},  // area 2
                   {5, 5, 5}, {6, 6, 6}, {7, 7, 7},  // collinear: area 0
                   {0, 0, 3}, {0, 3, 3}, {3, 0, 3}}; // area 4.5
  mesh.triangles = {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}, {9, 10, 11}};
  return mesh;
}

/** Distance of p to the plane of triangle t and its barycentric coordinates. */
void
barycentric(const SurfaceMesh& mesh,
            std::uint32_t t,
            const Eigen::Vector3d& p,
            double& plane_distance,
            Eigen::Vector3d& weights)
{
  const Eigen::Vector3d& a = mesh.vertices[mesh.triangles[t][0]];
  const Eigen::Vector3d& b = mesh.vertices[mesh.triangles[t][1]];
  const Eigen::Vector3d& c = mesh.vertices[mesh.triangles[t][2]];
  const Eigen::Vector3d n = (b - a).cross(c - a);
  plane_distance = std::abs((p - a).dot(n.normalized()));
  const double area2 = n.norm();
  weights.x() = (b - p).cross(c - p).dot(n) / (area2 * area2);
  weights.y() = (c - p).cross(a - p).dot(n) / (area2 * area2);
  weights.z() = 1.0 - weights.x() - weights.y();
}

TEST(MeshSampling, AreaOfTrianglesAndMesh)
{
  const SurfaceMesh mesh = unequalTriangles();
  EXPECT_DOUBLE_EQ(visfeat::meshArea(mesh), 7.0);
  EXPECT_DOUBLE_EQ(visfeat::triangleArea({0, 0, 0}, {2, 0, 0}, {0, 3, 0}), 3.0);
}

TEST(MeshSampling, ClosedMeshes)
{
  SurfaceMesh tetrahedron;
  tetrahedron.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  tetrahedron.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  EXPECT_TRUE(visfeat::meshIsClosed(tetrahedron));
  // a degenerate triangle changes nothing
  SurfaceMesh with_degenerate = tetrahedron;
  with_degenerate.triangles.push_back({0, 0, 1});
  EXPECT_TRUE(visfeat::meshIsClosed(with_degenerate));
  // one face removed: three border edges
  SurfaceMesh open = tetrahedron;
  open.triangles.pop_back();
  EXPECT_FALSE(visfeat::meshIsClosed(open));
  // the same triangles as a soup (each its own vertices): open, coincident vertices
  // are not merged
  SurfaceMesh soup;
  for (const auto& t : tetrahedron.triangles) {
    const auto base = static_cast<std::uint32_t>(soup.vertices.size());
    for (const std::uint32_t v : t)
      soup.vertices.push_back(tetrahedron.vertices[v]);
    soup.triangles.push_back({base, base + 1, base + 2});
  }
  EXPECT_FALSE(visfeat::meshIsClosed(soup));
  EXPECT_FALSE(visfeat::meshIsClosed(SurfaceMesh{}));
  EXPECT_FALSE(visfeat::meshIsClosed(unequalTriangles()));
}

TEST(MeshSampling, PointsLieOnTheirTriangles)
{
  const SurfaceMesh mesh = unequalTriangles();
  const auto samples = visfeat::sampleMesh(mesh, 20000, 7);
  ASSERT_EQ(samples.size(), 20000u);
  for (const auto& s : samples) {
    ASSERT_LT(s.triangle, mesh.triangles.size());
    double distance = 0.0;
    Eigen::Vector3d w;
    barycentric(mesh, s.triangle, s.position.cast<double>(), distance, w);
    ASSERT_LT(distance, 1e-6);
    ASSERT_GE(w.minCoeff(), -1e-6) << "outside triangle " << s.triangle;
  }
}

TEST(MeshSampling, CountsProportionalToAreaDegenerateGetNone)
{
  const SurfaceMesh mesh = unequalTriangles();
  const std::size_t n = 70000;
  const auto samples = visfeat::sampleMesh(mesh, n, 11);
  std::vector<std::size_t> counts(mesh.triangles.size(), 0);
  for (const auto& s : samples)
    ++counts[s.triangle];
  EXPECT_EQ(counts[2], 0u) << "the degenerate triangle received samples";
  const double areas[] = {0.5, 2.0, 0.0, 4.5};
  for (std::size_t t : {0u, 1u, 3u}) {
    // Binomial: mean n p, standard deviation sqrt(n p (1 - p)); allow 5 sigma.
    const double p = areas[t] / 7.0;
    const double mean = n * p, sigma = std::sqrt(n * p * (1.0 - p));
    EXPECT_NEAR(static_cast<double>(counts[t]), mean, 5.0 * sigma) << "triangle " << t;
  }
}

TEST(MeshSampling, UniformWithinATriangle)
{
  // The corner x + y <= 2 of the triangle (0,0) (4,0) (0,4) holds 1/4 of its area, so
  // uniform samples fall there with probability 1/4 (a sampler without the sqrt
  // would put half of them there).
  SurfaceMesh mesh;
  mesh.vertices = {{0, 0, 0}, {4, 0, 0}, {0, 4, 0}};
  mesh.triangles = {{0, 1, 2}};
  const std::size_t n = 40000;
  const auto samples = visfeat::sampleMesh(mesh, n, 3);
  std::size_t near_vertex0 = 0;
  for (const auto& s : samples)
    if (s.position.x() + s.position.y() <= 2.0f)
      ++near_vertex0;
  const double p = 0.25, sigma = std::sqrt(n * p * (1.0 - p));
  EXPECT_NEAR(static_cast<double>(near_vertex0), n * p, 5.0 * sigma);
}

TEST(MeshSampling, DeterministicForASeed)
{
  const SurfaceMesh mesh = unequalTriangles();
  const auto a = visfeat::sampleMesh(mesh, 1000, 42);
  const auto b = visfeat::sampleMesh(mesh, 1000, 42);
  const auto c = visfeat::sampleMesh(mesh, 1000, 43);
  ASSERT_EQ(a.size(), b.size());
  std::size_t differ = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].triangle, b[i].triangle);
    EXPECT_EQ(a[i].position, b[i].position);
    differ += a[i].position != c[i].position;
  }
  EXPECT_GT(differ, 900u) << "another seed should give other samples";
}

TEST(MeshSampling, RefusesBadMeshes)
{
  SurfaceMesh nan_vertex = unequalTriangles();
  nan_vertex.vertices[4].y() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(visfeat::sampleMesh(nan_vertex, 10, 1), visfeat::Error);

  SurfaceMesh bad_index = unequalTriangles();
  bad_index.triangles[1][2] = 12;
  EXPECT_THROW(visfeat::sampleMesh(bad_index, 10, 1), visfeat::Error);

  SurfaceMesh no_triangles = unequalTriangles();
  no_triangles.triangles.clear();
  EXPECT_THROW(visfeat::sampleMesh(no_triangles, 10, 1), visfeat::Error);

  SurfaceMesh flat = unequalTriangles();
  flat.triangles = {{6, 7, 8}, {0, 0, 1}};
  try {
    visfeat::sampleMesh(flat, 10, 1);
    FAIL() << "a zero-area mesh was sampled";
  } catch (const visfeat::Error& e) {
    EXPECT_NE(std::string(e.what()).find("zero area"), std::string::npos) << e.what();
  }
}

TEST(MeshSampling, SamplesForSpacing)
{
  EXPECT_EQ(visfeat::samplesForSpacing(6.0, 0.01, 1000000), 60000u);
  EXPECT_EQ(visfeat::samplesForSpacing(1.0, 0.3, 100), 12u); // ceil(11.1)
  EXPECT_THROW(visfeat::samplesForSpacing(6.0, 0.0, 100), visfeat::Error);
  EXPECT_THROW(visfeat::samplesForSpacing(6.0, -1.0, 100), visfeat::Error);
  EXPECT_THROW(visfeat::samplesForSpacing(0.0, 1.0, 100), visfeat::Error);
  EXPECT_THROW(visfeat::samplesForSpacing(6.0, 1e-6, 1000), visfeat::Error);
}

SurfaceMesh
readOffText(const std::string& text)
{
  std::istringstream in(text);
  return visfeat::readOff(in);
}

std::string
offError(const std::string& text)
{
  try {
    readOffText(text);
  } catch (const visfeat::Error& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(OffReader, ReadsPolygonsAndComments)
{
  const SurfaceMesh mesh = readOffText("OFF\n# a unit square and a triangle\n"
                                       "5 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n\n"
                                       "0.5 0.5 1e0 # apex\n"
                                       "4 0 1 2 3\n3 0 1 4 255 0 0\n");
  ASSERT_EQ(mesh.vertices.size(), 5u);
  ASSERT_EQ(mesh.triangles.size(), 3u);
  EXPECT_EQ(mesh.triangles[0], (std::array<std::uint32_t, 3>{0, 1, 2}));
  EXPECT_EQ(mesh.triangles[1], (std::array<std::uint32_t, 3>{0, 2, 3}));
  EXPECT_EQ(mesh.vertices[4], Eigen::Vector3d(0.5, 0.5, 1.0));
  EXPECT_DOUBLE_EQ(visfeat::meshArea(mesh), 1.0 + std::sqrt(1.25) / 2.0);

  const SurfaceMesh same_line =
    readOffText("OFF 3 1 3\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  EXPECT_EQ(same_line.triangles.size(), 1u);
}

TEST(OffReader, RefusesBrokenFiles)
{
  const std::string head = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n";
  struct Case
  {
    std::string text, expected;
  };
  const std::vector<Case> cases{
    {"", "empty"},
    {"ply\nformat ascii 1.0\n", "not an OFF file"},
    {"COFF\n3 1 0\n", "not an OFF file"},
    {"OFF\n", "no vertex and face counts"},
    {"OFF\n3 x 0\n", "counts"},
    {"OFF\n-3 1 0\n", "counts"},
    {"OFF\n3 1 0\n0 0 0\n1 0 0\n", "ends after 2 of 3 vertices"},
    {"OFF\n3 1 0\n0 0 0\n1 0\n0 1 0\n3 0 1 2\n", "line 4: vertex 1"},
    {"OFF\n3 1 0\n0 0 0\n1 0 zero\n0 1 0\n3 0 1 2\n", "vertex 1"},
    {"OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n", "NaN"},
    {head, "ends after 0 of 1 faces"},
    {head + "3 0 1 7\n", "vertex index 7 out of range"},
    {head + "2 0 1\n", "vertex count >= 3"},
    {head + "3 0 1\n", "expected 3 vertex indices"},
    {head + "3 0 -1 2\n", "bad vertex index"},
    {head + "3 0 1 2\n0 0 0\n", "after the last face"},
  };
  for (const Case& c : cases) {
    const std::string message = offError(c.text);
    EXPECT_NE(message.find(c.expected), std::string::npos)
      << "input:\n"
      << c.text << "\nmessage: " << message << "\nexpected: " << c.expected;
  }
}

} // namespace
