#pragma once

#include <visfeat/core/band/point_smoothing.h>
#include <visfeat/core/band/voxel_band.h>
#include <visfeat/core/graph/crease_angles.h>
#include <visfeat/core/graph/topology_graph.h>
#include <visfeat/core/grid/grid_spec.h>
#include <visfeat/core/grid/resolution.h>
#include <visfeat/core/segmentation/feature_segmentation.h>
#include <visfeat/core/segmentation/flat_feature_points.h>
#include <visfeat/core/visibility/free_space.h>
#include <visfeat/core/visibility/visibility_map.h>
#include <visfeat/phase_times.h>
#include <visfeat/surface_fill.h>

#include <cstddef>
#include <string>
#include <vector>

namespace visfeat {
namespace detail {

/** \brief What VisibilityFeatureEstimation::initCompute() settles for
 * computeFeature(): resolved parameters, grid, resolution estimate, the fill and what
 * it measured, notes and warnings (the estimator's private Run). */
struct EstimationRun
{
  VisibilityMap::Parameters visibility;
  SmoothingParameters smoothing;
  SegmentationParameters segmentation;
  TopologyGraphParameters graph;
  CreaseAngleParameters crease_angles;
  FlatPointParameters flat_points; // radius: point_feature_distance + kMargin, at use
  GridSpec grid;
  ResolutionEstimate resolution;
  SurfaceFill fill = SurfaceFill::kPoints;
  bool raised_for_fill = false;  // the automatic resolution counts on a fill
  int search_cap = 0;            // the search for narrow faces goes no finer (0: off)
  std::string search_cap_reason; // why it stops there
  std::string fill_reason;
  double point_noise = -1.0; // cells: the fill's measure (FillReport::noise), or -1
  double point_flat_share = -1.0; // FillReport::flat_share (kShapeNotNoiseShare)
  std::size_t noise_points = 0;   // FillReport::points (kNoiseReadablePoints)
  bool calmed = false, calmed_for_shape = false; // calmResolution(): noise or spread
  std::vector<std::string> notes;
  std::vector<std::string> warnings;
  /** The warnings before the checks of the results (checkResults()), to check them
   * again where the search changes its limit afterwards. */
  std::vector<std::string> warnings_before_checks;
  PhaseTimes times;
};

/** \brief Everything a compute() produces, built aside and moved into the estimator's
 * members on success (the estimator's private Results). */
struct EstimationResults
{
  VoxelBand band;
  FreeSpace free_space;
  VisibilityMap map;
  FeatureSegmentation segmentation;
  TopologyGraph graph;
};

} // namespace detail
} // namespace visfeat
