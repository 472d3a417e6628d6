#pragma once

#include <visfeat/core/common/error.h>
#include <visfeat/core/common/memory_budget.h>
#include <visfeat/core/common/threads.h>
#include <visfeat/core/graph/stray_regions.h>
#include <visfeat/core/grid/cloud_shape.h>
#include <visfeat/core/segmentation/point_labeling.h>
#include <visfeat/impl/resolution_estimation.hpp>
#include <visfeat/impl/voxel_band_from_cloud.hpp>
#include <visfeat/resolution_estimation.h>
#include <visfeat/visibility_feature_estimation.h>
#include <visfeat/voxel_band_from_cloud.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <new>
#include <sstream>

namespace visfeat {
namespace detail {

inline double
millisecondsSince(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() -
                                                   start)
    .count();
}

/** \brief The farthest apart two vertex regions are pieces of one split corner
 * (strayRegionMerge(), world units): 2 vertex_reach cells, twice the reach within which
 * vertex candidates are one corner. Split pieces were measured 8-19 cells apart. */
inline double
splitCornerDistance(const VoxelBand& band, const SegmentationParameters& segmentation)
{
  return 2.0 * segmentation.vertex_reach * band.grid().cell_size;
}

/** \brief The edges among labels 1..regions without a turn (turn_of(label) not
 * finite) that hold at least min_points points and have one face on both sides:
 * creases fading into a face (measureFadingCreases()). */
template <typename TurnOf>
std::vector<std::uint32_t>
fadingCreases(const TopologyGraph& graph,
              std::size_t regions,
              std::uint64_t min_points,
              const TurnOf& turn_of)
{
  std::vector<std::uint32_t> edges;
  for (std::uint32_t id = 1; id <= graph.size() && id <= regions; ++id)
    if (graph.node(id).feature_class == FeatureClass::kEdge &&
        !std::isfinite(turn_of(id)) && graph.node(id).points >= min_points &&
        graph.facesOfEdge(id).size() == 1)
      edges.push_back(id);
  return edges;
}

/** \brief Into angles (per region, measureCreaseAngles()), the turn of each edge of at
 * least kMinWideEdgePoints points without one that has one face on both sides (a
 * crease fading into it; measureFadingCreases()), so that the minimum crease angle
 * judges fading creases too (the public rocker arm at 512 kept one of 12.9 degrees).
 * Specks stay unmeasured for the rules that join them (cornerSpurMerge()). */
inline void
addFadingCreaseTurns(const TopologyGraph& graph,
                     const std::vector<FeatureClass>& classes,
                     const std::vector<Eigen::Vector3d>& points,
                     const std::vector<std::uint32_t>& labels,
                     double cell_size,
                     double window_cells,
                     int threads,
                     std::vector<CreaseAngle>& angles)
{
  const std::vector<std::uint32_t> edges =
    fadingCreases(graph, angles.size(), CreaseAngleParameters::kMinWideEdgePoints,
                  [&](std::uint32_t id) { return angles[id - 1].degrees; });
  if (edges.empty())
    return;
  const std::vector<CreaseAngle> fading = measureFadingCreases(
    points, labels, classes, edges, cell_size, window_cells, threads);
  for (const std::uint32_t e : edges)
    if (std::isfinite(fading[e - 1].degrees))
      angles[e - 1] = fading[e - 1];
}

/** \brief GraphNode::crease_angle of each edge still without one that has one face on
 * both sides (a crease fading into it), from the output's points and labels
 * (measureFadingCreases(); for the graph only, after the clean-up: a fading crease
 * the clean-up made, or a speck that addFadingCreaseTurns() left out). */
template <typename Cloud>
void
setFadingCreaseTurns(TopologyGraph& graph,
                     const std::vector<FeatureClass>& classes,
                     const Cloud& output,
                     double cell_size,
                     const CreaseAngleParameters& parameters,
                     int threads)
{
  const std::vector<std::uint32_t> edges =
    fadingCreases(graph, classes.size(), 0,
                  [&](std::uint32_t id) { return graph.node(id).crease_angle; });
  if (edges.empty())
    return;
  std::vector<Eigen::Vector3d> points(output.size());
  std::vector<std::uint32_t> labels(output.size());
  for (std::size_t i = 0; i < output.size(); ++i) {
    points[i] = output[i].getVector3fMap().template cast<double>();
    labels[i] = output[i].label;
  }
  const std::vector<CreaseAngle> angles = measureFadingCreases(
    points, labels, classes, edges, cell_size, parameters.window_cells, threads);
  for (const std::uint32_t e : edges)
    if (std::isfinite(angles[e - 1].degrees))
      graph.setCreaseAngle(e, angles[e - 1].degrees);
}

/** \brief A message on one line (newlines of foreign exceptions become spaces). */
inline std::string
oneLine(std::string message)
{
  std::replace(message.begin(), message.end(), '\n', ' ');
  std::replace(message.begin(), message.end(), '\r', ' ');
  return message;
}

/** \brief Copies what a spacing estimate measured (spacing, k, copies) into `run`'s
 * estimate, whose resolution and reason stay. */
inline void
takeSpacing(const ResolutionEstimate& density, ResolutionEstimate& run)
{
  run.spacing = density.spacing;
  run.k = density.k;
  run.copies = density.copies;
  run.copy_radius = density.copy_radius;
  run.queries = density.queries;
}

/** \brief The resolution at which a roughness (or noise) of `cells` cells at
 * `resolution` becomes kCalmRoughness: both are lengths, so they scale together (at
 * least GridSpec::kMinResolution). */
inline int
calmerResolution(int resolution, double cells)
{
  return std::max(GridSpec::kMinResolution,
                  static_cast<int>(std::floor(resolution * kCalmRoughness / cells)));
}

/** \brief The graph nodes' point geometry (centroid, box, point count) from the
 * labelled points; cells, arcs and crease angles stay. */
template <typename PointOutT>
void
refreshPointGeometry(std::size_t regions,
                     const pcl::PointCloud<PointOutT>& output,
                     TopologyGraph& graph)
{
  RegionPointGeometry geometry(regions);
  for (const PointOutT& p : output.points)
    geometry.add(p.label, Eigen::Vector3d(p.x, p.y, p.z));
  geometry.applyTo(graph);
}

} // namespace detail

