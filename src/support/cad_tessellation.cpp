#include <support/cad_frames.h>
#include <support/cad_tessellation.h>
#include <support/polygon_triangulation.h>
#include <visfeat/core/common/error.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>

namespace visfeat {
namespace synthetic {

using detail::CylinderFrame;
using detail::cylinderFrame;
using detail::kPi;
using detail::PlanarFrame;
using detail::planarFrame;

int
circleSegments(double radius, double chord_tolerance)
{
  if (!(radius > 0.0) || !std::isfinite(radius))
    throw Error("circleSegments: the radius must be positive and finite");
  if (!(chord_tolerance > 0.0) || !std::isfinite(chord_tolerance))
    throw Error("circleSegments: the chord tolerance must be positive and finite");
  constexpr int kMinSegments = 8;
  constexpr double kMaxSegments = 1 << 20;
  const double ratio = std::min(chord_tolerance / radius, 1.0);
  const double segments = std::ceil(kPi / std::acos(1.0 - ratio));
  if (!(segments <= kMaxSegments))
    throw Error("circleSegments: a chord tolerance of " +
                std::to_string(chord_tolerance) + " on a radius of " +
                std::to_string(radius) + " needs more than 2^20 segments");
  return std::max(kMinSegments, static_cast<int>(segments));
}

namespace {

using Triangle = std::array<std::uint32_t, 3>;

/** Builds the mesh: the model's vertices, then the circles' points, then the faces. */
class Tessellator
{
public:
  Tessellator(const CadModel& model, double chord_tolerance)
      : model_(model)
      , ring_start_(model.curves.size(), 0)
      , ring_size_(model.curves.size(), 0)
  {
    out_.mesh.vertices = model.vertices;
    for (const CadCurve& c : model.curves) {
      if (c.kind != CadCurve::Kind::kCircle)
        continue;
      const int n = circleSegments(c.radius, chord_tolerance);
      const Eigen::Vector3d axis = c.axis.normalized();
      const Eigen::Vector3d e1 = axis.unitOrthogonal();
      const Eigen::Vector3d e2 = axis.cross(e1);
      const auto id = static_cast<std::size_t>(c.id);
      ring_start_[id] = static_cast<std::uint32_t>(out_.mesh.vertices.size());
      ring_size_[id] = static_cast<std::uint32_t>(n);
      for (int k = 0; k < n; ++k) {
        const double angle = 2.0 * kPi * k / n;
        out_.mesh.vertices.push_back(
          c.centre + c.radius * (std::cos(angle) * e1 + std::sin(angle) * e2));
      }
    }
    if (out_.mesh.vertices.size() > 0xFFFFFFFFull)
      throw Error("tessellateCadModel: too many vertices");
  }

  CadMesh run()
  {
    for (const CadFace& face : model_.faces) {
      if (face.kind == CadFace::Kind::kPlanar)
        planar(face);
      else
        cylindrical(face);
    }
    return std::move(out_);
  }

private:
  /** The mesh vertices of a circle, counter-clockwise about `direction`. */
  std::vector<std::uint32_t> ring(int circle, const Eigen::Vector3d& direction) const
  {
    const auto id = static_cast<std::size_t>(circle);
    std::vector<std::uint32_t> ids(ring_size_[id]);
    for (std::uint32_t k = 0; k < ring_size_[id]; ++k)
      ids[k] = ring_start_[id] + k;
    if (model_.curves[id].axis.dot(direction) < 0.0)
      std::reverse(ids.begin(), ids.end());
    return ids;
  }

  void emit(const Triangle& t, int face)
  {
    out_.mesh.triangles.push_back(t);
    out_.face.push_back(face);
  }

