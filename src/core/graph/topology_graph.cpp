#include <visfeat/core/band/band_dilation.h>
#include <visfeat/core/common/error.h>
#include <visfeat/core/graph/topology_graph.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <sstream>

namespace visfeat {
namespace {

bool
validClass(FeatureClass cls)
{
  return static_cast<std::uint8_t>(cls) <=
         static_cast<std::uint8_t>(FeatureClass::kFace);
}

/** Whether the BFS from a region of class from should join a region of class to. */
bool
wanted(FeatureClass from, FeatureClass to)
{
  if (from == FeatureClass::kVertex)
    return to == FeatureClass::kEdge || to == FeatureClass::kFace;
  if (from == FeatureClass::kEdge)
    return to == FeatureClass::kFace;
  return false;
}

} // namespace

// --- Building: the steps of TopologyGraph::build ------------------------------

namespace {

/** Region pairs (smaller label first) to join by an arc. */
using LabelPairs = std::vector<std::pair<std::uint32_t, std::uint32_t>>;

/** Throws unless there is one label per band cell, the labels fit in 32 bits and
 * every region's class is a FeatureClass value. */
void
checkBuildInputs(std::size_t n_cells,
                 const std::vector<std::uint32_t>& cell_labels,
                 const std::vector<FeatureClass>& region_classes)
{
  const std::size_t n_regions = region_classes.size();
  if (cell_labels.size() != n_cells) {
    std::ostringstream msg;
    msg << "cell_labels has " << cell_labels.size() << " entries, the band " << n_cells
        << " cells";
    throw Error(msg.str());
  }
  if (n_regions > std::numeric_limits<std::uint32_t>::max() - 1u)
    throw Error("too many regions for 32-bit labels");
  for (std::size_t r = 0; r < n_regions; ++r) {
    if (!validClass(region_classes[r])) {
      std::ostringstream msg;
      msg << "region " << r + 1 << " has an invalid feature class "
          << static_cast<int>(static_cast<std::uint8_t>(region_classes[r]));
      throw Error(msg.str());
    }
  }
}

/** Cells of each region, ascending (CSR: the cells of label at
 * cells[offsets[label - 1] .. offsets[label])). */
struct RegionCells
{
  std::vector<std::size_t> offsets;
  std::vector<CellId> cells;

