#pragma once

#include <visfeat/core/band/voxel_band.h>
#include <visfeat/core/common/feature_class.h>
#include <visfeat/core/common/parameters.h>
#include <visfeat/core/grid/grid_spec.h>

#include <boost/graph/adjacency_list.hpp>

#include <Eigen/Core>

#include <cstdint>
#include <iosfwd>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace visfeat {

/** \brief One node of the topology graph: a region (vertex, edge or face).
 *
 * Geometry is in world units. TopologyGraph::build fills it from the cells (centroid =
 * point-count-weighted mean of the cell centres, bounds = the union of the cells'
 * boxes); TopologyGraph::setPointGeometry replaces it with the points' own. A region
 * with no cells has centroid, min and max NaN.
 */
struct GraphNode
{
  /** \brief The region label (1-based), as in FeatureSegmentation::cellLabels(). */
  std::uint32_t id = 0;
  FeatureClass feature_class = FeatureClass::kNone;
  /** \brief Band cells labelled with id. */
  std::uint32_t cells = 0;
  /** \brief Input points in those cells. */
  std::uint64_t points = 0;
  Eigen::Vector3d centroid{0.0, 0.0, 0.0};
  Eigen::Vector3d min{0.0, 0.0, 0.0};
  Eigen::Vector3d max{0.0, 0.0, 0.0};
  /** \brief Edges: the turn between the planes fitted to its two sides, degrees (0 =
   * flat, 90 = a right-angle crease; measureCreaseAngles(); for an edge with one face
   * on both sides, a crease fading into it, measureFadingCreases()); NaN where not
   * measured and for vertices and faces. Set by setCreaseAngle(). */
  double crease_angle = std::numeric_limits<double>::quiet_NaN();
};

/** \brief Parameters of TopologyGraph::build. */
struct TopologyGraphParameters
{
  /** \brief Reach, in cells, of the incidence test. Range [0, kMaxDilationRadius].
   *
   * Region A is joined to region B (vertex-edge, edge-face and vertex-face; never two
   * regions of the same class) when the geodesic dilation of A by dilation_radius
   * cells reaches a cell of B: some cell of B is at most dilation_radius 6-steps from
   * a cell of A, walking through band cells (any band cell, labelled or not). This is
   * the paper's vertex-edge rule (section 5) applied to all three pairs; the test is
   * symmetric (see also vertex_faces_from_edges). Two regions separated by a gap of k
   * unlabelled cells are joined iff
   * dilation_radius >= k + 1; touching regions iff dilation_radius >= 1; 0 joins
   * nothing.
   *
   * - Complete regions (the default segmentation: the regions cover the band) touch
   *   their neighbours, so 1-2 cells is enough. Default 2: it also bridges a one-cell
   *   seam of unlabelled cells (e.g. where an outlier piece was cut off). Larger
   *   values may reach across a thin region into the one behind it.
   * - Raw components (SegmentationParameters::raw, or cores only) leave a valley of
   *   about ComponentParameters::min_radius cells between a component and its
   *   neighbours; use at least min_radius (e.g. min_radius + 2), and keep it below
   *   the length of the shortest edge, or regions that are not incident get joined.
   */
  int dilation_radius = kDefaultDilationRadius;
  /** \brief An edge-face arc needs the edge's dilation to reach at least this fraction
   * of the cells it reaches of its strongest face. A true incident face touches the
   * edge along its whole length; the third face of a corner only near the edge's
   * ends, within the dilation. Range [0, 1]; 0 keeps every face reached. Default 0.2.
   */
  double min_face_contact = 0.2;
  /** \brief Faces an edge is joined to at most, after min_face_contact: the ones it
   * reaches with the most cells (all those tied with the last one kept). A crease of
   * a manifold part lies between two faces; a third face reached with a fair share of
   * contact leaked around the corner at the edge's end (sparse clouds: 10,000 points,
   * cells 4 times finer than the point spacing, where the icosahedron's and the U
   * prism's edges reached a third face with 22-55% of the second's contact). Range
   * [0, kMaxDilationRadius]; 0 = no limit (non-manifold parts, e.g. two solids
   * sharing an edge). Default 2. */
  int max_edge_faces = 2;
  /** \brief Also join a vertex to every face of its edges (vertex-edge and edge-face
   * arcs found as above): a corner lies on the faces of its edges even where its small
   * region does not reach their cells. Default true; false keeps the dilation rule
   * alone. */
  bool vertex_faces_from_edges = true;

