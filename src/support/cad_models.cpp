#include <support/cad_models.h>
#include <support/portable_random.h>
#include <visfeat/core/common/error.h>

#include <core/common/json_document.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <map>
#include <random>
#include <sstream>
#include <utility>

namespace visfeat {
namespace synthetic {
namespace {

constexpr double kPi = 3.14159265358979323846;

/** A point of a face's plane in the face's 2D frame (no Eigen alignment concerns). */
struct Point2
{
  double x = 0.0;
  double y = 0.0;
};

double
segmentDistance(const Eigen::Vector3d& a,
                const Eigen::Vector3d& b,
                const Eigen::Vector3d& p)
{
  const Eigen::Vector3d d = b - a;
  const double length2 = d.squaredNorm();
  double t = length2 > 0.0 ? (p - a).dot(d) / length2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return (a + t * d - p).norm();
}

double
circleDistance(const Eigen::Vector3d& centre,
               const Eigen::Vector3d& axis,
               double radius,
               const Eigen::Vector3d& p)
{
  const Eigen::Vector3d q = p - centre;
  const double h = q.dot(axis);
  const double rho = (q - h * axis).norm();
  return std::hypot(h, rho - radius);
}

/** Even-odd rule; points on the boundary may go either way (measure zero). */
bool
insidePolygon(const std::vector<Point2>& polygon, const Point2& q)
{
  bool inside = false;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const Point2& a = polygon[i];
    const Point2& b = polygon[j];
    if ((a.y > q.y) != (b.y > q.y) &&
        q.x < (b.x - a.x) * (q.y - a.y) / (b.y - a.y) + a.x)
      inside = !inside;
  }
  return inside;
}

/** A planar face in its own orthonormal frame (u, v, normal), u x v = normal. */
struct PlanarFrame
{
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d u = Eigen::Vector3d::UnitX();
  Eigen::Vector3d v = Eigen::Vector3d::UnitY();
  std::vector<Point2> polygon; // empty for a disc
  std::vector<Point2> centres; // the face's circles, in CadFace::circles order
  std::vector<double> radii;
  Point2 lo, hi; // bounding rectangle of the outer boundary

  Point2 project(const Eigen::Vector3d& p) const
  {
    const Eigen::Vector3d q = p - origin;
    return {q.dot(u), q.dot(v)};
  }

  Eigen::Vector3d lift(const Point2& q) const { return origin + q.x * u + q.y * v; }

  bool contains(const Point2& q) const
  {
    std::size_t first_hole = 0;
    if (polygon.empty()) {
      if (centres.empty() ||
          std::hypot(q.x - centres[0].x, q.y - centres[0].y) > radii[0])
        return false;
      first_hole = 1;
    } else if (!insidePolygon(polygon, q))
      return false;
    for (std::size_t c = first_hole; c < centres.size(); ++c)
      if (std::hypot(q.x - centres[c].x, q.y - centres[c].y) < radii[c])
        return false;
    return true;
  }

