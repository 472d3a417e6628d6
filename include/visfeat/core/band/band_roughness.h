#pragma once

#include <visfeat/core/grid/grid_spec.h>

#include <cstdint>
#include <vector>

namespace visfeat {

/** \brief How far the points scatter about the surface, in cells, measured on the
 * band's occupied cells: the median, over up to kRoughnessSamples cells spread evenly
 * through the band, of the RMS distance of the point centroids of the occupied cells
 * in the 3x3x3 block around a cell to their least-squares plane (PCA).
 *
 * A clean sampled surface gives about 0 (centroids on flat faces lie on the face;
 * crease and corner blocks are outvoted by the median); Gaussian noise of sigma cells
 * thickens the band and scatters the centroids (measured on the generated models at
 * 256 cells: see kNoisyRoughness in the estimator). Curvature adds about 1 / (8 R) for
 * a radius of R cells.
 *
 * \param coords occupied cells sorted by grid.linearKey() (no duplicates)
 * \param counts points per cell (cells with 0 points are skipped: fill cells)
 * \param sums sum of the positions of each cell's points, cell units
 * \return the median RMS in cells, or -1 when fewer than kMinRoughnessBlocks blocks
 *         hold kMinRoughnessCentroids centroids (sparse clouds: nothing measured).
 * Source: our own (issue 13: no silent wrong answer on a noisy cloud). */
double bandRoughness(const GridSpec& grid,
                     const std::vector<CellCoord>& coords,
                     const std::vector<std::uint32_t>& counts,
                     const std::vector<Eigen::Vector3d>& sums);

/** \brief Most blocks measured by bandRoughness(). */
constexpr std::size_t kRoughnessSamples = 4096;
/** \brief Fewest centroids in a block for a plane fit to mean anything. */
constexpr int kMinRoughnessCentroids = 6;
/** \brief Fewest measured blocks for a median. */
constexpr std::size_t kMinRoughnessBlocks = 32;

} // namespace visfeat
