#include <support/cad_depth_view.h>
#include <support/cad_frames.h>
#include <support/cad_queries.h>
#include <support/portable_random.h>
#include <visfeat/core/common/error.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace visfeat {
namespace synthetic {

using detail::CylinderFrame;
using detail::cylinderFrame;
using detail::kPi;
using detail::PlanarFrame;
using detail::planarFrame;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/** Ray casting against the exact faces: planes clipped to their face (outer boundary
 * and holes, PlanarFrame::contains) and finite cylinders. */
class RayCaster
{
public:
  explicit RayCaster(const CadModel& model)
      : model_(model)
      , planes_(model.faces.size())
      , cylinders_(model.faces.size())
  {
    for (std::size_t f = 0; f < model.faces.size(); ++f) {
      if (model.faces[f].kind == CadFace::Kind::kPlanar)
        planes_[f] = planarFrame(model, model.faces[f]);
      else
        cylinders_[f] = cylinderFrame(model, model.faces[f]);
    }
  }

  /** The nearest face along origin + t direction with t in (t_min, t_max): sets t and
   * returns the face id, or -1 for none. */
  int cast(const Eigen::Vector3d& origin,
           const Eigen::Vector3d& direction,
           double t_min,
           double t_max,
           double& t) const
  {
    int face = -1;
    t = t_max;
    for (std::size_t f = 0; f < model_.faces.size(); ++f) {
      const double tf = model_.faces[f].kind == CadFace::Kind::kPlanar
                          ? plane(planes_[f], origin, direction, t_min, t)
                          : cylinder(cylinders_[f], origin, direction, t_min, t);
      if (tf < t) {
        t = tf;
        face = static_cast<int>(f);
      }
    }
    return face;
  }

private:
  /** The ray's parameter in (t_min, t_max) at the face, or +infinity. */
  static double plane(const PlanarFrame& frame,
                      const Eigen::Vector3d& origin,
                      const Eigen::Vector3d& direction,
                      double t_min,
                      double t_max)
  {
    const double denominator = frame.normal.dot(direction);
    if (denominator == 0.0)
      return kInf;
    const double t = frame.normal.dot(frame.origin - origin) / denominator;
    if (!(t > t_min && t < t_max))
      return kInf;
    return frame.contains(frame.project(origin + t * direction)) ? t : kInf;
  }

  /** The nearest parameter in (t_min, t_max) on the cylinder between its two circles,
   * or +infinity. */
  static double cylinder(const CylinderFrame& frame,
                         const Eigen::Vector3d& origin,
                         const Eigen::Vector3d& direction,
                         double t_min,
                         double t_max)
  {
    const Eigen::Vector3d w = origin - frame.base;
    const Eigen::Vector3d dp = direction - direction.dot(frame.axis) * frame.axis;
    const Eigen::Vector3d wp = w - w.dot(frame.axis) * frame.axis;
    const double a = dp.squaredNorm();
    const double b = 2.0 * dp.dot(wp);
    const double c = wp.squaredNorm() - frame.radius * frame.radius;
    const double discriminant = b * b - 4.0 * a * c;
    if (a == 0.0 || discriminant < 0.0)
      return kInf;
    // The stable pair of roots.
    const double q = -0.5 * (b + std::copysign(std::sqrt(discriminant), b));
    double roots[2] = {q / a, q != 0.0 ? c / q : q / a};
    if (roots[1] < roots[0])
      std::swap(roots[0], roots[1]);
    for (double t : roots) {
      if (!(t > t_min && t < t_max))
        continue;
      const double h = (w + t * direction).dot(frame.axis);
      if (h >= 0.0 && h <= frame.height)
        return t;
    }
    return kInf;
  }

