// The automatic resolution of the visfeat tool (not installed, not public API): the
// shape of a cloud (collinear, coplanar) and its point spacing, from which the
// resolution follows when the user gives no -resolution.
#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Core>

#include <cstddef>
#include <string>

namespace visfeat_tools {

/** \brief Finite points of a cloud, their bounding box and principal widths. */
struct CloudShape
{
  std::size_t finite = 0;
  /** Longest side of the bounding box (the grid's extent). */
  double extent = 0.0;
  /** Width of the points along their three principal axes, largest first. */
  Eigen::Vector3d widths = Eigen::Vector3d::Zero();
};

/** \brief The shape of the finite points of `cloud` (extent and widths stay 0 for
 * fewer than 2 finite points). */
CloudShape cloudShape(const pcl::PointCloud<pcl::PointXYZ>& cloud);

/** \brief The point spacing of a cloud: the mean distance between neighbours as
 * visfeat_generate defines it (spacing^2 = surface area per point), estimated from the
 * median distance r to the k-th nearest neighbour over a deterministic subsample
 * (every n/queries-th finite point): k neighbours cover a disc of area pi r^2, so
 * spacing = r sqrt(pi / (k - 1/3)) (k - 1/3: the median of the count for uniform
 * random samples). The median ignores edges and outliers; k = 8 ignores a few
 * duplicate points. */
struct SpacingEstimate
{
  double spacing = 0.0;
  std::size_t queries = 0;
  int k = 0;
};

/** \brief Estimate the point spacing from at most `max_queries` points; false +
 * `error` when there are too few finite points or too many duplicates. */
bool estimateSpacing(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                     std::size_t max_queries,
                     SpacingEstimate& estimate,
                     std::string& error);

/** \brief Cells per point spacing of the automatic resolution: a cell of 2 spacings
 * holds ~4 points per face crossing it, so the band has no holes; visfeat_generate
 * samples at 0.5 cell by default, so its clouds come back at their own resolution. */
constexpr double kSpacingsPerCell = 2.0;

/** \brief extent / (kSpacingsPerCell spacing), rounded, clamped to GridSpec's range. */
int resolutionForSpacing(double extent, double spacing);

/** \brief Points the automatic resolution queries for their spacing. */
constexpr std::size_t kSpacingQueries = 10000;

/** \brief Refuse clouds without a surface and, when the user gave no -resolution,
 * choose it from the point spacing (printing what was chosen and why).
 *
 * - All points on a line (the second principal width below 1e-5 of the first), or
 *   within 2 cells of one at the resolution: refused, there is no surface to label.
 * - All points in a plane: processed (one face: the outline of a flat patch is a
 *   boundary, not a crease), with a note.
 * - No finite point, a single one, or all coincident: left to the estimator, whose
 *   message says so. */
bool checkShapeAndResolution(const std::string& input,
                             const pcl::PointCloud<pcl::PointXYZ>& xyz,
                             bool user_resolution,
                             int& resolution,
                             std::string& error);

} // namespace visfeat_tools
