#pragma once

#include <visfeat/core/band/local_triangles.h>
#include <visfeat/core/band/organized_triangles.h>
#include <visfeat/core/band/triangle_cells.h>
#include <visfeat/core/band/voxel_band.h>
#include <visfeat/core/grid/grid_spec.h>

#include <pcl/point_cloud.h>

#include <cstddef>
#include <string>
#include <vector>

namespace visfeat {

/** \brief Where the band's cells come from (DESIGN.md: the band from the surface).
 *
 * - kPoints: the cells that hold a point (the paper's band; right for clouds whose
 *   points lie at most about kFillSpacingCells cells apart).
 * - kLocalTriangles: those cells plus the cells of the umbrella triangles between each
 *   point and its neighbours (umbrellaTriangles()), for clouds sparser than the cells.
 * - kMesh: the cells of the input mesh's triangles, rasterised exactly
 *   (rasterizeTriangles()); the points land on those cells (pointsOnCells()).
 * - kOrganized: an organized cloud's pixel grid cut at depth jumps
 *   (organizedTriangles()), rasterised, plus the cells of the points.
 * - kAuto: kMesh when a mesh is given, else kOrganized for an organized cloud (height
 *   > 1), else kLocalTriangles when the points lie more than kFillSpacingCells cells
 *   apart, else kPoints. */
enum class SurfaceFill
{
  kAuto,
  kPoints,
  kLocalTriangles,
  kMesh,
  kOrganized,
};

/** \brief "auto", "points", "triangles", "mesh", "grid". */
const char* surfaceFillName(SurfaceFill fill);

/** \brief The fill named by surfaceFillName(); false for another name. */
bool parseSurfaceFill(const std::string& name, SurfaceFill& fill);

/** \brief kAuto fills between the points when their mean spacing exceeds this many
 * cells: at the automatic resolution (2 spacings per cell, ResolutionEstimate) a cloud
 * is never filled, so dense clouds keep the paper's band. Measured at a set resolution
 * of 256 on the 7 generated models (seeds 1-3, random rotations, uniform samples at a
 * spacing of s cells): the points band gives exact counts in 21 of 21 runs at s = 0.5
 * and 0.55, 18 at 0.6, 16 at 0.65 and 5 at 0.7; of 14 runs (seeds 1-2) none at 0.75, 1
 * at 0.8 and none at 0.9 (mostly 0/0/1), 4 of those wrong answers with no warning. Its
 * repair share grows from 0.09-0.15 at 0.5 to 0.20-0.26 at 0.7. The fill between the
 * points gives exact counts in 70 of 70 runs (seeds 1-2) at 0.6, 0.7, 0.8, 0.9 and 1.0
 * (its band costs about 3 s against 0.2 s on 300,000 points; 2 cores). The limit
 * was 1.0 before: a mesh sampled for 1024 cells and run at 2048 (0.81 cells apart) kept
 * its points band and gave F1 0.11. */
constexpr double kFillSpacingCells = 0.55;

/** \brief The automatic resolution is raised to this when a fill lets the cells be
 * finer than the points: at 256 cells the generated models' features (faces >= 1/8 of
 * the part, 2 min_radius = 32 cells apart) separate exactly. */
constexpr int kTopologyResolution = 256;

/** \brief Cells a point spacing the local-triangle fill is trusted with (the
 * automatic resolution stays at or below extent / spacing times this): the fill
 * rounds creases by about a spacing, which must stay well below 2 min_radius cells. */
constexpr double kMaxFillCellsPerSpacing = 4.0;

/** \brief Fewest finite points a cloud needs where its points give the band (any fill
 * but a mesh's): a face is found from a core of cells min_radius rings from its
 * creases, so it spans at least 2 min_radius cells each way, and a fill bridges at most
 * kMaxFillCellsPerSpacing cells a point spacing: (2 min_radius /
 * kMaxFillCellsPerSpacing)^2 points, 64 at the defaults. Fewer cannot hold one face at
 * any resolution (3 points gave an empty result with a warning that advised sampling
 * denser at resolution 4). */
constexpr std::size_t
minimumCloudPoints(int min_radius)
{
  const auto across = static_cast<std::size_t>(
    (2.0 * static_cast<double>(min_radius) + kMaxFillCellsPerSpacing - 1.0) /
    kMaxFillCellsPerSpacing); // rounded up
  return across * across;
}

/** \brief The automatic resolution is raised for a fill only by at least this factor:
 * a dense cloud whose points support 238 cells was filled to reach 256, which cost
 * 18.7 s of fill for 7% more cells (a generated cube, 500,000 points, 2 cores). */
constexpr double kMinFillRaise = 1.25;

/** \brief With a given resolution R, the spacing (which decides the automatic fill) is
 * measured before the band for clouds of fewer than this many points per R^2 (a point
 * per cell on any surface of area below this many times extent^2); a denser cloud is
 * spared the k-d tree unless its points band turns out to have holes
 * (kSpacingCheckRepairShare). */
constexpr double kFillCheckPointsPerCell2 = 4.0;

/** \brief Bytes a filled band needs per cell of the surface's area (area / cell_size^2,
 * a lower bound of its cells: a plane crosses at least one cell per cell area) while it
 * is rasterised and built, for the refusal before the fill allocates anything.
 * Measured 2026-12-07 on the generated cube, 2,352,361 points filled at 2048 cells:
 * 14.2 M mixed cells for 9.4 M cells of area (1.5 times), peak 3.13 GB, about 330 bytes
 * per cell of area; 200 leaves a margin so that no run that fits is refused (the band
 * itself is checked again once built). A cloud of 562,000 points 16 cells apart at
 * 8192 (a fresh user's trial) rose past 15 GB in the fill before this check. */
constexpr double kFillBytesPerCell = 200.0;

/** \brief Bytes the fill between points (SurfaceFill::kLocalTriangles) needs per
 * point besides kFillBytesPerCell: its neighbours and triangles. Where points lie less
 * than a cell apart they, not the area, set its memory. Measured 2026-12-07 (peaks of
 * whole runs, points 0.7 cells apart): the box with hole at 1024, 5.2 M points and 2.6
 * M cells of area, 3.48 GB; at 2048, 20.9 M points and 10.2 M cells of area, 13.4 GB
 * (before this term the check counted 0.5 and 2.0 GB, and a fill decided after the
 * points band, as these were, was not checked at all). A fit over those and the cube
 * above gives about 190 bytes a cell of area and 580 a point; 450 keeps the estimate
 * at 82-94% of each measured peak, so no run that fits is refused. */
constexpr double kFillBytesPerPoint = 450.0;

/** \brief At a set resolution, a points band whose spacing was not measured (a cloud
 * of kFillCheckPointsPerCell2 points per cell^2 or more) is checked after all when
 * more of its cells than this were added by the repair: then the spacing is measured,
 * and above kFillSpacingCells the band is made again, filled between the points.
 * Measured on the 7 generated models at 256 (seeds 1-3): the repair share is 0.09-0.15
 * at a spacing of 0.5 cells (no check, no cost), 0.12-0.18 at 0.55, 0.15-0.21 at 0.6
 * and 0.18-0.23 at 0.65, where counts break in 5 of 21 runs. (A generated cube at
 * 0.7 cells, 4.4 points per cell^2 at 256, is checked only this way.) */
constexpr double kSpacingCheckRepairShare = 0.16;

/** \brief Appended to the warnings of too few face cores when noise mode is off: noise
 * roughens the band as much as close features do (the tool says -noise_mode). */
constexpr const char* kNoisyScanAdvice =
  "; if the scan is noisy, use noise mode (setNoiseMode(true))";

/** \brief compute() warns, outside the noise mode, when the band's roughness
 * (VoxelBand::roughness(), cells) is above this: the points scatter about the surface
 * more than the exact band bears. Measured on the generated models at 256 cells (0.5-
 * cell spacing, Gaussian noise sigma per coordinate): roughness is about 0.8 sigma
 * (0.000 clean, 0.029 at sigma 0.05, 0.066 at 0.1, 0.11 at 0.15, 0.18 at 0.22); counts
 * stay exact up to 0.124 (sigma 0.16) on cube, tetrahedron, icosahedron, U-prism, box
 * with hole and cylinder, and break from 0.150 (U-prism and box with hole at sigma
 * 0.19; cube and icosahedron at 0.22: 4/8/5 and 1/3/8). */
constexpr double kNoisyRoughness = 0.13;

/** \brief compute() warns when the points' noise measured by the triangle fill
 * (getPointNoise(), cells) is above this: the band filled between the points is as
 * rough as the points. Measured on the generated models at 10,000 and 40,000 points
 * (resolution about 256, 2-4 cells a point spacing; Gaussian noise sigma cells per
 * coordinate; seed 11, 7 models x 2 counts): the noise reads 0.85-0.9 sigma (0.00
 * clean, 0.04 on the clean cylinder at 10,000 points); exact counts in 12 of 14 at
 * sigma 0.1 (noise 0.08-0.10), 11 of 14 at sigma 0.2 (0.17-0.18: tetrahedron 5/7/4,
 * box with hole 8/16/7), none at sigma 0.3 (0.25-0.27, mostly 0 vertices and edges,
 * before with no warning), as on the dense clouds (kNoisyRoughness). Noise mode
 * does not help there: its smoothing radius holds few points this sparse. The noise
 * reads lower where the points lie closer together than sigma (a cube at 256, sigma 1
 * cell: 0.77 sigma from 20,000 points, 0.39 from 400,000). */
constexpr double kNoisyPointNoise = 0.13;

/** \brief With the automatic resolution, a filled band whose points' noise is above
 * this (cells) is recomputed at the resolution where the noise is kCalmRoughness, still
 * filled, with a warning that closer features merge. Measured on the generated models
 * (seed 11, 7 models x 10,000 / 40,000 points, Gaussian noise sigma cells at 256):
 * sigma 0.2 (noise 0.17) stays at 256 (11 of 14 exact; lowered to about 150, 10 of 14:
 * the icosahedron's corners merge); sigma 0.3 (noise 0.25): 0 of 14 exact at 256, 8 of
 * 14 lowered to about 100; sigma 0.5 (0.4): 0 of 14, 2 of 14 lowered to about 60. */
constexpr double kLowerForPointNoise = 0.2;

/** \brief Where the automatic resolution is lowered for the points' noise, the warning
 * also names noise mode when its smoothing disc (kNoiseSmoothingRadius cells, at the
 * resolution before lowering) holds at least this many points: 8. Measured 2026-12-07
 * (noise 0.3 cells at 256, automatic resolution, without and with noise mode): the
 * generated stepped block from 150,000 points (19 points in the disc) 6/10/8 at 112
 * and 8/18/11 at 256 (truth 16/24/10); the box with hole from 150,000 (12) 2/9/4 and
 * 8/14/7 (exact); a fresh user's scan of the CGAL part, 200,000 points (16), 0/3/3 and
 * 3/11/6 (truth 2/5/5); but the stepped block from 40,000 (4 points) 5/10/8 and 3/5/4:
 * the smoothing holds too few. */
constexpr double kNoiseModeSmoothedPoints = 8.0;

/** \brief ... and when the points' noise (getPointNoise(), cells, at the resolution
 * before lowering) is at most this: 0.35, about sigma 0.4 by its 0.85-0.9 sigma
 * reading; noise mode recovers every generated model at sigma 0.32 and 6 of 7 at 0.45
 * (README, "Evaluation"). The fresh user's heavier scan (0.375 there, sigma about 1.1
 * read low on its dense points) went to 68 cells in noise mode too. */
constexpr double kNoiseModeMaxPointNoise = 0.35;

/** \brief The roughness the warning's suggested resolution aims at, cells: 0.10 (sigma
 * about 0.12, exact on every generated model, see kNoisyRoughness). */
constexpr double kCalmRoughness = 0.10;

/** \brief compute() warns when fewer of the band's cells than this reach min_radius
 * (the face cores): measured 0.3-0.6 on the generated models at 256 cells, 0.11 on a
 * 20,000-point cube at the 48 cells its density alone allows (1 face of 6 found). */
constexpr double kMinCoreShare = 0.15;

/** \brief compute() warns when the band's largest 6-connected piece holds fewer of its
 * cells than this: a points-only band of a cloud sparser than the cells falls into
 * specks (the largest under 1% of the band on a 5,000-point tetrahedron at 200 cells),
 * while a scene of a few objects keeps pieces of a sizeable share each. */
constexpr double kMinLargestPieceShare = 0.1;

/** \brief compute() warns when more of the band's cells than this were added by the
 * repair (a band full of holes; with the automatic fill such a points band is filled
 * instead, kUnevenRepairShare, so this is for a fill set by setSurfaceFill()). Measured
 * on the points bands of the 7 generated models at 256 (seeds 1-3): 0.09-0.15 at a
 * spacing of 0.5 cells, 0.15-0.21 at 0.6 (exact counts in 18 of 21), 0.20-0.26 at 0.7
 * (5 of 21). It was 0.3 before: a mesh sampled for 1024 cells and run at 2048 with its
 * points band (0.81 cells apart) repaired 0.294 of its cells and gave F1 0.11 with no
 * such warning. */
constexpr double kMaxRepairShare = 0.2;

/** \brief A points band chosen automatically is made again, filled between the points,
 * when it has holes as kMaxRepairShare defines them, whatever the median spacing: the
 * density is uneven, and the sparser parts leave holes. Measured: uniform samples of
 * the 7 generated models at 256 (seeds 1-3) repair at most 0.147 of their points band
 * at 0.5 cells apart and 0.177 at 0.55 (kFillSpacingCells); the box with a hole with
 * one face 6 times denser (seeds 1-2, automatic resolution 281-328, median
 * spacing 0.5 cells) repairs 0.21 and 0.27 and gives 2/6/6 and 7/18/7 for 8/14/7,
 * filled 8/14/7 in both (its band 12-15 s, with a second job on the 2 cores, against
 * 0.5 s for the points). */
constexpr double kUnevenRepairShare = kMaxRepairShare;

/** \brief One point of every cluster of copies: the finite points with those closer
 * than `radius` (world units) to a kept point removed.
 *
 * Duplicate points and overlapping copies of a scan (ResolutionEstimate::copies > 1)
 * would give the umbrella triangles of localTriangleCells() neighbours at distance 0
 * and degenerate triangles; the fill is made between the sites instead. Points are
 * visited in lexicographic (x, y, z) order, so the result does not depend on the order
 * of the input (copies at one position are interchangeable). radius <= 0 keeps the
 * finite points, without exact duplicates. Cost: a sort and one radius search per kept
 * point. */
template <typename PointT>
pcl::PointCloud<PointT> distinctSites(const pcl::PointCloud<PointT>& cloud,
                                      double radius);

/** \brief What a fill measured on the way. */
struct FillReport
{
  /** \brief Triangles made. */
  std::size_t triangles = 0;
  /** \brief The points' noise (world units; tangentPlanes()' measure: about 0.85 sigma
   * for Gaussian noise of sigma per coordinate), or -1 when the fill did not measure
   * it (meshes, organized clouds, creases not rebuilt). */
  double noise = -1.0;
  /** \brief The share of the points whose neighbourhood lies flat (tangentPlanes()'
   * flat_share), or -1 when the noise was not measured. */
  double flat_share = -1.0;
  /** \brief The finite points the noise was measured on (kNoiseReadablePoints). */
  std::size_t points = 0;
};

/** \brief The cells of the umbrella triangles of a cloud's finite points
 * (umbrellaTriangles() with neighbours from pcl::search::KdTree), rasterised on grid.
 * \param[out] report if not null, the triangles made and the points' noise
 * \throws visfeat::Error for bad parameters. */
template <typename PointT>
std::vector<CellCoord> localTriangleCells(const pcl::PointCloud<PointT>& cloud,
                                          const GridSpec& grid,
                                          const LocalTriangleParameters& parameters,
                                          int threads,
                                          FillReport* report = nullptr);

/** \brief The cells of an organized cloud's pixel grid (organizedTriangles() from
 * the cloud's sensor_origin_), rasterised on grid.
 * \param[out] report if not null, the triangles made (noise not measured: -1)
 * \throws visfeat::Error when the cloud is not organized (height 1, or width x height
 * is not its size) or for bad parameters. */
template <typename PointT>
std::vector<CellCoord> organizedCells(const pcl::PointCloud<PointT>& cloud,
                                      const GridSpec& grid,
                                      const OrganizedTriangleParameters& parameters,
                                      int threads,
                                      FillReport* report = nullptr);

/** \brief The points of a cloud as entries of given cells (a mesh's band): each finite
 * point joins the cell it falls in when that is one of `cells`, else the nearest of
 * them among its 26 neighbours (points a rounding away from a face that lies on a cell
 * boundary), else none (-1). The points then add no cell of their own to the band.
 * \param[in] cells sorted by GridSpec::linearKey, no duplicates (rasterizeTriangles())
 * \param[out] occupied one entry per cell that received points, in the order of their
 *             first point
 * \param[out] point_occupied per point, its entry in occupied, or -1
 * \param[in] threads threads for the cell lookups (0 = all available); the result is
 *            the same for any count */
template <typename PointT>
void pointsOnCells(const pcl::PointCloud<PointT>& cloud,
                   const GridSpec& grid,
                   const std::vector<CellCoord>& cells,
                   std::vector<OccupiedCell>& occupied,
                   std::vector<std::int32_t>& point_occupied,
                   int threads = 1);

} // namespace visfeat

#ifdef PCL_NO_PRECOMPILE
#include <visfeat/impl/surface_fill.hpp>
#endif