  /** Signed area of the outer boundary (positive: counter-clockwise about normal). */
  double outerArea() const
  {
    if (polygon.empty())
      return radii.empty() ? 0.0 : kPi * radii[0] * radii[0];
    double twice = 0.0;
    for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++)
      twice += polygon[j].x * polygon[i].y - polygon[i].x * polygon[j].y;
    return 0.5 * twice;
  }
};

PlanarFrame
planarFrame(const CadModel& model, const CadFace& face)
{
  PlanarFrame frame;
  frame.normal = face.normal.normalized();
  if (!face.polygon.empty())
    frame.origin = model.vertices[static_cast<std::size_t>(face.polygon[0])];
  else if (!face.circles.empty())
    frame.origin = model.curves[static_cast<std::size_t>(face.circles[0])].centre;
  frame.u = frame.normal.unitOrthogonal();
  frame.v = frame.normal.cross(frame.u);
  for (int id : face.polygon)
    frame.polygon.push_back(
      frame.project(model.vertices[static_cast<std::size_t>(id)]));
  for (int id : face.circles) {
    const CadCurve& circle = model.curves[static_cast<std::size_t>(id)];
    frame.centres.push_back(frame.project(circle.centre));
    frame.radii.push_back(circle.radius);
  }
  const double inf = std::numeric_limits<double>::infinity();
  frame.lo = {inf, inf};
  frame.hi = {-inf, -inf};
  auto extend = [&](const Point2& p, double r) {
    frame.lo = {std::min(frame.lo.x, p.x - r), std::min(frame.lo.y, p.y - r)};
    frame.hi = {std::max(frame.hi.x, p.x + r), std::max(frame.hi.y, p.y + r)};
  };
  if (frame.polygon.empty()) {
    if (!frame.centres.empty())
      extend(frame.centres[0], frame.radii[0]);
  } else
    for (const Point2& p : frame.polygon)
      extend(p, 0.0);
  return frame;
}

/** The lateral patch of a finite cylinder: base + t axis + radius (cos a e1 + sin a
 * e2), t in [0, height]. */
struct CylinderFrame
{
  Eigen::Vector3d base = Eigen::Vector3d::Zero();
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d e1 = Eigen::Vector3d::UnitX();
  Eigen::Vector3d e2 = Eigen::Vector3d::UnitY();
  double radius = 0.0;
  double height = 0.0;
};

CylinderFrame
cylinderFrame(const CadModel& model, const CadFace& face)
{
  CylinderFrame frame;
  const CadCurve& c0 = model.curves[static_cast<std::size_t>(face.circles[0])];
  const CadCurve& c1 = model.curves[static_cast<std::size_t>(face.circles[1])];
  const Eigen::Vector3d d = c1.centre - c0.centre;
  frame.base = c0.centre;
  frame.height = d.norm();
  frame.axis = frame.height > 0.0 ? Eigen::Vector3d(d / frame.height)
                                  : Eigen::Vector3d(c0.axis.normalized());
  frame.e1 = frame.axis.unitOrthogonal();
  frame.e2 = frame.axis.cross(frame.e1);
  frame.radius = c0.radius;
  return frame;
}

/** The consecutive vertex pairs of a face's polygon. */
std::vector<std::pair<int, int>>
polygonEdges(const CadFace& face)
{
  std::vector<std::pair<int, int>> edges;
  const std::size_t n = face.polygon.size();
  for (std::size_t i = 0; i < n; ++i)
    edges.emplace_back(face.polygon[i], face.polygon[(i + 1) % n]);
  return edges;
}

std::pair<int, int>
sortedPair(int a, int b)
{
  return {std::min(a, b), std::max(a, b)};
}

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
  for (const auto& n : cadModelNames())
    known += (known.empty() ? "" : ", ") + n;
  return known;
}

} // namespace

Eigen::AlignedBox3d
CadModel::bounds() const
{
  Eigen::AlignedBox3d box;
  for (const auto& v : vertices)
    box.extend(v);
  for (const CadCurve& c : curves) {
    if (c.kind != CadCurve::Kind::kCircle)
      continue;
    const Eigen::Vector3d a = c.axis.normalized();
    Eigen::Vector3d half;
    for (int i = 0; i < 3; ++i)
      half[i] = c.radius * std::sqrt(std::max(0.0, 1.0 - a[i] * a[i]));
    box.extend(Eigen::Vector3d(c.centre - half));
    box.extend(Eigen::Vector3d(c.centre + half));
  }
  return box;
}

double
CadModel::area() const
{
  double sum = 0.0;
  for (std::size_t f = 0; f < faces.size(); ++f)
    sum += faceArea(*this, static_cast<int>(f));
  return sum;
}

std::vector<std::string>
cadModelNames()
{
  return {"cube",    "tetrahedron",   "icosahedron", "triangular_prism",
          "u_prism", "box_with_hole", "cylinder"};
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
  throw Error("unknown CAD model '" + name + "' (known: " + knownModels() + ")");
}