  std::size_t count(std::size_t r) const { return offsets[r + 1] - offsets[r]; }
};

/** The cells grouped by label (0 = none, left out). Throws for a label above
 * n_regions. */
RegionCells
groupCellsByRegion(const std::vector<std::uint32_t>& cell_labels, std::size_t n_regions)
{
  const std::size_t n_cells = cell_labels.size();
  RegionCells regions;
  std::vector<std::size_t>& offsets = regions.offsets;
  offsets.assign(n_regions + 1, 0);
  for (std::size_t c = 0; c < n_cells; ++c) {
    const std::uint32_t label = cell_labels[c];
    if (label > n_regions) {
      std::ostringstream msg;
      msg << "cell " << c << " has label " << label << ", above the " << n_regions
          << " regions";
      throw Error(msg.str());
    }
    if (label != 0)
      ++offsets[label];
  }
  for (std::size_t r = 0; r < n_regions; ++r)
    offsets[r + 1] += offsets[r];
  regions.cells.resize(offsets[n_regions]);
  std::vector<std::size_t> fill(offsets.begin(), offsets.end() - 1);
  for (std::size_t c = 0; c < n_cells; ++c) {
    const std::uint32_t label = cell_labels[c];
    if (label != 0)
      regions.cells[fill[label - 1]++] = static_cast<CellId>(c);
  }
  return regions;
}

/** A node's cell-based geometry from the cells of region r: its point count, the
 * centroid of its cell centres weighted by their points (unweighted when it has no
 * point), its cells' bounds; NaN for a region without cells. */
void
setCellGeometry(GraphNode& node,
                const VoxelBand& band,
                const RegionCells& regions,
                std::size_t r)
{
  if (node.cells == 0) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    node.points = 0;
    node.centroid.setConstant(nan);
    node.min.setConstant(nan);
    node.max.setConstant(nan);
    return;
  }
  const GridSpec& grid = band.grid();
  Eigen::Vector3d weighted = Eigen::Vector3d::Zero();
  Eigen::Vector3d plain = Eigen::Vector3d::Zero();
  std::uint64_t points = 0;
  CellCoord lo = band.coord(regions.cells[regions.offsets[r]]);
  CellCoord hi = lo;
  for (std::size_t k = regions.offsets[r]; k < regions.offsets[r + 1]; ++k) {
    const CellId c = regions.cells[k];
    const CellCoord& coord = band.coord(c);
    const Eigen::Vector3d centre = grid.cellCenter(coord);
    const std::uint32_t count = band.pointCount(c);
    points += count;
    weighted += static_cast<double>(count) * centre;
    plain += centre;
    lo = lo.cwiseMin(coord);
    hi = hi.cwiseMax(coord);
  }
  node.points = points;
  node.centroid = points > 0 ? Eigen::Vector3d(weighted / static_cast<double>(points))
                             : Eigen::Vector3d(plain / static_cast<double>(node.cells));
  node.min = grid.origin + grid.cell_size * lo.cast<double>();
  node.max = grid.origin + grid.cell_size * (hi.array() + 1).matrix().cast<double>();
}

/** The arcs of region `label` (class from) given the labels of the cells its dilation
 * reached (sorted, one entry per reached cell), appended to pairs. */
void
appendContactArcs(std::uint32_t label,
                  FeatureClass from,
                  const std::vector<std::uint32_t>& found,
                  const std::vector<FeatureClass>& region_classes,
                  double min_face_contact,
                  int max_edge_faces,
                  LabelPairs& pairs)
{
  // Reached cells per region; an edge keeps a face only if it reaches a fair share
  // of its strongest face (the corner's third face touches an edge at its ends).
  std::vector<std::pair<std::uint32_t, std::size_t>> counts;
  for (const std::uint32_t other : found)
    if (counts.empty() || counts.back().first != other)
      counts.emplace_back(other, 1);
    else
      ++counts.back().second;
  std::size_t strongest_face = 0;
  for (const auto& [other, count] : counts)
    if (region_classes[other - 1] == FeatureClass::kFace)
      strongest_face = std::max(strongest_face, count);
  const auto fairFace = [&](std::uint32_t other, std::size_t count) {
    return region_classes[other - 1] == FeatureClass::kFace &&
           static_cast<double>(count) >=
             min_face_contact * static_cast<double>(strongest_face);
  };
  // A manifold edge bounds two faces: beyond the fair share, an edge keeps the
  // max_edge_faces faces it reaches most (all those tied with the last one kept).
  std::vector<std::size_t> face_counts;
  for (const auto& [other, count] : counts)
    if (fairFace(other, count))
      face_counts.push_back(count);
  std::size_t least_kept = 0;
  const auto max_faces = static_cast<std::size_t>(max_edge_faces);
  if (from == FeatureClass::kEdge && max_faces > 0 && face_counts.size() > max_faces) {
    const auto last = face_counts.begin() + static_cast<std::ptrdiff_t>(max_faces - 1);
    std::nth_element(face_counts.begin(), last, face_counts.end(), std::greater<>());
    least_kept = *last;
  }
  for (const auto& [other, count] : counts) {
    const bool weak_face = from == FeatureClass::kEdge &&
                           region_classes[other - 1] == FeatureClass::kFace &&
                           (!fairFace(other, count) || count < least_kept);
    if (!weak_face)
      pairs.emplace_back(std::min(label, other), std::max(label, other));
  }
}

/** Arcs: the geodesic dilation (BandDilation) of every vertex and edge region by
 * dilation_radius, and the labels of the cells it reaches. */
LabelPairs
dilationArcs(const VoxelBand& band,
             const std::vector<std::uint32_t>& cell_labels,
             const std::vector<FeatureClass>& region_classes,
             const RegionCells& regions,
             const TopologyGraphParameters& parameters)
{
  LabelPairs pairs;
  const int radius = parameters.dilation_radius;
  if (radius <= 0 || band.size() == 0)
    return pairs;
  BandDilation dilation(band);
  std::vector<CellId> cells;
  std::vector<std::uint32_t> found;
  for (std::size_t r = 0; r < region_classes.size(); ++r) {
    const FeatureClass from = region_classes[r];
    if (from != FeatureClass::kVertex && from != FeatureClass::kEdge)
      continue;
    if (regions.count(r) == 0)
      continue;
    const std::uint32_t label = static_cast<std::uint32_t>(r + 1);
    const auto first = regions.cells.begin();
    cells.assign(first + static_cast<std::ptrdiff_t>(regions.offsets[r]),
                 first + static_cast<std::ptrdiff_t>(regions.offsets[r + 1]));
    found.clear();
    dilation.run(cells, static_cast<std::uint32_t>(radius), [&](CellId c) {
      const std::uint32_t other = cell_labels[static_cast<std::size_t>(c)];
      if (other != 0 && other != label && wanted(from, region_classes[other - 1]))
        found.push_back(other);
    });
    std::sort(found.begin(), found.end());
    appendContactArcs(label, from, found, region_classes, parameters.min_face_contact,
                      parameters.max_edge_faces, pairs);
  }
  return pairs;
}

/** A corner lies on every face of its edges, even where its (small) region does not
 * reach that face's cells: vertex-face arcs also follow vertex-edge-face paths. */
void
addVertexFacesFromEdges(const std::vector<FeatureClass>& region_classes,
                        LabelPairs& pairs)
{
  const std::size_t n_regions = region_classes.size();
  std::vector<std::vector<std::uint32_t>> edges_of_vertex(n_regions + 1),
    faces_of_edge(n_regions + 1);
  for (const auto& [a, b] : pairs) {
    const FeatureClass ca = region_classes[a - 1], cb = region_classes[b - 1];
    if (ca == FeatureClass::kVertex && cb == FeatureClass::kEdge)
      edges_of_vertex[a].push_back(b);
    else if (cb == FeatureClass::kVertex && ca == FeatureClass::kEdge)
      edges_of_vertex[b].push_back(a);
    else if (ca == FeatureClass::kEdge && cb == FeatureClass::kFace)
      faces_of_edge[a].push_back(b);
    else if (cb == FeatureClass::kEdge && ca == FeatureClass::kFace)
      faces_of_edge[b].push_back(a);
  }
  for (std::uint32_t v = 1; v <= n_regions; ++v)
    for (const std::uint32_t e : edges_of_vertex[v])
      for (const std::uint32_t f : faces_of_edge[e])
        pairs.emplace_back(std::min(v, f), std::max(v, f));
}

} // namespace

