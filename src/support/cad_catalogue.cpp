#include <support/cad_catalogue.h>
#include <support/cad_frames.h>
#include <visfeat/core/common/error.h>

#include <cmath>
#include <map>
#include <utility>

namespace visfeat {
namespace synthetic {

using detail::Point2;
using detail::polygonEdges;
using detail::sortedPair;

namespace {

/** A right prism: the counter-clockwise profile (x, y) extruded along z over
 * [-depth/2, depth/2], centred on the profile's bounding rectangle. Faces: bottom, top,
 * then the side of profile edge i -> i+1. */
PolygonMesh
extrudedProfile(const std::vector<Point2>& profile, double depth)
{
  double x0 = profile[0].x, x1 = x0, y0 = profile[0].y, y1 = y0;
  for (const Point2& p : profile) {
    x0 = std::min(x0, p.x);
    x1 = std::max(x1, p.x);
    y0 = std::min(y0, p.y);
    y1 = std::max(y1, p.y);
  }
  const double cx = 0.5 * (x0 + x1), cy = 0.5 * (y0 + y1);
  const int n = static_cast<int>(profile.size());
  PolygonMesh mesh;
  for (double z : {-0.5 * depth, 0.5 * depth})
    for (const Point2& p : profile)
      mesh.vertices.emplace_back(p.x - cx, p.y - cy, z);
  std::vector<int> bottom, top;
  for (int i = 0; i < n; ++i) {
    bottom.push_back(n - 1 - i);
    top.push_back(n + i);
  }
  mesh.faces.push_back(bottom);
  mesh.faces.push_back(top);
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    mesh.faces.push_back({i, j, n + j, n + i});
  }
  return mesh;
}

CadModel
prismModel(const std::string& name, const std::vector<Point2>& profile, double depth)
{
  return polyhedralModel(name, extrudedProfile(profile, depth));
}

CadModel
boxWithHole()
{
  const double side = 2.0, depth = 1.5, radius = 0.5;
  CadModel model = polyhedralModel(
    "box_with_hole",
    extrudedProfile({{0, 0}, {side, 0}, {side, side}, {0, side}}, depth));
  // Faces 0 (bottom, z = -depth/2) and 1 (top) get the hole.
  const int wall = static_cast<int>(model.faces.size());
  for (int end = 0; end < 2; ++end) {
    CadCurve circle;
    circle.kind = CadCurve::Kind::kCircle;
    circle.id = static_cast<int>(model.curves.size());
    circle.centre = Eigen::Vector3d(0, 0, end == 0 ? -0.5 * depth : 0.5 * depth);
    circle.axis = Eigen::Vector3d::UnitZ();
    circle.radius = radius;
    circle.faces = {{end, wall}};
    model.faces[static_cast<std::size_t>(end)].circles.push_back(circle.id);
    model.curves.push_back(circle);
  }
  CadFace face;
  face.kind = CadFace::Kind::kCylindrical;
  face.id = wall;
  face.normal = Eigen::Vector3d::Zero();
  face.circles = {static_cast<int>(model.curves.size()) - 2,
                  static_cast<int>(model.curves.size()) - 1};
  face.hole = true;
  model.faces.push_back(face);
  checkCadModel(model);
  return model;
}

CadModel
cylinder()
{
  const double radius = 1.0, height = 2.0;
  CadModel model;
  model.name = "cylinder";
  for (int end = 0; end < 2; ++end) {
    CadCurve circle;
    circle.kind = CadCurve::Kind::kCircle;
    circle.id = end;
    circle.centre = Eigen::Vector3d(0, 0, end == 0 ? -0.5 * height : 0.5 * height);
    circle.axis = Eigen::Vector3d::UnitZ();
    circle.radius = radius;
    circle.faces = {{end, 2}};
    model.curves.push_back(circle);

    CadFace disc;
    disc.kind = CadFace::Kind::kPlanar;
    disc.id = end;
    disc.normal = Eigen::Vector3d(0, 0, end == 0 ? -1.0 : 1.0);
    disc.circles = {end};
    model.faces.push_back(disc);
  }
  CadFace lateral;
  lateral.kind = CadFace::Kind::kCylindrical;
  lateral.id = 2;
  lateral.normal = Eigen::Vector3d::Zero();
  lateral.circles = {0, 1};
  model.faces.push_back(lateral);
  checkCadModel(model);
  return model;
}

std::string
knownModels()
{
  std::string known;
  for (const auto& n : allCadModelNames())
    known += (known.empty() ? "" : ", ") + n;
  return known;
}

} // namespace

std::vector<std::string>
cadModelNames()
{
  return {"cube",    "tetrahedron",   "icosahedron", "triangular_prism",
          "u_prism", "box_with_hole", "cylinder"};
}

std::vector<std::string>
smallFeatureModelNames()
{
  return {"stepped_block"};
}

std::vector<std::string>
allCadModelNames()
{
  std::vector<std::string> names = cadModelNames();
  for (const std::string& name : smallFeatureModelNames())
    names.push_back(name);
  return names;
}

CadModel
cadModelByName(const std::string& name)
{
  if (name == "cube" || name == "tetrahedron" || name == "icosahedron")
    return polyhedralModel(name, platonicSolid(name));
  if (name == "triangular_prism")
    return prismModel(name, {{0, 0}, {2, 0}, {1, std::sqrt(3.0)}}, 2.0);
  if (name == "u_prism")
    return prismModel(
      name, {{0, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}}, 1.5);
  if (name == "box_with_hole")
    return boxWithHole();
  if (name == "cylinder")
    return cylinder();
  if (name == "stepped_block")
    return prismModel(name,
                      {{0, 0},
                       {1.8, 0},
                       {1.8, 0.15},
                       {1.2, 0.15},
                       {1.2, 0.3},
                       {0.6, 0.3},
                       {0.6, 0.45},
                       {0, 0.45}},
                      1.2);
  throw Error("unknown CAD model '" + name + "' (known: " + knownModels() + ")");
}

namespace {

[[noreturn]] void
failMesh(const std::string& name, const std::string& what)
{
  throw Error("polyhedral model '" + name + "': " + what);
}

/** Newell's normal of a mesh face (not normalised). */
Eigen::Vector3d
newellNormal(const PolygonMesh& mesh, const std::vector<int>& polygon)
{
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Eigen::Vector3d& a = mesh.vertices[static_cast<std::size_t>(polygon[i])];
    const Eigen::Vector3d& b =
      mesh.vertices[static_cast<std::size_t>(polygon[(i + 1) % polygon.size()])];
    normal += a.cross(b);
  }
  return normal;
}

/** The planar face of mesh face f; throws for a face of fewer than 3 vertices, a
 * vertex id out of range or a zero area. */
CadFace
meshFace(const std::string& name, const PolygonMesh& mesh, std::size_t f)
{
  const std::vector<int>& polygon = mesh.faces[f];
  const int vertex_count = static_cast<int>(mesh.vertices.size());
  const std::string face_name = "face " + std::to_string(f);
  if (polygon.size() < 3)
    failMesh(name, face_name + " has fewer than 3 vertices");
  for (int v : polygon)
    if (v < 0 || v >= vertex_count)
      failMesh(name,
               face_name + " has vertex id " + std::to_string(v) + " out of range");
  const Eigen::Vector3d normal = newellNormal(mesh, polygon);
  if (!(normal.norm() > 0.0))
    failMesh(name, face_name + " is degenerate (zero area)");
  CadFace face;
  face.kind = CadFace::Kind::kPlanar;
  face.id = static_cast<int>(f);
  face.normal = normal.normalized();
  face.polygon = polygon;
  return face;
}

/** The mesh's edges seen so far: the curve of each undirected edge, the face of each
 * directed one. */
struct MeshEdges
{
  std::map<std::pair<int, int>, int> curve_of;
  std::map<std::pair<int, int>, int> directed;
};

/** The face's boundary edges as curves: a new segment for an edge seen first, the
 * second face of one seen before. */
void
addFaceCurves(const std::string& name,
              const CadFace& face,
              MeshEdges& seen,
              CadModel& model)
{
  const std::string face_name = "face " + std::to_string(face.id);
  for (const auto& edge : polygonEdges(face)) {
    if (edge.first == edge.second)
      failMesh(name, face_name + " repeats vertex " + std::to_string(edge.first));
    if (!seen.directed.emplace(edge, face.id).second)
      failMesh(name, "edge " + std::to_string(edge.first) + "-" +
                       std::to_string(edge.second) +
                       " is traversed twice in the same direction (faces not "
                       "consistently oriented, or more than two faces on it)");
    const auto key = sortedPair(edge.first, edge.second);
    const auto it = seen.curve_of.find(key);
    if (it == seen.curve_of.end()) {
      CadCurve curve;
      curve.kind = CadCurve::Kind::kSegment;
      curve.id = static_cast<int>(model.curves.size());
      curve.vertices = {{edge.first, edge.second}};
      curve.faces = {{face.id, -1}};
      seen.curve_of.emplace(key, curve.id);
      model.curves.push_back(curve);
    } else {
      CadCurve& curve = model.curves[static_cast<std::size_t>(it->second)];
      if (curve.faces[1] >= 0)
        failMesh(name, "edge " + std::to_string(key.first) + "-" +
                         std::to_string(key.second) + " has more than two faces");
      curve.faces[1] = face.id;
    }
  }
}

/** Every edge has two faces, and they are not coplanar. */
void
checkSharpEdges(const std::string& name, const CadModel& model)
{
  for (const CadCurve& curve : model.curves) {
    const std::string edge_name = "edge " + std::to_string(curve.vertices[0]) + "-" +
                                  std::to_string(curve.vertices[1]);
    if (curve.faces[1] < 0)
      failMesh(name, edge_name + " has one face only (the mesh is not closed)");
    const Eigen::Vector3d& n0 =
      model.faces[static_cast<std::size_t>(curve.faces[0])].normal;
    const Eigen::Vector3d& n1 =
      model.faces[static_cast<std::size_t>(curve.faces[1])].normal;
    if (n0.dot(n1) > 1.0 - 1e-9)
      failMesh(name, edge_name + " lies between coplanar faces (not a sharp edge)");
  }
}

} // namespace

CadModel
polyhedralModel(const std::string& name, const PolygonMesh& mesh)
{
  CadModel model;
  model.name = name;
  model.vertices = mesh.vertices;
  MeshEdges seen;
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const CadFace face = meshFace(name, mesh, f);
    addFaceCurves(name, face, seen, model);
    model.faces.push_back(face);
  }
  checkSharpEdges(name, model);
  checkCadModel(model);
  return model;
}

} // namespace synthetic
} // namespace visfeat
