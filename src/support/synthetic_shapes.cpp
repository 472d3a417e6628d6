#include <support/portable_random.h>
#include <support/synthetic_shapes.h>
#include <visfeat/core/common/error.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace visfeat {
namespace synthetic {
namespace {

/** A vertex set scaled to circumradius 1. */
std::vector<Eigen::Vector3d>
normalized(std::vector<Eigen::Vector3d> vertices)
{
  for (auto& v : vertices)
    v.normalize();
  return vertices;
}

} // namespace

PolygonMesh
convexHull(const std::vector<Eigen::Vector3d>& vertices)
{
  PolygonMesh mesh;
  mesh.vertices = vertices;
  const int n = static_cast<int>(vertices.size());
  std::vector<Eigen::Vector3d> normals;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      for (int k = j + 1; k < n; ++k) {
        Eigen::Vector3d normal =
          (vertices[j] - vertices[i]).cross(vertices[k] - vertices[i]);
        if (normal.norm() < 1e-9)
          continue;
        normal.normalize();
        // A face when every vertex is on one side; the normal then points away from
        // them (outwards).
        const double offset = normal.dot(vertices[i]);
        bool above = false, below = false;
        std::vector<int> on_plane;
        for (int m = 0; m < n; ++m) {
          const double h = normal.dot(vertices[m]) - offset;
          above = above || h > 1e-9;
          below = below || h < -1e-9;
          if (std::abs(h) < 1e-9)
            on_plane.push_back(m);
        }
        if (above && below)
          continue;
        if (above)
          normal = -normal;
        bool known = false;
        for (const auto& nrm : normals)
          known = known || (nrm - normal).norm() < 1e-9;
        if (!known) {
          mesh.faces.push_back(on_plane);
          normals.push_back(normal);
        }
      }
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    std::vector<int>& face = mesh.faces[f];
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (int v : face)
      centre += vertices[v];
    centre /= static_cast<double>(face.size());
    const Eigen::Vector3d u = (vertices[face[0]] - centre).normalized();
    const Eigen::Vector3d w = normals[f].cross(u);
    std::sort(face.begin(), face.end(), [&](int a, int b) {
      const Eigen::Vector3d pa = vertices[a] - centre, pb = vertices[b] - centre;
      return std::atan2(pa.dot(w), pa.dot(u)) < std::atan2(pb.dot(w), pb.dot(u));
    });
  }
  return mesh;
}

TriangleMesh
fanTriangulation(const PolygonMesh& mesh)
{
  TriangleMesh out;
  out.vertices = mesh.vertices;
  for (const std::vector<int>& face : mesh.faces)
    for (std::size_t t = 1; t + 1 < face.size(); ++t)
      out.triangles.push_back({face[0], face[t], face[t + 1]});
  return out;
}

double
TriangleMesh::area() const
{
  double sum = 0.0;
  for (const auto& t : triangles)
    sum +=
      0.5 *
      (vertices[t[1]] - vertices[t[0]]).cross(vertices[t[2]] - vertices[t[0]]).norm();
  return sum;
}

Eigen::AlignedBox3d
TriangleMesh::bounds() const
{
  Eigen::AlignedBox3d box;
  for (const auto& v : vertices)
    box.extend(v);
  return box;
}

std::vector<std::string>
shapeNames()
{
  return {"tetrahedron", "cube", "octahedron", "icosahedron"};
}

PolygonMesh
platonicSolid(const std::string& name)
{
  if (name == "tetrahedron")
    return convexHull(normalized({{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}}));
  if (name == "cube") {
    std::vector<Eigen::Vector3d> v;
    for (int i = 0; i < 8; ++i)
      v.emplace_back(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
    return convexHull(normalized(v));
  }
  if (name == "octahedron")
    return convexHull(normalized(
      {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}}));
  if (name == "icosahedron") {
    const double phi = (1.0 + std::sqrt(5.0)) / 2.0;
    std::vector<Eigen::Vector3d> v;
    for (int a : {-1, 1})
      for (int b : {-1, 1}) {
        v.emplace_back(0, a, b * phi);
        v.emplace_back(a, b * phi, 0);
        v.emplace_back(b * phi, 0, a);
      }
    return convexHull(normalized(v));
  }
  std::string known;
  for (const auto& n : shapeNames())
    known += (known.empty() ? "" : ", ") + n;
  throw Error("unknown shape '" + name + "' (known: " + known + ")");
}

TriangleMesh
tetrahedron()
{
  return fanTriangulation(platonicSolid("tetrahedron"));
}

TriangleMesh
cube()
{
  return fanTriangulation(platonicSolid("cube"));
}

TriangleMesh
octahedron()
{
  return fanTriangulation(platonicSolid("octahedron"));
}

TriangleMesh
icosahedron()
{
  return fanTriangulation(platonicSolid("icosahedron"));
}

TriangleMesh
shapeByName(const std::string& name)
{
  return fanTriangulation(platonicSolid(name));
}

Eigen::Matrix3d
randomRotation(std::uint64_t seed)
{
  std::mt19937_64 rng(seed);
  visfeat::synthetic::Normal normal;
  Eigen::Quaterniond q;
  do
    q.coeffs() << normal(rng), normal(rng), normal(rng), normal(rng);
  while (q.coeffs().norm() < 1e-6);
  return q.normalized().toRotationMatrix();
}

TriangleMesh
rotated(const TriangleMesh& mesh, const Eigen::Matrix3d& rotation)
{
  TriangleMesh out = mesh;
  for (auto& v : out.vertices)
    v = rotation * v;
  return out;
}

std::size_t
samplesForSpacing(const TriangleMesh& mesh, int resolution, double spacing_cells)
{
  const double cell = mesh.bounds().sizes().maxCoeff() / resolution;
  const double spacing = spacing_cells * cell;
  return static_cast<std::size_t>(std::ceil(mesh.area() / (spacing * spacing)));
}

std::vector<Eigen::Vector3f>
sampleSurface(const TriangleMesh& mesh, std::size_t count, std::uint64_t seed)
{
  std::vector<double> cumulative;
  double total = 0.0;
  for (const auto& t : mesh.triangles) {
    total += 0.5 * (mesh.vertices[t[1]] - mesh.vertices[t[0]])
                     .cross(mesh.vertices[t[2]] - mesh.vertices[t[0]])
                     .norm();
    cumulative.push_back(total);
  }
  std::vector<Eigen::Vector3f> points;
  if (cumulative.empty() || !(total > 0.0))
    return points;
  std::mt19937_64 rng(seed);
  visfeat::synthetic::UniformReal unit(0.0, 1.0);
  points.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    const double pick = unit(rng) * total;
    const std::size_t t = std::min<std::size_t>(
      static_cast<std::size_t>(
        std::lower_bound(cumulative.begin(), cumulative.end(), pick) -
        cumulative.begin()),
      cumulative.size() - 1);
    const double r1 = std::sqrt(unit(rng)), r2 = unit(rng);
    const auto& tri = mesh.triangles[t];
    const Eigen::Vector3d p = (1.0 - r1) * mesh.vertices[tri[0]] +
                              r1 * (1.0 - r2) * mesh.vertices[tri[1]] +
                              r1 * r2 * mesh.vertices[tri[2]];
    points.push_back(p.cast<float>());
  }
  return points;
}

} // namespace synthetic
} // namespace visfeat
