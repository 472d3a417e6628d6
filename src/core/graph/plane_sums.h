// The turn between two least-squares planes (PlaneSums) (private to core/graph: the
// crease-angle measurement).
#pragma once

#include "../common/angles.h"
#include "../common/plane_sums.h"

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace visfeat {
namespace detail {

/** The line where two sides meet (unit): where their planes (normals na, nb) cross;
 * for nearly parallel planes (the cross product is then noise), across the way from
 * one side's centroid (ua, in its plane) to the other's (ub). Zero when undefined. */
inline Eigen::Vector3d
creaseLine(const Eigen::Vector3d& na,
           const Eigen::Vector3d& nb,
           const Eigen::Vector3d& ua,
           const Eigen::Vector3d& ub)
{
  constexpr double kMinLineSine = 0.0175; // sin(1 degree)
  Eigen::Vector3d line = na.cross(nb);
  if (line.norm() <= kMinLineSine)
    line = (na + (na.dot(nb) >= 0.0 ? 1.0 : -1.0) * nb).cross(ub - ua);
  return line.norm() > 0.0 ? Eigen::Vector3d(line.normalized())
                           : Eigen::Vector3d::Zero();
}

/** 180 degrees minus the angle between ua and ub, the directions from a point of a
 * crease into its two sides, once their components along the unit `line` (zero: none)
 * are removed; NaN when one vanishes. */
inline double
turnAcross(Eigen::Vector3d ua, Eigen::Vector3d ub, const Eigen::Vector3d& line)
{
  ua -= ua.dot(line) * line;
  ub -= ub.dot(line) * line;
  const double la = ua.norm(), lb = ub.norm();
  if (!(la > 0.0) || !(lb > 0.0))
    return std::numeric_limits<double>::quiet_NaN();
  const double cosine = std::clamp(ua.dot(ub) / (la * lb), -1.0, 1.0);
  return 180.0 - std::acos(cosine) * 180.0 / detail::kPi;
}

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
  return turnAcross(ua, ub, creaseLine(na, nb, ua, ub));
}

/** The turn between the two halves of a window split across `line` (unit, in the
 * split plane), degrees: as turnOfSides() with the line given instead of found. Two
 * halves of one plane read 0 whatever the spread of their points along the line
 * (turnOfSides() reads the offset of their centroids along it as a turn where the
 * planes are nearly parallel: up to 18 degrees on flat faces at 4 cells a point
 * spacing). Sums relative to a point of the split plane; NaN as turnOfSides(). */
inline double
turnOfHalves(const PlaneSums& a, const PlaneSums& b, const Eigen::Vector3d& line)
{
  if (a.count < 3 || b.count < 3)
    return std::numeric_limits<double>::quiet_NaN();
  const Eigen::Vector3d na = a.normal(), nb = b.normal();
  Eigen::Vector3d ua = a.mean(), ub = b.mean();
  ua -= ua.dot(na) * na;
  ub -= ub.dot(nb) * nb;
  return turnAcross(ua, ub, line);
}

/** From a point of a crease between sides a and b (sums relative to it), where side a
 * lies: `foot`, the point's foot on a's plane, and `away`, the unit direction in a's
 * plane from the crease line towards a's centroid; false when undefined. */
inline bool
sideDirection(const PlaneSums& a,
              const PlaneSums& b,
              Eigen::Vector3d& foot,
              Eigen::Vector3d& away)
{
  if (a.count < 3 || b.count < 3)
    return false;
  const Eigen::Vector3d na = a.normal(), nb = b.normal();
  Eigen::Vector3d ua = a.mean(), ub = b.mean();
  foot = ua.dot(na) * na;
  ua -= foot;
  ub -= ub.dot(nb) * nb;
  const Eigen::Vector3d line = creaseLine(na, nb, ua, ub);
  away = ua - ua.dot(line) * line;
  if (!(away.norm() > 0.0))
    return false;
  away.normalize();
  return true;
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
