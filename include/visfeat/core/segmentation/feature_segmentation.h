#pragma once

#include <visfeat/core/band/voxel_band.h>
#include <visfeat/core/segmentation/components.h>
#include <visfeat/core/visibility/visibility_map.h>

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <vector>

namespace visfeat {

/** \brief How the band is split into vertex, edge and face regions. */
struct SegmentationParameters
{
  ComponentParameters components;
  /** \brief The paper's literal method: components (cores) only, raw classification,
   * the cells between them stay unlabeled. Off by default. */
  bool raw = false;
  /** \brief Grow the components into regions that cover the whole band (default mode
   * only). Off: the cleaned-up cores only. On by default. */
  bool complete_regions = true;
  /** \brief 6-connected pieces of the band with fewer cells than this are outlier
   * clusters: their cells and points get no region (label 0). Default 16, range
   * kMinPieceCellsRange. */
  int min_piece_cells = 16;
  /** \brief Geodesic reach, in cells through the band, of the vertex test (default
   * mode): a small component is a vertex when the edges it reaches within this
   * distance separate at least two different pairs of faces (or its region touches
   * three faces); vertex candidates within this reach of each other are one vertex.
   * Edge components stop about min_radius cells short of a corner, so keep it above
   * min_radius; it must stay below the shortest edge length. Default 24, range
   * kVertexReachRange. */
  int vertex_reach = 24;
  /** \brief Joining: pieces of one edge (cores that separate the same two faces),
   * split by noise, by a speck or by a vertex region between them, are one edge when
   * their closest core cells are at most this many cells apart and connected through
   * the band within sqrt(3) times as many 6-steps (pieces that touch are always
   * joined; pieces of one straight edge on one line join at any distance). Also the
   * longest gap bridged in an edge's skeleton. Keep it below the distance between two
   * parallel edges of the same two faces. Default 24, range kJoinDistanceRange. */
  int join_distance = 24;
  /** \brief Complete regions: edge and vertex regions keep the cells within this many
   * 6-steps of their skeleton (their core cells and the ridge paths that join each
   * edge to its vertices); the rest of their watershed basin goes to the nearest face.
   * Cores lie within about 1.5 cells of the true curve. Default 1 cell, range
   * kFeatureWidthRange. */
  int feature_width = 1;
  /** \brief Per point (the PCL front class): a point is a vertex or edge point when
   * it lies within this distance, in cells, of the middle line of a skeleton around
   * it (skeletonCentres(); the nearest names its region); otherwise it belongs to its
   * face cell, or to the nearest face cell around it. Cells are coarser than the
   * points and the cores of obtuse edges are several cells wide: this keeps feature
   * points within about this distance of the curve. 0 = off (points take their cell's
   * label). Default 1.0 (kNoisePointFeatureDistance = 1.25 in the estimator's noise
   * mode), range kPointFeatureDistanceRange. */
  double point_feature_distance = 1.0;
  /** \brief OpenMP threads of the steps that run core by core (the geodesic
   * dilations of the vertex test and of the edges' joining); 0 (default) = all
   * available (OpenMP's default). The result does not depend on it. Range
   * kThreadsRange. The estimator sets it from setNumberOfThreads(). */
  int threads = 0;

  /** \brief point_feature_distance of the noise mode: with the noise left along the
   * surface after smoothing, feature points keep the same 2-cell bound (cells). */
  static constexpr double kNoisePointFeatureDistance = 1.25;

  /** \brief [0, 1000000] cells. */
  static constexpr ParameterRange<int> kMinPieceCellsRange{0, 1000000};
  /** \brief [1, 1000] cells. */
  static constexpr ParameterRange<int> kVertexReachRange{1, 1000};
  /** \brief [0, 1000] cells. */
  static constexpr ParameterRange<int> kJoinDistanceRange{0, 1000};
  /** \brief [0, 1000] cells (6-steps). */
  static constexpr ParameterRange<int> kFeatureWidthRange{0, 1000};
  /** \brief [0, 10] cells. */
  static constexpr ParameterRange<double> kPointFeatureDistanceRange{0.0, 10.0};
  /** \brief [0, 1024], 0 = all available (VisibilityMap::kMaxThreads). */
  static constexpr ParameterRange<int> kThreadsRange{0, VisibilityMap::kMaxThreads};

