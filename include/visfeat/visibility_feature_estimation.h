#pragma once

#include <visfeat/core/band/point_smoothing.h>
#include <visfeat/core/band/voxel_band.h>
#include <visfeat/core/graph/topology_graph.h>
#include <visfeat/core/segmentation/feature_segmentation.h>
#include <visfeat/core/visibility/free_space.h>
#include <visfeat/core/visibility/visibility_map.h>
#include <visfeat/point_types.h>

#include <pcl/features/feature.h>

#include <cstdint>
#include <memory>
#include <string>

namespace visfeat {

/** \brief Wall-clock milliseconds of each phase of the last compute(). */
struct PhaseTimes
{
  double grid_ms = 0.0;         // bounding box and grid
  double smoothing_ms = 0.0;    // noise mode: points onto local planes
  double band_ms = 0.0;         // octree, mixed cells, repair, adjacency
  double free_space_ms = 0.0;   // 2x2x2 subcell mask
  double visibility_ms = 0.0;   // visibility map
  double segmentation_ms = 0.0; // components, regions, vertex/edge/face classes
  double output_ms = 0.0;       // per-point fields
  double graph_ms = 0.0;        // topology graph

  double total() const
  {
    return grid_ms + smoothing_ms + band_ms + free_space_ms + visibility_ms +
           segmentation_ms + output_ms + graph_ms;
  }
};

/** \brief Visibility-based feature estimation (Chica et al., "Visibility-Based Feature
 * Extraction From Discrete Models") as a pcl::Feature.
 *
 * The cloud is immersed in a grid of `resolution` cells along its longest side; the
 * cells holding points form the band. For every band cell the visibility radius counts
 * the successive rings of band cells around it that it fully sees; radii are high on
 * face interiors, edges and corners, and drop in the valleys between them. Every
 * output point gets the radius of its cell in `visibility_radius`.
 *
 * \code
 * visfeat::VisibilityFeatureEstimation<pcl::PointXYZ, visfeat::PointVisibility> est;
 * est.setInputCloud(cloud);
 * est.setResolution(256);
 * pcl::PointCloud<visfeat::PointVisibility> out;
 * est.compute(out); // out.empty() on error, with the reason in getErrorMessage()
 * \endcode
 *
 * No search tree is used: the estimator overrides initCompute(), so neither k nor a
 * radius has to be set. The band is built from the search surface (the input unless
 * setSearchSurface() was called); output is produced for the input's indices.
 *
 * PointOutT needs the fields x, y, z, visibility_radius, label and feature_class.
 */
template <typename PointInT, typename PointOutT = PointVisibility>
class VisibilityFeatureEstimation : public pcl::Feature<PointInT, PointOutT>
{
public:
  using Ptr = std::shared_ptr<VisibilityFeatureEstimation<PointInT, PointOutT>>;
  using ConstPtr =
    std::shared_ptr<const VisibilityFeatureEstimation<PointInT, PointOutT>>;
  using PointCloudIn = typename pcl::Feature<PointInT, PointOutT>::PointCloudIn;
  using PointCloudOut = typename pcl::Feature<PointInT, PointOutT>::PointCloudOut;

  VisibilityFeatureEstimation()
  {
    feature_name_ = "VisibilityFeatureEstimation";
    // Voxel-based: no neighbourhood search; these keep Feature's checks satisfied.
    k_ = 1;
    search_radius_ = 0.0;
    visibility_.max_radius = segmentation_parameters_.components.min_radius;
  }

  /** \brief Cells along the longest side of the bounding box (default 256).
   * The paper's defaults (min_radius 11) are tuned for 256-768; below ~64 the
   * valleys between features are too narrow to separate them. */
  inline void setResolution(int resolution) { resolution_ = resolution; }
  inline int getResolution() const { return resolution_; }

  /** \brief Cap of the visibility radius in rings (default 16 = min_radius, range
   * 1-64). Must be at least min_radius; higher values only cost time. */
  inline void setMaxRadius(int max_radius) { visibility_.max_radius = max_radius; }
  inline int getMaxRadius() const { return visibility_.max_radius; }