template <typename PointInT, typename PointOutT>
bool
VisibilityFeatureEstimation<PointInT, PointOutT>::fail(const std::string& message)
{
  error_ = message;
  PCL_ERROR("[visfeat::%s::compute] %s\n", getClassName().c_str(), message.c_str());
  return false;
}

template <typename PointInT, typename PointOutT>
bool
VisibilityFeatureEstimation<PointInT, PointOutT>::initCompute()
{
  error_.clear();
  run_.reset();
  if (!input_)
    return fail("no input cloud: call setInputCloud() first");
  if (!pcl::PCLBase<PointInT>::initCompute())
    return fail("the input cloud or its indices are invalid");
  if (input_->empty()) {
    this->deinitCompute();
    return fail("the input cloud is empty");
  }
  if (!surface_) {
    fake_surface_ = true;
    surface_ = input_;
  }
  std::string problem;
  try {
    run_ = std::make_unique<Run>(prepare());
  } catch (const Error& e) {
    problem = e.what();
  } catch (const std::bad_alloc&) {
    problem = "out of memory while checking the cloud";
  } catch (const std::exception& e) {
    problem = "unexpected error: " + detail::oneLine(e.what());
  }
  if (!problem.empty()) {
    run_.reset();
    this->deinitCompute();
    return fail(problem);
  }
  for (const std::string& note : run_->notes)
    PCL_WARN("[visfeat::%s::compute] %s\n", getClassName().c_str(), note.c_str());
  return true;
}

