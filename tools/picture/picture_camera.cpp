// Where the visfeat tool's pictures look from; see picture_camera.h.

#include "picture/picture_camera.h"

#include <visfeat/core/common/feature_class.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <utility>
#include <vector>

namespace visfeat_tools {

namespace {

/** \brief The default direction the camera looks from (see chooseDirection()). */
const Eigen::Vector3d kDefaultDirection = Eigen::Vector3d(1.0, 0.78, 0.62).normalized();

/** \brief Face regions with fewer points do not steer the camera (specks). */
constexpr double kMinFacePoints = 10.0;

/** \brief A face region is planar when its points' smallest covariance eigenvalue is
 * at most this fraction of the middle one. */
constexpr double kPlanarEigenRatio = 0.01;

/** \brief A face is seen from a direction when its outward normal lies within about
 * 72 degrees of it (cosine 0.3): faces seen edge-on show little. */
constexpr double kFacingCosine = 0.3;

} // namespace

Eigen::Vector3d
chooseDirection(const pcl::PointCloud<visfeat::PointVisibility>& cloud)
{
  struct Moments
  {
    double n = 0.0;
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    Eigen::Matrix3d outer = Eigen::Matrix3d::Zero();
  };
  std::map<std::uint32_t, Moments> faces;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  double finite = 0.0;
  for (const auto& p : cloud) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      continue;
    const Eigen::Vector3d q(p.x, p.y, p.z);
    centroid += q;
    finite += 1.0;
    if (p.feature_class != static_cast<std::uint8_t>(visfeat::FeatureClass::kFace))
      continue;
    Moments& m = faces[p.label];
    m.n += 1.0;
    m.sum += q;
    m.outer += q * q.transpose();
  }
  if (finite > 0.0)
    centroid /= finite;
  struct Face
  {
    Eigen::Vector3d normal; // outward: away from the object's centroid
    double points = 0.0;
    bool planar = false;
  };
  std::vector<Face> seen_faces;
  for (const auto& [label, m] : faces) {
    (void)label;
    if (m.n < kMinFacePoints)
      continue;
    const Eigen::Vector3d mean = m.sum / m.n;
    const Eigen::Matrix3d cov = m.outer / m.n - mean * mean.transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
    if (eig.info() != Eigen::Success)
      continue;
    Face f;
    f.normal = eig.eigenvectors().col(0);
    if (f.normal.dot(mean - centroid) < 0.0)
      f.normal = -f.normal;
    f.points = m.n;
    f.planar = eig.eigenvalues()(0) <= kPlanarEigenRatio * eig.eigenvalues()(1);
    seen_faces.push_back(f);
  }
  if (std::none_of(seen_faces.begin(), seen_faces.end(),
                   [](const Face& f) { return f.planar; }))
    return kDefaultDirection;

  // Directions spread evenly over the sphere (a Fibonacci lattice). A direction
  // scores the faces it sees (outward normal within ~72 degrees of it), then the
  // projected area of the planar ones facing it.
  constexpr int kCandidates = 2000;
  std::vector<Eigen::Vector3d> candidates;
  std::vector<int> counts;
  std::vector<double> areas;
  int most = 0;
  for (int i = 0; i < kCandidates; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / kCandidates;
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double phi = i * M_PI * (3.0 - std::sqrt(5.0));
    const Eigen::Vector3d d(r * std::cos(phi), r * std::sin(phi), z);
    int count = 0;
    double area = 0.0;
    for (const Face& f : seen_faces) {
      const double facing = f.normal.dot(d);
      count += facing > kFacingCosine;
      if (f.planar && facing > 0.0)
        area += f.points * facing;
    }
    candidates.push_back(d);
    counts.push_back(count);
    areas.push_back(area);
    most = std::max(most, count);
  }
  double best = 0.0;
  for (std::size_t i = 0; i < candidates.size(); ++i)
    if (counts[i] == most)
      best = std::max(best, areas[i]);
  Eigen::Vector3d chosen = kDefaultDirection;
  double closest = -2.0;
  for (std::size_t i = 0; i < candidates.size(); ++i)
    if (counts[i] == most && areas[i] >= 0.97 * best &&
        candidates[i].dot(kDefaultDirection) > closest) {
      closest = candidates[i].dot(kDefaultDirection);
      chosen = candidates[i];
    }
  return chosen.normalized();
}

