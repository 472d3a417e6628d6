#pragma once

#include <visfeat/core/band/voxel_band.h>
#include <visfeat/core/common/feature_class.h>

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <cstdint>
#include <set>
#include <vector>

namespace visfeat {

/** \brief Parameters of creasedFacePieces(): where a face's own points say it holds a
 * crease the visibility map did not see.
 *
 * A crease shallower than about 30 degrees leaves no valley in the map when the cells
 * on it see across it (the chord stays in the band): the public fandisk at 1024 has
 * three such creases of 22-27 degrees, 384 cells long and 16 cells apart, at the cap
 * radius all along, inside one face. Its points do not lie on one plane there: the
 * points of a face within a block of 3 x 3 x 3 bricks (kBrickCells cells each) read a
 * surface variation (PCL's curvature, lambda_0 / (lambda_0 + lambda_1 + lambda_2)) of
 * about sin^2(theta / 2) / 8 where a crease of turn theta runs through the block's
 * middle (3.8e-3 at 20 degrees), 0 on a plane, and about 0.3 / r^2 on a cylinder of
 * radius r cells (1.2e-3 at 16 cells). The ridges of such blocks cut the face into
 * pieces; the estimator makes them faces of their own and lets the crease-angle rule
 * judge each contact (a pair whose contact turns by less than min_crease_angle joins
 * again), so a fillet or a curved face that reads above the bound costs time, not a
 * wrong edge.
 *
 * Source: visfeat (not in the paper).
 */
struct FaceCreaseParameters
{
  /** \brief Side of a brick, cells: a block is 3 bricks a side (6 cells). */
  static constexpr int kBrickCells = 2;
  /** \brief A block whose face points read at least this surface variation holds a
   * crease (see above: 3.8e-3 on a 20-degree crease through its middle, less off it).
   * Default kDefaultMinSurfaceVariation. */
  double min_surface_variation = kDefaultMinSurfaceVariation;
  /** \brief Fewest face points in a block for a judgement. */
  std::size_t min_points = kDefaultMinPoints;
  /** \brief Fewest cells of a piece that becomes a face (smaller ones join the piece
   * nearest to them); the estimator sets min_radius^2 (a core's patch). */
  std::size_t min_piece_cells = 256;
  /** \brief OpenMP threads (0 = all available); the result does not depend on it. */
  int threads = 0;

  /** \brief 2.5e-3: below a 20-degree crease's 3.8e-3, above a plane sampled with
   * noise of 0.1 cell (1.7e-3) and a cylinder of radius 11 cells. */
  static constexpr double kDefaultMinSurfaceVariation = 2.5e-3;
  /** \brief The estimator splits faces only on bands no rougher than this, cells
   * (VoxelBand::roughness() below it; -1, not measured, passes): Gaussian noise of
   * sigma cells reads about sigma^2 / 6 in a block, and the roughness is about 0.8
   * sigma (kNoisyRoughness), so 0.06 (sigma 0.075) keeps the noise below 0.4 of the
   * bound; noisier points read ridges at random, which cut faces where edges are near.
   */
  static constexpr double kMaxRoughness = 0.06;
  /** \brief 30 points: a block of a cloud of 1 point a cell squared holds about 36. */
  static constexpr std::size_t kDefaultMinPoints = 30;
};

/** \brief A piece of a face that its ridges of non-planar points cut off: it becomes a
 * face of its own.
 */
struct CreasedFacePiece
{
  /** \brief The face it is cut from. */
  std::uint32_t face = 0;
  /** \brief Its cells, ascending ids. */
  std::vector<CellId> cells;
};

/** \brief The pieces into which ridges of non-planar points cut the faces.
 *
 * The points of face cells, each taking its cell's label, are summed per face and
 * brick (per cell first: one pass over the points, then a sort of the cells); a brick
 * of face F is a ridge brick when the points of F in the 3 x 3 x 3 bricks around it (at
 * least min_points) read at least min_surface_variation. The cells of F in ridge bricks
 * are set aside, the rest of F falls into 6-connected parts, and where two or more
 * parts hold at least min_piece_cells cells each, every cell of F joins the part
 * nearest to it (breadth-first through F's cells from all large parts at once, in
 * order of cell id: deterministic); F's cells no large part reaches stay in F.
 * Every part but the largest is returned as a piece.
 * \param[in] band the band the labels are of
 * \param[in] cell_labels per band cell, its region label (0 = none)
 * \param[in] points the points the band was built from (world units)
 * \param[in] point_cells per point, its band cell (VoxelBand::pointCell()), kNoCell
 *            for none
 * \param[in] classes per region, its class (classes[label - 1])
 * \param[in] parameters see FaceCreaseParameters
 * \return the pieces, in order of face label, then of their first cell
 * \throws visfeat::Error when points and point_cells differ in size, a point cell is
 *         not a band cell, or cell_labels does not match the band. */
std::vector<CreasedFacePiece>
creasedFacePieces(const VoxelBand& band,
                  const std::vector<std::uint32_t>& cell_labels,
                  const std::vector<Eigen::Vector3d>& points,
                  const std::vector<CellId>& point_cells,
                  const std::vector<FeatureClass>& classes,
                  const FaceCreaseParameters& parameters);

/** \brief Which pieces of split faces join again, per label (index 0 unused): the
 * label it joins, itself when kept.
 *
 * Two regions cut from one face (origin[a] == origin[b]; the face's remaining part is
 * its own origin) whose cells touch (6-neighbours) join unless `creases` holds their
 * pair (smaller label first): a contact that is no crease, or too short to measure,
 * is no reason to keep a face apart. Joins are transitive; each set points at its
 * smallest label (as FeatureSegmentation::mergeRegions() takes them).
 * \param[in] band the band the labels are of
 * \param[in] cell_labels per band cell, its region label
 * \param[in] origin per label (index 0 unused), the face it was cut from, or itself
 * \param[in] creases the pairs whose contact is a crease */
std::vector<std::uint32_t>
rejoinCreasedFacePieces(const VoxelBand& band,
                        const std::vector<std::uint32_t>& cell_labels,
                        const std::vector<std::uint32_t>& origin,
                        const std::set<std::array<std::uint32_t, 2>>& creases);

} // namespace visfeat
