#pragma once

#include <visfeat/core/common/parameters.h>
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
   * rounding creases only within about this distance. 2 cells averages ~50 points at
   * 0.5-cell spacing. Default kDefaultRadius (2, the estimator's noise mode); range
   * (0, 8] for smoothPoints(), kRadiusRange = [0, 8] for the estimator, where 0 = off.
   */
  double radius = kDefaultRadius;
  /** \brief Points with fewer neighbours (itself included) stay where they are.
   * Default 6, range kMinNeighboursRange (points). */
  int min_neighbours = 6;
  /** \brief OpenMP threads; 0 = all. The result does not depend on it. Range
   * kThreadsRange. */
  int threads = 0;

  static constexpr double kDefaultRadius = 2.0;
  /** \brief [0, 8] cells; smoothPoints() itself needs radius > 0 (0 = off is the
   * estimator's). */
  static constexpr ParameterRange<double> kRadiusRange{0.0, 8.0};
  /** \brief [0, 100000] points. */
  static constexpr ParameterRange<int> kMinNeighboursRange{0, 100000};
  /** \brief [0, 1024], 0 = all available. */
  static constexpr ParameterRange<int> kThreadsRange{0, 1024};

  /** \brief Throws visfeat::Error naming the first parameter out of range, with its
   * value, range and unit. A radius of 0 passes (the estimator's "off"). */
  void validate() const;
};

/** \brief Projects every point onto the least-squares plane of its neighbours within
 * parameters.radius cells (the noise mode of VisibilityFeatureEstimation).
 *
 * Neighbours are found through the grid's cells (no search tree): the points are
 * bucketed by cell, the cells within the radius are looked up once for all the points
 * of a cell, and each point scans their points. Non-finite points are returned
 * unchanged and are nobody's neighbour.
 *
 * \param[in] points the cloud (world units); every finite point must lie in the grid
 * \param[in] grid   the grid (cell size, origin, dims)
 * \return the projected points, in the input's order.
 * \throws visfeat::Error for a radius out of range (0, 8], other parameters out of
 *         range (SmoothingParameters::validate), or a finite point outside the grid
 *         (GridSpec::cellOf). */
std::vector<Eigen::Vector3f> smoothPoints(const std::vector<Eigen::Vector3f>& points,
                                          const GridSpec& grid,
                                          const SmoothingParameters& parameters);

} // namespace visfeat
