#pragma once

#include <visfeat/core/band/voxel_band.h>
#include <visfeat/core/segmentation/flat_cores.h>

#include <cstdint>
#include <vector>

namespace visfeat {

/** \brief Opening radius that tells an edge ridge from a face core, in 6-steps: 3.
 * Edge ridges are 2-4 cells wide (depth <= 2, ComponentParameters::face_min_depth), so
 * erosion by 3 steps removes them while a face core, tens of cells wide, keeps its
 * middle; dilating that middle back by 3 steps restores the face core up to its border
 * and leaves the ridges out. Measured 2026-12-03 on the public fandisk mesh at 512
 * cells: two 80-90 degree creases, 368 and 417 cells long, whose ridges of radius 16
 * join a face core where their valleys fade (a 30-36 degree stretch at one end), were
 * labelled face along their whole length. Not swept. */
constexpr std::uint32_t kRidgeOpeningSteps = 3;

/** \brief A face core split into the edge ridges joined to it and what is left. */
struct RidgeSplit
{
  /** \brief The rest of the face core, in connected pieces (each in the order of a
   * 6-step flood from its first cell in `members`; pieces in that order too). */
  std::vector<std::vector<CellId>> face_pieces;
  /** \brief The ridges, each a connected list of cells, in the order of their first
   * cell in `members`. */
  std::vector<std::vector<CellId>> ridges;
  /** \brief The cells between the face core and the ridges, to leave out of every
   * core. */
  std::vector<CellId> gap;
};

/** \brief Thin parts of a face core that are edge ridges joined to it.
 *
 * A crease's ridge of cells that reach min_radius is separated from the face cores
 * beside it by the crease's valleys; where a valley fades (a crease that turns shallow
 * at one end, a corner whose cells all see far), the ridge and a face core form one
 * component, which is thick enough to be a face, and the watershed then labels the
 * whole crease face. This finds such ridges by a morphological opening within the
 * component: cells at least kRidgeOpeningSteps 6-steps from its border, dilated back
 * by kRidgeOpeningSteps steps through the component, are the face core; the rest falls
 * into connected thin pieces. A piece is a ridge when, without the cells next to the
 * face core (left out of every core, so that the two never touch), it still bends like
 * a crease fading into its face (fadingCreaseCore(): more than 5 min_radius connected
 * cells, a turn of about 40 degrees): such a ridge stands as an edge even with one face
 * on both sides. Thin pieces that bend less stay in the face: on a sparse cloud's rough
 * band a face core is lacy, its thin pieces read 0.010-0.013 (the box with hole at
 * 10,000 points), and split off they broke its rims into several edges.
 * \param[in] band the voxel band
 * \param[in] members the face core's cells (non-empty)
 * \param[in] depth per band cell, the 6-step distance of a member from the core's
 *            border (ComponentSet::measure())
 * \param[in] min_radius the core radius, rings
 * \param[in,out] stamp scratch, one entry per band cell (band.size()); entries are
 *            left as any value above their previous maximum
 * \param[in,out] next_stamp the next unused stamp (advanced)
 * \return the split; all empty when no ridge was found */
RidgeSplit attachedRidges(const VoxelBand& band,
                          const std::vector<CellId>& members,
                          const std::vector<std::uint32_t>& depth,
                          int min_radius,
                          std::vector<std::uint32_t>& stamp,
                          std::uint32_t& next_stamp);

} // namespace visfeat