  static constexpr int kDefaultDilationRadius = 2;
  static constexpr int kMaxDilationRadius = 1000;
  /** \brief [0, kMaxDilationRadius] cells. */
  static constexpr ParameterRange<int> kDilationRadiusRange{0, kMaxDilationRadius};
  /** \brief [0, 1], a fraction. */
  static constexpr ParameterRange<double> kMinFaceContactRange{0.0, 1.0};
  /** \brief [0, 1000] faces; 0 = no limit. */
  static constexpr ParameterRange<int> kMaxEdgeFacesRange{0, 1000};
};

/** \brief Metadata written with TopologyGraph::writeJson. */
struct GraphMetadata
{
  /** \brief The grid of the band (origin and cell_size in world units). */
  GridSpec grid;
  /** \brief Name -> value. A value that is a JSON number (e.g. "16", "-0.5", "1e-3")
   * or true/false is written as such, anything else as a JSON string. */
  std::vector<std::pair<std::string, std::string>> parameters;
  /** \brief Where the graph came from, e.g. the input file name. */
  std::string source;
  /** \brief Results that cannot be trusted, one line each with the cause and what to
   * do (VisibilityFeatureEstimation::getWarnings()); written as "warnings", always
   * (an empty array when there are none). */
  std::vector<std::string> warnings;
  /** \brief Notes on the input (getNotes()), written as "notes". */
  std::vector<std::string> notes;
  /** \brief What was subtracted from the input's coordinates before the computation
   * (world units; e.g. survey coordinates recentred before the cast to float).
   * writeJson() adds it back to every coordinate it writes (the grid origin, the
   * nodes' centroid, min and max), so the JSON is in the input's frame, and writes it
   * as "offset". Zero (the default) when the cloud was not moved. */
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();
};

/** \brief The topology graph: which vertex touches which edge, which edge bounds which
 * face (and which vertex lies on which face).
 *
 * Nodes are the regions of a segmentation (FeatureSegmentation or raw components),
 * one per label 1..N in label order: graph vertex index = label - 1. Arcs join regions
 * of different classes (vertex-edge, edge-face, vertex-face) found by the dilation
 * test of TopologyGraphParameters. The graph is a boost::adjacency_list, so the Boost
 * Graph algorithms run on graph() directly (e.g. connected_components).
 *
 * PCL-free (Eigen and Boost Graph only). The result is deterministic: it depends only
 * on the band, the labels and the parameters.
 */
class TopologyGraph
{
public:
  using Graph =
    boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, GraphNode>;

  TopologyGraph() = default;

  /** \brief Build the graph of a labelled band.
   *
   * Inputs:
   * \param[in] band the voxel band (cell centres, point counts, 6-neighbours)
   * \param[in] cell_labels per band cell, its region label 1..N, 0 = none; size
   *            band.size()
   * \param[in] region_classes per region, its class: region_classes[label - 1]
   *            (N = region_classes.size(); labels with no cell become empty nodes)
   * \param[in] parameters see TopologyGraphParameters
   *
   * Output: N nodes (cells, points and cell-based geometry per region) and the arcs.
   *
   * Cost: one bounded BFS per vertex and edge region, with a reusable mark array;
   * about (cells of the vertex and edge regions dilated by dilation_radius) steps.
   *
   * \throws visfeat::Error when cell_labels has the wrong size or holds a label above
   *         N, a class is not a FeatureClass value, or dilation_radius is out of range.
   */
  static TopologyGraph build(const VoxelBand& band,
                             const std::vector<std::uint32_t>& cell_labels,
                             const std::vector<FeatureClass>& region_classes,
                             const TopologyGraphParameters& parameters);

  /** \brief Throws visfeat::Error naming the first parameter out of range. */
  static void validate(const TopologyGraphParameters& parameters);

  /** \brief Replace the cell-based geometry of a node with its points' own (point
   * count, centroid and bounds, world units). \throws visfeat::Error for an unknown
   * id. */
  void setPointGeometry(std::uint32_t id,
                        std::uint64_t points,
                        const Eigen::Vector3d& centroid,
                        const Eigen::Vector3d& min,
                        const Eigen::Vector3d& max);

