#include <support/cad_frames.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace visfeat {
namespace synthetic {
namespace detail {

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

bool
PlanarFrame::contains(const Point2& q) const
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

double
PlanarFrame::outerArea() const
{
  if (polygon.empty())
    return radii.empty() ? 0.0 : kPi * radii[0] * radii[0];
  double twice = 0.0;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++)
    twice += polygon[j].x * polygon[i].y - polygon[i].x * polygon[j].y;
  return 0.5 * twice;
}

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

} // namespace detail
} // namespace synthetic
} // namespace visfeat
