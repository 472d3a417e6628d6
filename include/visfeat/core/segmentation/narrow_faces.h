#pragma once

#include <visfeat/core/band/voxel_band.h>
#include <visfeat/core/visibility/visibility_map.h>

#include <cstddef>
#include <vector>

namespace visfeat {

/** \brief A peak of the visibility map below min_radius that stands clear of its
 * surroundings: a face too narrow for a core at this resolution.
 *
 * Across a face the radius rises from the creases on its sides to its middle; a face
 * at least 2 min_radius cells wide reaches min_radius there (its core), a narrower one
 * peaks lower and has no core, so the segmentation merges it into the edges around it.
 * Its peak is separated from every higher part of the map by the valleys of its
 * creases; the depth of the shallowest such valley (the peak's persistence, in the
 * sense of a merge tree of the map's superlevel sets) tells a narrow face from the
 * roughness of a band, whose bumps are a ring or two high. */
struct NarrowFace
{
  /** \brief Largest radius of the face, rings (< min_radius). */
  int peak = 0;
  /** \brief Radius of the highest path from the peak to a higher peak (or 0 when
   * there is none), rings: the crease valley the face ends at. */
  int saddle = 0;
  /** \brief Cells of the face above the saddle. */
  std::size_t cells = 0;
  /** \brief A cell at the peak (the lowest id among the part's highest cells). */
  CellId peak_cell = kNoCell;
};

/** \brief The narrow faces of a map (see NarrowFace): peaks below min_radius whose
 * persistence (peak - saddle) is at least min_persistence rings, with at least
 * min_cells cells above their saddle. The merge tree joins cells through their six face
 * neighbours in the band, from the highest radius down (elder rule: where two parts
 * meet, the one with the lower peak ends; ties go to the lower cell id), so the result
 * does not depend on thread counts or point order.
 * \param[in] min_radius the core radius, rings
 * \param[in] min_persistence rings a peak must rise above its saddle
 * \param[in] min_cells fewest cells above the saddle
 * \return the narrow faces, most cells first (ties: higher peak first) */
std::vector<NarrowFace> narrowFaces(const VoxelBand& band,
                                    const VisibilityMap& map,
                                    int min_radius,
                                    int min_persistence,
                                    std::size_t min_cells);

} // namespace visfeat
