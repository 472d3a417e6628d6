#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace visfeat {

/** \brief Cells per point spacing of the automatic resolution: a cell of 2 spacings
 * holds ~4 points per face crossing it, so the band has no holes; clouds sampled at
 * 0.5 cell of resolution N (visfeat_generate's default) come back at about N. */
constexpr double kSpacingsPerCell = 2.0;

/** \brief Points (evenly spread over the finite ones) whose neighbour distance is
 * measured for the point spacing. */
constexpr std::size_t kSpacingQueries = 10000;

/** \brief Rank of the neighbour whose distance is measured (fewer when the cloud has
 * fewer points): 8 ignores a few duplicate points. */
constexpr int kSpacingNeighbour = 8;

/** \brief The automatic resolution of a cloud and how it was found (see
 * visfeat::estimateResolution() for a PCL cloud). */
struct ResolutionEstimate
{
  /** \brief Cells along the longest side of the bounding box, in
   * [GridSpec::kMinResolution, GridSpec::kMaxResolution]. */
  int resolution = 0;
  /** \brief Point spacing, world units: the mean distance between neighbours
   * (spacing^2 = surface area per point). */
  double spacing = 0.0;
  /** \brief Rank of the neighbour measured. */
  int k = 0;
  /** \brief Points whose k-th neighbour distance was measured. */
  std::size_t queries = 0;
  /** \brief Longest side of the bounding box of the finite points, world units. */
  double extent = 0.0;
  /** \brief extent / (kSpacingsPerCell spacing), rounded, before clamping. */
  double unclamped = 0.0;
  /** \brief True when unclamped was outside the range of GridSpec. */
  bool clamped = false;
  /** \brief One line saying why, without the resolution itself, e.g. "point spacing
   * 0.0039 (median distance to the 8th nearest neighbour over 10000 points), 2
   * spacings per cell, extent 2". */
  std::string reason;
};

/** \brief The point spacing from the distance r to the k-th nearest neighbour: k
 * neighbours cover a disc of area pi r^2, and for uniform random samples
 * pi r^2 / spacing^2 is Gamma(k, 1) distributed, whose median is about k - 1/3; so
 * spacing = r sqrt(pi / (k - 1/3)). */
double spacingFromNeighbourDistance(double r, int k);

/** \brief extent / (kSpacingsPerCell spacing), rounded, clamped to
 * [GridSpec::kMinResolution, GridSpec::kMaxResolution] (a NaN gives the minimum). */
int resolutionForSpacing(double extent, double spacing);

/** \brief The estimate from the k-th neighbour distances of the queried points (any
 * order; world units) and the extent: the median distance (robust to edges and
 * outliers) gives the spacing (spacingFromNeighbourDistance()), the spacing the
 * resolution (resolutionForSpacing()).
 * \throws visfeat::Error when distances is empty, or the median is 0 ("most points
 *         have k or more duplicates"). */
ResolutionEstimate
resolutionFromNeighbourDistances(std::vector<double> distances, int k, double extent);

} // namespace visfeat