View
fitView(const pcl::PointCloud<visfeat::PointVisibility>& cloud,
        const Eigen::Vector3d& lo,
        const Eigen::Vector3d& hi,
        const Eigen::Vector3d& direction,
        int width,
        int height,
        double right_reserve,
        const Eigen::Vector3d* up_hint)
{
  View v;
  const Eigen::Vector3d d = direction.normalized();
  const Eigen::Vector3d centre = 0.5 * (lo + hi);

  // Spread of the points in the image plane.
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  double n = 0.0;
  for (const auto& p : cloud) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      continue;
    Eigen::Vector3d q = Eigen::Vector3d(p.x, p.y, p.z) - centre;
    q -= q.dot(d) * d;
    cov += q * q.transpose();
    n += 1.0;
  }
  Eigen::Vector3d up;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov / std::max(n, 1.0));
  // eigenvalues ascending: 0 ~ along d, 1 minor, 2 major in-plane axis.
  if (eig.info() == Eigen::Success &&
      eig.eigenvalues()(2) > 1.3 * eig.eigenvalues()(1)) {
    up = d.cross(eig.eigenvectors().col(2)).normalized(); // major axis horizontal
  } else {
    const Eigen::Vector3d world_up =
      std::abs(d.z()) < 0.95 ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d::UnitY();
    up = (world_up - world_up.dot(d) * d).normalized();
  }
  if (up.z() < 0.0)
    up = -up;
  if (up_hint != nullptr) {
    const Eigen::Vector3d across = *up_hint - up_hint->dot(d) * d;
    if (across.norm() > 1e-6 * up_hint->norm())
      up = across.normalized();
  }
  const Eigen::Vector3d right = up.cross(d);

  // Centre the projected box, then the nearest distance that keeps every point inside
  // the frame (perspective: x / (D - z) <= tan of the half angle).
  Eigen::Vector2d min2 = Eigen::Vector2d::Constant(std::numeric_limits<double>::max());
  Eigen::Vector2d max2 = -min2;
  for (const auto& p : cloud) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      continue;
    const Eigen::Vector3d q = Eigen::Vector3d(p.x, p.y, p.z) - centre;
    const Eigen::Vector2d xy(q.dot(right), q.dot(up));
    min2 = min2.cwiseMin(xy);
    max2 = max2.cwiseMax(xy);
  }
  const Eigen::Vector2d mid = 0.5 * (min2 + max2);
  v.focal = centre + mid.x() * right + mid.y() * up;
  constexpr double kFill = 0.86; // of the half width / height
  const double half_v = 0.5 * v.view_angle_deg * M_PI / 180.0;
  const double tan_v = std::tan(half_v) * kFill;
  // The object fills the left (1 - right_reserve) of the frame: its centre appears at
  // -right_reserve in normalised [-1, 1] coordinates (window centre +right_reserve).
  const double tan_h =
    std::tan(half_v) * width / height * kFill * (1.0 - right_reserve);
  v.window_center_x = right_reserve;
  double distance = 1e-9;
  for (const auto& p : cloud) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      continue;
    const Eigen::Vector3d q = Eigen::Vector3d(p.x, p.y, p.z) - v.focal;
    const double z = q.dot(d);
    distance = std::max(distance, z + std::abs(q.dot(right)) / tan_h);
    distance = std::max(distance, z + std::abs(q.dot(up)) / tan_v);
  }
  distance = std::max(distance, 1e-6 * (hi - lo).norm());
  v.position = v.focal + distance * d;
  v.up = up;
  v.pixels_per_unit = height / (2.0 * distance * std::tan(half_v));
  return v;
}

float
pointSize(double cell_size,
          std::size_t band_cells,
          std::size_t points,
          const View& view)
{
  if (points == 0 || cell_size <= 0.0 || band_cells == 0)
    return 2.f;
  const double spacing =
    cell_size * std::sqrt(static_cast<double>(band_cells) / points);
  const double pixels = 2.2 * spacing * view.pixels_per_unit;
  return static_cast<float>(std::clamp(std::round(pixels), 2.0, 10.0));
}

bool
sensorView(const pcl::PointCloud<visfeat::PointVisibility>& cloud,
           Eigen::Vector3d& direction,
           Eigen::Vector3d& up)
{
  if (cloud.height <= 1)
    return false;
  const Eigen::Matrix3d turn =
    cloud.sensor_orientation_.toRotationMatrix().cast<double>();
  direction = -turn.col(2);
  up = -turn.col(1);
  return true;
}

} // namespace visfeat_tools