  /** \brief Throws visfeat::Error naming the first parameter out of range, with its
   * value, range and unit (components first, see ComponentParameters::validate;
   * max_radius is the cap of the visibility map, in rings). FeatureSegmentation::
   * validate() checks the same ranges. */
  void validate(int max_radius) const;
};

/** \brief A final region: a vertex, an edge or a face of the object. */
struct Region
{
  FeatureClass feature_class = FeatureClass::kNone;
  /** \brief Cells of the region (its core and what it grew). */
  std::uint32_t cells = 0;
  /** \brief Cells of its core(s) (radius >= min_radius). */
  std::uint32_t core_cells = 0;
};

/** \brief Vertices, edges and faces of a band from its visibility map.
 *
 * Raw mode is section 5 of the paper: the components of ComponentSet are the regions.
 *
 * The default mode fixes what the literal method gets wrong on exact topology
 * (measured: spurious 1-25 cell components in valleys and near corners, edges broken
 * into fragments, faces classified as edges by the mean-neighbour rule):
 *  1. cores = ComponentSet in default mode (min_radius 16, depth-based face test);
 *     cores inside outlier pieces are dropped;
 *  2. every band cell joins a core by a watershed on the radius (growRegions);
 *  3. each non-face region is judged by the face regions it touches: two faces make
 *     it an edge between that pair; three or more make a small one a vertex (a larger
 *     one an edge between its two main faces); one or none make it a speck, merged into
 *     the neighbour it shares most boundary with;
 *  4. edge regions that touch each other and separate the same two faces are one edge
 *     (fragments of a ridge); vertex regions that touch each other are one vertex;
 *     a small core with pieces of its own edge on both sides is never a vertex;
 *  5. complete regions: edges and vertices are cut to their skeleton; a vertex with
 *     two or more straight edges becomes the point nearest to their lines (the
 *     corner), and each edge is drawn from its core's end to it.
 * Labels are then renumbered 1.. in the order of each region's smallest cell id.
 *
 * Each step is a function of its own over a shared state, declared in order in
 * src/core/segmentation/segmentation_steps.h (not installed); its tuned constants are
 * named, with what they were measured on, in the step's source file.
 */
class FeatureSegmentation
{
public:
  /** \brief Segments the band (size n cells) with its map (one radius per cell).
   * \throws visfeat::Error for parameters out of range (see validate()), checked
   * against the map's max_radius. */
  static FeatureSegmentation compute(const VoxelBand& band,
                                     const VisibilityMap& map,
                                     const SegmentationParameters& parameters);

  /** \brief Same as parameters.validate(max_radius). */
  static void validate(const SegmentationParameters& parameters, int max_radius);

  /** \brief Per cell, its region label (1-based), 0 = none. */
  const std::vector<std::uint32_t>& cellLabels() const { return labels_; }

  /** \brief regions()[label - 1]. */
  const std::vector<Region>& regions() const { return regions_; }

  /** \brief Per region (index label - 1), its class: regions()[r].feature_class. */
  std::vector<FeatureClass> regionClasses() const
  {
    std::vector<FeatureClass> classes(regions_.size());
    for (std::size_t r = 0; r < regions_.size(); ++r)
      classes[r] = regions_[r].feature_class;
    return classes;
  }

  FeatureClass cellClass(CellId id) const
  {
    const std::uint32_t label = labels_[static_cast<std::size_t>(id)];
    return label == 0 ? FeatureClass::kNone : regions_[label - 1].feature_class;
  }

  /** \brief Per cell, 1 if it is on the skeleton of an edge or vertex region (its
   * core cells and the ridge paths to its vertices); empty unless complete regions. */
  const std::vector<char>& skeleton() const { return skeleton_; }

  /** \brief Per cell, for skeleton cells, the middle of the skeleton of its region
   * around it: the mean of the region's skeleton cells within 3 cells, in cell units
   * (cell (i,j,k) spans [i, i+1) x [j, j+1) x [k, k+1); world = origin + cell_size *
   * value). NaN elsewhere; empty unless complete regions. Where an edge's core is
   * several cells wide (obtuse edges) this is its middle line, near the true curve. */
  const std::vector<Eigen::Vector3f>& skeletonCentres() const
  {
    return skeleton_centres_;
  }