  /** \brief Set GraphNode::crease_angle of node id (degrees). \throws visfeat::Error
   * for an unknown id. */
  void setCreaseAngle(std::uint32_t id, double degrees)
  {
    checkedNode(id, "setCreaseAngle");
    graph_[id - 1].crease_angle = degrees;
  }

  /** \brief The Boost graph: vertex index = id - 1, bundled property GraphNode. */
  const Graph& graph() const { return graph_; }

  /** \brief Number of nodes (regions), N. */
  std::size_t size() const { return boost::num_vertices(graph_); }

  bool empty() const { return size() == 0; }

  /** \brief Number of arcs. */
  std::size_t arcCount() const { return boost::num_edges(graph_); }

  /** \brief Nodes of a class. */
  std::size_t classCount(FeatureClass cls) const;

  /** \brief Whether id names a node (1..size()). */
  bool contains(std::uint32_t id) const { return id >= 1 && id <= size(); }

  /** \brief The node with this id. \throws visfeat::Error for an unknown id. */
  const GraphNode& node(std::uint32_t id) const;

  /** \brief Ids of the nodes joined to id, ascending. \throws visfeat::Error for an
   * unknown id. */
  std::vector<std::uint32_t> neighbours(std::uint32_t id) const;

  /** \brief Same, only those of class cls. */
  std::vector<std::uint32_t> neighbours(std::uint32_t id, FeatureClass cls) const;

  /** \brief Whether an arc joins a and b. \throws visfeat::Error for an unknown id. */
  bool adjacent(std::uint32_t a, std::uint32_t b) const;

  /** \brief The edges bounding face id, ascending. \throws visfeat::Error when id is
   * unknown or not a face. */
  std::vector<std::uint32_t> edgesOfFace(std::uint32_t id) const;

  /** \brief The vertices at the ends of edge id, ascending. \throws visfeat::Error
   * when id is unknown or not an edge. */
  std::vector<std::uint32_t> verticesOfEdge(std::uint32_t id) const;

  /** \brief The faces on either side of edge id, ascending. \throws visfeat::Error
   * when id is unknown or not an edge. */
  std::vector<std::uint32_t> facesOfEdge(std::uint32_t id) const;

  /** \brief All arcs as (a, b) with a < b, ascending. */
  std::vector<std::pair<std::uint32_t, std::uint32_t>> arcs() const;

  /** \brief GraphViz DOT: one node per region, named by its id and labelled by class
   * and id ("V3", "E7", "F2"); vertices are red circles, edges orange boxes, faces
   * yellow ellipses; attributes cells and points. */
  void writeDot(std::ostream& out) const;

  /** \brief writeDot() preceded by comment lines ("// ...", which GraphViz ignores)
   * with what a reader needs to trust the graph: the source, the cell size, the
   * resolution's reason where meta.parameters has "resolution_reason", each warning and
   * note (the JSON has every parameter). */
  void writeDot(std::ostream& out, const GraphMetadata& meta) const;

  /** \brief JSON (format "visfeat-topology-graph", version 1): source, grid,
   * parameters, counts, nodes (id, class, cells, points, centroid, min, max;
   * edges also crease_angle, null where not measured) and arcs [[a, b], ...] with a <
   * b. Doubles round-trip exactly; NaN and infinities are written as null. */
  void writeJson(std::ostream& out, const GraphMetadata& meta) const;

  /** \brief Write DOT (extension .dot or .gv) or JSON (.json), case-insensitive.
   * \return true (errors throw)
   * \throws visfeat::Error for another extension or when the file cannot be written.
   */
  bool writeFile(const std::string& path, const GraphMetadata& meta) const;

  /** \brief "vertex", "edge", "face" or "none". */
  static const char* className(FeatureClass cls);

  /** \brief The parameters the graph was built with. */
  const TopologyGraphParameters& parameters() const { return parameters_; }

private:
  const GraphNode& checkedNode(std::uint32_t id, const char* what) const;

  Graph graph_;
  TopologyGraphParameters parameters_;
};

} // namespace visfeat