CadModel
polyhedralModel(const std::string& name, const PolygonMesh& mesh)
{
  const auto fail = [&](const std::string& what) {
    throw Error("polyhedral model '" + name + "': " + what);
  };
  CadModel model;
  model.name = name;
  model.vertices = mesh.vertices;
  const int vertex_count = static_cast<int>(mesh.vertices.size());
  std::map<std::pair<int, int>, int> curve_of;
  std::map<std::pair<int, int>, int> directed;
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    const std::vector<int>& polygon = mesh.faces[f];
    const std::string face_name = "face " + std::to_string(f);
    if (polygon.size() < 3)
      fail(face_name + " has fewer than 3 vertices");
    for (int v : polygon)
      if (v < 0 || v >= vertex_count)
        fail(face_name + " has vertex id " + std::to_string(v) + " out of range");
    // Newell's normal.
    Eigen::Vector3d normal = Eigen::Vector3d::Zero();
    for (std::size_t i = 0; i < polygon.size(); ++i) {
      const Eigen::Vector3d& a = mesh.vertices[static_cast<std::size_t>(polygon[i])];
      const Eigen::Vector3d& b =
        mesh.vertices[static_cast<std::size_t>(polygon[(i + 1) % polygon.size()])];
      normal += a.cross(b);
    }
    if (!(normal.norm() > 0.0))
      fail(face_name + " is degenerate (zero area)");
    CadFace face;
    face.kind = CadFace::Kind::kPlanar;
    face.id = static_cast<int>(f);
    face.normal = normal.normalized();
    face.polygon = polygon;
    for (const auto& edge : polygonEdges(face)) {
      if (edge.first == edge.second)
        fail(face_name + " repeats vertex " + std::to_string(edge.first));
      if (!directed.emplace(edge, face.id).second)
        fail("edge " + std::to_string(edge.first) + "-" + std::to_string(edge.second) +
             " is traversed twice in the same direction (faces not consistently "
             "oriented, or more than two faces on it)");
      const auto key = sortedPair(edge.first, edge.second);
      const auto it = curve_of.find(key);
      if (it == curve_of.end()) {
        CadCurve curve;
        curve.kind = CadCurve::Kind::kSegment;
        curve.id = static_cast<int>(model.curves.size());
        curve.vertices = {{edge.first, edge.second}};
        curve.faces = {{face.id, -1}};
        curve_of.emplace(key, curve.id);
        model.curves.push_back(curve);
      } else {
        CadCurve& curve = model.curves[static_cast<std::size_t>(it->second)];
        if (curve.faces[1] >= 0)
          fail("edge " + std::to_string(key.first) + "-" + std::to_string(key.second) +
               " has more than two faces");
        curve.faces[1] = face.id;
      }
    }
    model.faces.push_back(face);
  }
  for (const CadCurve& curve : model.curves) {
    const std::string edge_name = "edge " + std::to_string(curve.vertices[0]) + "-" +
                                  std::to_string(curve.vertices[1]);
    if (curve.faces[1] < 0)
      fail(edge_name + " has one face only (the mesh is not closed)");
    const Eigen::Vector3d& n0 =
      model.faces[static_cast<std::size_t>(curve.faces[0])].normal;
    const Eigen::Vector3d& n1 =
      model.faces[static_cast<std::size_t>(curve.faces[1])].normal;
    if (n0.dot(n1) > 1.0 - 1e-9)
      fail(edge_name + " lies between coplanar faces (not a sharp edge)");
  }
  checkCadModel(model);
  return model;
}