  /** \brief Per skeleton cell, the unit direction of the middle line through its
   * centre (the edge's line, a drawn segment, or the main axis of the skeleton around
   * it); zero where the skeleton is not locally a line (blobs at corners). */
  const std::vector<Eigen::Vector3f>& skeletonTangents() const
  {
    return skeleton_tangents_;
  }

  /** \brief The cores the regions grew from. */
  const ComponentSet& cores() const { return cores_; }

  /** \brief Regions of each class: [none, vertex, edge, face]. */
  std::array<std::size_t, 4> classCounts() const;

  /** \brief Joins regions: region l's cells take region into[l]'s label and class
   * (into has size regions().size() + 1, index 0 unused; into[l] = l keeps l, and
   * into[into[l]] must be into[l]). Skeleton cells that end in a face leave the
   * skeleton. Labels are then renumbered 1.. in the order of each region's smallest
   * cell id, as compute() numbers them (e.g. CreaseAngleParameters' merge).
   * \return per old label (index 0 unused, 0 -> 0), its new label.
   * \throws visfeat::Error when into has the wrong size or a label out of range. */
  std::vector<std::uint32_t> mergeRegions(const std::vector<std::uint32_t>& into);

  /** \brief New edge regions, one per list of cells (e.g. the creases where two faces
   * touch, locateContactCreases()): the listed cells that belong to a face region take
   * the new region's label (other cells keep theirs; a list left with no face cell
   * adds no region). Labels are then renumbered as mergeRegions() does.
   * \return per old label (index 0 unused, 0 -> 0), its new label; the new regions'
   * labels are those of their cells in cellLabels().
   * \throws visfeat::Error for a cell id out of range. */
  std::vector<std::uint32_t>
  addEdgeRegions(const std::vector<std::vector<CellId>>& cells);

  /** \brief New edge or vertex regions, one per list of cells, in list order: a listed
   * cell takes the list's new label when it belongs to a region of lower rank (face <
   * edge < vertex) that is a face of before the call or a region of an earlier list
   * (the edges and vertices of before are never taken). E.g. the contact creases as
   * edges, then the corners where they meet as vertices. Renumbered as
   * addEdgeRegions(), which is this with every list an edge.
   * \throws visfeat::Error for a cell id out of range, a class that is not an edge or
   *         a vertex, or list_classes of another size than cells. */
  std::vector<std::uint32_t> addRegions(const std::vector<std::vector<CellId>>& cells,
                                        const std::vector<FeatureClass>& list_classes);

  /** \brief Moves face cells to other faces: each listed cell that belongs to a face
   * region takes the label faces[r] of its list r (a face region), e.g. a piece of a
   * face that a new edge cut off, to the face on its side (the estimator's contact
   * creases). Other cells keep theirs. Labels are then renumbered as mergeRegions()
   * does.
   * \return per old label (index 0 unused, 0 -> 0), its new label.
   * \throws visfeat::Error for a cell id out of range, faces of another size than
   *         cells, or a target that is not a face region. */
  std::vector<std::uint32_t>
  moveFaceCells(const std::vector<std::vector<CellId>>& cells,
                const std::vector<std::uint32_t>& faces);

  /** \brief New face regions, one per list of cells, in list order: the listed cells
   * that belong to a face region take the list's new label (e.g. the pieces of a face
   * that its ridges of non-planar points cut apart, creasedFacePieces()); other cells
   * keep theirs. Renumbered as mergeRegions() does.
   * \return per old label (index 0 unused, 0 -> 0), its new label; the new regions'
   * labels are those of their cells in cellLabels().
   * \throws visfeat::Error for a cell id out of range. */
  std::vector<std::uint32_t> splitFaces(const std::vector<std::vector<CellId>>& cells);

private:
  ComponentSet cores_;
  std::vector<std::uint32_t> labels_;
  std::vector<Region> regions_;
  std::vector<char> skeleton_;
  std::vector<Eigen::Vector3f> skeleton_centres_;
  std::vector<Eigen::Vector3f> skeleton_tangents_;
};

} // namespace visfeat
