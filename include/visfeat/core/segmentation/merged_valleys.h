#pragma once

#include <visfeat/core/band/voxel_band.h>
#include <visfeat/core/segmentation/feature_segmentation.h>
#include <visfeat/core/visibility/visibility_map.h>

#include <cstddef>

namespace visfeat {

/** \brief Face cells in deep valleys of the visibility map, far from every edge and
 * vertex: creases the segmentation merged into a face.
 *
 * A crease hides the band beyond it, so the cells along it have small radii (a valley
 * of the map), and a segmentation that finds the crease puts an edge there. When
 * features lie closer than about 2 min_radius cells (the rims of a plate thinner than
 * that, steps, parallel creases), no core forms between them and their valleys can end
 * up inside faces, with nothing in the graph to show it: a plate 12 cells thick at 255
 * cells gave 0 vertices, 1 edge and 2 faces (truth 8/14/7), a closed graph, no
 * warning. Those faces hold cells whose radius is a few rings although no edge or
 * vertex lies near them; a curved face (a cylinder of radius R cells reaches about
 * sqrt(12 R) rings) or a fillet does not go that low. Shallow creases (below about 45
 * degrees) leave shallower valleys, 8-10 rings, that follow the crease: a long, narrow
 * line of such cells (longest_line, kValleyLineRadius) says the same.
 *
 * Source: visfeat (not in the paper), after the narrow faces of narrowFaces(). */
struct MergedValleys
{
  /** \brief Face cells with radius <= the valley radius and more than the reach from
   * every edge or vertex cell. */
  std::size_t cells = 0;
  /** \brief Smallest radius among them, rings (0 when there are none). */
  int deepest = 0;
  /** \brief The longest valley line, cells: of the 26-connected groups of face cells
   * with radius <= the line radius and more than the reach from every edge or vertex
   * cell, those at least kValleyLineElongation times longer than wide and at least
   * kValleyLineMinWidth wide, the greatest
   * length (length and width: sqrt(12 lambda) of the first two principal axes of the
   * group's cell centres, the sides of a uniform strip with the same spread); 0 when
   * there is none. */
  double longest_line = 0.0;
  /** \brief That line's width, cells. */
  double line_width = 0.0;
  /** \brief That line's cells. */
  std::size_t line_cells = 0;

