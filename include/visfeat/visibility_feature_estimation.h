#pragma once

#include <visfeat/core/band/point_smoothing.h>
#include <visfeat/core/band/voxel_band.h>
#include <visfeat/core/graph/crease_angles.h>
#include <visfeat/core/graph/topology_graph.h>
#include <visfeat/core/grid/cloud_shape.h>
#include <visfeat/core/grid/resolution.h>
#include <visfeat/core/grid/resolution_search.h>
#include <visfeat/core/mesh/mesh_sampling.h>
#include <visfeat/core/segmentation/feature_segmentation.h>
#include <visfeat/core/visibility/free_space.h>
#include <visfeat/core/visibility/visibility_map.h>
#include <visfeat/impl/estimation_run.h>
#include <visfeat/phase_times.h>
#include <visfeat/point_types.h>
#include <visfeat/surface_fill.h>

#include <pcl/features/feature.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace visfeat {

/** \brief Visibility-based feature estimation (Chica et al., "Visibility-Based Feature
 * Extraction From Discrete Models") as a pcl::Feature.
 *
 * The cloud is immersed in a grid of `resolution` cells along its longest side; the
 * cells holding points form the band. For every band cell the visibility radius counts
 * the successive rings of band cells around it that it fully sees; radii are high on
 * face interiors, edges and corners, and drop in the valleys between them. Every
 * output point gets the radius of its cell in `visibility_radius`, its region in
 * `label` and its class in `feature_class` (PointLabeling).
 *
 * \code
 * visfeat::VisibilityFeatureEstimation<pcl::PointXYZ, visfeat::PointVisibility> est;
 * est.setInputCloud(cloud);
 * est.setResolution(256); // or 0: from the point spacing (getResolutionEstimate())
 * pcl::PointCloud<visfeat::PointVisibility> out;
 * est.compute(out); // out.empty() on error, with the reason in getErrorMessage()
 * \endcode
 *
 * No search method is used: the estimator overrides initCompute(), so neither k nor a
 * radius has to be set (the automatic resolution builds its own k-d tree). The band is
 * built from the search surface (the input unless setSearchSurface() was called);
 * output is produced for the input's indices, each point labelled from the band cell it
 * falls in (GridSpec::cellOf), but for the corner point that a vertex region no point
 * falls in claims (the nearest input point: with a search surface, possibly another
 * point than the full run's).
 *
 * Parameters are read when compute() runs, so the order of the set calls does not
 * matter: max_radius 0 ("auto", the default) is min_radius; the noise mode gives the
 * smoothing radius and point_feature_distance that were not set explicitly. The
 * getters return the values compute() will use.
 *
 * compute() refuses, with a one-line getErrorMessage() and a PCL_ERROR, a missing or
 * empty cloud, clouds without a surface (no finite point, one point, all points
 * coincident or collinear, or within 2 cells of a line at the resolution), clouds too
 * small for one face where the points give the band (minimumCloudPoints()), parameters
 * out of range (the message names the parameter, its value, range and unit), grids
 * over the memory limit, and any exception of the pipeline (visfeat::Error,
 * std::bad_alloc, std::exception). A failed compute() leaves every result getter as it
 * was after the last successful one (the new results are built aside and moved in on
 * success; so during a compute() the previous results still hold their memory). A
 * coplanar cloud is processed (one face), with a note in getNotes() and a PCL_WARN.
 *
 * PointOutT needs the fields x, y, z, visibility_radius, label and feature_class.
 * Explicitly instantiated for PCL_XYZ_POINT_TYPES (PointXYZ, PointXYZI, PointNormal,
 * ...) with PointVisibility; other types need PCL_NO_PRECOMPILE.
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

  /** \brief setResolution(kAutomaticResolution): from the point spacing. */
  static constexpr int kAutomaticResolution = 0;
  /** \brief setMaxRadius(kAutoMaxRadius): the cap is min_radius. */
  static constexpr int kAutoMaxRadius = 0;
  /** \brief Smoothing radius of the noise mode (cells). */
  static constexpr double kNoiseSmoothingRadius = SmoothingParameters::kDefaultRadius;
  /** \brief point_feature_distance of the noise mode (cells). */
  static constexpr double kNoisePointDistance =
    SegmentationParameters::kNoisePointFeatureDistance;
  /** \brief The paper's opacity for noise (its Section 6): 3 cell edges. */
  static constexpr double kPaperNoiseOpacity = 3.0;

  VisibilityFeatureEstimation()
  {
    feature_name_ = "VisibilityFeatureEstimation";
    // Voxel-based: no neighbourhood search; these keep Feature's checks satisfied.
    k_ = 1;
    search_radius_ = 0.0;
  }

  /** \brief Cells along the longest side of the bounding box of the finite points of
   * the search surface. Default GridSpec::kDefaultResolution (256); range
   * GridSpec::kResolutionRange ([4, 8192]) or kAutomaticResolution (0): two point
   * spacings per cell (estimateResolution()), raised to kTopologyResolution (256) where
   * the band is filled between the points (at most kMaxFillCellsPerSpacing cells a
   * spacing), and kTopologyResolution for a mesh (setInputMesh()) whatever the density
   * of its points; then, while the map shows narrow faces (visfeat::narrowFaces(),
   * faces narrower than 2 min_radius cells), or, on a closed surface (meshIsClosed(),
   * bandIsClosed()), while the graph has gaps (findGraphGaps(); kSearchOnGraphGaps),
   * doubled and computed again, up to getMaxSearchResolution() and what the mesh, the
   * fill or the points support (a warning where it cannot go finer); what was chosen
   * and why is in getResolutionEstimate() after compute(). Features must be about 2
   * min_radius cells apart: 256 for faces >= 1/10 of the part, 512 for finer detail.
   * Memory grows with the surface (setMemoryLimit()). */
  inline void setResolution(int resolution) { resolution_ = resolution; }
  /** \brief The resolution as set (0 = automatic). */
  inline int getResolution() const { return resolution_; }
  /** \brief The automatic search goes no finer (cells; default kMaxSearchResolution,
   * 1024; GridSpec::kResolutionRange; at most searchSteps() doublings). 2048 resolves
   * narrow faces at a cost in time and memory, and may split coarse facets (README). */
  inline void setMaxSearchResolution(int cells) { max_search_resolution_ = cells; }
  inline int getMaxSearchResolution() const { return max_search_resolution_; }
  /** \brief Cap of the visibility radius, in rings. Default kAutoMaxRadius (0): the
   * min_radius compute() uses (the trimmed map; higher caps only cost time, radii above
   * min_radius change no region). Range VisibilityMap::Parameters::kMaxRadiusRange
   * ([1, 64]) and at least min_radius. */
  inline void setMaxRadius(int max_radius) { max_radius_ = max_radius; }
  /** \brief The cap compute() will use (auto resolved to min_radius). */
  inline int getMaxRadius() const
  {
    return max_radius_ == kAutoMaxRadius ? getMinRadius() : max_radius_;
  }

  /** \brief Cells with radius >= min_radius form components, in rings. Default
   * kDefaultMinRadius (16; the paper used 11, see ComponentParameters::min_radius);
   * range ComponentParameters::kMinRadiusRange and at most max_radius. In cells: it
   * does not scale with resolution. */
  inline void setMinRadius(int min_radius)
  {
    segmentation_parameters_.components.min_radius = min_radius;
  }
  inline int getMinRadius() const
  {
    return segmentation_parameters_.components.min_radius;
  }

  /** \brief Components of at most this many cells are vertex candidates. Default 25,
   * range ComponentParameters::kVertexMaxCellsRange (cells). */
  inline void setVertexMaxCells(int cells)
  {
    segmentation_parameters_.components.vertex_max_cells = cells;
  }
  inline int getVertexMaxCells() const
  {
    return segmentation_parameters_.components.vertex_max_cells;
  }

  /** \brief Faces narrower than a core get one when their peak of the map stands this
   * many rings above their creases' valleys (ComponentParameters::
   * narrow_face_persistence; issue 14). Default 3, range
   * ComponentParameters::kNarrowFacePersistenceRange (rings); 0 = off. */
  inline void setNarrowFacePersistence(int rings)
  {
    segmentation_parameters_.components.narrow_face_persistence = rings;
  }
  inline int getNarrowFacePersistence() const
  {
    return segmentation_parameters_.components.narrow_face_persistence;
  }

  /** \brief A core too thin for a face by its depth but flat across (the middle of a
   * face about 2 min_radius cells wide between two creases) is a face
   * (ComponentParameters::flat_core_faces, visfeat::flatCore(); issue 14). Default
   * on; off, such cores are edges by depth alone (what it gains and loses: see
   * ComponentParameters::flat_core_faces). */
  inline void setFlatCoreFaces(bool on)
  {
    segmentation_parameters_.components.flat_core_faces = on;
  }
  inline bool getFlatCoreFaces() const
  {
    return segmentation_parameters_.components.flat_core_faces;
  }

  /** \brief Raw mode's edge/face threshold on mean same-component 6-neighbours.
   * Default 3.5 (the paper's), range ComponentParameters::kDimensionalityRange. */
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

  /** \brief All segmentation parameters at once (see SegmentationParameters for
   * defaults, units and ranges). point_feature_distance counts as set explicitly
   * (setPointFeatureDistance()) only when it differs from getPointFeatureDistance():
   * so getSegmentationParameters(), a change, then setSegmentationParameters() leaves
   * it to the noise mode. */
  inline void setSegmentationParameters(const SegmentationParameters& parameters)
  {
    if (parameters.point_feature_distance != getPointFeatureDistance())
      point_feature_distance_ = parameters.point_feature_distance;
    segmentation_parameters_ = parameters;
  }
  /** \brief The segmentation parameters compute() will use (point_feature_distance as
   * the noise mode gives it unless set explicitly). */
  inline SegmentationParameters getSegmentationParameters() const
  {
    SegmentationParameters parameters = segmentation_parameters_;
    parameters.point_feature_distance = getPointFeatureDistance();
    return parameters;
  }

  /** \brief Per point: a point is an edge or vertex point when within this distance,
   * in cells, of the middle line of a skeleton around it (PointLabeling; 0 = points
   * take their cell's label). Default 1.0, or kNoisePointDistance (1.25) in the noise
   * mode, unless set; when the band is filled between points sparser than the cells
   * (getSurfaceFillUsed(), spacing s > 1 cell) the default is multiplied by s, so it
   * counts point spacings. Range SegmentationParameters::kPointFeatureDistanceRange
   * ([0, 10] cells). */
  inline void setPointFeatureDistance(double cells) { point_feature_distance_ = cells; }
  /** \brief The distance compute() will use. */
  inline double getPointFeatureDistance() const
  {
    if (point_feature_distance_)
      return *point_feature_distance_;
    return noise_mode_ ? kNoisePointDistance
                       : SegmentationParameters{}.point_feature_distance;
  }

  /** \brief Sharp versus smooth: an edge whose two sides, fitted by planes within
   * CreaseAngleParameters::window_cells of it, turn by less than this many degrees is
   * a blend or a shallow facet, not a crease: its points join its sides, which become
   * one face, and corners that no longer end two different creases stop being
   * vertices (shallowCreaseMerge()). Each edge's measured turn is in the graph
   * (GraphNode::crease_angle). Default CreaseAngleParameters::kDefaultMinCreaseAngle
   * (20 degrees, why: CreaseAngleParameters), 0 = off; range
   * CreaseAngleParameters::kMinCreaseAngleRange ([0, 180] degrees). Applies to complete
   * regions (the default segmentation); raw components are neither measured nor
   * merged. */
  inline void setMinCreaseAngle(double degrees)
  {
    crease_angles_.min_crease_angle = degrees;
  }
  inline double getMinCreaseAngle() const { return crease_angles_.min_crease_angle; }

  /** \brief Edge and vertex points on flat ground go to the nearest face (the last
   * step of compute(), flatFeaturePoints(); the ball, the bound and their figures:
   * FlatPointParameters); the graph is unchanged. Default 1e-3 (surface variation),
   * 0 = off; range FlatPointParameters::kMaxSurfaceVariationRange. Not in raw mode. */
  inline void setFlatPointVariation(double v) { flat_point_variation_ = v; }
  inline double getFlatPointVariation() const { return flat_point_variation_; }

  /** \brief Smoothing radius in cells: before the band is built, every point is
   * projected onto the least-squares plane of its neighbours within this radius
   * (smoothPoints()); creases are rounded within it. Default 0 = off, or
   * kNoiseSmoothingRadius (2) in the noise mode, unless set; range
   * SmoothingParameters::kRadiusRange ([0, 8] cells). */
  inline void setSmoothingRadius(double cells) { smoothing_radius_ = cells; }
  /** \brief The radius compute() will use. */
  inline double getSmoothingRadius() const
  {
    if (smoothing_radius_)
      return *smoothing_radius_;
    return noise_mode_ ? kNoiseSmoothingRadius : 0.0;
  }

  /** \brief Noise mode for scans with Gaussian noise up to about half a cell (default
   * off). At compute time it gives the smoothing radius kNoiseSmoothingRadius (2
   * cells) and point_feature_distance kNoisePointDistance (1.25 cells: feature points
   * keep the same 2-cell bound with the noise left along the surface) to whichever of
   * the two was not set explicitly (setSmoothingRadius(), setPointFeatureDistance()),
   * whatever the order of the calls. Off: smoothing 0 and point_feature_distance 1
   * unless set. Noise is in cells: at a finer resolution the same scan is noisier. */
  inline void setNoiseMode(bool on) { noise_mode_ = on; }
  inline bool getNoiseMode() const { return noise_mode_; }

  /** \brief Opacity in cell edges (default 0 = exact visibility; range
   * VisibilityMap::Parameters::kOpacityRange, [0, 64]). The paper's setting for noisy
   * scans is kPaperNoiseOpacity with its component joining (on by default,
   * SegmentationParameters::join_distance); measured here, the noise mode
   * (setNoiseMode()) does better. */
  inline void setOpacity(double opacity) { opacity_ = opacity; }
  inline double getOpacity() const { return opacity_; }

  /** \brief Where the band's cells come from (SurfaceFill; default kAuto: the input
   * mesh when one is set, an organized cloud's pixel grid, the triangles between the
   * points when they lie more than kFillSpacingCells (0.55) cells apart, else the
   * points). */
  inline void setSurfaceFill(SurfaceFill fill) { surface_fill_ = fill; }
  inline SurfaceFill getSurfaceFill() const { return surface_fill_; }

  /** \brief The fill's triangles between the points (LocalTriangleParameters). */
  inline void setLocalTriangleParameters(const LocalTriangleParameters& parameters)
  {
    local_triangles_ = parameters;
  }
  inline const LocalTriangleParameters& getLocalTriangleParameters() const
  {
    return local_triangles_;
  }

  /** \brief The fill's triangles of an organized cloud (OrganizedTriangleParameters).
   */
  inline void setOrganizedTriangleParameters(const OrganizedTriangleParameters& p)
  {
    organized_triangles_ = p;
  }
  inline const OrganizedTriangleParameters& getOrganizedTriangleParameters() const
  {
    return organized_triangles_;
  }

  /** \brief A triangle mesh of the same surface (world units, the input cloud's
   * frame): with the fill kAuto or kMesh the band is its exact rasterisation
   * (rasterizeTriangles()) plus the cells of the points, and the grid covers both.
   * Per-point output stays on the input cloud (e.g. the mesh's vertices or points
   * sampled on it). nullptr (default) = none. */
  inline void setInputMesh(const std::shared_ptr<const SurfaceMesh>& mesh)
  {
    mesh_ = mesh;
    mesh_closed_ = mesh_ && meshIsClosed(*mesh_);
  }
  inline const std::shared_ptr<const SurfaceMesh>& getInputMesh() const
  {
    return mesh_;
  }

  /** \brief Make the band 6-connected by adding cells (default true). */
  inline void setBandRepair(bool repair) { band_options_.repair = repair; }
  inline bool getBandRepair() const { return band_options_.repair; }

  /** \brief Threads for the smoothing, the visibility map and the segmentation (and the
   * parallel steps of the band and the graph); 0 (default) = all
   * available; at most VisibilityMap::kMaxThreads. Results are identical for any
   * count. */
  inline void setNumberOfThreads(unsigned int threads)
  {
    threads_ = static_cast<int>(threads);
  }
  inline unsigned int getNumberOfThreads() const
  {
    return static_cast<unsigned int>(threads_);
  }

  /** \brief Refuse grids whose estimated memory exceeds this many bytes
   * (default 0 = 3/4 of the physical memory). */
  inline void setMemoryLimit(std::uint64_t bytes) { memory_limit_ = bytes; }
  inline std::uint64_t getMemoryLimit() const { return memory_limit_; }

  /** \brief Called during the visibility map with (cells done, cells total), from one
   * thread at a time (see visfeat::ProgressCallback); it runs inside an OpenMP region,
   * so it must not throw. */
  inline void setProgressCallback(const ProgressCallback& progress)
  {
    progress_ = progress;
  }

  /** \brief Keep the free-space mask after compute() (default false: it is released
   * as soon as the visibility map is done; sparse, about 12 bytes a mixed cell, see
   * FreeSpace::memoryBytes()). */
  inline void setKeepFreeSpace(bool keep) { keep_free_space_ = keep; }
  inline bool getKeepFreeSpace() const { return keep_free_space_; }

  /** \brief Dilation radius of the topology graph's arcs in cells (default -1 = auto:
   * 2 with complete regions, which touch; min_radius otherwise, to cross the valleys
   * between raw components; range TopologyGraphParameters::kDilationRadiusRange). See
   * TopologyGraphParameters. */
  inline void setGraphDilation(int cells) { graph_dilation_ = cells; }
  inline int getGraphDilation() const { return graph_dilation_; }

  /** \brief Results of the last successful compute() (empty before the first one; a
   * failed compute() leaves them as they were). */
  inline const GridSpec& getGrid() const { return band_.grid(); }
  inline const VoxelBand& getVoxelBand() const { return band_; }
  /** \brief The free-space mask: empty (dims 0) unless setKeepFreeSpace(true). */
  inline const FreeSpace& getFreeSpace() const { return free_space_; }
  inline const VisibilityMap& getVisibilityMap() const { return map_; }
  /** \brief The topology graph: nodes are regions (with the centroid and bounds of
   * their points), arcs vertex-edge, edge-face, vertex-face. */
  inline const TopologyGraph& getTopologyGraph() const { return graph_; }
  /** \brief Vertex, edge and face regions. */
  inline const FeatureSegmentation& getSegmentation() const { return segmentation_; }
  inline const PhaseTimes& getPhaseTimes() const { return times_; }
  /** \brief The resolution used and why: with setResolution(0) the estimate from the
   * point spacing (ResolutionEstimate: spacing, k, queries, extent, clamped, reason);
   * with a given resolution, that resolution with queries 0 and the reason "set by
   * setResolution()". */
  inline const ResolutionEstimate& getResolutionEstimate() const
  {
    return resolution_estimate_;
  }
  /** \brief The fill the last successful compute() used (never kAuto) and why, in
   * one line. */
  inline SurfaceFill getSurfaceFillUsed() const { return fill_used_; }
  inline const std::string& getSurfaceFillReason() const { return fill_reason_; }
  /** \brief The points' noise measured by the last successful compute()'s fill, in
   * cells: the median over the points of the RMS distance of a point and its nearest
   * neighbours from their least-squares plane (tangentPlanes(); about 0.85 sigma for
   * Gaussian noise of sigma cells per coordinate), or -1 when the fill did not measure
   * it (the band from the points alone, a mesh, an organized cloud: see
   * VoxelBand::roughness() for the band from the points). */
  inline double getPointNoise() const { return point_noise_; }

  /** \brief Warnings on the last successful compute(), one line each with the cause
   * and what to do: results that cannot be trusted (no region, too few cells reach
   * min_radius, a band too sparse for the resolution). Also sent as PCL_WARN. */
  inline const std::vector<std::string>& getWarnings() const { return warnings_; }

  /** \brief Notes on the input, one line each (e.g. a coplanar cloud: one face). */
  inline const std::vector<std::string>& getNotes() const { return notes_; }

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

  /** \brief Checks input and parameters, the shape of the cloud, chooses the
   * resolution and builds the grid; no search tree. */
  bool initCompute() override;

  void computeFeature(PointCloudOut& output) override;