template <typename PointInT, typename PointOutT>
typename VisibilityFeatureEstimation<PointInT, PointOutT>::Run
VisibilityFeatureEstimation<PointInT, PointOutT>::prepare() const
{
  auto start = std::chrono::steady_clock::now();
  Run run;
  // Parameters as compute() uses them: auto max_radius, the noise mode's values.
  checkRange("min_radius", getMinRadius(), ComponentParameters::kMinRadiusRange,
             "rings");
  run.visibility.max_radius = getMaxRadius();
  run.visibility.opacity = opacity_;
  run.visibility.threads = threads_;
  VisibilityMap::validate(run.visibility);
  run.segmentation = getSegmentationParameters();
  run.segmentation.threads = threads_;
  run.segmentation.validate(run.visibility.max_radius);
  run.crease_angles = crease_angles_;
  run.crease_angles.validate();
  run.flat_points.max_surface_variation = flat_point_variation_;
  run.flat_points.threads = threads_;
  run.flat_points.validate();
  run.smoothing.radius = getSmoothingRadius();
  run.smoothing.threads = threads_;
  run.smoothing.validate();
  const bool touching = !run.segmentation.raw && run.segmentation.complete_regions;
  run.graph.dilation_radius =
    graph_dilation_ >= 0 ? graph_dilation_
                         : (touching ? TopologyGraphParameters::kDefaultDilationRadius
                                     : run.segmentation.components.min_radius);
  TopologyGraph::validate(run.graph);
  checkRange("max_search_resolution", max_search_resolution_,
             GridSpec::kResolutionRange, "cells");
  if (resolution_ != kAutomaticResolution &&
      !GridSpec::kResolutionRange.contains(resolution_)) {
    std::ostringstream msg;
    msg << "resolution " << resolution_ << " is out of range: " << kAutomaticResolution
        << " (automatic) or [" << GridSpec::kMinResolution << ", "
        << GridSpec::kMaxResolution
        << "] (cells along the longest side of the bounding box)";
    throw Error(msg.str());
  }

  // The shape: refuse clouds without a surface, note flat ones; the resolution, the
  // fill.
  const CloudShape shape = cloudShapeOf(*surface_);
  std::string problem = shapeProblem(shape, 0);
  if (!problem.empty())
    throw Error(problem);
  // too small for one face (no finite point, one point or all coincident: the grid
  // says so)
  const bool band_from_mesh = mesh_ && (surface_fill_ == SurfaceFill::kAuto ||
                                        surface_fill_ == SurfaceFill::kMesh);
  const std::size_t fewest = minimumCloudPoints(run.segmentation.components.min_radius);
  if (!band_from_mesh && hasExtent(shape) && shape.finite < fewest) {
    std::ostringstream msg;
    msg << "only " << shape.finite << " finite points: too few for one face (a face "
        << "spans 2 min_radius = " << 2 * run.segmentation.components.min_radius
        << " cells each way, and the band is filled over at most "
        << int(kMaxFillCellsPerSpacing) << " cells a point spacing: at least " << fewest
        << " points); sample denser, or give the surface as a mesh (setInputMesh())";
    throw Error(msg.str());
  }
  const int resolution = chooseResolution(shape, run);
  problem = shapeProblem(shape, resolution);
  if (!problem.empty())
    throw Error(problem);
  const std::string note = shapeNote(shape);
  if (!note.empty())
    run.notes.push_back(note);
  // Points without a position get no feature: say how many (a fresh user's PLY had 715
  // such points, passed through without a word)
  std::size_t skipped = 0;
  for (const auto i : *indices_) {
    const PointInT& p = (*input_)[static_cast<std::size_t>(i)];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      ++skipped;
  }
  if (skipped > 0)
    run.notes.push_back(
      std::to_string(skipped) + " of " + std::to_string(indices_->size()) +
      " points have a NaN or infinite coordinate: they are skipped (visibility_radius "
      "NaN, label 0)" +
      (input_->isOrganized() ? " (an organized cloud's empty pixels)" : ""));
  if (resolution_ != kAutomaticResolution &&
      max_search_resolution_ != kMaxSearchResolution)
    run.notes.push_back("setMaxSearchResolution() (" +
                        std::to_string(max_search_resolution_) +
                        ") has no effect: the resolution is set (setResolution()), so "
                        "there is no search");
  run.times.shape_ms = detail::millisecondsSince(start);

  start = std::chrono::steady_clock::now();
  prepareGrid(run, resolution);
  run.times.grid_ms = detail::millisecondsSince(start);
  return run;
}