  /** \brief Whether there is anything: deep valley cells or a line. */
  bool any() const { return cells > 0 || longest_line > 0.0; }
};

/** \brief Largest radius of a merged valley's cell, rings. Measured 2026-12-07 at 256
 * cells (dense clouds, rotations 1-2, face cells more than 8 rings from any edge or
 * vertex): the cube, icosahedron, cylinder, box with hole and U prism have 4-13 such
 * cells at 5 rings (11-20 at 6), and noisy clouds (sigma 0.1 cells, noise mode) 0-2;
 * the thin plate with hole (12 cells thick) 800-1,426 at 5 rings, 2,280-3,266 at 6
 * (rotation 3, which finds half its edges: 212 at 5). */
constexpr int kMergedValleyRadius = 5;

/** \brief kMergedValleyRadius for another min_radius: in proportion (5/16 of it,
 * rounded down), as the radii of a crease's valley scale with the cells. */
constexpr int
mergedValleyRadius(int min_radius)
{
  return kMergedValleyRadius * min_radius / 16;
}

/** \brief Merged valley cells a result may hold before the search goes finer and
 * compute() warns, as a multiple of min_radius^2 (a core's patch; 256 cells at the
 * defaults). Measured 2026-12-07 (kMergedValleyRadius, reach min_radius / 2): sparse
 * clouds of 10,000 points filled between the points hold 9-53 (the bumps of a rough
 * band); the public meshes at the resolution the search gives them 1-127 (fandisk
 * at 512 and 1024: 74 and 127; V-HACD block at 512: 116; CGAL part at 1024: 1); the
 * thin plate 800-1,426, the stepped block at 256 46-570, the ABC 00000050 assembly
 * at 1024 12,221 (its plates 12-30 cells thick, parts 1-2 cells apart). */
constexpr int kMergedValleyCoreAreas = 1;

/** \brief The merged valley cells that say creases merged at this min_radius:
 * kMergedValleyCoreAreas min_radius^2 (256 at the defaults). */
constexpr std::size_t
mergedValleyCoreCells(int min_radius)
{
  return static_cast<std::size_t>(kMergedValleyCoreAreas) *
         static_cast<std::size_t>(min_radius) * static_cast<std::size_t>(min_radius);
}

/** \brief Largest radius of a valley line's cell (MergedValleys::longest_line) at
 * min_radius 16, rings. A crease shallower than about 45 degrees leaves no deep valley:
 * the cells on it see across it (the chord stays in the band), and its valley's floor,
 * a few cells to each side, reaches only 8-10 rings. Three such creases 10 cells apart
 * (parallel_creases, turns of 30, 60 and 30 degrees) merged into one face at 256 with
 * a closed graph and no warning (rotation 23: 10/14/7 for 14/21/9). Measured
 * 2026-12-07 at 256, dense clouds (reach min_radius / 2): there the far face cells of
 * radius 9 or less form lines 68-145 cells long and 7-16 wide along the merged creases
 * (rotations 1-3 and 21-24; the stepped block 63-76, the chamfered box 25-90, the thin
 * plate 152-187 where they have one); the longest line on the cube, icosahedron, box
 * with hole, cylinder, U prism, tetrahedron and triangular prism (rotation 21) is 11
 * cells, on noisy clouds (sigma 0.1 cells, noise mode) 14, on sparse clouds of 10,000
 * points, filled, 16; their longest groups of any shape, blobs, 28 cells (the bumps of
 * a rough band). */
constexpr int kValleyLineRadius = 9;

/** \brief kValleyLineRadius for another min_radius, in proportion (9/16 of it). */
constexpr int
valleyLineRadius(int min_radius)
{
  return kValleyLineRadius * min_radius / 16;
}

/** \brief A valley line is at least this many times longer than wide: a crease's
 * valley follows the crease; the low radii of a rough band or of a corner's
 * neighbourhood make blobs (measured on the clouds of kValleyLineRadius: the merged
 * creases' lines 4.5-16 times longer than wide, the blobs longer than 10 cells at most
 * 2.3). */
constexpr double kValleyLineElongation = 3.0;

/** \brief A valley line is at least this wide, cells: a crease's valley has two sides a
 * few cells wide each (measured widths 2.9-16 cells, see kValleyLineRadius), while the
 * stair steps of a thin band on a plane tilted against the grid leave rows of one cell
 * at radius 8 (measured on the public V-HACD block at 512: rows 47-53 cells long, width
 * 0). */
constexpr double kValleyLineMinWidth = 2.0;

/** \brief A valley line at least this many times min_radius long says creases merged
 * into a face (32 cells at the defaults; measured: lines along merged creases 68-145
 * cells, the longest elsewhere 16, see kValleyLineRadius). */
constexpr int kValleyLineMinRadii = 2;

/** \brief The merged valleys of a segmented band (see MergedValleys).
 * \param[in] band the band the map and segmentation were computed on
 * \param[in] map its visibility map
 * \param[in] segmentation its regions (cellClass() per cell)
 * \param[in] valley_radius largest radius of a valley cell, rings
 * \param[in] reach rings (6-steps through the band) from the nearest edge or vertex
 *            cell beyond which a valley cell counts
 * \param[in] line_radius largest radius of a valley line's cell, rings (0: no lines)
 * \return the count, the deepest radius and the longest line; none when the
 *         segmentation has no face */
MergedValleys mergedValleys(const VoxelBand& band,
                            const VisibilityMap& map,
                            const FeatureSegmentation& segmentation,
                            int valley_radius,
                            int reach,
                            int line_radius = 0);

} // namespace visfeat