// --- Building ----------------------------------------------------------------

void
TopologyGraph::validate(const TopologyGraphParameters& p)
{
  checkRange("dilation_radius", p.dilation_radius,
             TopologyGraphParameters::kDilationRadiusRange, "cells");
  checkRange("min_face_contact", p.min_face_contact,
             TopologyGraphParameters::kMinFaceContactRange,
             "fraction of the strongest face contact");
  checkRange("max_edge_faces", p.max_edge_faces,
             TopologyGraphParameters::kMaxEdgeFacesRange, "faces, 0 = no limit");
}

TopologyGraph
TopologyGraph::build(const VoxelBand& band,
                     const std::vector<std::uint32_t>& cell_labels,
                     const std::vector<FeatureClass>& region_classes,
                     const TopologyGraphParameters& parameters)
{
  validate(parameters);
  checkBuildInputs(band.size(), cell_labels, region_classes);
  const std::size_t n_regions = region_classes.size();
  const RegionCells regions = groupCellsByRegion(cell_labels, n_regions);

  TopologyGraph result;
  result.parameters_ = parameters;
  result.graph_ = Graph(n_regions);

  // Nodes: cells, points, cell-based geometry.
  for (std::size_t r = 0; r < n_regions; ++r) {
    GraphNode& node = result.graph_[static_cast<Graph::vertex_descriptor>(r)];
    node.id = static_cast<std::uint32_t>(r + 1);
    node.feature_class = region_classes[r];
    node.cells = static_cast<std::uint32_t>(regions.count(r));
    setCellGeometry(node, band, regions, r);
  }

  LabelPairs pairs =
    dilationArcs(band, cell_labels, region_classes, regions, parameters);
  if (parameters.vertex_faces_from_edges)
    addVertexFacesFromEdges(region_classes, pairs);
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  for (const auto& p : pairs)
    boost::add_edge(p.first - 1, p.second - 1, result.graph_);
  return result;
}

