#pragma once

#include <visfeat/core/band/voxel_band.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace visfeat {

/** \brief Radius of the band patch around a core cell that flatCore() fits, cells
 * (6-steps through the band): 10. Measured 2026-12-02 (median surface variation of the
 * patches around up to 32 cells of a core): the 42-degree edges of the generated
 * icosahedron at 256 read 0.019-0.028 (within 6 cells: 0.024-0.037), 90-degree creases
 * of the public fandisk mesh at 512 0.10-0.11, face cores 0.003-0.006, and the thin
 * core in the middle of a 30-cell-wide face between two creases (fandisk at 512) 0.007
 * (0.017 within 6 cells, 0.035 within 4: cell centres scatter a cell about the surface,
 * and a small patch does not average that out). A face narrower than 2 x 10 cells
 * reaches its creases within the patch and stays an edge core, as before. */
constexpr int kFlatCoreRadius = 10;

/** \brief A core whose patches' median surface variation is below this is flat: 0.010,
 * half the smallest value of a 42-degree edge (above) and above the thin face core's
 * 0.007. Two half-planes turning by t degrees read about 0.14 sin^2(t / 2) over
 * patches this wide, plus about 0.004 of cell scatter: the limit lies near a
 * 25-30 degree turn, so an edge core on a shallower crease may read flat (such creases
 * are blends under the default min_crease_angle of 20 degrees, or close to it). */
constexpr double kFlatCoreVariation = 0.010;

/** \brief An edge core with the same face on both sides is kept as a crease (a crease
 * fading into its face, segmentation step 3; with more than kFadingCreaseMinRadii
 * min_radius cells) when
 * its median surface variation (coreVariation()) is at least this: 0.020, twice the
 * flat limit, about a 40-degree turn by the formula above. Measured 2026-12-03 on the
 * public fandisk mesh at 512 cells: the cores on its two fading creases (80-90 degrees
 * along most of their 368 and 417 cells) read 0.022-0.088 but for one of 127 cells
 * (0.016), while 22 cores on its curved faces and shallow (below 30 degrees) creases,
 * 16-92 cells from every crease of more than 30 degrees, read 0.012-0.016. Pieces of
 * the 42-degree edges of the generated icosahedron that touch one face read 0.020-0.049
 * (sigma 0.45 in the noise mode: 49-53 cells; 10,000 points, seed 33: 67 cells), hence
 * the size. Not swept. */
constexpr double kFadingCreaseVariation = 0.020;

/** \brief A crease fading into its face (kFadingCreaseVariation) has more than this
 * many times min_radius cells: 5, a ridge 2-3 cells wide along more than one separation
 * (2 min_radius). Also the smallest ridge split off a face core (attachedRidges()). */
constexpr std::size_t kFadingCreaseMinRadii = 5;

/** \brief The median, over up to 32 of a core's cells (evenly spaced in `members`'
 * order), of the surface variation (smallest eigenvalue of the covariance over their
 * sum) of the band cells within kFlatCoreRadius 6-steps of the cell: 0 on a plane,
 * about 0.14 sin^2(t / 2) + 0.004 across a crease turning by t degrees. Arguments as
 * flatCore(). */
double coreVariation(const VoxelBand& band,
                     const std::vector<CellId>& members,
                     std::vector<std::uint32_t>& stamp,
                     std::uint32_t& next_stamp);

/** \brief Whether a core's cells bend like a crease fading into its face: more than
 * kFadingCreaseMinRadii x min_radius cells and a coreVariation() of at least
 * kFadingCreaseVariation. The test of a fading crease (segmentation step 3) and of a
 * ridge split off a face core (attachedRidges()). Other arguments as flatCore(). */
bool fadingCreaseCore(const VoxelBand& band,
                      const std::vector<CellId>& members,
                      int min_radius,
                      std::vector<std::uint32_t>& stamp,
                      std::uint32_t& next_stamp);

/** \brief Whether a core lies on a flat part of the band: its coreVariation() is below
 * kFlatCoreVariation.
 *
 * A core too thin for a face by its depth (ComponentParameters::face_min_depth) is an
 * edge ridge when the surface bends across it, and the middle of a face between two
 * creases about 2 min_radius cells apart when it does not (the map reaches min_radius
 * there only along a strip a few cells wide). Deterministic for a given order of
 * `members`.
 * \param[in] band the voxel band
 * \param[in] members the core's cells (non-empty)
 * \param[in,out] stamp scratch, one entry per band cell (band.size()); entries are
 *            left as any value above their previous maximum
 * \param[in,out] next_stamp the stamp of the next patch (incremented per patch) */
bool flatCore(const VoxelBand& band,
              const std::vector<CellId>& members,
              std::vector<std::uint32_t>& stamp,
              std::uint32_t& next_stamp);

} // namespace visfeat
