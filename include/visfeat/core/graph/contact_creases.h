#pragma once

#include <visfeat/core/band/voxel_band.h>
#include <visfeat/core/common/feature_class.h>
#include <visfeat/core/graph/crease_angles.h>

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <cstdint>
#include <set>
#include <vector>

namespace visfeat {

/** \brief A crease where two face regions meet with no edge region between them, and
 * the band cells along it.
 *
 * Where two features lie closer than the separation of the map (about 2 min_radius
 * cells), or a crease is curved or short, no edge core forms on it: the watershed
 * grows the two faces into each other, and their boundary lies where the floods met,
 * not on the crease (measured: several cells off on the public CAD meshes). The turn
 * across the contact (measureFaceContacts()) tells a crease from a blend; the crease's
 * line is where the two faces' fitted planes cross. */
struct ContactCrease
{
  /** \brief The two face labels (smaller first). */
  std::array<std::uint32_t, 2> faces{{0, 0}};
  /** \brief The median turn over the samples that placed it, degrees. */
  double degrees = 0.0;
  /** \brief Contact cells whose sides turned by at least the minimum crease angle. */
  std::uint32_t samples = 0;
  /** \brief Cells of the two faces whose centres lie within the half width of the
   * crease's line, ascending ids (with those of its line followed beyond its ends). */
  std::vector<CellId> cells;

  /** \brief An end of the crease that touches no vertex region: its line, followed
   * beyond the last sample, ran into an edge region (meets_edge) or left the two faces
   * (into a third face, or off the band past a convex corner or a border), at `at`
   * (world units), going `direction` (unit, outward). */
  struct End
  {
    Eigen::Vector3d at = Eigen::Vector3d::Zero();
    Eigen::Vector3d direction = Eigen::Vector3d::Zero();
    bool meets_edge = false;
  };
  /** \brief Its ends that need a corner (contactCorners()). */
  std::vector<End> open_ends;
};

/** \brief Ends of contact creases farther apart than this are not one corner, cells:
 * 10, the clearance (CreaseAngleParameters::kContactClearanceCells) plus 2, as each
 * crease's samples stop that far from the features around a corner. */
constexpr double kContactCornerGatherCells = 10.0;

/** \brief Least radius of a corner's cells, cells: 1.5 (the 3x3x3 block around it). */
constexpr double kContactCornerRadiusCells = 1.5;

/** \brief Largest radius of a corner's cells, cells: 4 (a window). */
constexpr double kContactCornerMaxRadiusCells = 4.0;

/** \brief Half the width of a contact crease's cells, cells: 1, as feature_width keeps
 * about the skeleton of an edge (its points then lie within about 2 cells of the
 * crease's line). */
constexpr double kContactCreaseHalfWidth = 1.0;

/** \brief Fewest samples (contact cells that turn) of a contact crease: 16, about
 * min_radius cells of crease. Shorter pieces are the watershed's spills near corners:
 * with CreaseAngleParameters::kMinContactSamples (8) the icosahedron at 20,000 points
 * (rotation 4007 of the invariance test) gained a 27-cell edge beside a corner. */
constexpr std::size_t kMinContactCreaseSamples = 16;

/** \brief The creases where two face regions touch (6-neighbour cells) and turn.
 *
 * One sample per cell of a face that is a 6-neighbour of another face, the pair not in
 * `excluded`, farther than CreaseAngleParameters::kContactClearanceCells from every
 * edge and vertex point (near them the watershed spills across creases that have
 * their edge; so a crease stops a few cells short of the edges it meets): the points of
 * each face within window_cells are fitted by a plane (least squares; at least
 * CreaseAngleParameters::kMinSidePoints a side), and where the sides turn by at least
 * min_crease_angle degrees (detail: the turn of measureCreaseAngles), the cells of the
 * two faces within the window whose centres lie within half_width_cells of the line
 * where the planes cross are the crease's. A pair is a crease when at least
 * CreaseAngleParameters::kMinContactSamples samples turned (a contact of a few cells
 * near a corner is none); its turn is their median. Deterministic; pairs in ascending
 * order. \param[in] band the voxel band \param[in] cell_labels per band cell, its
 * region label (0 = none) \param[in] points the labelled points (world units)
 * \param[in] labels per point, its region label (1..N, 0 = none)
 * \param[in] classes per region, its class (classes[label - 1])
 * \param[in] excluded face pairs (smaller label first) to leave alone, e.g. those an
 *   edge region already separates (their contact is the watershed spilling across it)
 * \param[in] window_cells radius of the fit, cells (CreaseAngleParameters)
 * \param[in] min_crease_angle degrees (CreaseAngleParameters); 0 = none found
 * \param[in] half_width_cells half the width of the crease's cells, cells
 * \param[in] threads threads over the contact cells (0 = all available); the result
 *            is the same for any count */
std::vector<ContactCrease>
locateContactCreases(const VoxelBand& band,
                     const std::vector<std::uint32_t>& cell_labels,
                     const std::vector<Eigen::Vector3d>& points,
                     const std::vector<std::uint32_t>& labels,
                     const std::vector<FeatureClass>& classes,
                     const std::set<std::array<std::uint32_t, 2>>& excluded,
                     double window_cells,
                     double min_crease_angle,
                     double half_width_cells,
                     int threads = 1);

/** \brief The corners where contact creases end (ContactCrease::open_ends), as lists
 * of face cells to become vertex regions.
 *
 * A crease's line followed beyond its last sample (up to kContactCornerGatherCells)
 * touches a vertex (nothing to add), an edge region (a corner where it meets that
 * edge), or leaves its two faces (into a third face, or off the band: past a convex
 * corner the line leaves the surface): ends of two or more creases that left
 * their faces within kContactCornerGatherCells of each other meet at one corner, the
 * point nearest all their lines (least squares; their ends' mean where the lines are
 * near parallel or the point lies farther than that from an end). A corner's cells
 * are the face cells (by cell_labels, before the creases are added) within the
 * distance of its farthest end plus half a cell, at least kContactCornerRadiusCells
 * and at most kContactCornerMaxRadiusCells. A lone end that left its faces makes no
 * corner (a crease that fades into a blend, or reaches a border of an open scan).
 * Deterministic (creases in order). */
std::vector<std::vector<CellId>>
contactCorners(const VoxelBand& band,
               const std::vector<std::uint32_t>& cell_labels,
               const std::vector<FeatureClass>& classes,
               const std::vector<ContactCrease>& creases);

/** \brief The turn of each edge region made from contact creases (after
 * FeatureSegmentation::addRegions()): per label (index 0 unused, size classes.size() +
 * 1), ContactCrease::degrees of the crease holding most of the region's cells (the
 * first such crease among equals) where is_new[label] and the region is an edge; NaN
 * elsewhere. Creases of one face that meet overlap at their ends, and addRegions()
 * gives their shared cells to one of them: a crease's first cells may lie in its
 * neighbour's edge region (measured: 6 of the public fandisk's 50 edges at 512 were
 * left without a turn when each crease named the region of its first cell).
 * cell_labels: per band cell its region label; is_new: per label (size at least
 * classes.size() + 1). Throws visfeat::Error on a label beyond them. */
std::vector<double> contactCreaseTurns(const std::vector<ContactCrease>& creases,
                                       const std::vector<std::uint32_t>& cell_labels,
                                       const std::vector<FeatureClass>& classes,
                                       const std::vector<char>& is_new);

} // namespace visfeat
