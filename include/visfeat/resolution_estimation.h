#pragma once

#include <visfeat/core/grid/cloud_shape.h>
#include <visfeat/core/grid/resolution.h>

#include <pcl/point_cloud.h>

namespace visfeat {

/** \brief The shape of a PCL cloud (visfeat::cloudShape over its points whose x, y, z
 * are all finite): extent and principal widths, world units. */
template <typename PointT>
CloudShape cloudShapeOf(const pcl::PointCloud<PointT>& cloud);

/** \brief The automatic resolution of a cloud: 2 point spacings per cell.
 *
 * The spacing is the median distance to the kSpacingNeighbour-th (8th) nearest
 * neighbour (pcl::KdTreeFLANN over the finite x y z) of kSpacingQueries (10,000)
 * finite points evenly spread through the cloud (every n/10000-th), turned into a mean
 * spacing by spacingFromNeighbourDistance(); the resolution is extent / (2 spacing),
 * rounded and clamped to [GridSpec::kMinResolution, GridSpec::kMaxResolution], where
 * extent is the longest side of the bounding box of the finite points. A cloud sampled
 * at half a cell of resolution N comes back at about N.
 *
 * Copies do not fool it: duplicate points (merged or re-exported scans) and copies a
 * little apart (overlapping registered scans, closer than kCopyRadiusSpacings of the
 * apparent spacing) are recognised from up to 8 x kMaxCopies neighbours of each
 * queried point, and the spacing is that of the sites of the surface, not of the
 * points (resolutionFromNeighbourTable(); ResolutionEstimate::copies says how many
 * copies most points have, and the reason says it too).
 *
 * Cost: a k-d tree of the finite points and 10,000 queries of 64 neighbours (~0.2-0.6 s
 * for 10^6 points); memory: a copy of the finite points (16 bytes each), the tree and
 * 5 MB of distances.
 * \return the resolution with the spacing, k, copies, queries, extent, whether it was
 *         clamped and a one-line reason (ResolutionEstimate).
 * \throws visfeat::Error with fewer than 2 finite points, or when most points have
 *         64 (kSpacingNeighbour x kMaxCopies) or more copies. */
template <typename PointT>
ResolutionEstimate estimateResolution(const pcl::PointCloud<PointT>& cloud);

/** \brief The same with the extent (world units) already known. */
template <typename PointT>
ResolutionEstimate estimateResolution(const pcl::PointCloud<PointT>& cloud,
                                      double extent);

} // namespace visfeat

#ifdef PCL_NO_PRECOMPILE
#include <visfeat/impl/resolution_estimation.hpp>
#endif
