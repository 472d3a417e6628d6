// VisibilityFeatureEstimation (not for inclusion on its own): the checks that refuse a
// run before it allocates more than the memory limit, and those that say when a result
// cannot be trusted, and why (the band, the map, the noise, the graph).
#pragma once

#include <visfeat/core/band/band_enclosure.h>
#include <visfeat/core/band/band_pieces.h>
#include <visfeat/core/band/tangent_planes.h>
#include <visfeat/core/common/memory_budget.h>
#include <visfeat/core/common/threads.h>
#include <visfeat/core/graph/graph_gaps.h>
#include <visfeat/core/mesh/mesh_sampling.h>
#include <visfeat/core/segmentation/merged_valleys.h>
#include <visfeat/impl/visibility_feature_estimation.hpp>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

namespace visfeat {
namespace detail {

/** Whether compute() warns that the points are rough: the band's roughness outside
 * noise mode (kNoisyRoughness) or the noise of the points a fill measured
 * (kNoisyPointNoise). Finer cells make a rough band rougher, so the other warnings
 * then point to that one instead of to a finer resolution. */
inline bool
roughPoints(double band_roughness, bool noise_mode, double point_noise)
{
  return (!noise_mode && band_roughness > kNoisyRoughness) ||
         point_noise > kNoisyPointNoise;
}

/** How rough the points read, cells: the noise the fill measured, or the band's
 * roughness outside noise mode, whichever is larger (what roughPoints() compares with
 * their limits, both 0.13). */
inline double
pointRoughness(double band_roughness, bool noise_mode, double point_noise)
{
  return std::max(point_noise, noise_mode ? 0.0 : band_roughness);
}

/** Why the search for narrow faces stops where it does when nothing but its own limit
 * stops it (Run::search_cap_reason); any other reason is what the points support. */
constexpr const char* kSearchLimitReason = "the search's limit";

/** \brief The start of the note on a mesh's point spacing (chooseFill()): one such
 * note, that of the resolution used. */
constexpr const char* kSpacingNotePrefix = "the points lie ";

/** \brief The advice of the too-few-cores warnings where the band has holes: a finer
 * resolution would leave more of them. */
constexpr const char* kHolesFirst =
  "close the band's holes first (next warning): a finer resolution would leave more";

/** ", e.g. to 2R" after "raise the resolution" (the search's own step), or "" at the
 * largest resolution. */
inline std::string
finerExample(int resolution)
{
  if (resolution >= GridSpec::kMaxResolution)
    return "";
  return ", e.g. to " +
         std::to_string(std::min(2 * resolution, GridSpec::kMaxResolution));
}

/** \brief The way on where the automatic search stopped at its maximum (narrow faces
 * or a closed mesh's graph gaps left): the setter and its value. */
inline std::string
searchFurtherAdvice(int max_search_resolution)
{
  return "let the automatic search go finer: setMaxSearchResolution(), now " +
         std::to_string(max_search_resolution);
}

/** Whether the points' noise the fill measured (the Run's point_flat_share and
 * noise_points) cannot be noise: too few points to tell (kNoiseReadablePoints). */
template <typename Run>
bool
tooFewPointsForNoise(const Run& run)
{
  return run.noise_points > 0 && run.noise_points < kNoiseReadablePoints;
}

/** Whether the points' noise the fill measured reads the shape of a cloud too sparse
 * for its creases rather than noise (kShapeNotNoiseShare, kNoiseReadablePoints). */
template <typename Run>
bool
noiseIsShape(const Run& run)
{
  return run.point_flat_share >= kShapeNotNoiseShare || tooFewPointsForNoise(run);
}

/** The points' noise in words: "noise", or "spread" with its cause when it is the
 * shape. */
template <typename Run>
std::string
pointSpreadName(const Run& run)
{
  return noiseIsShape(run) ? "spread" : "noise";
}

/** Whether the points' spread is their shape rather than noise: as judged where the
 * resolution was lowered for it (a lowered run measures its points again, at cells too
 * coarse to tell), or as measured at this resolution. */
template <typename Run>
bool
spreadIsShape(const Run& run)
{
  return run.calmed ? run.calmed_for_shape : noiseIsShape(run);
}

/** The advice of a warning that finer cells would help, unless the points are rough
 * (or too sparse for their creases, which reads the same). */
inline const char*
roughPointsAdvice(bool shape)
{
  return shape ? "the points are too sparse for the part (see the warning on their "
                 "spread), and finer cells would not help: follow that warning first"
               : "the points are rough (see the warning on their noise), and finer "
                 "cells would make that worse: follow that warning first";
}

/** A resolution is advised against noise only if it leaves at least this many
 * min_radius along the part (4: 64 cells at the defaults), where features half the
 * part apart separate (they need 2 min_radius cells). A fresh user was told "a
 * resolution of 20 or lower", then "7 or lower": no face can have a core there. */
constexpr int kMinAdvisedResolutionRadii = 4;

/** Whether `calmer`, the resolution where the noise would be calm, is worth advising
 * (kMinAdvisedResolutionRadii). */
inline bool
calmerIsUseful(int calmer, int min_radius)
{
  return calmer >= kMinAdvisedResolutionRadii * min_radius;
}

/** What to say where the calm resolution is not worth advising. */
inline std::string
calmerTooCoarse(int calmer)
{
  return "a resolution calm enough (" + std::to_string(calmer) +
         " or lower) would merge all features less than half the part apart";
}

/** Why the search stops where the next resolution is, or would be, too rough
 * (Run::search_cap_reason; keepUnderNoise()). */
constexpr const char* kNoiseLimitReason = "what the points' noise allows";

/** The advice where the automatic resolution is as fine as the points support
 * (atPointsCap()): "sample denser: resolution R is <the cap's reason>", or, where the
 * points' noise set the cap (kNoiseLimitReason: calmResolution(), keepUnderNoise()),
 * smoothing first: a denser sample is as noisy. */
template <typename Run>
std::string
pointsCapAdvice(const Run& run)
{
  const std::string at = "resolution " + std::to_string(run.resolution.resolution) +
                         " is " + run.search_cap_reason;
  if (run.search_cap_reason != kNoiseLimitReason)
    return "sample denser: " + at;
  return "smooth the points first (pcl::MovingLeastSquares; a denser sample is as "
         "noisy): " +
         at;
}

/** Whether the automatic resolution is as fine as the points support (with the fill
 * or without), so that finer cells need a denser sample. */
template <typename Run>
bool
atPointsCap(const Run& run)
{
  return run.search_cap > 0 && run.resolution.resolution >= run.search_cap &&
         run.search_cap_reason != kSearchLimitReason;
}

/** \brief The merged valleys of a result (mergedValleys(): radius at most
 * mergedValleyRadius(min_radius), more than min_radius / 2 rings from any edge or
 * vertex), or none
 * where they are too few to say that creases merged (kMergedValleyCoreAreas core
 * patches) or the regions do not cover the band (raw mode, cores only). */
template <typename Results>
MergedValleys
manyMergedValleys(const Results& results, const SegmentationParameters& segmentation)
{
  if (segmentation.raw || !segmentation.complete_regions)
    return {};
  const int min_radius = segmentation.components.min_radius;
  const MergedValleys valleys = mergedValleys(
    results.band, results.map, results.segmentation, mergedValleyRadius(min_radius),
    min_radius / 2, valleyLineRadius(min_radius));
  const bool line = valleys.longest_line >= kValleyLineMinRadii * min_radius;
  return valleys.cells >= mergedValleyCoreCells(min_radius) || line ? valleys
                                                                    : MergedValleys{};
}

/** \brief The merged valleys in words, e.g. "1426 face cells in valleys of the map
 * (radius 5 rings or less, the deepest 4) more than 8 cells from any edge or vertex".
 */
inline std::string
describeMergedValleys(const MergedValleys& valleys, int min_radius)
{
  const std::string far =
    " more than " + std::to_string(min_radius / 2) + " cells from any edge or vertex";
  if (valleys.cells < mergedValleyCoreCells(min_radius)) // a line only
    return "a line of face cells in a valley of the map (radius " +
           std::to_string(valleyLineRadius(min_radius)) + " rings or less), " +
           std::to_string(std::lround(valleys.longest_line)) + " cells long and " +
           std::to_string(std::lround(valleys.line_width)) + " wide," + far;
  return std::to_string(valleys.cells) + " face cells in valleys of the map (radius " +
         std::to_string(mergedValleyRadius(min_radius)) +
         " rings or less, the deepest " + std::to_string(valleys.deepest) + ")" + far;
}

/** \brief Where faces hold creases merged into them (manyMergedValleys()), a warning
 * that says so and what to do (a finer resolution, or a denser sample where the
 * automatic resolution is as fine as the points support). */
template <typename Results, typename Run>
void
warnMergedValleys(const Results& results, Run& run, int max_search_resolution)
{
  const MergedValleys valleys = manyMergedValleys(results, run.segmentation);
  if (!valleys.any())
    return;
  const int min_radius = run.segmentation.components.min_radius;
  const int resolution = run.resolution.resolution;
  std::ostringstream w;
  w << describeMergedValleys(valleys, min_radius) << ": creases closer than about "
    << 2 * min_radius << " cells (2 min_radius) at resolution " << resolution
    << " were merged into faces (the rims of a plate or wall thinner than that, steps, "
       "close parallel creases), although the graph looks whole; ";
  if (atPointsCap(run))
    w << pointsCapAdvice(run);
  else if (run.search_cap > 0 && run.search_cap_reason == kSearchLimitReason)
    w << "raise the resolution" << finerExample(resolution) << " (setResolution(), or "
      << searchFurtherAdvice(max_search_resolution) << ")";
  else
    w << "raise the resolution" << finerExample(resolution);
  run.warnings.push_back(w.str());
}

/** \brief Whether the surface of a run is closed, so that a graph with gaps means
 * features the resolution did not separate (an open surface's border leaves gaps too):
 * a mesh when it is closed (meshIsClosed()), a one-view depth image never, any other
 * cloud when its band encloses a volume (bandIsClosed(): sampled all around a solid).
 */
template <typename Results, typename Run>
bool
closedSurface(const Results& results, const Run& run, bool has_mesh, bool mesh_closed)
{
  if (has_mesh)
    return mesh_closed;
  return run.fill != SurfaceFill::kOrganized && bandIsClosed(results.band);
}

} // namespace detail

template <typename PointInT, typename PointOutT>
void
VisibilityFeatureEstimation<PointInT, PointOutT>::checkResults(const Results& results,
                                                               Run& run) const
{
  const VoxelBand& band = results.band;
  const int min_radius = run.segmentation.components.min_radius;
  std::size_t cores = 0;
  for (std::size_t c = 0; c < band.size(); ++c)
    if (results.map.radius(static_cast<CellId>(c)) >= min_radius)
      ++cores;
  std::size_t faces = 0;
  for (const Region& region : results.segmentation.regions())
    if (region.feature_class == FeatureClass::kFace)
      ++faces;
  const int resolution = run.resolution.resolution;
  const bool rough =
    detail::roughPoints(band.roughness(), noise_mode_, run.point_noise) || run.calmed;
  // the automatic resolution is already as fine as the points support: finer cells
  // need more points (or the fill, from the points alone)
  const bool at_points_cap = detail::atPointsCap(run);
  // noise mode smooths points: no advice for a mesh's band, which has no noise
  const bool scan_advice = !noise_mode_ && run.fill != SurfaceFill::kMesh;
  const auto denser = [&](std::ostream& out) {
    out << detail::pointsCapAdvice(run);
    if (run.fill == SurfaceFill::kPoints)
      out << "; or fill the band between the points (fill 'triangles')";
  };
  const double core_share = band.empty() ? 0.0 : double(cores) / double(band.size());
  const double repair_share =
    band.empty() ? 0.0 : double(band.repairCellCount()) / double(band.size());
  // a band full of holes (its own warning below): a finer resolution makes it worse
  const bool holes = repair_share > kMaxRepairShare;
  // a band in pieces: the points are sparser than the cells
  std::size_t largest_piece = 0;
  for (const std::uint32_t size : bandPieceSizes(band))
    largest_piece = std::max<std::size_t>(largest_piece, size);
  std::ostringstream w;
  if (double(largest_piece) < kMinLargestPieceShare * double(band.size())) {
    w << "the band falls apart: its largest 6-connected piece holds " << largest_piece
      << " of " << band.size() << " cells (the points are sparser than the cells at "
      << "resolution " << resolution << "); "
      << (run.fill == SurfaceFill::kPoints
            ? "fill the band between the points (fill 'triangles') or lower the "
              "resolution"
            : "lower the resolution");
    run.warnings.push_back(w.str());
  } else if (results.segmentation.regions().empty() || faces == 0) {
    w << (faces == 0 && !results.segmentation.regions().empty() ? "no face found"
                                                                : "no region found")
      << ": " << cores << " of " << band.size() << " band cells reach min_radius "
      << min_radius << " rings (a face core needs them); the features lie closer than "
      << 2 * min_radius << " cells at resolution " << resolution
      << " or the band is broken: ";
    if (rough) {
      w << detail::roughPointsAdvice(detail::spreadIsShape(run));
    } else if (at_points_cap) {
      denser(w); // (a lower min_radius on points this sparse gives fragments)
    } else if (holes) {
      w << detail::kHolesFirst;
    } else {
      w << "raise the resolution";
      if (run.fill == SurfaceFill::kPoints && run.resolution.spacing > 0.0)
        w << " and fill the band between the points (fill 'triangles')";
      w << ", or lower min_radius";
      if (scan_advice)
        w << kNoisyScanAdvice;
    }
    run.warnings.push_back(w.str());
  } else if (core_share < kMinCoreShare) {
    w << "only " << std::round(1000.0 * core_share) / 10.0
      << "% of the band's cells reach"
      << " min_radius " << min_radius << " rings: most of the surface lies within "
      << min_radius << " cells of a feature at resolution " << resolution
      << ", so small faces and close edges merge or vanish; ";
    if (rough) {
      w << detail::roughPointsAdvice(detail::spreadIsShape(run));
    } else if (at_points_cap) {
      denser(w);
    } else if (holes) {
      w << detail::kHolesFirst;
    } else {
      w << "raise the resolution";
      if (scan_advice)
        w << kNoisyScanAdvice;
    }
    run.warnings.push_back(w.str());
  }
  checkNoise(band, run);
  if (holes) {
    std::ostringstream r;
    r << "the band has holes: " << band.repairCellCount() << " of " << band.size()
      << " cells were added to close it (the points are sparser than the cells)";
    if (run.fill == SurfaceFill::kPoints)
      r << "; fill the band between the points (fill 'triangles') or lower the "
           "resolution";
    else
      r << "; lower the resolution";
    run.warnings.push_back(r.str());
  }
  checkGraph(results, run);
  if (run.warnings.empty()) // the graph looks whole, yet creases may have merged
    detail::warnMergedValleys(results, run, max_search_resolution_);
}

template <typename PointInT, typename PointOutT>
void
VisibilityFeatureEstimation<PointInT, PointOutT>::checkNoise(const VoxelBand& band,
                                                             Run& run) const
{
  const int min_radius = run.segmentation.components.min_radius;
  const int resolution = run.resolution.resolution;
  if (!noise_mode_ && band.roughness() > kNoisyRoughness) {
    const int calmer = detail::calmerResolution(resolution, band.roughness());
    std::ostringstream r;
    const bool shape = detail::spreadIsShape(run);
    r << (shape ? "the band is rough" : "the points scatter about the surface")
      << ": roughness " << std::round(1000.0 * band.roughness()) / 1000.0
      << " cells (RMS distance of the cells' point centroids to local planes; clean "
         "clouds give about 0, and counts break from about 0.15): the result may be "
         "wrong; ";
    if (shape)
      r << "on points this sparse that is their shape, not noise (see the warning on "
           "their spread): sample denser";
    else if (detail::calmerIsUseful(calmer, min_radius))
      r << "use noise mode (setNoiseMode(true)) or a resolution of " << calmer
        << " or lower";
    else
      r << "use noise mode (setNoiseMode(true)) or smooth the points first "
           "(pcl::MovingLeastSquares): "
        << detail::calmerTooCoarse(calmer);
    run.warnings.push_back(r.str());
  }
  if (run.point_noise > kNoisyPointNoise) {
    const int calmer = detail::calmerResolution(resolution, run.point_noise);
    std::ostringstream r;
    if (detail::noiseIsShape(run)) {
      r << "the points are too sparse for the part: the planes fitted to each point's "
           "neighbours leave "
        << std::round(1000.0 * run.point_noise) / 1000.0 << " cells (median RMS), ";
      if (detail::tooFewPointsForNoise(run))
        r << "and with only " << run.noise_points << " points (fewer than "
          << kNoiseReadablePoints
          << ") no neighbourhood lies within one face, so noise "
          << "cannot be told from the shape: read it as the shape";
      else
        r << "yet " << std::round(100.0 * run.point_flat_share)
          << "% of the neighbourhoods lie exactly flat, so this is the shape, not "
             "noise: the neighbours of most points span a crease (faces only a few "
             "point spacings wide)";
      r << "; the band filled between them is as rough, and the result may be wrong; "
           "sample denser (faces about 10 spacings wide or more)";
    } else {
      r << "the points scatter about their local planes: noise "
        << std::round(1000.0 * run.point_noise) / 1000.0
        << " cells (RMS about the planes fitted to each point's neighbours; clean "
           "clouds give about 0, and counts break from about 0.17): the band filled "
           "between the points is as rough, and the result may be wrong; smooth the "
           "points first (pcl::MovingLeastSquares; a denser sample is as noisy)";
      if (detail::calmerIsUseful(calmer, min_radius))
        r << ", or use a resolution of " << calmer
          << " or lower with the fill 'triangles' (setSurfaceFill()), where "
          << "features need to lie about " << std::setprecision(3)
          << 2 * min_radius * run.grid.cell_size * resolution / calmer
          << " apart (world units)";
      else
        r << ": " << detail::calmerTooCoarse(calmer);
    }
    run.warnings.insert(run.warnings.begin(), r.str()); // the cause of the others
  }
}

template <typename PointInT, typename PointOutT>
void
VisibilityFeatureEstimation<PointInT, PointOutT>::checkGraph(const Results& results,
                                                             Run& run) const
{
  // a one-view depth image is an open surface: its edges end at its border
  if (run.segmentation.raw || !run.segmentation.complete_regions ||
      run.fill == SurfaceFill::kOrganized ||
      !run.warnings.empty()) // a warning of the band or the map says more
    return;
  const GraphGaps gaps = findGraphGaps(results.graph);
  if (!gaps.any())
    return;
  const int min_radius = run.segmentation.components.min_radius;
  const bool closed =
    detail::closedSurface(results, run, mesh_ != nullptr, mesh_closed_);
  std::ostringstream w;
  w << "the graph is not that of a closed part: " << gaps.describe() << ". ";
  if (closed)
    w << "Features";
  else // the border's gaps first: no resolution closes them
    w << (mesh_ ? "The mesh is open" : "The band encloses no volume (an open scan?)")
      << ": its border leaves edges without their outer corner, which no resolution "
         "closes; where gaps lie away from the border, features";
  w << " closer than about " << 2 * min_radius << " cells (2 min_radius) at "
    << "resolution " << run.resolution.resolution
    << " were not all separated: read the graph as approximate, or ";
  if (detail::atPointsCap(run))
    w << detail::pointsCapAdvice(run);
  else
    w << "raise the resolution" << detail::finerExample(run.resolution.resolution);
  if (closed && run.search_cap > 0 &&
      run.search_cap_reason == detail::kSearchLimitReason)
    w << " (setResolution(), or " << detail::searchFurtherAdvice(max_search_resolution_)
      << ")";
  else if (!closed && run.search_cap > 0) // the automatic search left it here
    w << " (setResolution(): the automatic search rises on such gaps for a closed "
         "surface only, a closed mesh or a cloud whose band encloses a volume)";
  run.warnings.push_back(w.str());
}

template <typename PointInT, typename PointOutT>
void
VisibilityFeatureEstimation<PointInT, PointOutT>::checkMemoryBudget(
  const Run& run) const
{
  // Refuse before allocating the band: the cells of the points are at most the points;
  // a fill makes cells between them, at least one a cell area of the surface (the
  // mesh's area, or the points' count times their spacing squared), and holds each
  // about kFillBytesPerCell while it rasterises (a fill between points also
  // kFillBytesPerPoint a point). The free space and the map are checked
  // again once the band is known (checkBandMemory).
  const GridSpec& grid = run.grid;
  const std::size_t points = surface_->size();
  const double cell_area = grid.cell_size * grid.cell_size;
  double surface_area = 0.0;
  if (run.fill == SurfaceFill::kMesh && mesh_)
    surface_area = meshArea(*mesh_);
  else if (run.fill == SurfaceFill::kLocalTriangles && run.resolution.spacing > 0.0)
    surface_area = double(points) * run.resolution.spacing * run.resolution.spacing;
  const double fill_cells =
    cell_area > 0.0 ? std::min(surface_area / cell_area, double(grid.cellCount()))
                    : 0.0;
  // the fill between points also holds each point's neighbours and triangles
  const bool between_points = run.fill == SurfaceFill::kLocalTriangles;
  if (fill_cells > 0.0)
    checkMemory(static_cast<std::uint64_t>(
                  fill_cells * kFillBytesPerCell +
                  (between_points ? double(points) * kFillBytesPerPoint : 0.0)),
                memory_limit_,
                "filling the band between " +
                  std::string(between_points ? "the points" : "the mesh's triangles") +
                  " at resolution " + std::to_string(run.resolution.resolution) +
                  " (at least " + std::to_string(std::llround(fill_cells)) +
                  " cells: the surface's area in cells" +
                  (between_points ? ", and " + std::to_string(points) + " points"
                                  : std::string()) +
                  ")");
  const std::size_t cells =
    static_cast<std::size_t>(std::min<std::uint64_t>(points, grid.cellCount()));
  const int threads = resolveThreads(run.visibility.threads);
  const std::uint64_t octree_bytes = std::uint64_t{160} * cells + 4 * points;
  const std::uint64_t estimate =
    VoxelBand::estimateBytes(grid, cells, points) + octree_bytes +
    std::uint64_t{4} * cells * static_cast<std::uint64_t>(threads) +
    (run.smoothing.radius > 0.0 ? (sizeof(PointInT) + 40) * std::uint64_t{points} : 0);
  checkMemory(estimate, memory_limit_,
              "a grid of " + std::to_string(grid.dims.x()) + "x" +
                std::to_string(grid.dims.y()) + "x" + std::to_string(grid.dims.z()) +
                " cells");
}

template <typename PointInT, typename PointOutT>
void
VisibilityFeatureEstimation<PointInT, PointOutT>::checkBandMemory(
  const VoxelBand& band, std::uint64_t mask_bytes, const Run& run) const
{
  // Counted from the band itself: the sparse mask's bricks, the map's working set.
  const std::uint64_t estimate = band.memoryBytes() + mask_bytes +
                                 VisibilityMap::estimateBytes(band, run.visibility);
  checkMemory(estimate, memory_limit_,
              "the free space and visibility map of " + std::to_string(band.size()) +
                " mixed cells");
}

} // namespace visfeat
