#pragma once

// Internal to the segmentation (not installed): the least-squares line of an edge's
// core, and what makes an edge straight.

#include <visfeat/core/band/voxel_band.h>

#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace visfeat {
namespace segmentation {

/** \brief An edge is straight when its core cells lie within this many cells of their
 * line. Set with the corners from edge lines (145ed0d: noise-free, 7 models x 3
 * rotations at 256), where cores are up to about 4 cells wide (the icosahedron's
 * 138-degree edges); kept for the noise mode (d39ae0a). Not swept. Also the sideways
 * tolerance of "on the line" (CoreLine::onLine, the vertex ahead of an edge). */
constexpr double kStraightTolerance = 3.0;

/** \brief Fewest core cells for an edge's line to stand for it (corner drawing,
 * centres on straight edges): fewer give no direction worth trusting. Set with the
 * corners from edge lines (145ed0d, 7 models x 3 rotations at 256); not swept. */
constexpr std::size_t kMinLineCells = 4;

/** \brief Pieces of one straight edge join across any gap when each is at least this
 * long (cells) and they are parallel and on one line: shorter pieces give directions
 * too loose to extrapolate tens of cells. Set on the icosahedron at sigma 0.32 (256),
 * whose 138-degree edges lost their ridge for 24-39 cells; not swept. */
constexpr double kMinJoinLength = 8.0;

/** \brief ... and parallel when the cosine of their angle is at least this: cos(15
 * degrees). Same measurement as kMinJoinLength. */
constexpr double kJoinCosine = 0.966;

/** \brief A core's least-squares line, in cell index units (cell (i, j, k) at
 * (i, j, k), not its centre). */
struct CoreLine
{
  /** \brief Mean of the cells. */
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  /** \brief Unit main axis of the cells' scatter. */
  Eigen::Vector3d direction = Eigen::Vector3d::UnitX();
  /** \brief Extent of the cells along the direction (cells). */
  double length = 0.0;
  /** \brief Largest distance of a cell from the line (cells). */
  double width = 0.0;

  /** \brief Its cells lie within kStraightTolerance of the line, at any length. */
  bool narrow() const { return width <= kStraightTolerance; }

  /** \brief Narrow and long enough (kMinJoinLength) to join other pieces on its line.
   */
  bool straight() const { return narrow() && length >= kMinJoinLength; }

  /** \brief `other` (shorter) continues this straight line: both are straight, they
   * are parallel within kJoinCosine, and other's middle lies within
   * kStraightTolerance of this line. */
  bool onLine(const CoreLine& other) const;
};

/** \brief The line of a set of cells (empty: the default CoreLine). */
CoreLine fitCoreLine(const VoxelBand& band, const std::vector<CellId>& cells);

} // namespace segmentation
} // namespace visfeat