void
checkCadModel(const CadModel& model)
{
  const auto fail = [&](const std::string& what) {
    throw Error("CAD model '" + model.name + "': " + what);
  };
  const int vertex_count = static_cast<int>(model.vertices.size());
  const int curve_count = static_cast<int>(model.curves.size());
  const int face_count = static_cast<int>(model.faces.size());
  for (const auto& v : model.vertices)
    if (!v.allFinite())
      fail("a vertex is not finite");
  const double tolerance = 1e-9 * std::max(1.0, model.bounds().sizes().maxCoeff());

  std::map<std::pair<int, int>, int> segment_of;
  for (int c = 0; c < curve_count; ++c) {
    const CadCurve& curve = model.curves[static_cast<std::size_t>(c)];
    const std::string curve_name = "curve " + std::to_string(c);
    if (curve.id != c)
      fail(curve_name + " has id " + std::to_string(curve.id));
    for (int f : curve.faces)
      if (f < 0 || f >= face_count)
        fail(curve_name + " has face id " + std::to_string(f) + " out of range");
    if (curve.faces[0] == curve.faces[1])
      fail(curve_name + " separates a face from itself");
    if (curve.kind == CadCurve::Kind::kSegment) {
      for (int v : curve.vertices)
        if (v < 0 || v >= vertex_count)
          fail(curve_name + " has vertex id " + std::to_string(v) + " out of range");
      if ((model.vertices[static_cast<std::size_t>(curve.vertices[0])] -
           model.vertices[static_cast<std::size_t>(curve.vertices[1])])
            .norm() <= tolerance)
        fail(curve_name + " has zero length");
      if (!segment_of.emplace(sortedPair(curve.vertices[0], curve.vertices[1]), c)
             .second)
        fail(curve_name + " duplicates another segment");
    } else {
      if (curve.vertices[0] != -1 || curve.vertices[1] != -1)
        fail(curve_name + " is a circle with vertices");
      if (!(curve.radius > 0.0) || !std::isfinite(curve.radius) ||
          !curve.centre.allFinite() || std::abs(curve.axis.norm() - 1.0) > 1e-9)
        fail(curve_name + " is a circle with a bad centre, axis or radius");
    }
  }

  const auto boundedBy = [&](const CadFace& face, const CadCurve& curve) {
    if (curve.kind == CadCurve::Kind::kCircle)
      return std::find(face.circles.begin(), face.circles.end(), curve.id) !=
             face.circles.end();
    for (const auto& edge : polygonEdges(face))
      if (sortedPair(edge.first, edge.second) ==
          sortedPair(curve.vertices[0], curve.vertices[1]))
        return true;
    return false;
  };

  for (int f = 0; f < face_count; ++f) {
    const CadFace& face = model.faces[static_cast<std::size_t>(f)];
    const std::string face_name = "face " + std::to_string(f);
    if (face.id != f)
      fail(face_name + " has id " + std::to_string(face.id));
    for (int c : face.circles)
      if (c < 0 || c >= curve_count ||
          model.curves[static_cast<std::size_t>(c)].kind != CadCurve::Kind::kCircle)
        fail(face_name + " lists curve " + std::to_string(c) + " as a circle");
    for (int v : face.polygon)
      if (v < 0 || v >= vertex_count)
        fail(face_name + " has vertex id " + std::to_string(v) + " out of range");
    if (face.kind == CadFace::Kind::kPlanar) {
      if (std::abs(face.normal.norm() - 1.0) > 1e-9)
        fail(face_name + " has a normal that is not a unit vector");
      if (face.polygon.empty() ? face.circles.empty() : face.polygon.size() < 3)
        fail(face_name + " has no outer boundary");
      const PlanarFrame frame = planarFrame(model, face);
      for (int v : face.polygon)
        if (std::abs(face.normal.dot(model.vertices[static_cast<std::size_t>(v)] -
                                     frame.origin)) > tolerance)
          fail(face_name + " is not planar");
      for (int c : face.circles) {
        const CadCurve& circle = model.curves[static_cast<std::size_t>(c)];
        if (std::abs(face.normal.dot(circle.centre - frame.origin)) > tolerance ||
            face.normal.cross(circle.axis).norm() > 1e-9)
          fail(face_name + ": circle " + std::to_string(c) + " is not in its plane");
      }
      if (!(frame.outerArea() > 0.0))
        fail(face_name + " is not counter-clockwise about its normal");
    } else {
      if (face.circles.size() != 2 || !face.polygon.empty())
        fail(face_name + " is a cylinder without exactly two circles");
      const CadCurve& c0 = model.curves[static_cast<std::size_t>(face.circles[0])];
      const CadCurve& c1 = model.curves[static_cast<std::size_t>(face.circles[1])];
      const Eigen::Vector3d d = c1.centre - c0.centre;
      if (std::abs(c0.radius - c1.radius) > tolerance || d.norm() <= tolerance ||
          c0.axis.cross(c1.axis).norm() > 1e-9 ||
          c0.axis.cross(d.normalized()).norm() > 1e-9)
        fail(face_name + " is a cylinder between circles that are not coaxial with "
                         "one radius");
    }
    // Face -> curve: every boundary element is a curve that lists this face.
    for (const auto& edge : polygonEdges(face)) {
      const auto it = segment_of.find(sortedPair(edge.first, edge.second));
      if (it == segment_of.end())
        fail(face_name + ": boundary edge " + std::to_string(edge.first) + "-" +
             std::to_string(edge.second) + " is not a curve");
      const CadCurve& curve = model.curves[static_cast<std::size_t>(it->second)];
      if (curve.faces[0] != f && curve.faces[1] != f)
        fail(face_name + ": curve " + std::to_string(curve.id) +
             " does not list the face");
    }
    for (int c : face.circles) {
      const CadCurve& curve = model.curves[static_cast<std::size_t>(c)];
      if (curve.faces[0] != f && curve.faces[1] != f)
        fail(face_name + ": circle " + std::to_string(c) + " does not list the face");
    }
  }
  // Curve -> face: each of its faces has it on its boundary.
  for (const CadCurve& curve : model.curves)
    for (int f : curve.faces)
      if (!boundedBy(model.faces[static_cast<std::size_t>(f)], curve))
        fail("curve " + std::to_string(curve.id) + " is not on the boundary of face " +
             std::to_string(f));
}