  /** \brief Cells with radius >= min_radius form components (default 16 rings; the
   * paper used 11, see ComponentParameters::min_radius). */
  inline void setMinRadius(int min_radius)
  {
    segmentation_parameters_.components.min_radius = min_radius;
  }
  inline int getMinRadius() const
  {
    return segmentation_parameters_.components.min_radius;
  }

  /** \brief Components of at most this many cells are vertex candidates (default 25).
   */
  inline void setVertexMaxCells(int cells)
  {
    segmentation_parameters_.components.vertex_max_cells = cells;
  }
  inline int getVertexMaxCells() const
  {
    return segmentation_parameters_.components.vertex_max_cells;
  }

  /** \brief Raw mode's edge/face threshold on mean same-component 6-neighbours
   * (default 3.5, the paper's). */
  inline void setDimensionality(double dimensionality)
  {
    segmentation_parameters_.components.dimensionality = dimensionality;
  }
  inline double getDimensionality() const
  {
    return segmentation_parameters_.components.dimensionality;
  }

  /** \brief The paper's literal section 5 (default false); see FeatureSegmentation. */
  inline void setRawMode(bool raw) { segmentation_parameters_.raw = raw; }
  inline bool getRawMode() const { return segmentation_parameters_.raw; }

  /** \brief Grow components into regions covering every point (default true). */
  inline void setCompleteRegions(bool complete)
  {
    segmentation_parameters_.complete_regions = complete;
  }
  inline bool getCompleteRegions() const
  {
    return segmentation_parameters_.complete_regions;
  }

  /** \brief All segmentation parameters at once (see SegmentationParameters). */
  inline void setSegmentationParameters(const SegmentationParameters& parameters)
  {
    segmentation_parameters_ = parameters;
  }
  inline const SegmentationParameters& getSegmentationParameters() const
  {
    return segmentation_parameters_;
  }

  /** \brief Smoothing radius in cells (default 0 = off): before the band is built,
   * every point is projected onto the least-squares plane of its neighbours within
   * this radius (smoothPoints()). For noisy scans; see setNoiseMode(). */
  inline void setSmoothingRadius(double cells) { smoothing_.radius = cells; }
  inline double getSmoothingRadius() const { return smoothing_.radius; }

  /** \brief Noise mode for scans with Gaussian noise up to about half a cell: smoothing
   * radius 2 cells and point_feature_distance 1.25 cells (feature points keep the same
   * 2-cell bound with the noise left along the surface). Off: smoothing 0 and
   * point_feature_distance 1. Call before setting either individually. */
  inline void setNoiseMode(bool on)
  {
    smoothing_.radius = on ? kNoiseSmoothingRadius : 0.0;
    segmentation_parameters_.point_feature_distance = on ? kNoisePointDistance : 1.0;
  }
  static constexpr double kNoiseSmoothingRadius = 2.0;
  static constexpr double kNoisePointDistance = 1.25;

  /** \brief Opacity in cell edges (default 0 = exact visibility). The paper's setting
   * for noisy scans is kPaperNoiseOpacity with its component joining (on by default,
   * SegmentationParameters::join_distance); measured here, the noise mode
   * (setNoiseMode()) does better. */
  inline void setOpacity(double opacity) { visibility_.opacity = opacity; }
  inline double getOpacity() const { return visibility_.opacity; }
  /** \brief The paper's opacity for noise (its Section 6): 3 cell edges. */
  static constexpr double kPaperNoiseOpacity = 3.0;

  /** \brief Make the band 6-connected by adding cells (default true). */
  inline void setBandRepair(bool repair) { band_options_.repair = repair; }
  inline bool getBandRepair() const { return band_options_.repair; }

