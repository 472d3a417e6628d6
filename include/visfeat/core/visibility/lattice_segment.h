#pragma once

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <vector>

namespace visfeat {

/** \brief A piece of a lattice segment that lies in one place of the subcell complex.
 *
 * Subcell s spans [s, s+1) in each axis, in subcell units. Inside a stretch the segment
 * is either in the open interior of one subcell (count 1), in the open interior of the
 * face between two subcells (count 2, the segment runs along the face) or on the open
 * edge between four subcells (count 4). The stretch passes through the interior of the
 * occluder exactly when all of its `count` subcells are occluded.
 */
struct SegmentStretch
{
  /** \brief Length in subcell edges (half a cell edge each). */
  double length = 0.0;
  /** \brief Parameter of the stretch's midpoint along the segment, in (0, 1). */
  double t_mid = 0.0;
  /** \brief 1, 2 or 4: how many of `subcells` are used. */
  int count = 0;
  /** \brief The subcells around the stretch, relative to the segment's start point. */
  std::array<Eigen::Vector3i, 4> subcells;
};

/** \brief Exact decomposition of the segment from the lattice point 0 to the lattice
 * point d (both subcell-grid vertices) into stretches of positive length.
 *
 * Integer arithmetic decides where the segment crosses subcell boundaries, so segments
 * that run along faces or edges (whenever d has a zero coordinate) are handled exactly.
 * Points where the segment only crosses a face, edge or corner have zero length and
 * are not listed: both sides of such a crossing are listed stretches already.
 * Returns no stretch for d = 0.
 */
std::vector<SegmentStretch> decomposeLatticeSegment(const Eigen::Vector3i& d);

} // namespace visfeat