CadModel
rotated(const CadModel& model, const Eigen::Matrix3d& rotation)
{
  CadModel out = model;
  for (auto& v : out.vertices)
    v = rotation * v;
  for (CadCurve& c : out.curves) {
    c.centre = rotation * c.centre;
    c.axis = rotation * c.axis;
  }
  for (CadFace& f : out.faces)
    f.normal = rotation * f.normal;
  return out;
}

double
faceArea(const CadModel& model, int face)
{
  const CadFace& f = model.faces.at(static_cast<std::size_t>(face));
  if (f.kind == CadFace::Kind::kCylindrical) {
    const CylinderFrame frame = cylinderFrame(model, f);
    return 2.0 * kPi * frame.radius * frame.height;
  }
  const PlanarFrame frame = planarFrame(model, f);
  double area = std::abs(frame.outerArea());
  for (std::size_t c = frame.polygon.empty() ? 1 : 0; c < frame.radii.size(); ++c)
    area -= kPi * frame.radii[c] * frame.radii[c];
  return area;
}

double
curveLength(const CadModel& model, int curve)
{
  const CadCurve& c = model.curves.at(static_cast<std::size_t>(curve));
  if (c.kind == CadCurve::Kind::kCircle)
    return 2.0 * kPi * c.radius;
  return (model.vertices[static_cast<std::size_t>(c.vertices[1])] -
          model.vertices[static_cast<std::size_t>(c.vertices[0])])
    .norm();
}

double
curveDistance(const CadModel& model, int curve, const Eigen::Vector3d& p)
{
  const CadCurve& c = model.curves.at(static_cast<std::size_t>(curve));
  if (c.kind == CadCurve::Kind::kCircle)
    return circleDistance(c.centre, c.axis, c.radius, p);
  return segmentDistance(model.vertices[static_cast<std::size_t>(c.vertices[0])],
                         model.vertices[static_cast<std::size_t>(c.vertices[1])], p);
}

double
curveDistance(const CadModel& model, const Eigen::Vector3d& p)
{
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t c = 0; c < model.curves.size(); ++c)
    best = std::min(best, curveDistance(model, static_cast<int>(c), p));
  return best;
}

double
faceDistance(const CadModel& model, int face, const Eigen::Vector3d& p)
{
  const CadFace& f = model.faces.at(static_cast<std::size_t>(face));
  double best = std::numeric_limits<double>::infinity();
  for (int c : f.circles)
    best = std::min(best, curveDistance(model, c, p));
  if (f.kind == CadFace::Kind::kCylindrical) {
    const CylinderFrame frame = cylinderFrame(model, f);
    const Eigen::Vector3d q = p - frame.base;
    const double t = q.dot(frame.axis);
    if (t >= 0.0 && t <= frame.height)
      return std::abs((q - t * frame.axis).norm() - frame.radius);
    return best; // beyond an end: the nearest point is on an end circle
  }
  const PlanarFrame frame = planarFrame(model, f);
  if (frame.contains(frame.project(p)))
    return std::abs(frame.normal.dot(p - frame.origin));
  for (const auto& edge : polygonEdges(f))
    best = std::min(
      best, segmentDistance(model.vertices[static_cast<std::size_t>(edge.first)],
                            model.vertices[static_cast<std::size_t>(edge.second)], p));
  return best;
}

std::vector<std::vector<int>>
vertexCurves(const CadModel& model)
{
  std::vector<std::vector<int>> out(model.vertices.size());
  for (const CadCurve& c : model.curves)
    if (c.kind == CadCurve::Kind::kSegment)
      for (int v : c.vertices)
        out[static_cast<std::size_t>(v)].push_back(c.id);
  for (auto& list : out)
    std::sort(list.begin(), list.end());
  return out;
}