  const CadModel& model_;
  std::vector<PlanarFrame> planes_;
  std::vector<CylinderFrame> cylinders_;
};

[[noreturn]] void
fail(const std::string& what)
{
  throw Error("renderOrganizedView: " + what);
}

/** The radius of the sphere about `target` that holds the model (world units). */
double
boundingRadius(const CadModel& model, const Eigen::Vector3d& target)
{
  double radius = 0.0;
  for (const Eigen::Vector3d& v : model.vertices)
    radius = std::max(radius, (v - target).norm());
  for (const CadCurve& c : model.curves)
    if (c.kind == CadCurve::Kind::kCircle)
      radius = std::max(radius, (c.centre - target).norm() + c.radius);
  return radius;
}

void
checkOptions(const OrganizedViewOptions& o)
{
  if (o.width < 1 || o.height < 1 ||
      static_cast<double>(o.width) * static_cast<double>(o.height) > 1e9)
    fail("the image size " + std::to_string(o.width) + "x" + std::to_string(o.height) +
         " must be at least 1x1 and at most 1e9 pixels");
  if (!(o.horizontal_fov > 0.0 && o.horizontal_fov < 180.0))
    fail("the horizontal field of view must be in (0, 180) degrees");
  if (!o.camera_direction.allFinite() || !(o.camera_direction.norm() > 0.0) ||
      !o.up.allFinite() || !(o.up.norm() > 0.0) || !o.target.allFinite())
    fail("the camera direction, up and target must be finite, the directions non-zero");
  if (!(o.distance >= 0.0) || !std::isfinite(o.distance))
    fail("the distance must be finite and >= 0");
  if (!(o.noise_a >= 0.0) || !std::isfinite(o.noise_a) || !(o.noise_b >= 0.0) ||
      !std::isfinite(o.noise_b))
    fail("the noise coefficients must be finite and >= 0");
  if (!std::isfinite(o.baseline))
    fail("the baseline must be finite");
}

/** The camera of the options: position, axes, focal length, projector. */
OrganizedView
placeCamera(const CadModel& model, const OrganizedViewOptions& o)
{
  OrganizedView view;
  view.width = o.width;
  view.height = o.height;
  const Eigen::Vector3d z = -o.camera_direction.normalized();
  Eigen::Vector3d up = o.up.normalized();
  if (z.cross(up).norm() < 1e-6) { // parallel: the world axis most across the view
    Eigen::Index axis = 0;
    z.cwiseAbs().minCoeff(&axis);
    up = Eigen::Vector3d::Unit(axis);
  }
  const Eigen::Vector3d x = z.cross(up).normalized();
  const Eigen::Vector3d y = z.cross(x);
  view.camera_axes.col(0) = x;
  view.camera_axes.col(1) = y;
  view.camera_axes.col(2) = z;
  const double half_h = 0.5 * o.horizontal_fov * kPi / 180.0;
  view.focal = 0.5 * o.width / std::tan(half_h);
  const double half_v = std::atan(0.5 * o.height / view.focal);
  const double radius = boundingRadius(model, o.target);
  double distance = o.distance;
  if (distance == 0.0)
    distance = radius / std::sin(0.9 * std::min(half_h, half_v));
  else if (distance <= radius)
    fail("the camera at distance " + std::to_string(distance) +
         " is inside the model's bounding sphere (radius " + std::to_string(radius) +
         ")");
  view.camera_position = o.target - distance * z;
  view.projector_position = view.camera_position + o.baseline * x;
  return view;
}

} // namespace

OrganizedView
renderOrganizedView(const CadModel& model, const OrganizedViewOptions& options)
{
  checkOptions(options);
  OrganizedView view = placeCamera(model, options);
  const RayCaster caster(model);
  const std::size_t pixels =
    static_cast<std::size_t>(options.width) * static_cast<std::size_t>(options.height);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  view.points.assign(pixels, Eigen::Vector3f(nan, nan, nan));
  view.face.assign(pixels, -1);
  view.curve_distance.assign(pixels, std::numeric_limits<double>::quiet_NaN());
  // The shadow test stops short of the point by a margin of this size (world units).
  const double margin =
    1e-7 * std::max(1.0, (view.camera_position - options.target).norm());

  RandomEngine rng(options.seed ^ 0x9E3779B97F4A7C15ull);
  Normal gauss(0.0, 1.0);
  for (int row = 0; row < options.height; ++row)
    for (int column = 0; column < options.width; ++column) {
      const double noise = gauss(rng); // drawn for every pixel
      const Eigen::Vector3d ray =
        view.camera_axes *
        Eigen::Vector3d((column + 0.5 - 0.5 * options.width) / view.focal,
                        (row + 0.5 - 0.5 * options.height) / view.focal, 1.0);
      double depth = 0.0; // the ray's z component is 1: t is the depth
      const int face = caster.cast(view.camera_position, ray, 0.0, kInf, depth);
      if (face < 0)
        continue;
      const Eigen::Vector3d p = view.camera_position + depth * ray;
      if (options.baseline != 0.0) {
        const Eigen::Vector3d to_p = p - view.projector_position;
        const double length = to_p.norm();
        double t = 0.0;
        if (caster.cast(view.projector_position, to_p, 0.0, 1.0 - margin / length, t) >=
            0)
          continue; // the projector does not light p
      }
      const double sigma = options.noise_a + options.noise_b * depth * depth;
      const std::size_t i = static_cast<std::size_t>(row) * options.width + column;
      view.points[i] =
        (view.camera_position + (depth + sigma * noise) * ray).cast<float>();
      view.face[i] = face;
      view.curve_distance[i] = curveDistance(model, p);
    }
  return view;
}

} // namespace synthetic
} // namespace visfeat
