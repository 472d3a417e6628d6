#pragma once

#include <visfeat/core/band/voxel_band.h>
#include <visfeat/core/common/feature_class.h>

#include <array>
#include <cstdint>
#include <vector>

namespace visfeat {

/** \brief A piece of a face that a new edge cut off (a contact crease's), and the face
 * it goes to. */
struct FacePiece
{
  /** \brief Its cells, ascending ids. */
  std::vector<CellId> cells;
  /** \brief The face on its side of the crease (the other face of the pair). */
  std::uint32_t into = 0;
};

/** \brief The pieces of the contact creases' faces that their new edges cut off.
 *
 * Where the watershed spilled across a crease, one face holds a strip of the other's
 * surface up to the contact; the crease's edge (its line found walking across the
 * contact, locateContactCreases()) then runs through that face and cuts the strip off
 * from it. For each pair (a, b), every 6-connected piece of face a but its largest
 * (by cells) goes to b when it shares more boundary with b (6-neighbour pairs of cells)
 * than with any other face, and the same the other way round. Deterministic.
 *
 * Source: visfeat (not in the paper).
 * \param[in] band the band the labels are of
 * \param[in] cell_labels per band cell, its region label, the creases' edges added
 * \param[in] classes per region, its class (classes[label - 1])
 * \param[in] pairs the creases' face pairs, in the labels of cell_labels
 * \return the pieces, in order of the pairs, a's before b's */
std::vector<FacePiece>
cutOffFacePieces(const VoxelBand& band,
                 const std::vector<std::uint32_t>& cell_labels,
                 const std::vector<FeatureClass>& classes,
                 const std::vector<std::array<std::uint32_t, 2>>& pairs);

} // namespace visfeat
