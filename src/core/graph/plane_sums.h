// Least-squares planes of point sets and the turn between two of them (private to
// core/graph: the crease-angle measurement).
#pragma once

#include "../common/angles.h"

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace visfeat {
namespace detail {

/** Points accumulated for a least-squares plane. */
struct PlaneSums
{
  std::size_t count = 0;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  Eigen::Matrix3d outer = Eigen::Matrix3d::Zero();

  /** p relative to a nearby origin, so the sums stay well conditioned. */
  void add(const Eigen::Vector3d& p)
  {
    ++count;
    sum += p;
    outer += p * p.transpose();
  }
  /** Another set's points (relative to the same origin). */
  void add(const PlaneSums& other)
  {
    count += other.count;
    sum += other.sum;
    outer += other.outer;
  }
  Eigen::Vector3d mean() const { return sum / double(count); }
  /** The unit normal of the least-squares plane (smallest principal axis). */
  Eigen::Vector3d normal() const
  {
    const Eigen::Vector3d m = mean();
    const Eigen::Matrix3d covariance = outer / double(count) - m * m.transpose();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
    return solver.eigenvectors().col(0);
  }
};

/** The turn between two sides, degrees (sideTurnDegrees()), with their normals
 * (a.normal(), b.normal()); their sums are relative to the sample point. */
inline double
turnOfSides(const PlaneSums& a,
            const PlaneSums& b,
            const Eigen::Vector3d& na,
            const Eigen::Vector3d& nb)
{
  if (a.count < 3 || b.count < 3)
    return std::numeric_limits<double>::quiet_NaN();
  Eigen::Vector3d ua = a.mean(), ub = b.mean(); // the sample point is the origin
  ua -= ua.dot(na) * na;
  ub -= ub.dot(nb) * nb;
  // The line where the sides meet: where the planes cross; for nearly parallel
  // planes (the cross product is then noise), across the way from one side to the
  // other.
  constexpr double kMinLineSine = 0.0175; // sin(1 degree)
  Eigen::Vector3d line = na.cross(nb);
  if (line.norm() <= kMinLineSine)
    line = (na + (na.dot(nb) >= 0.0 ? 1.0 : -1.0) * nb).cross(ub - ua);
  if (line.norm() > 0.0) { // keep only the directions across that line
    const Eigen::Vector3d t = line.normalized();
    ua -= ua.dot(t) * t;
    ub -= ub.dot(t) * t;
  }
  const double la = ua.norm(), lb = ub.norm();
  if (!(la > 0.0) || !(lb > 0.0))
    return std::numeric_limits<double>::quiet_NaN();
  const double cosine = std::clamp(ua.dot(ub) / (la * lb), -1.0, 1.0);
  return 180.0 - std::acos(cosine) * 180.0 / detail::kPi;
}

/** The turn between two sides, degrees (sideTurnDegrees()); their sums are relative to
 * the sample point. */
inline double
turnOfSides(const PlaneSums& a, const PlaneSums& b)
{
  if (a.count < 3 || b.count < 3)
    return std::numeric_limits<double>::quiet_NaN();
  return turnOfSides(a, b, a.normal(), b.normal());
}

/** The unit direction from b's centroid to a's, in the plane fitted to both (sums
 * relative to the same origin); zero when it vanishes. */
inline Eigen::Vector3d
acrossDirection(const PlaneSums& a, const PlaneSums& b)
{
  PlaneSums both = a;
  both.add(b);
  const Eigen::Vector3d n = both.normal();
  Eigen::Vector3d across = a.mean() - b.mean();
  across -= across.dot(n) * n;
  return across.norm() > 0.0 ? Eigen::Vector3d(across.normalized())
                             : Eigen::Vector3d::Zero();
}

/** The points (relative to the sample) split by the plane through `origin` across
 * `direction`: `after` those beyond it, `before` the others; both sums relative to
 * origin. */
inline void
splitAcross(const std::vector<Eigen::Vector3d>& local,
            const Eigen::Vector3d& origin,
            const Eigen::Vector3d& direction,
            PlaneSums& before,
            PlaneSums& after)
{
  for (const Eigen::Vector3d& p : local)
    ((p - origin).dot(direction) > 0.0 ? after : before).add(p - origin);
}

} // namespace detail
} // namespace visfeat