template <typename PointInT, typename PointOutT>
std::vector<CellCoord>
VisibilityFeatureEstimation<PointInT, PointOutT>::fillCells(
  Run& run, const PointCloudIn& surface) const
{
  switch (run.fill) {
  case SurfaceFill::kMesh:
    return rasterizeTriangles(run.grid, mesh_->vertices, mesh_->triangles,
                              run.visibility.threads);
  case SurfaceFill::kLocalTriangles: {
    FillReport report;
    std::vector<CellCoord> cells =
      run.resolution.copies > 1 // triangles between sites, not between copies
        ? localTriangleCells(distinctSites(surface, run.resolution.copy_radius),
                             run.grid, local_triangles_, run.visibility.threads,
                             &report)
        : localTriangleCells(surface, run.grid, local_triangles_,
                             run.visibility.threads, &report);
    if (report.noise >= 0.0)
      run.point_noise = report.noise / run.grid.cell_size;
    run.point_flat_share = report.flat_share;
    run.noise_points = report.points;
    return cells;
  }
  case SurfaceFill::kOrganized:
    return organizedCells(surface, run.grid, organized_triangles_,
                          run.visibility.threads);
  default:
    return {};
  }
}

template <typename PointInT, typename PointOutT>
bool
VisibilityFeatureEstimation<PointInT, PointOutT>::refillSparseBand(
  Run& run, const VoxelBand& band) const
{
  // Only the automatic choice of the points band, and only where it has holes.
  if (run.fill != SurfaceFill::kPoints || surface_fill_ != SurfaceFill::kAuto ||
      band.empty())
    return false;
  const double repair_share = double(band.repairCellCount()) / double(band.size());
  std::ostringstream why;
  why << " (" << band.repairCellCount() << " of " << band.size()
      << " cells added by the repair)";
  // A set resolution with kFillCheckPointsPerCell2 points per cell^2 or more: the
  // spacing was not measured before the band.
  if (!(run.resolution.spacing > 0.0) && repair_share > kSpacingCheckRepairShare) {
    try {
      detail::takeSpacing(estimateResolution(*surface_, run.resolution.extent),
                          run.resolution);
    } catch (const Error&) {
      return false; // no spacing (e.g. mostly duplicates): the points band stays
    }
    chooseFill(run);
    if (run.fill != SurfaceFill::kPoints) {
      run.fill_reason += "; measured as the cells of the points left holes" + why.str();
      return true;
    }
  }
  // Dense enough by the median spacing, yet full of holes: the density is uneven, and
  // the sparser parts lie farther apart than the cells (kUnevenRepairShare).
  if (repair_share > kUnevenRepairShare) {
    std::ostringstream reason;
    reason << "the cells of the points left holes" << why.str()
           << " although the median point spacing is "
           << run.resolution.spacing / run.grid.cell_size
           << " cells: the density is uneven, so the band is filled between "
              "neighbouring points";
    run.fill = SurfaceFill::kLocalTriangles;
    run.fill_reason = reason.str();
    return true;
  }
  return false;
}

template <typename PointInT, typename PointOutT>
typename VisibilityFeatureEstimation<PointInT, PointOutT>::PointCloudIn::ConstPtr
VisibilityFeatureEstimation<PointInT, PointOutT>::smoothedSurface(Run& run) const
{
  if (!(run.smoothing.radius > 0.0))
    return surface_;
  const auto start = std::chrono::steady_clock::now();
  std::vector<Eigen::Vector3f> points(surface_->size());
  for (std::size_t i = 0; i < points.size(); ++i)
    points[i] = (*surface_)[i].getVector3fMap();
  points = smoothPoints(points, run.grid, run.smoothing);
  auto smoothed = std::make_shared<pcl::PointCloud<PointInT>>(*surface_);
  for (std::size_t i = 0; i < points.size(); ++i)
    (*smoothed)[i].getVector3fMap() = points[i];
  run.times.smoothing_ms = detail::millisecondsSince(start);
  return smoothed;
}

template <typename PointInT, typename PointOutT>
void
VisibilityFeatureEstimation<PointInT, PointOutT>::buildGraph(
  Results& results, const Run& run, const PointCloudOut& output) const
{
  results.graph = TopologyGraph::build(results.band, results.segmentation.cellLabels(),
                                       results.segmentation.regionClasses(), run.graph);
  // Node geometry from the labelled output points themselves.
  detail::refreshPointGeometry(results.segmentation.regions().size(), output,
                               results.graph);
}

