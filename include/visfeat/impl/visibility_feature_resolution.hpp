// VisibilityFeatureEstimation (not for inclusion on its own): the automatic
// resolution, its search for narrow faces, the grid and the surface fill.
#pragma once

#include <visfeat/core/graph/graph_gaps.h>
#include <visfeat/core/grid/resolution_search.h>
#include <visfeat/core/segmentation/narrow_faces.h>
#include <visfeat/impl/visibility_feature_checks.hpp>
#include <visfeat/impl/visibility_feature_estimation.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <optional>
#include <sstream>

namespace visfeat {

template <typename PointInT, typename PointOutT>
void
VisibilityFeatureEstimation<PointInT, PointOutT>::prepareGrid(Run& run,
                                                              int resolution) const
{
  if (mesh_ && surface_fill_ != SurfaceFill::kPoints) {
    // the grid covers the mesh too: its triangles reach beyond the points
    validateMesh(*mesh_);
    Eigen::Vector3d lo =
      Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
    Eigen::Vector3d hi = -lo;
    for (const PointInT& p : surface_->points)
      if (pcl::isXYZFinite(p)) {
        lo = lo.cwiseMin(Eigen::Vector3d(p.x, p.y, p.z));
        hi = hi.cwiseMax(Eigen::Vector3d(p.x, p.y, p.z));
      }
    for (const Eigen::Vector3d& v : mesh_->vertices) {
      lo = lo.cwiseMin(v);
      hi = hi.cwiseMax(v);
    }
    pcl::PointCloud<pcl::PointXYZ> corners;
    corners.push_back(pcl::PointXYZ(static_cast<float>(lo.x()),
                                    static_cast<float>(lo.y()),
                                    static_cast<float>(lo.z())));
    corners.push_back(pcl::PointXYZ(static_cast<float>(hi.x()),
                                    static_cast<float>(hi.y()),
                                    static_cast<float>(hi.z())));
    run.grid = gridForCloud(corners, resolution);
  } else {
    run.grid = gridForCloud(*surface_, resolution);
  }
  chooseFill(run);
  checkMemoryBudget(run);
}

template <typename PointInT, typename PointOutT>
int
VisibilityFeatureEstimation<PointInT, PointOutT>::chooseResolution(
  const CloudShape& shape, Run& run) const
{
  if (resolution_ != kAutomaticResolution) {
    run.resolution.resolution = resolution_;
    run.resolution.extent = shape.extent;
    run.resolution.reason = "set by setResolution()";
    // The fill and the widths below it need the spacing, as the automatic resolution
    // measures it: the same grid then gives the same result both ways (a mesh sampled
    // to 1,000,000 points at 1024 cells, 1.26 cells apart, gave 3/7/6 automatic and
    // 2/5/6 set). It is cheap to measure on clouds that may need it.
    if (surface_fill_ != SurfaceFill::kPoints && hasExtent(shape) &&
        static_cast<double>(surface_->size()) <
          kFillCheckPointsPerCell2 * double(resolution_) * double(resolution_)) {
      detail::takeSpacing(estimateResolution(*surface_, shape.extent), run.resolution);
    }
    return resolution_;
  }
  if (!hasExtent(shape))
    return GridSpec::kMinResolution; // the grid refuses the cloud, saying why
  try {
    run.resolution = estimateResolution(*surface_, shape.extent);
  } catch (const Error& e) {
    throw Error(std::string(e.what()) + "; set the resolution (setResolution())");
  }
  const bool may_fill = surface_fill_ == SurfaceFill::kAuto ||
                        surface_fill_ == SurfaceFill::kLocalTriangles ||
                        surface_fill_ == SurfaceFill::kOrganized ||
                        (surface_fill_ == SurfaceFill::kMesh && mesh_);
  const int from_density = run.resolution.resolution;
  if (mesh_ && may_fill) {
    // A mesh's triangles give the band at any resolution: the density of the points
    // sampled on it says nothing about the features (a public icosahedron mesh sampled
    // to 1,000,000 points gave 322 cells and 12/28/20; 256 gives 12/30/20).
    std::ostringstream reason;
    reason << "a mesh: " << kTopologyResolution << " cells for the topology (features "
           << "about " << 2 * getMinRadius() << " cells apart separate, "
           << kTopologyResolution << " suits parts whose faces span 1/8 of their "
           << "size); its triangles give the band at any resolution, so the points "
              "sampled on it do not set the cells (their "
           << run.resolution.reason << " would support " << from_density << ")";
    run.resolution.resolution = kTopologyResolution;
    run.resolution.reason = reason.str();
    run.search_cap = std::min(max_search_resolution_, GridSpec::kMaxResolution);
    run.search_cap_reason = detail::kSearchLimitReason;
    return run.resolution.resolution;
  }
  if (may_fill && from_density < kTopologyResolution) {
    // the fill lets cells be finer than the points, up to kMaxFillCellsPerSpacing
    const double supported = kMaxFillCellsPerSpacing * run.resolution.extent /
                             std::max(run.resolution.spacing, 1e-300);
    const int raised =
      static_cast<int>(std::min<double>(kTopologyResolution, std::floor(supported)));
    // a cloud only where the fill makes a worthwhile difference
    if (raised >= kMinFillRaise * from_density) {
      std::ostringstream reason;
      reason << run.resolution.reason << "; the points alone support " << from_density
             << ", raised to " << raised << " for the topology ("
             << "the band is filled between the points, at most "
             << int(kMaxFillCellsPerSpacing) << " cells a spacing"
             << "; features about " << 2 * getMinRadius() << " cells apart separate, "
             << kTopologyResolution
             << " suits parts whose faces span 1/8 of their size)";
      run.resolution.resolution = raised;
      run.resolution.reason = reason.str();
      run.raised_for_fill = true;
    }
  }
  // The search for narrow faces may go finer, as far as the mesh or the fill allow.
  run.search_cap = std::min(max_search_resolution_, GridSpec::kMaxResolution);
  run.search_cap_reason = detail::kSearchLimitReason;
  if (!may_fill) {
    run.search_cap = from_density;
    run.search_cap_reason = "what the points support without a fill";
  } else if (!mesh_) {
    const double supported = kMaxFillCellsPerSpacing * run.resolution.extent /
                             std::max(run.resolution.spacing, 1e-300);
    if (supported < run.search_cap) {
      run.search_cap = static_cast<int>(std::floor(supported));
      run.search_cap_reason = "what the fill supports (" +
                              std::to_string(int(kMaxFillCellsPerSpacing)) +
                              " cells a point spacing)";
    }
  }
  return run.resolution.resolution;
}

template <typename PointInT, typename PointOutT>
void
VisibilityFeatureEstimation<PointInT, PointOutT>::chooseFill(Run& run) const
{
  if (surface_fill_ == SurfaceFill::kMesh && !mesh_)
    throw Error("the surface fill 'mesh' needs a mesh: call setInputMesh() first");
  const double spacing_cells = run.resolution.spacing / run.grid.cell_size;
  std::ostringstream reason;
  if (surface_fill_ != SurfaceFill::kAuto) {
    run.fill = surface_fill_;
    reason << "set by setSurfaceFill()";
  } else if (mesh_) {
    run.fill = SurfaceFill::kMesh;
    reason << "a mesh was given: its triangles rasterised";
  } else if (surface_->height > 1) {
    run.fill = SurfaceFill::kOrganized;
    reason << "an organized cloud (" << surface_->width << " x " << surface_->height
           << "): its pixel grid, cut at depth jumps";
  } else if (run.raised_for_fill ||
             (run.resolution.spacing > 0.0 && spacing_cells > kFillSpacingCells)) {
    run.fill = SurfaceFill::kLocalTriangles;
    reason << "point spacing " << spacing_cells << " cells, ";
    if (run.raised_for_fill)
      reason << "the resolution was raised beyond the points";
    else
      reason << "above " << kFillSpacingCells
             << " (the cells of the points would leave holes)";
    reason << ": the band is filled between neighbouring points";
  } else {
    run.fill = SurfaceFill::kPoints;
    reason << "the cells of the points";
    if (run.resolution.spacing > 0.0)
      reason << " (point spacing " << spacing_cells << " cells)";
  }
  run.fill_reason = reason.str();
  // Cells finer than the points: a point is a feature point within the distance in
  // point spacings (unless set), as its neighbours lie that far apart. Widened from the
  // parameters, not from run's values: the search and the calmer resolution choose
  // the fill again on a copy of the first run, already widened at its resolution.
  const bool widen = run.fill != SurfaceFill::kPoints && spacing_cells > 1.0;
  if (!point_feature_distance_)
    run.segmentation.point_feature_distance =
      widen ? std::min(getPointFeatureDistance() * spacing_cells,
                       SegmentationParameters::kPointFeatureDistanceRange.max)
            : getPointFeatureDistance();
  // Likewise the window of the crease angles holds as many points as on dense clouds.
  run.crease_angles.window_cells =
    widen ? std::min(crease_angles_.window_cells * spacing_cells,
                     CreaseAngleParameters::kWindowCellsRange.max)
          : crease_angles_.window_cells;
  // A mesh's band is as fine as the cells, its points are not: say what widened (at
  // this resolution only).
  const auto spacing_note = [](const std::string& note) {
    return note.rfind(detail::kSpacingNotePrefix, 0) == 0;
  };
  run.notes.erase(std::remove_if(run.notes.begin(), run.notes.end(), spacing_note),
                  run.notes.end());
  if (run.fill == SurfaceFill::kMesh && spacing_cells > 1.0) {
    std::ostringstream note;
    note << detail::kSpacingNotePrefix << spacing_cells << " cells apart at resolution "
         << run.resolution.resolution
         << ": feature points are taken that much wider, and the crease angles in a "
            "window that much larger; for one point a cell, sample the mesh to about "
         << static_cast<std::uint64_t>(std::ceil(static_cast<double>(surface_->size()) *
                                                 spacing_cells * spacing_cells))
         << " points";
    run.notes.push_back(note.str());
  }
}

template <typename PointInT, typename PointOutT>
std::optional<typename VisibilityFeatureEstimation<PointInT, PointOutT>::Results>
VisibilityFeatureEstimation<PointInT, PointOutT>::runAt(Run& run,
                                                        int resolution,
                                                        PointCloudOut& output,
                                                        std::string& problem) const
{
  const auto start = std::chrono::steady_clock::now();
  try {
    prepareGrid(run, resolution);
    run.times.grid_ms = detail::millisecondsSince(start);
    return computeResults(run, output);
  } catch (const Error& e) {
    problem = e.what();
  } catch (const std::bad_alloc&) {
    problem = "out of memory";
  }
  return std::nullopt;
}

template <typename PointInT, typename PointOutT>
typename VisibilityFeatureEstimation<PointInT, PointOutT>::Results
VisibilityFeatureEstimation<PointInT, PointOutT>::searchResolution(
  const Run& base, Run& run, Results results, PointCloudOut& output) const
{
  const int min_radius = run.segmentation.components.min_radius;
  const std::size_t min_cells = static_cast<std::size_t>(kNarrowFaceCoreAreas) *
                                static_cast<std::size_t>(min_radius * min_radius);
  double discarded_ms = 0.0;
  const int max_steps = searchSteps(max_search_resolution_);
  for (int step = 0;; ++step) {
    const std::vector<NarrowFace> faces = narrowFaces(
      results.band, results.map, min_radius, kNarrowFacePersistence, min_cells);
    const int current = run.resolution.resolution;
    const int next =
      step < max_steps ? nextSearchResolution(current, run.search_cap) : 0;
    std::ostringstream found;
    if (faces.empty()) {
      // A closed surface bounds a solid: a graph that is not that of a closed part
      // means features the resolution did not separate (kSearchOnGraphGaps).
      const GraphGaps gaps =
        kSearchOnGraphGaps && run.segmentation.complete_regions && !run.segmentation.raw
          ? findGraphGaps(results.graph)
          : GraphGaps{};
      const bool closed = gaps.any() && detail::closedSurface(
                                          results, run, mesh_ != nullptr, mesh_closed_);
      if (closed) {
        found << (mesh_ ? "a closed mesh"
                        : "a closed surface (the band encloses a volume)")
              << " whose graph at resolution " << current
              << " is not that of a closed part (" << gaps.describe() << ")";
      } else {
        // creases merged into faces, which leave the graph closed (any input)
        const MergedValleys valleys =
          detail::manyMergedValleys(results, run.segmentation);
        if (!valleys.any()) {
          if (gaps.any()) // say why the gaps did not raise it
            run.resolution.reason +=
              "; the graph at resolution " + std::to_string(current) +
              " has gaps, not raised on them: " +
              (mesh_                                 ? "the mesh is open"
               : run.fill == SurfaceFill::kOrganized ? "a one-view depth image"
                                                     : "the band encloses no volume") +
              " (an open surface's border leaves such gaps)";
          break;
        }
        found << detail::describeMergedValleys(valleys, min_radius) << " at resolution "
              << current << " (creases merged into faces)";
      }
      if (next == 0)
        break; // checkGraph() or detail::warnMergedValleys() has said so
    } else {
      int narrowest = min_radius;
      for (const NarrowFace& face : faces)
        narrowest = std::min(narrowest, face.peak);
      found << faces.size() << " narrow face" << (faces.size() == 1 ? "" : "s")
            << " at resolution " << current << " (peaks of the visibility map below "
            << "min_radius " << min_radius << " rings, the narrowest " << narrowest
            << " rings)";
    }
    if (next == 0) {
      std::ostringstream w;
      w << found.str() << ": they merge into the edges around them; the resolution "
        << "stays at " << current << ": ";
      if (step >= max_steps)
        w << "the search's last step";
      else if (current >= run.search_cap) // e.g. a chosen resolution above the cap
        w << "the search stops at " << run.search_cap << " (" << run.search_cap_reason
          << ")"
          << (current > run.search_cap
                ? " and " + std::to_string(current) + " is already beyond it"
                : "");
      else
        w << "the search goes up to " << run.search_cap << ", "
          << run.search_cap_reason;
      w << "; ";
      if (run.calmed ||
          detail::roughPoints(results.band.roughness(), noise_mode_, run.point_noise))
        w << detail::roughPointsAdvice(detail::spreadIsShape(run));
      else if (run.fill == SurfaceFill::kPoints && run.search_cap <= current)
        w << "fill the band between the points (fill 'triangles') so that the "
             "resolution can rise to resolve them, or lower min_radius";
      else if (run.search_cap <= current &&
               run.search_cap_reason != detail::kSearchLimitReason)
        w << "sample denser so that the resolution can rise to resolve them";
      else
        w << "set a finer resolution to resolve them (or "
          << detail::searchFurtherAdvice(max_search_resolution_)
          << "), or lower min_radius";
      run.warnings.push_back(w.str());
      break;
    }
    // Finer cells make noisy points rougher in cells, and counts break on rough points
    // (kNoisyPointNoise, kNoisyRoughness): the search does not go where they would be
    // rough. Noise in cells grows at least with the resolution (more in noise mode,
    // whose smoothing radius is in cells), so a run that would be rough is not tried,
    // and one that turns out rough is dropped (a fresh user's scan in noise mode: 0.04
    // cells at 256 after smoothing, 0.52 at 512, 1.10 at 1024, and 130/219/134 for
    // 2/5/5; 256 gives 3/11/6).
    const double finer_by = static_cast<double>(next) / current;
    if (detail::roughPoints(results.band.roughness() * finer_by, noise_mode_,
                            run.point_noise * finer_by)) {
      keepUnderNoise(results, run, found.str(), next,
                     finer_by * detail::pointRoughness(results.band.roughness(),
                                                       noise_mode_, run.point_noise),
                     true);
      break;
    }
    Run finer = base;
    finer.resolution.resolution = next;
    finer.resolution.reason = run.resolution.reason + "; " + found.str() +
                              ": raised to " + std::to_string(next);
    const int density =
      run.resolution.spacing > 0.0
        ? resolutionForSpacing(run.resolution.extent, run.resolution.spacing)
        : 0;
    finer.raised_for_fill = !mesh_ && density > 0 && next > density;
    finer.search_cap = run.search_cap;
    finer.search_cap_reason = run.search_cap_reason;
    PointCloudOut finer_output = output;
    std::string problem;
    if (std::optional<Results> finer_results =
          runAt(finer, next, finer_output, problem)) {
      if (detail::roughPoints(finer_results->band.roughness(), noise_mode_,
                              finer.point_noise)) {
        discarded_ms += finer.times.total() - finer.times.shape_ms;
        keepUnderNoise(results, run, found.str(), next,
                       detail::pointRoughness(finer_results->band.roughness(),
                                              noise_mode_, finer.point_noise),
                       false);
        break;
      }
      discarded_ms += run.times.total() - run.times.shape_ms;
      results = std::move(*finer_results);
      run = std::move(finer);
      output.swap(finer_output);
      continue;
    }
    run.warnings.push_back(found.str() + ": features merge; resolution " +
                           std::to_string(next) + " failed (" +
                           detail::oneLine(problem) +
                           "); set a finer resolution within the memory limit, or "
                           "lower min_radius");
    break;
  }
  run.times.search_ms += discarded_ms;
  return results;
}

template <typename PointInT, typename PointOutT>
void
VisibilityFeatureEstimation<PointInT, PointOutT>::keepUnderNoise(
  const Results& results,
  Run& run,
  const std::string& found,
  int next,
  double noise,
  bool predicted) const
{
  const int current = run.resolution.resolution;
  std::ostringstream step;
  step << found << ": kept, since at " << next << " the points "
       << (predicted ? "would scatter at least " : "scatter ")
       << std::round(1000.0 * noise) / 1000.0
       << " cells about their local planes (noise; rough from " << kNoisyPointNoise
       << ", where the results are warned of)";
  run.resolution.reason += "; " + step.str();
  // The results were checked with the search's own limit, whose advice is a finer
  // resolution: checked again with the noise as the limit, they advise a denser sample.
  run.search_cap = current;
  run.search_cap_reason = detail::kNoiseLimitReason;
  run.warnings = run.warnings_before_checks;
  checkResults(results, run);
  std::ostringstream w;
  w << step.str() << ": they merge into the edges around them at " << current << "; "
    << (noise_mode_
          ? "sample denser (noise mode's smoothing radius is in cells: finer "
            "cells hold fewer points) or smooth the points first "
            "(pcl::MovingLeastSquares)"
          : "smooth the points first (pcl::MovingLeastSquares; a denser sample "
            "is as noisy)")
    << " to resolve them";
  run.warnings.push_back(w.str());
}

template <typename PointInT, typename PointOutT>
typename VisibilityFeatureEstimation<PointInT, PointOutT>::Results
VisibilityFeatureEstimation<PointInT, PointOutT>::calmResolution(
  const Run& base, Run& run, Results results, PointCloudOut& output) const
{
  // The band filled between noisy points is as rough as they are, in cells: the
  // resolution at which their noise is kCalmRoughness cells, with the fill, and no
  // finer search (see kNoisyPointNoise).
  const int current = run.resolution.resolution;
  const int calmer = detail::calmerResolution(current, run.point_noise);
  if (calmer >= current)
    return results;
  std::ostringstream why;
  const bool shape = detail::noiseIsShape(run);
  why << "the points' " << detail::pointSpreadName(run) << " "
      << std::round(1000.0 * run.point_noise) / 1000.0 << " cells at " << current
      << ", where counts break: lowered to " << calmer << ", where it is about "
      << kCalmRoughness << " cells"
      << (!shape ? std::string()
          : detail::tooFewPointsForNoise(run)
            ? "; read as the shape: with fewer than " +
                std::to_string(kNoiseReadablePoints) +
                " points no neighbourhood lies within one face, so noise cannot be "
                "told from it"
            : std::string("; that spread is the shape, not noise: the neighbourhoods "
                          "of most points span a crease"));
  Run calm = base;
  calm.resolution.resolution = calmer;
  calm.resolution.reason = run.resolution.reason + "; " + why.str();
  calm.raised_for_fill = !mesh_; // the band stays filled between the points
  calm.search_cap = calmer;
  calm.calmed = true;
  calm.calmed_for_shape = shape;
  calm.search_cap_reason = shape ? std::string("what the points' spread allows")
                                 : std::string(detail::kNoiseLimitReason);
  PointCloudOut calm_output = output;
  std::string problem;
  if (std::optional<Results> calm_results = runAt(calm, calmer, calm_output, problem)) {
    calm.times.search_ms += run.times.total() - run.times.shape_ms;
    const double apart =
      2.0 * run.segmentation.components.min_radius * calm.grid.cell_size;
    std::ostringstream w;
    w << (shape ? "the points are too sparse for the part: " : "") << "resolution "
      << calmer << " for the points' " << detail::pointSpreadName(run) << " ("
      << why.str() << "): features closer than about " << std::setprecision(3) << apart
      << " (world units) merge and small ones may be lost";
    if (apart >= 0.5 * run.resolution.extent)
      w << ", at least half the cloud's extent of " << run.resolution.extent
        << ": expect few features or none";
    w << "; "
      << (shape ? "sample denser to resolve them"
                : "smooth the points (pcl::MovingLeastSquares) to resolve them: a "
                  "denser sample is as noisy");
    // Noise mode smooths over kNoiseSmoothingRadius cells: where that holds enough
    // points at the resolution before lowering, it calms the noise there (a fresh
    // user's scan: 0/3/3 lowered to 92, 3/11/6 in noise mode at 256).
    const double spacing_cells = run.resolution.spacing / run.grid.cell_size;
    const double smoothed = spacing_cells > 0.0 ? EIGEN_PI * kNoiseSmoothingRadius *
                                                    kNoiseSmoothingRadius /
                                                    (spacing_cells * spacing_cells)
                                                : 0.0;
    if (!shape && !noise_mode_ && smoothed >= kNoiseModeSmoothedPoints &&
        run.point_noise <= kNoiseModeMaxPointNoise)
      w << ", or use noise mode (setNoiseMode(true)): its smoothing over "
        << kNoiseSmoothingRadius << " cells holds about " << std::lround(smoothed)
        << " points at resolution " << current << ", enough to calm this noise there";
    calm.warnings.insert(calm.warnings.begin(), w.str());
    output.swap(calm_output);
    run = std::move(calm);
    return std::move(*calm_results);
  }
  run.warnings.push_back("resolution " + std::to_string(calmer) + ", " + why.str() +
                         ", failed (" + detail::oneLine(problem) + ")");
  return results;
}

} // namespace visfeat
