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
 * fewer points), counted in sites of the surface when points have copies (see
 * kMaxCopies). */
constexpr int kSpacingNeighbour = 8;

/** \brief Most copies of a point the automatic resolution recognises: duplicate points
 * (merged or re-exported scans) and copies a little apart (overlapping registered
 * scans). Up to kSpacingNeighbour * kMaxCopies neighbours of each queried point are
 * looked at. */
constexpr int kMaxCopies = 8;

/** \brief Points closer than this many apparent spacings (the spacing of all points,
 * copies included) are copies of one site of the surface. On a clean, uniformly
 * sampled surface about a quarter of the points have a neighbour that close, so the
 * median copy count stays 1; on a cloud whose points all have a copy it is 2. */
constexpr double kCopyRadiusSpacings = 0.3;

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
  /** \brief Rank of the neighbour measured, in sites (a site is one point and its
   * copies). */
  int k = 0;
  /** \brief Copies of most points: the median, over the queried points, of the number
   * of points within copy_radius of each (itself included). 1 for a clean cloud; 3
   * when every point was stored three times (merged scans), 2 for two overlapping
   * copies of a scan a little apart. The spacing is that of the sites: the distance
   * measured is the one to the (k copies)-th neighbour, so the copies do not shrink it.
   */
  int copies = 1;
  /** \brief Points closer than this are copies of one site, world units:
   * kCopyRadiusSpacings times the apparent spacing (all points counted). 0 when not
   * measured. */
  double copy_radius = 0.0;
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

/** \brief Sorted distances from queried points to their nearest neighbours (the point
 * itself excluded), world units: row q is values[q * per_query, (q + 1) * per_query),
 * ranks 1..per_query. */
struct NeighbourDistanceTable
{
  std::size_t per_query = 0;
  std::vector<double> values;

  std::size_t queries() const { return per_query ? values.size() / per_query : 0; }
  double at(std::size_t query, std::size_t rank) const
  {
    return values[query * per_query + rank - 1];
  }
};

/** \brief The estimate with copies recognised (duplicate points, overlapping copies a
 * little apart).
 *
 * 1. The apparent spacing: the median distance to the k-th neighbour that does not
 *    coincide with the queried point (closer than 1e-9 extent), as
 *    spacingFromNeighbourDistance() turns it into a spacing.
 * 2. copy_radius = kCopyRadiusSpacings apparent spacings; each queried point's copy
 *    count is 1 + its neighbours within copy_radius (at most kMaxCopies and
 *    per_query / k); `copies` is the median count.
 * 3. The spacing: resolutionFromNeighbourDistances() over the distances to the
 *    (k copies)-th neighbour, the k-th site when every site has `copies` points. A
 *    clean cloud (copies 1) gets exactly the k-th neighbour's estimate. The reason
 *    says how many copies were found when there are any.
 *
 * Clouds where fewer than half the points have copies keep copies = 1 (their estimate
 * is the plain one).
 * \throws visfeat::Error when the table is empty, k is out of [1, per_query], or the
 *         median distance is 0 (most points have k x copies points at distance 0: 64 or
 * more with a full table; more than kMaxCopies copies are counted as kMaxCopies). */
ResolutionEstimate
resolutionFromNeighbourTable(const NeighbourDistanceTable& table, int k, double extent);

} // namespace visfeat
