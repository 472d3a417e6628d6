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
   * crease's line, ascending ids. */
  std::vector<CellId> cells;
};

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

} // namespace visfeat