template <typename PointInT, typename PointOutT>
std::vector<std::uint32_t>
VisibilityFeatureEstimation<PointInT, PointOutT>::applyRegionMerge(
  Results& results,
  const Run& run,
  PointCloudOut& output,
  const std::vector<std::uint32_t>& into) const
{
  bool merged = false;
  for (std::size_t l = 1; l < into.size(); ++l)
    merged = merged || into[l] != l;
  if (!merged)
    return {};
  std::vector<std::uint32_t> renumbered = results.segmentation.mergeRegions(into);
  const std::vector<Region>& regions = results.segmentation.regions();
  for (PointOutT& p : output.points) {
    p.label = renumbered[p.label];
    p.feature_class = static_cast<std::uint8_t>(
      p.label == 0 ? FeatureClass::kNone : regions[p.label - 1].feature_class);
  }
  buildGraph(results, run, output);
  return renumbered;
}

template <typename PointInT, typename PointOutT>
std::vector<CreaseAngle>
VisibilityFeatureEstimation<PointInT, PointOutT>::mergeShallowCreases(
  Results& results, const Run& run, PointCloudOut& output) const
{
  std::vector<Eigen::Vector3d> points(output.size());
  std::vector<std::uint32_t> labels(output.size());
  const auto readLabels = [&]() {
    for (std::size_t i = 0; i < output.size(); ++i)
      labels[i] = output[i].label;
  };
  for (std::size_t i = 0; i < output.size(); ++i)
    points[i] = output[i].getVector3fMap().template cast<double>();
  readLabels();
  const auto measure = [&]() {
    return measureCreaseAngles(
      points, labels, results.segmentation.regionClasses(),
      results.band.grid().cell_size, run.crease_angles.window_cells,
      run.crease_angles.min_crease_angle, run.visibility.threads);
  };
  // the first angles and the contacts share their index of the face points
  CreaseMeasures measures = measureCreasesAndContacts(
    results.band, results.segmentation.cellLabels(), points, labels,
    results.segmentation.regionClasses(), run.crease_angles.window_cells,
    run.crease_angles.min_crease_angle, run.visibility.threads);
  std::vector<CreaseAngle> angles = std::move(measures.angles);
  const auto addFading = [&]() {
    detail::addFadingCreaseTurns(results.graph, results.segmentation.regionClasses(),
                                 points, labels, results.band.grid().cell_size,
                                 run.crease_angles.window_cells, run.visibility.threads,
                                 angles);
  };
  addFading();
  const std::vector<CreaseAngle>& contacts = measures.contacts;
  std::vector<std::uint32_t> into = shallowCreaseMerge(
    results.graph, angles, contacts, run.crease_angles.min_crease_angle);
  // Merged faces change the sides of the edges between them: their angles are measured
  // again, and an edge now below the minimum joins its sides too, until none is (each
  // round removes an edge: at most as many rounds as edges). Before, one round: the
  // public rocker arm kept an edge of 16.5 degrees under the default 20.
  while (!applyRegionMerge(results, run, output, into).empty()) {
    readLabels();
    angles = measure();
    addFading();
    into =
      shallowCreaseMerge(results.graph, angles, {}, run.crease_angles.min_crease_angle);
  }
  return angles;
}

