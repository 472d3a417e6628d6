#pragma once

#include <visfeat/core/band/triangle_cells.h>
#include <visfeat/core/common/parameters.h>

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace visfeat {

/** \brief How a cloud too sparse for its resolution is filled between its points
 * (LocalTriangleFill). */
struct LocalTriangleParameters
{
  /** \brief Nearest neighbours looked at per point (the umbrella's candidates). */
  int neighbours = 24;
  static constexpr ParameterRange<int> kNeighboursRange{4, 64};
  /** \brief Triangles whose angle at the point exceeds this (degrees, on its tangent
   * plane) are left out: slivers along the border of the scanned surface. */
  double max_gap_degrees = 170.0;
  static constexpr ParameterRange<double> kMaxGapRange{30.0, 180.0};
  /** \brief Triangle edges longer than this many local spacings (the point's distance
   * to its kSpacingNeighbour-th neighbour) are left out: they would bridge gaps and
   * holes of the scan. */
  double max_edge_spacings = 3.5;
  static constexpr ParameterRange<double> kMaxEdgeRange{1.0, 10.0};
  /** \brief Triangles whose corners' tangent planes differ by more than this (degrees)
   * lie across a crease and are rebuilt sharp (creaseFillCells()); 180: off, every
   * triangle rasterised as it is. */
  double crease_degrees = 20.0;
  static constexpr ParameterRange<double> kCreaseDegreesRange{1.0, 180.0};
  /** \brief A triangle is kept when at least this many of its 3 corners find it
   * Delaunay around themselves: 2 drops the chords that only one corner's tangent
   * plane allows (across creases, where the planes disagree). */
  int min_votes = 1;
  static constexpr ParameterRange<int> kMinVotesRange{1, 3};
  /** \brief The neighbour whose distance is a point's local spacing (1-based, among
   * the distinct neighbours: copies at distance 0 are skipped). */
  static constexpr int kSpacingNeighbour = 12;

  /** \throws visfeat::Error for a value out of its range. */
  void validate() const;
};

/** \brief The umbrella of every point: the triangles of a local Delaunay
 * triangulation around each point on its tangent plane, which together cover the
 * surface between the points.
 *
 * For point p, among its `k` nearest neighbours (distinct positions, within
 * max_edge_spacings local spacings): the tangent plane is the least-squares plane of p
 * and those neighbours (smallest eigenvector of their covariance); every triangle
 * (p, a, b) of two neighbours whose circumcircle on that plane holds no other
 * neighbour (Delaunay), with edges up to max_edge_spacings and an angle at p up to
 * max_gap_degrees, is kept. Near a crease the triangles join the nearest points across
 * it, so the filled surface cuts the crease by less than about a point spacing.
 *
 * \param[in] points positions (any units; non-finite points get no triangle)
 * \param[in] neighbours k indices per point, row i = neighbours[i * k, (i + 1) * k),
 *            nearest first; an index >= points.size() (or the point itself) is skipped
 * \param[in] k neighbours per point in `neighbours`
 * \param[in] parameters see LocalTriangleParameters (validated)
 * \param[in] threads 0 = all available; the result does not depend on it
 * \return triangles as indices into points, in point order.
 * \throws visfeat::Error for bad parameters or a neighbour table of the wrong size. */
std::vector<TriangleIndices>
umbrellaTriangles(const std::vector<Eigen::Vector3d>& points,
                  const std::vector<std::uint32_t>& neighbours,
                  int k,
                  const LocalTriangleParameters& parameters,
                  int threads);

} // namespace visfeat