std::vector<std::vector<int>>
vertexFaces(const CadModel& model)
{
  std::vector<std::vector<int>> out(model.vertices.size());
  for (const CadCurve& c : model.curves)
    if (c.kind == CadCurve::Kind::kSegment)
      for (int v : c.vertices)
        for (int f : c.faces)
          out[static_cast<std::size_t>(v)].push_back(f);
  for (auto& list : out) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  return out;
}

std::vector<std::vector<int>>
faceCurves(const CadModel& model)
{
  std::vector<std::vector<int>> out(model.faces.size());
  for (const CadCurve& c : model.curves)
    for (int f : c.faces)
      out[static_cast<std::size_t>(f)].push_back(c.id);
  for (auto& list : out) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  return out;
}

int
eulerCharacteristic(const CadModel& model)
{
  int chi = static_cast<int>(model.vertices.size());
  for (const CadCurve& c : model.curves)
    if (c.kind == CadCurve::Kind::kSegment)
      --chi; // an open segment; a circle (closed, no vertex) counts 0
  for (const CadFace& f : model.faces)
    if (f.kind == CadFace::Kind::kPlanar) {
      const int holes =
        static_cast<int>(f.circles.size()) - (f.polygon.empty() ? 1 : 0);
      chi += 1 - holes; // an open disc minus closed discs; an open cylinder counts 0
    }
  return chi;
}

std::string
cadModelJson(const CadModel& model)
{
  using visfeat::json_document::Json;
  using visfeat::json_document::vector3;
  std::size_t circles = 0;
  for (const CadCurve& c : model.curves)
    circles += c.kind == CadCurve::Kind::kCircle ? 1 : 0;
  const auto vertex_curves = vertexCurves(model);
  const auto vertex_faces = vertexFaces(model);
  const auto face_curves = faceCurves(model);

  Json vertices = Json::array();
  for (std::size_t v = 0; v < model.vertices.size(); ++v)
    vertices.push_back({{"id", v},
                        {"xyz", vector3(model.vertices[v])},
                        {"edges", vertex_curves[v]},
                        {"faces", vertex_faces[v]}});
  Json edges = Json::array();
  for (std::size_t i = 0; i < model.curves.size(); ++i) {
    const CadCurve& c = model.curves[i];
    const bool circle = c.kind == CadCurve::Kind::kCircle;
    Json edge = {{"id", i},
                 {"kind", circle ? "circle" : "straight"},
                 {"vertices", circle ? std::vector<int>()
                                     : std::vector<int>{c.vertices[0], c.vertices[1]}},
                 {"faces", {c.faces[0], c.faces[1]}},
                 {"length", curveLength(model, static_cast<int>(i))}};
    if (circle) {
      edge["centre"] = vector3(c.centre);
      edge["axis"] = vector3(c.axis);
      edge["radius"] = c.radius;
    }
    edges.push_back(edge);
  }
  Json faces = Json::array();
  for (std::size_t i = 0; i < model.faces.size(); ++i) {
    const CadFace& f = model.faces[i];
    const bool planar = f.kind == CadFace::Kind::kPlanar;
    Json face = {{"id", i},
                 {"kind", planar ? "planar" : "cylindrical"},
                 {"area", faceArea(model, static_cast<int>(i))},
                 {"edges", face_curves[i]},
                 {"polygon", f.polygon},
                 {"circles", f.circles}};
    if (planar)
      face["normal"] = vector3(f.normal);
    else
      face["hole"] = f.hole;
    faces.push_back(face);
  }
  Json document;
  document["name"] = model.name;
  document["counts"] = {{"vertices", model.vertices.size()},
                        {"edges", model.curves.size()},
                        {"straight_edges", model.curves.size() - circles},
                        {"circular_edges", circles},
                        {"faces", model.faces.size()}};
  document["euler_characteristic"] = eulerCharacteristic(model);
  document["vertices"] = vertices;
  document["edges"] = edges;
  document["faces"] = faces;
  std::ostringstream out;
  visfeat::json_document::write(out, document);
  return out.str();
}

double
cellSize(const CadModel& model, int resolution)
{
  if (resolution <= 0)
    throw Error("cellSize: the resolution must be positive, got " +
                std::to_string(resolution));
  return model.bounds().sizes().maxCoeff() / resolution;
}

