#include <support/cad_frames.h>
#include <support/cad_model.h>
#include <support/cad_queries.h>
#include <visfeat/core/common/error.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>

namespace visfeat {
namespace synthetic {

using detail::polygonEdges;
using detail::sortedPair;

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

// --- checkCadModel and its steps -----------------------------------------------

namespace {

/** The segments by their sorted vertex pair. */
using SegmentIds = std::map<std::pair<int, int>, int>;

[[noreturn]] void
fail(const CadModel& model, const std::string& what)
{
  throw Error("CAD model '" + model.name + "': " + what);
}

/** Ids, face ids, segment ends and lengths, circles' geometry; returns the segments. */
SegmentIds
checkCurves(const CadModel& model, double tolerance)
{
  const int vertex_count = static_cast<int>(model.vertices.size());
  const int curve_count = static_cast<int>(model.curves.size());
  const int face_count = static_cast<int>(model.faces.size());
  SegmentIds segment_of;
  for (int c = 0; c < curve_count; ++c) {
    const CadCurve& curve = model.curves[static_cast<std::size_t>(c)];
    const std::string curve_name = "curve " + std::to_string(c);
    if (curve.id != c)
      fail(model, curve_name + " has id " + std::to_string(curve.id));
    for (int f : curve.faces)
      if (f < 0 || f >= face_count)
        fail(model, curve_name + " has face id " + std::to_string(f) + " out of range");
    if (curve.faces[0] == curve.faces[1])
      fail(model, curve_name + " separates a face from itself");
    if (curve.kind == CadCurve::Kind::kSegment) {
      for (int v : curve.vertices)
        if (v < 0 || v >= vertex_count)
          fail(model,
               curve_name + " has vertex id " + std::to_string(v) + " out of range");
      if ((model.vertices[static_cast<std::size_t>(curve.vertices[0])] -
           model.vertices[static_cast<std::size_t>(curve.vertices[1])])
            .norm() <= tolerance)
        fail(model, curve_name + " has zero length");
      if (!segment_of.emplace(sortedPair(curve.vertices[0], curve.vertices[1]), c)
             .second)
        fail(model, curve_name + " duplicates another segment");
    } else {
      if (curve.vertices[0] != -1 || curve.vertices[1] != -1)
        fail(model, curve_name + " is a circle with vertices");
      if (!(curve.radius > 0.0) || !std::isfinite(curve.radius) ||
          !curve.centre.allFinite() || std::abs(curve.axis.norm() - 1.0) > 1e-9)
        fail(model, curve_name + " is a circle with a bad centre, axis or radius");
    }
  }
  return segment_of;
}

/** Whether the curve is on the face's boundary (its polygon or its circles). */
bool
boundedBy(const CadFace& face, const CadCurve& curve)
{
  if (curve.kind == CadCurve::Kind::kCircle)
    return std::find(face.circles.begin(), face.circles.end(), curve.id) !=
           face.circles.end();
  for (const auto& edge : polygonEdges(face))
    if (sortedPair(edge.first, edge.second) ==
        sortedPair(curve.vertices[0], curve.vertices[1]))
      return true;
  return false;
}

/** A planar face: unit normal, an outer boundary, its vertices and circles in its
 * plane, counter-clockwise about its normal. */
void
checkPlanarFace(const CadModel& model,
                const CadFace& face,
                const std::string& face_name,
                double tolerance)
{
  if (std::abs(face.normal.norm() - 1.0) > 1e-9)
    fail(model, face_name + " has a normal that is not a unit vector");
  if (face.polygon.empty() ? face.circles.empty() : face.polygon.size() < 3)
    fail(model, face_name + " has no outer boundary");
  const detail::PlanarFrame frame = detail::planarFrame(model, face);
  for (int v : face.polygon)
    if (std::abs(face.normal.dot(model.vertices[static_cast<std::size_t>(v)] -
                                 frame.origin)) > tolerance)
      fail(model, face_name + " is not planar");
  for (int c : face.circles) {
    const CadCurve& circle = model.curves[static_cast<std::size_t>(c)];
    if (std::abs(face.normal.dot(circle.centre - frame.origin)) > tolerance ||
        face.normal.cross(circle.axis).norm() > 1e-9)
      fail(model, face_name + ": circle " + std::to_string(c) + " is not in its plane");
  }
  if (!(frame.outerArea() > 0.0))
    fail(model, face_name + " is not counter-clockwise about its normal");
}

/** A cylindrical face: between two coaxial circles of one radius, no polygon. */
void
checkCylindricalFace(const CadModel& model,
                     const CadFace& face,
                     const std::string& face_name,
                     double tolerance)
{
  if (face.circles.size() != 2 || !face.polygon.empty())
    fail(model, face_name + " is a cylinder without exactly two circles");
  const CadCurve& c0 = model.curves[static_cast<std::size_t>(face.circles[0])];
  const CadCurve& c1 = model.curves[static_cast<std::size_t>(face.circles[1])];
  const Eigen::Vector3d d = c1.centre - c0.centre;
  if (std::abs(c0.radius - c1.radius) > tolerance || d.norm() <= tolerance ||
      c0.axis.cross(c1.axis).norm() > 1e-9 ||
      c0.axis.cross(d.normalized()).norm() > 1e-9)
    fail(model, face_name + " is a cylinder between circles that are not coaxial with "
                            "one radius");
}

/** Face -> curve: every boundary element is a curve that lists this face. */
void
checkFaceBoundary(const CadModel& model,
                  int f,
                  const std::string& face_name,
                  const SegmentIds& segment_of)
{
  const CadFace& face = model.faces[static_cast<std::size_t>(f)];
  for (const auto& edge : polygonEdges(face)) {
    const auto it = segment_of.find(sortedPair(edge.first, edge.second));
    if (it == segment_of.end())
      fail(model, face_name + ": boundary edge " + std::to_string(edge.first) + "-" +
                    std::to_string(edge.second) + " is not a curve");
    const CadCurve& curve = model.curves[static_cast<std::size_t>(it->second)];
    if (curve.faces[0] != f && curve.faces[1] != f)
      fail(model, face_name + ": curve " + std::to_string(curve.id) +
                    " does not list the face");
  }
  for (int c : face.circles) {
    const CadCurve& curve = model.curves[static_cast<std::size_t>(c)];
    if (curve.faces[0] != f && curve.faces[1] != f)
      fail(model,
           face_name + ": circle " + std::to_string(c) + " does not list the face");
  }
}

/** Ids, boundary ids, the face's own geometry, then its boundary's curves. */
void
checkFaces(const CadModel& model, const SegmentIds& segment_of, double tolerance)
{
  const int vertex_count = static_cast<int>(model.vertices.size());
  const int curve_count = static_cast<int>(model.curves.size());
  const int face_count = static_cast<int>(model.faces.size());
  for (int f = 0; f < face_count; ++f) {
    const CadFace& face = model.faces[static_cast<std::size_t>(f)];
    const std::string face_name = "face " + std::to_string(f);
    if (face.id != f)
      fail(model, face_name + " has id " + std::to_string(face.id));
    for (int c : face.circles)
      if (c < 0 || c >= curve_count ||
          model.curves[static_cast<std::size_t>(c)].kind != CadCurve::Kind::kCircle)
        fail(model, face_name + " lists curve " + std::to_string(c) + " as a circle");
    for (int v : face.polygon)
      if (v < 0 || v >= vertex_count)
        fail(model,
             face_name + " has vertex id " + std::to_string(v) + " out of range");
    if (face.kind == CadFace::Kind::kPlanar)
      checkPlanarFace(model, face, face_name, tolerance);
    else
      checkCylindricalFace(model, face, face_name, tolerance);
    checkFaceBoundary(model, f, face_name, segment_of);
  }
}

} // namespace

void
checkCadModel(const CadModel& model)
{
  for (const auto& v : model.vertices)
    if (!v.allFinite())
      fail(model, "a vertex is not finite");
  const double tolerance = 1e-9 * std::max(1.0, model.bounds().sizes().maxCoeff());

  const SegmentIds segment_of = checkCurves(model, tolerance);
  checkFaces(model, segment_of, tolerance);
  // Curve -> face: each of its faces has it on its boundary.
  for (const CadCurve& curve : model.curves)
    for (int f : curve.faces)
      if (!boundedBy(model.faces[static_cast<std::size_t>(f)], curve))
        fail(model, "curve " + std::to_string(curve.id) +
                      " is not on the boundary of face " + std::to_string(f));
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

} // namespace synthetic
} // namespace visfeat