  /** \brief Threads for the visibility map; 0 (default) = all available. */
  inline void setNumberOfThreads(unsigned int threads)
  {
    visibility_.threads = static_cast<int>(threads);
  }
  inline unsigned int getNumberOfThreads() const
  {
    return static_cast<unsigned int>(visibility_.threads);
  }

  /** \brief Refuse grids whose estimated memory exceeds this many bytes
   * (default 0 = 3/4 of the physical memory). */
  inline void setMemoryLimit(std::uint64_t bytes) { memory_limit_ = bytes; }
  inline std::uint64_t getMemoryLimit() const { return memory_limit_; }

  /** \brief Called during the visibility map with (cells done, cells total), from one
   * thread at a time (see visfeat::ProgressCallback). */
  inline void setProgressCallback(const ProgressCallback& progress)
  {
    progress_ = progress;
  }

  /** \brief The grid, band and map of the last successful compute(). */
  inline const GridSpec& getGrid() const { return band_.grid(); }
  inline const VoxelBand& getVoxelBand() const { return band_; }
  inline const FreeSpace& getFreeSpace() const { return free_space_; }
  inline const VisibilityMap& getVisibilityMap() const { return map_; }
  /** \brief Dilation radius of the topology graph's arcs in cells (default -1 = auto:
   * 2 with complete regions, which touch; min_radius otherwise, to cross the valleys
   * between raw components). See TopologyGraphParameters. */
  inline void setGraphDilation(int cells) { graph_dilation_ = cells; }
  inline int getGraphDilation() const { return graph_dilation_; }

  /** \brief The topology graph of the last compute(): nodes are regions (with the
   * centroid and bounds of their points), arcs vertex-edge, edge-face, vertex-face. */
  inline const TopologyGraph& getTopologyGraph() const { return graph_; }

  /** \brief Vertex, edge and face regions of the last compute(). */
  inline const FeatureSegmentation& getSegmentation() const { return segmentation_; }
  inline const PhaseTimes& getPhaseTimes() const { return times_; }

  /** \brief Why the last compute() produced an empty output ("" after success). */
  inline const std::string& getErrorMessage() const { return error_; }

protected:
  using pcl::Feature<PointInT, PointOutT>::feature_name_;
  using pcl::Feature<PointInT, PointOutT>::getClassName;
  using pcl::Feature<PointInT, PointOutT>::input_;
  using pcl::Feature<PointInT, PointOutT>::indices_;
  using pcl::Feature<PointInT, PointOutT>::surface_;
  using pcl::Feature<PointInT, PointOutT>::fake_surface_;
  using pcl::Feature<PointInT, PointOutT>::k_;
  using pcl::Feature<PointInT, PointOutT>::search_radius_;

  /** \brief Checks input and parameters and builds the grid; no search tree. */
  bool initCompute() override;

  void computeFeature(PointCloudOut& output) override;

private:
  /** \brief Marks the cells within one cell (26-neighbourhood) of a skeleton cell: only
   * their points can be feature points. */
  void markCellsNearSkeleton();

  void refinePointLabel(const PointInT& p,
                        CellId cell,
                        std::uint32_t& label,
                        FeatureClass& cls) const;

  void buildGraph(const PointCloudOut& output);

  bool fail(const std::string& message);

  int resolution_ = 256;
  VoxelBand::Options band_options_;
  VisibilityMap::Parameters visibility_;
  SmoothingParameters smoothing_{0.0, 6, 0};
  SegmentationParameters segmentation_parameters_;
  std::uint64_t memory_limit_ = 0;
  ProgressCallback progress_;

  GridSpec grid_;
  VoxelBand band_;
  FreeSpace free_space_;
  VisibilityMap map_;
  FeatureSegmentation segmentation_;
  std::vector<char> near_skeleton_;
  int graph_dilation_ = -1;
  TopologyGraph graph_;
  PhaseTimes times_;
  std::string error_;
};

} // namespace visfeat

#ifdef PCL_NO_PRECOMPILE
#include <visfeat/impl/visibility_feature_estimation.hpp>
#endif
