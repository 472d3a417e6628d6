// Points accumulated for a least-squares plane (private to the core: the crease
// angles, the smoothing of noisy points, the flat-ground test of feature points).
#pragma once

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cstddef>
#include <limits>

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
  Eigen::Matrix3d covariance() const
  {
    const Eigen::Vector3d m = mean();
    return outer / double(count) - m * m.transpose();
  }
  /** The unit normal of the least-squares plane (smallest principal axis). */
  Eigen::Vector3d normal() const
  {
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance());
    return solver.eigenvectors().col(0);
  }
  /** lambda_0 / (lambda_0 + lambda_1 + lambda_2) of the covariance (PCL's curvature,
   * 0 on a plane); NaN for fewer than 3 points or no spread. */
  double surfaceVariation() const
  {
    if (count < 3)
      return std::numeric_limits<double>::quiet_NaN();
    const Eigen::Matrix3d c = covariance();
    const double trace = c.trace();
    if (!(trace > 0.0))
      return std::numeric_limits<double>::quiet_NaN();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
    solver.computeDirect(c, Eigen::EigenvaluesOnly);
    return std::max(0.0, solver.eigenvalues()(0)) / trace;
  }
};

} // namespace detail
} // namespace visfeat