void
TopologyGraph::setPointGeometry(std::uint32_t id,
                                std::uint64_t points,
                                const Eigen::Vector3d& centroid,
                                const Eigen::Vector3d& min,
                                const Eigen::Vector3d& max)
{
  checkedNode(id, "setPointGeometry");
  GraphNode& node = graph_[id - 1];
  node.points = points;
  node.centroid = centroid;
  node.min = min;
  node.max = max;
}

// --- Queries -----------------------------------------------------------------

const GraphNode&
TopologyGraph::checkedNode(std::uint32_t id, const char* what) const
{
  if (!contains(id)) {
    std::ostringstream msg;
    msg << what << ": no region " << id << " in the topology graph (ids 1.." << size()
        << ")";
    throw Error(msg.str());
  }
  return graph_[id - 1];
}

const GraphNode&
TopologyGraph::node(std::uint32_t id) const
{
  return checkedNode(id, "node");
}

std::size_t
TopologyGraph::classCount(FeatureClass cls) const
{
  std::size_t n = 0;
  for (std::size_t v = 0; v < size(); ++v)
    n += graph_[v].feature_class == cls ? 1 : 0;
  return n;
}

std::vector<std::uint32_t>
TopologyGraph::neighbours(std::uint32_t id) const
{
  checkedNode(id, "neighbours");
  std::vector<std::uint32_t> ids;
  const auto range = boost::adjacent_vertices(id - 1, graph_);
  for (auto it = range.first; it != range.second; ++it)
    ids.push_back(static_cast<std::uint32_t>(*it + 1));
  std::sort(ids.begin(), ids.end());
  return ids;
}

std::vector<std::uint32_t>
TopologyGraph::neighbours(std::uint32_t id, FeatureClass cls) const
{
  std::vector<std::uint32_t> ids = neighbours(id);
  ids.erase(
    std::remove_if(ids.begin(), ids.end(),
                   [&](std::uint32_t o) { return graph_[o - 1].feature_class != cls; }),
    ids.end());
  return ids;
}

bool
TopologyGraph::adjacent(std::uint32_t a, std::uint32_t b) const
{
  checkedNode(a, "adjacent");
  checkedNode(b, "adjacent");
  return boost::edge(a - 1, b - 1, graph_).second;
}

namespace {

void
requireClass(const GraphNode& node, FeatureClass cls, const char* what)
{
  if (node.feature_class != cls) {
    std::ostringstream msg;
    msg << what << ": region " << node.id << " is a "
        << TopologyGraph::className(node.feature_class) << ", not a "
        << TopologyGraph::className(cls);
    throw Error(msg.str());
  }
}

} // namespace

std::vector<std::uint32_t>
TopologyGraph::edgesOfFace(std::uint32_t id) const
{
  requireClass(checkedNode(id, "edgesOfFace"), FeatureClass::kFace, "edgesOfFace");
  return neighbours(id, FeatureClass::kEdge);
}

std::vector<std::uint32_t>
TopologyGraph::verticesOfEdge(std::uint32_t id) const
{
  requireClass(checkedNode(id, "verticesOfEdge"), FeatureClass::kEdge,
               "verticesOfEdge");
  return neighbours(id, FeatureClass::kVertex);
}

std::vector<std::uint32_t>
TopologyGraph::facesOfEdge(std::uint32_t id) const
{
  requireClass(checkedNode(id, "facesOfEdge"), FeatureClass::kEdge, "facesOfEdge");
  return neighbours(id, FeatureClass::kFace);
}

std::vector<std::pair<std::uint32_t, std::uint32_t>>
TopologyGraph::arcs() const
{
  std::vector<std::pair<std::uint32_t, std::uint32_t>> result;
  result.reserve(arcCount());
  const auto range = boost::edges(graph_);
  for (auto it = range.first; it != range.second; ++it) {
    const auto a = static_cast<std::uint32_t>(boost::source(*it, graph_) + 1);
    const auto b = static_cast<std::uint32_t>(boost::target(*it, graph_) + 1);
    result.emplace_back(std::min(a, b), std::max(a, b));
  }
  std::sort(result.begin(), result.end());
  return result;
}

const char*
TopologyGraph::className(FeatureClass cls)
{
  switch (cls) {
  case FeatureClass::kVertex:
    return "vertex";
  case FeatureClass::kEdge:
    return "edge";
  case FeatureClass::kFace:
    return "face";
  default:
    return "none";
  }
}

} // namespace visfeat
