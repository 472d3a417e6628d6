#pragma once

#include <visfeat/core/grid/grid_spec.h>

#include <Eigen/Core>

#include <vector>

namespace visfeat {

/** \brief Parameters of smoothPoints(). */
struct SmoothingParameters
{
  /** \brief Neighbourhood radius, in cells of the grid. A noisy surface (Gaussian noise
   * of sigma cells) makes a band several cells thick and rough, whose bumps hide cells
   * from each other; a plane fitted over this radius averages the noise down while
   * rounding creases only within about this distance. Range (0, 8]. Default 2. */
  double radius = 2.0;
  /** \brief Points with fewer neighbours (itself included) stay where they are. */
  int min_neighbours = 6;
  /** \brief OpenMP threads; 0 = all. The result does not depend on it. */
  int threads = 0;
};

/** \brief Projects every point onto the least-squares plane of its neighbours within
 * parameters.radius cells (the noise mode of VisibilityFeatureEstimation).
 *
 * Neighbours are found through the grid's cells (no search tree): the points are
 * bucketed by cell and each point scans the cells within the radius. Non-finite points
 * are returned unchanged and are nobody's neighbour.
 *
 * \param[in] points the cloud (world units); every finite point must lie in the grid
 * \param[in] grid   the grid (cell size, origin, dims)
 * \return the projected points, in the input's order.
 * \throws visfeat::Error for a radius out of range, negative threads, or a finite point
 *         outside the grid. */
std::vector<Eigen::Vector3f> smoothPoints(const std::vector<Eigen::Vector3f>& points,
                                          const GridSpec& grid,
                                          const SmoothingParameters& parameters);

} // namespace visfeat
