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

/** A box of width x height x depth with a through-hole of `radius` along z (the
 * extrusion), at the centre of the width x height faces. */
CadModel
boxWithHole(
  const std::string& name, double width, double height, double depth, double radius)
{
  CadModel model = polyhedralModel(
    name, extrudedProfile({{0, 0}, {width, 0}, {width, height}, {0, height}}, depth));
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

/** The cell of a grid of 256 cells along 2 units, the longest side of the unrotated
 * small-feature models: their feature sizes are set in these cells. */
constexpr double kSmallFeatureCell = 2.0 / 256.0;

/** A 2 x 1.5 x 1 box whose four edges along z are chamfered at 45 degrees, the
 * chamfer faces 6, 10, 14 and 20 cells wide at 256 (an octagonal prism). */
CadModel
chamferedBox()
{
  const double w = 2.0, h = 1.5;
  double leg[4];
  const double widths[4] = {6.0, 10.0, 14.0, 20.0};
  for (int i = 0; i < 4; ++i)
    leg[i] = widths[i] * kSmallFeatureCell / std::sqrt(2.0);
  return prismModel("chamfered_box",
                    {{leg[0], 0},
                     {w - leg[1], 0},
                     {w, leg[1]},
                     {w, h - leg[2]},
                     {w - leg[2], h},
                     {leg[3], h},
                     {0, h - leg[3]},
                     {0, leg[0]}},
                    1.0);
}

/** A 2 x 0.6 x 1 block whose top carries three parallel creases 10 cells apart at 256
 * (turns of 30, 60 and 30 degrees: flat, up 30 degrees, down 30 degrees, flat),
 * extruded along z. */
CadModel
parallelCreases()
{
  const double length = 2.0, height = 0.6, first = 0.9;
  const double d = 10.0 * kSmallFeatureCell;
  const double rise = d * std::tan(30.0 * 3.14159265358979323846 / 180.0);
  return prismModel("parallel_creases",
                    {{0, 0},
                     {length, 0},
                     {length, height},
                     {first + 2 * d, height},
                     {first + d, height + rise},
                     {first, height},
                     {0, height}},
                    1.0);
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
  return {"stepped_block", "chamfered_box", "thin_plate_with_hole", "parallel_creases"};
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
    return boxWithHole(name, 2.0, 2.0, 1.5, 0.5);
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
  if (name == "chamfered_box")
    return chamferedBox();
  if (name == "thin_plate_with_hole")
    return boxWithHole(name, 2.0, 1.5, kSmallFeatureCell * 12.0, 0.3);
  if (name == "parallel_creases")
    return parallelCreases();
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
