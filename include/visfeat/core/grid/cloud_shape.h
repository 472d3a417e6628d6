#pragma once

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace visfeat {

/** \brief The extent and principal widths of the finite points of a cloud: what tells
 * a surface from a line or a plane, before any grid is made.
 *
 * World units. A cloud with fewer than 2 finite points has finite < 2 and zeros
 * elsewhere. */
struct CloudShape
{
  /** \brief Number of finite points. */
  std::size_t finite = 0;
  /** \brief Longest side of the axis-aligned bounding box (the grid's extent). */
  double extent = 0.0;
  /** \brief Width of the points along their three principal axes (eigenvectors of their
   * scatter), largest first. */
  Eigen::Vector3d widths = Eigen::Vector3d::Zero();
};

/** \brief Relative width below which a cloud is flat along an axis: collinear when the
 * second principal width is <= this times the first, coplanar when the third is. */
constexpr double kFlatRelativeWidth = 1e-5;

/** \brief A surface needs at least this many cells across (second principal width),
 * or its band is a line of cells. */
constexpr double kMinCellsAcross = 2.0;

/** \brief The shape of a cloud, from a function that visits its finite points.
 *
 * \param[in] for_each_point called three times as for_each_point(visit); it must call
 *            visit(const Eigen::Vector3d&) once per finite point, in the same order
 *            each time (world units).
 * Three passes: bounding box and mean, scatter, extent along the principal axes. */
template <typename ForEachPoint>
CloudShape
cloudShape(const ForEachPoint& for_each_point)
{
  CloudShape shape;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::max());
  Eigen::Vector3d hi = -lo;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for_each_point([&](const Eigen::Vector3d& v) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
    sum += v;
    ++shape.finite;
  });
  if (shape.finite < 2)
    return shape;
  shape.extent = (hi - lo).maxCoeff();
  const Eigen::Vector3d mean = sum / static_cast<double>(shape.finite);
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for_each_point([&](const Eigen::Vector3d& v) {
    const Eigen::Vector3d d = v - mean;
    covariance += d * d.transpose();
  });
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
  // Eigenvalues ascending: axis 2 is the main one.
  Eigen::Vector3d pmin = Eigen::Vector3d::Constant(std::numeric_limits<double>::max());
  Eigen::Vector3d pmax = -pmin;
  for_each_point([&](const Eigen::Vector3d& v) {
    const Eigen::Vector3d q = solver.eigenvectors().transpose() * (v - mean);
    pmin = pmin.cwiseMin(q);
    pmax = pmax.cwiseMax(q);
  });
  const Eigen::Vector3d w = pmax - pmin;
  shape.widths = Eigen::Vector3d(w[2], w[1], w[0]);
  return shape;
}

/** \brief cloudShape() of a vector of points; non-finite points are skipped. */
CloudShape cloudShape(const std::vector<Eigen::Vector3d>& points);

/** \brief True when the shape can be judged: at least 2 finite points and a positive
 * extent (otherwise the grid refuses the cloud with its own message). */
bool hasExtent(const CloudShape& shape);

/** \brief All points on a line: the second principal width is <= kFlatRelativeWidth
 * times the first. False when !hasExtent(shape). */
bool isCollinear(const CloudShape& shape);

/** \brief All points in a plane: the third principal width is <= kFlatRelativeWidth
 * times the first. False when !hasExtent(shape). */
bool isCoplanar(const CloudShape& shape);

/** \brief Why a cloud has no surface to label, in one line, or "" when it has one.
 *
 * - collinear (isCollinear()): "all N finite points lie on a line (collinear): there is
 *   no surface to label";
 * - with resolution > 0, within kMinCellsAcross cells of a line at that resolution
 *   (cell = extent / resolution): "the points lie within X cells of a line at
 *   resolution R: a surface needs at least 2 cells across; raise the resolution".
 * "" when !hasExtent(shape): the grid's own checks (no finite point, all coincident)
 * report those clouds. */
std::string shapeProblem(const CloudShape& shape, int resolution);

/** \brief A note for a coplanar cloud (processed as one face), or "":
 * "all points lie in a plane: expect one face and no edges or vertices (the outline of
 * a flat patch is a boundary, not a crease)". */
std::string shapeNote(const CloudShape& shape);

} // namespace visfeat