  /** The outer boundary (polygon or disc) and the holes, in the face's plane. */
  void planar(const CadFace& face)
  {
    const PlanarFrame frame = planarFrame(model_, face);
    std::vector<std::uint32_t> ids;
    for (int v : face.polygon)
      ids.push_back(static_cast<std::uint32_t>(v));
    std::size_t first_hole = 0;
    if (face.polygon.empty()) {
      ids = ring(face.circles[0], frame.normal);
      first_hole = 1;
    }
    auto project = [&](std::uint32_t id) {
      const detail::Point2 q = frame.project(out_.mesh.vertices[id]);
      return Eigen::Vector2d(q.x, q.y);
    };
    Polygon2 outer;
    for (std::uint32_t id : ids)
      outer.push_back(project(id));
    std::vector<Polygon2> holes;
    for (std::size_t c = first_hole; c < face.circles.size(); ++c) {
      const std::vector<std::uint32_t> hole = ring(face.circles[c], frame.normal);
      holes.emplace_back();
      for (std::uint32_t id : hole) {
        holes.back().push_back(project(id));
        ids.push_back(id);
      }
    }
    std::vector<Triangle> triangles;
    try {
      triangles = triangulatePolygon(outer, holes);
    } catch (const Error& e) {
      throw Error("tessellateCadModel: face " + std::to_string(face.id) + " of '" +
                  model_.name + "': " + e.what());
    }
    for (const Triangle& t : triangles)
      emit({{ids[t[0]], ids[t[1]], ids[t[2]]}}, face.id);
  }

  /** A circle's ring as seen about a cylinder's axis: from its point of the smallest
   * angle in [0, 2 pi), with the angles made increasing, and the first again at the
   * end (plus 2 pi). */
  struct AngularRing
  {
    std::vector<std::uint32_t> ids;
    std::vector<double> angles;
  };

  AngularRing angularRing(const CylinderFrame& frame,
                          const std::vector<std::uint32_t>& ccw) const
  {
    const std::size_t n = ccw.size();
    std::vector<double> raw(n);
    for (std::size_t k = 0; k < n; ++k) {
      const Eigen::Vector3d d = out_.mesh.vertices[ccw[k]] - frame.base;
      raw[k] = std::atan2(d.dot(frame.e2), d.dot(frame.e1));
      if (raw[k] < 0.0)
        raw[k] += 2.0 * kPi;
    }
    const auto start =
      static_cast<std::size_t>(std::min_element(raw.begin(), raw.end()) - raw.begin());
    AngularRing out;
    for (std::size_t k = 0; k <= n; ++k) {
      out.ids.push_back(ccw[(start + k) % n]);
      double angle = raw[(start + k) % n];
      while (k > 0 && angle <= out.angles.back())
        angle += 2.0 * kPi;
      out.angles.push_back(angle);
    }
    return out;
  }

  /** A strip between the two circles, merged by angle about the axis (the circles may
   * have different segment counts or phases). */
  void cylindrical(const CadFace& face)
  {
    const CylinderFrame frame = cylinderFrame(model_, face);
    const AngularRing a = angularRing(frame, ring(face.circles[0], frame.axis));
    const AngularRing b = angularRing(frame, ring(face.circles[1], frame.axis));
    const std::size_t na = a.ids.size() - 1, nb = b.ids.size() - 1;
    const double inf = std::numeric_limits<double>::infinity();
    std::size_t i = 0, j = 0;
    while (i < na || j < nb) {
      Triangle t;
      if ((i < na ? a.angles[i + 1] : inf) <= (j < nb ? b.angles[j + 1] : inf)) {
        t = {{a.ids[i], a.ids[i + 1], b.ids[j]}};
        ++i;
      } else {
        t = {{a.ids[i], b.ids[j + 1], b.ids[j]}};
        ++j;
      }
      if (face.hole)
        std::swap(t[1], t[2]); // the outward normal points to the axis
      emit(t, face.id);
    }
  }

  const CadModel& model_;
  std::vector<std::uint32_t> ring_start_;
  std::vector<std::uint32_t> ring_size_;
  CadMesh out_;
};

} // namespace

CadMesh
tessellateCadModel(const CadModel& model, double chord_tolerance)
{
  return Tessellator(model, chord_tolerance).run();
}

} // namespace synthetic
} // namespace visfeat