template <typename PointInT, typename PointOutT>
typename VisibilityFeatureEstimation<PointInT, PointOutT>::Results
VisibilityFeatureEstimation<PointInT, PointOutT>::computeResults(
  Run& run, PointCloudOut& output) const
{
  using Clock = std::chrono::steady_clock;
  Results results;
  // Noise mode: the band (and the per-point decision) use the smoothed surface.
  const typename PointCloudIn::ConstPtr surface = smoothedSurface(run);

  auto start = Clock::now();
  VoxelBand::Options band_options = band_options_;
  band_options.threads = run.visibility.threads;
  if (run.fill == SurfaceFill::kMesh) {
    // the mesh alone makes the band; the points land on its cells
    std::vector<CellCoord> cells = fillCells(run, *surface);
    std::vector<OccupiedCell> occupied;
    std::vector<std::int32_t> point_occupied;
    pointsOnCells(*surface, run.grid, cells, occupied, point_occupied,
                  run.visibility.threads);
    results.band = VoxelBand::build(run.grid, std::move(occupied), point_occupied,
                                    band_options, cells);
  } else {
    results.band =
      buildVoxelBand(*surface, run.grid, band_options, fillCells(run, *surface));
    if (refillSparseBand(run, results.band)) {
      // the fill decided now is checked as one decided before the band (it was not:
      // the box with hole at 2048, 0.7 cells apart, filled up to 13.4 GB unchecked)
      results.band = VoxelBand();
      checkMemoryBudget(run);
      results.band =
        buildVoxelBand(*surface, run.grid, band_options, fillCells(run, *surface));
    }
  }
  run.times.band_ms = detail::millisecondsSince(start);

  start = Clock::now();
  results.free_space = FreeSpace(results.band, [&](std::uint64_t mask_bytes) {
    checkBandMemory(results.band, mask_bytes, run);
  });
  run.times.free_space_ms = detail::millisecondsSince(start);

  start = Clock::now();
  results.map =
    VisibilityMap::compute(results.band, results.free_space, run.visibility, progress_);
  if (!keep_free_space_)
    results.free_space = FreeSpace(); // the mask is no longer needed
  run.times.visibility_ms = detail::millisecondsSince(start);

  start = Clock::now();
  results.segmentation =
    FeatureSegmentation::compute(results.band, results.map, run.segmentation);
  run.times.segmentation_ms = detail::millisecondsSince(start);

  start = Clock::now();
  labelPoints(results, run, *surface, output);
  run.times.output_ms = detail::millisecondsSince(start);

  start = Clock::now();
  buildGraph(results, run, output);
  cleanUpRegions(results, run, *surface, output);
  claimCornerPoints(results, run, *surface, output);
  joinSplitCorners(results, run, output);
  placeCornersAtMeets(results, run, output);
  bridgeEdgesToCorners(results, run, output);
  moveFlatFeaturePoints(results, run, *surface, output);
  if (!run.segmentation.raw && run.segmentation.complete_regions)
    detail::setFadingCreaseTurns(results.graph, results.segmentation.regionClasses(),
                                 output, results.band.grid().cell_size,
                                 run.crease_angles, run.visibility.threads);
  run.times.graph_ms = detail::millisecondsSince(start);
  run.warnings_before_checks = run.warnings;
  checkResults(results, run);
  return results;
}

template <typename PointInT, typename PointOutT>
void
VisibilityFeatureEstimation<PointInT, PointOutT>::computeFeature(PointCloudOut& output)
{
  std::string problem;
  if (!run_) {
    problem = "compute() was not prepared: call compute(), not computeFeature()";
  } else {
    try {
      Run run = std::move(*run_);
      run_.reset();
      const Run base = run;
      Results results = computeResults(run, output);
      if (run.search_cap > 0) { // the automatic resolution
        if (run.point_noise > kLowerForPointNoise)
          results = calmResolution(base, run, std::move(results), output);
        // look for narrow faces, no finer than the noise allows
        results = searchResolution(base, run, std::move(results), output);
      }
      // Success: the new results replace the previous ones.
      band_ = std::move(results.band);
      free_space_ = std::move(results.free_space);
      map_ = std::move(results.map);
      segmentation_ = std::move(results.segmentation);
      graph_ = std::move(results.graph);
      times_ = run.times;
      resolution_estimate_ = std::move(run.resolution);
      fill_used_ = run.fill;
      fill_reason_ = std::move(run.fill_reason);
      point_noise_ = run.point_noise;
      notes_ = std::move(run.notes);
      warnings_ = std::move(run.warnings);
      for (const std::string& warning : warnings_)
        PCL_WARN("[visfeat::%s::compute] %s\n", getClassName().c_str(),
                 warning.c_str());
      return;
    } catch (const Error& e) {
      problem = e.what();
    } catch (const std::bad_alloc&) {
      problem = "out of memory: lower the resolution";
    } catch (const std::exception& e) {
      problem = "unexpected error: " + detail::oneLine(e.what());
    }
  }
  run_.reset();
  fail(problem);
  output.width = output.height = 0;
  output.clear();
}

} // namespace visfeat

// the creases where faces touch; the per-point labels; the resolution, its search, the
// grid and the fill
#include <visfeat/impl/visibility_feature_checks.hpp>
#include <visfeat/impl/visibility_feature_contacts.hpp>
#include <visfeat/impl/visibility_feature_labels.hpp>
#include <visfeat/impl/visibility_feature_resolution.hpp>

#define PCL_INSTANTIATE_VisibilityFeatureEstimation(T, OUTT)                           \
  template class visfeat::VisibilityFeatureEstimation<T, OUTT>;