private:
  using Run = detail::EstimationRun;         // impl/estimation_run.h
  using Results = detail::EstimationResults; // impl/estimation_run.h

  Run prepare() const;
  int chooseResolution(const CloudShape& shape, Run& run) const;
  void prepareGrid(Run& run, int resolution) const;
  /** Prepares run at `resolution` and computes it into output: the results, or none
   * with the reason in problem (a memory refusal, out of memory). */
  std::optional<Results>
  runAt(Run& run, int resolution, PointCloudOut& output, std::string& problem) const;
  Results searchResolution(const Run& base,
                           Run& run,
                           Results results,
                           PointCloudOut& output) const;
  /** The search stops: the next resolution `next` is (would be) rough with `noise`
   * cells; says so in reason and warnings, checks results again with that limit. */
  void keepUnderNoise(const Results& results,
                      Run& run,
                      const std::string& found,
                      int next,
                      double noise,
                      bool predicted) const;
  /** The automatic resolution lowered where the fill measured noisy points. */
  Results calmResolution(const Run& base,
                         Run& run,
                         Results results,
                         PointCloudOut& output) const;
  void chooseFill(Run& run) const;
  /** Sets run.point_noise where the fill measures it. */
  std::vector<CellCoord> fillCells(Run& run, const PointCloudIn& surface) const;
  /** An automatic points band with holes: true when run's fill changed, to build. */
  bool refillSparseBand(Run& run, const VoxelBand& band) const;
  void checkResults(const Results& results, Run& run) const;
  /** Warnings on rough points (kNoisyRoughness, kNoisyPointNoise). */
  void checkNoise(const VoxelBand& band, Run& run) const;
  /** A warning where the graph is not that of a closed part (findGraphGaps()). */
  void checkGraph(const Results& results, Run& run) const;
  void checkMemoryBudget(const Run& run) const;
  void checkBandMemory(const VoxelBand& band,
                       std::uint64_t mask_bytes,
                       const Run& run) const;
  typename PointCloudIn::ConstPtr smoothedSurface(Run& run) const;
  Results computeResults(Run& run, PointCloudOut& output) const;
  void labelPoints(const Results& results,
                   const Run& run,
                   const PointCloudIn& surface,
                   PointCloudOut& output) const;
  /** The band cell of input point `index` (kNoCell if not finite; the band's record for
   * its own cloud, the noise mode's smoothed surface). */
  CellId bandCellOf(const VoxelBand& band, std::size_t index) const;
  /** A vertex region no point took (pointlessVertices) claims the nearest point within
   * kCornerClaimDistances x point_feature_distance that is no other vertex's. */
  void claimCornerPoints(Results& results,
                         const Run& run,
                         const PointCloudIn& surface,
                         PointCloudOut& output) const;
  void buildGraph(Results& results, const Run& run, const PointCloudOut& output) const;
  /** mergeRegions(into) on cells, points, graph; its renumbering (empty: none). */
  std::vector<std::uint32_t>
  applyRegionMerge(Results& results,
                   const Run& run,
                   PointCloudOut& output,
                   const std::vector<std::uint32_t>& into) const;
  /** The minimum crease angle's merge; returns the crease angles of the regions it
   * leaves (per label - 1). */
  std::vector<CreaseAngle>
  mergeShallowCreases(Results& results, const Run& run, PointCloudOut& output) const;
  /** After the graph: the crease rule, the stray regions, creased faces split (from
   * the surface's points: splitCreasedFaces()), then the contact creases. */
  void cleanUpRegions(Results&, const Run&, const PointCloudIn&, PointCloudOut&) const;
  /** Faces touching across a turn of at least the minimum crease angle, no edge between
   * them, get an edge region along it (locateContactCreases()), and all follows. */
  void addContactCreases(Results& results, const Run& run, PointCloudOut& output) const;
  /** Corners split in two, corner spurs, dead-end corners, open faces (see there). */
  void joinSplitCorners(Results& results, const Run& run, PointCloudOut& output) const;
  /** Then an edge stopping short of its corner is bridged to it (clouds only). */
  void
  bridgeEdgesToCorners(Results& results, const Run& run, PointCloudOut& output) const;
  /** Before the bridges: each corner takes the point nearest where its creases meet
   * (cornerMeets) and the face cells around it. */
  void
  placeCornersAtMeets(Results& results, const Run& run, PointCloudOut& output) const;
  /** Last: feature points on flat ground go to a face (flatFeaturePoints); a note
   * says how many, or that the cloud is too sparse for the step. */
  void moveFlatFeaturePoints(Results& results,
                             Run& run,
                             const PointCloudIn& surface,
                             PointCloudOut& output) const;
  /** Points after addRegions() (addContactCreases()); then `into` joins the added
   * regions (merge, graph, crease angles angle_of through both renumberings). */
  void relabelAddedPoints(const Results& results,
                          PointCloudOut& output,
                          const std::vector<std::uint32_t>& renumbered) const;
  void joinAddedRegions(Results& results,
                        const Run& run,
                        PointCloudOut& output,
                        const std::vector<std::uint32_t>& into,
                        const std::vector<std::uint32_t>& renumbered,
                        const std::vector<double>& angle_of) const;

  bool fail(const std::string& message);

  // Settings.
  int resolution_ = GridSpec::kDefaultResolution;
  int max_radius_ = kAutoMaxRadius;
  double opacity_ = 0.0;
  int threads_ = 0;
  bool noise_mode_ = false;
  std::optional<double> smoothing_radius_;
  std::optional<double> point_feature_distance_;
  VoxelBand::Options band_options_;
  SegmentationParameters segmentation_parameters_;
  CreaseAngleParameters crease_angles_;
  double flat_point_variation_ = FlatPointParameters::kDefaultMaxSurfaceVariation;
  std::uint64_t memory_limit_ = 0;
  int max_search_resolution_ = kMaxSearchResolution;
  ProgressCallback progress_;
  int graph_dilation_ = -1;
  bool keep_free_space_ = false;
  SurfaceFill surface_fill_ = SurfaceFill::kAuto;
  LocalTriangleParameters local_triangles_;
  OrganizedTriangleParameters organized_triangles_;
  std::shared_ptr<const SurfaceMesh> mesh_;
  bool mesh_closed_ = false; // meshIsClosed(*mesh_), set with the mesh

  // Between initCompute() and computeFeature().
  std::unique_ptr<Run> run_;

  // Results of the last successful compute().
  VoxelBand band_;
  FreeSpace free_space_;
  VisibilityMap map_;
  FeatureSegmentation segmentation_;
  TopologyGraph graph_;
  PhaseTimes times_;
  ResolutionEstimate resolution_estimate_;
  SurfaceFill fill_used_ = SurfaceFill::kPoints;
  std::string fill_reason_;
  double point_noise_ = -1.0;
  std::vector<std::string> notes_;
  std::vector<std::string> warnings_;
  std::string error_;
};

} // namespace visfeat

#ifdef PCL_NO_PRECOMPILE
#include <visfeat/impl/visibility_feature_estimation.hpp>
#endif