std::size_t
samplesForSpacing(const CadModel& model, int resolution, double spacing_cells)
{
  if (!(spacing_cells > 0.0) || !std::isfinite(spacing_cells))
    throw Error("samplesForSpacing: the spacing must be positive and finite");
  const double spacing = spacing_cells * cellSize(model, resolution);
  return static_cast<std::size_t>(std::ceil(model.area() / (spacing * spacing)));
}

CadSamples
sampleCadModel(const CadModel& model, const SamplingOptions& options)
{
  if (!(options.noise_sigma >= 0.0) || !std::isfinite(options.noise_sigma))
    throw Error("sampleCadModel: the noise sigma must be finite and >= 0");
  if (!options.rotation.allFinite())
    throw Error("sampleCadModel: the rotation is not finite");
  const std::size_t face_count = model.faces.size();
  std::vector<double> cumulative;
  double total = 0.0;
  for (std::size_t f = 0; f < face_count; ++f) {
    total += faceArea(model, static_cast<int>(f));
    cumulative.push_back(total);
  }
  if (!(total > 0.0))
    throw Error("sampleCadModel: model '" + model.name + "' has no area");
  std::size_t count = options.count;
  if (count == 0) {
    if (!(options.spacing > 0.0) || !std::isfinite(options.spacing))
      throw Error("sampleCadModel: give a count or a positive spacing");
    const double n = std::ceil(total / (options.spacing * options.spacing));
    if (!(n < 1e12))
      throw Error("sampleCadModel: the spacing gives too many points");
    count = static_cast<std::size_t>(n);
  }

  std::vector<PlanarFrame> planes(face_count);
  std::vector<CylinderFrame> cylinders(face_count);
  for (std::size_t f = 0; f < face_count; ++f) {
    if (model.faces[f].kind == CadFace::Kind::kPlanar)
      planes[f] = planarFrame(model, model.faces[f]);
    else
      cylinders[f] = cylinderFrame(model, model.faces[f]);
  }

  std::mt19937_64 rng(options.seed);
  std::mt19937_64 noise_rng(options.seed ^ 0x9E3779B97F4A7C15ull); // a stream apart
  visfeat::synthetic::UniformReal unit(0.0, 1.0);
  visfeat::synthetic::Normal gauss(0.0, options.noise_sigma > 0.0 ? options.noise_sigma
                                                                  : 1.0);
  CadSamples out;
  out.points.reserve(count);
  out.face.reserve(count);
  out.curve_distance.reserve(count);
  constexpr int kMaxRejections = 1000000;
  for (std::size_t i = 0; i < count; ++i) {
    const double pick = unit(rng) * total;
    const std::size_t f = std::min<std::size_t>(
      static_cast<std::size_t>(
        std::lower_bound(cumulative.begin(), cumulative.end(), pick) -
        cumulative.begin()),
      face_count - 1);
    Eigen::Vector3d p;
    if (model.faces[f].kind == CadFace::Kind::kCylindrical) {
      const CylinderFrame& c = cylinders[f];
      const double angle = 2.0 * kPi * unit(rng);
      const double t = c.height * unit(rng);
      p = c.base + t * c.axis +
          c.radius * (std::cos(angle) * c.e1 + std::sin(angle) * c.e2);
    } else {
      const PlanarFrame& plane = planes[f];
      Point2 q;
      int tries = 0;
      do {
        if (++tries > kMaxRejections)
          throw Error("sampleCadModel: face " + std::to_string(f) + " of model '" +
                      model.name + "' rejects every sample");
        q.x = plane.lo.x + (plane.hi.x - plane.lo.x) * unit(rng);
        q.y = plane.lo.y + (plane.hi.y - plane.lo.y) * unit(rng);
      } while (!plane.contains(q));
      p = plane.lift(q);
    }
    out.curve_distance.push_back(curveDistance(model, p));
    out.face.push_back(static_cast<int>(f));
    Eigen::Vector3d x = options.rotation * p;
    if (options.noise_sigma > 0.0)
      x += Eigen::Vector3d(gauss(noise_rng), gauss(noise_rng), gauss(noise_rng));
    out.points.push_back(x.cast<float>());
  }
  return out;
}

} // namespace synthetic
} // namespace visfeat
