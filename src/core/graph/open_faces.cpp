#include <visfeat/core/common/error.h>
#include <visfeat/core/graph/open_faces.h>

#include "region_boundaries.h"

#include <algorithm>
#include <iterator>
#include <map>
#include <numeric>
#include <string>

namespace visfeat {
namespace {

std::vector<std::uint32_t>
identityMerge(const TopologyGraph& graph)
{
  std::vector<std::uint32_t> into(graph.size() + 1);
  std::iota(into.begin(), into.end(), 0u);
  return into;
}

/** The vertex at the other end of edge e from v, or 0 unless e has exactly two. */
std::uint32_t
otherEnd(const TopologyGraph& graph, std::uint32_t e, std::uint32_t v)
{
  const std::vector<std::uint32_t> ends = graph.verticesOfEdge(e);
  if (ends.size() != 2 || (ends[0] != v && ends[1] != v))
    return 0;
  return ends[0] == v ? ends[1] : ends[0];
}

/** Per face region, the faces that could have lost it (openFaceMerge()): the faces
 * joined to both ends of its one edge, but the edge's two; empty for a face that is no
 * open face. */
std::vector<std::vector<std::uint32_t>>
openFaceSources(const TopologyGraph& graph)
{
  const auto n = static_cast<std::uint32_t>(graph.size());
  std::vector<std::vector<std::uint32_t>> sources(n + 1);
  for (std::uint32_t f = 1; f <= n; ++f) {
    if (graph.node(f).feature_class != FeatureClass::kFace)
      continue;
    const std::vector<std::uint32_t> edges = graph.neighbours(f, FeatureClass::kEdge);
    if (edges.size() != 1)
      continue;
    const std::vector<std::uint32_t> ends = graph.verticesOfEdge(edges[0]);
    const std::vector<std::uint32_t> faces = graph.facesOfEdge(edges[0]);
    const std::vector<std::uint32_t> corners =
      graph.neighbours(f, FeatureClass::kVertex);
    if (ends.size() != 2 || faces.size() != 2 ||
        !std::includes(ends.begin(), ends.end(), corners.begin(), corners.end()))
      continue;
    // the faces of both ends but the edge's two (all lists ascending)
    const std::vector<std::uint32_t> a = graph.neighbours(ends[0], FeatureClass::kFace);
    const std::vector<std::uint32_t> b = graph.neighbours(ends[1], FeatureClass::kFace);
    std::vector<std::uint32_t> both;
    std::set_intersection(a.begin(), a.end(), b.begin(), b.end(),
                          std::back_inserter(both));
    std::set_difference(both.begin(), both.end(), faces.begin(), faces.end(),
                        std::back_inserter(sources[f]));
  }
  return sources;
}

/** Per face with several sources, the boundary it shares with each region
 * (detail::sharedBoundary()); the faces' cells gathered in one pass over the band. */
std::map<std::uint32_t, std::map<std::uint32_t, std::size_t>>
sharedBoundaries(const std::vector<std::vector<std::uint32_t>>& sources,
                 const VoxelBand& band,
                 const std::vector<std::uint32_t>& cell_labels)
{
  std::map<std::uint32_t, std::vector<CellId>> cells_of;
  for (std::uint32_t f = 0; f < sources.size(); ++f)
    if (sources[f].size() > 1)
      cells_of[f];
  if (cells_of.empty())
    return {};
  detail::gatherCells(cell_labels, cells_of);
  std::map<std::uint32_t, std::map<std::uint32_t, std::size_t>> shared;
  for (const auto& [f, cells] : cells_of)
    shared[f] = detail::sharedBoundary(band, cell_labels, cells, f);
  return shared;
}

std::vector<std::uint32_t>
mergeOpenFaces(const TopologyGraph& graph,
               const VoxelBand* band,
               const std::vector<std::uint32_t>* cell_labels)
{
  std::vector<std::uint32_t> into = identityMerge(graph);
  const std::vector<std::vector<std::uint32_t>> sources = openFaceSources(graph);
  const auto shared =
    band ? sharedBoundaries(sources, *band, *cell_labels)
         : std::map<std::uint32_t, std::map<std::uint32_t, std::size_t>>{};
  for (std::uint32_t f = 1; f < sources.size(); ++f) {
    std::uint32_t from = 0;
    if (sources[f].size() == 1) {
      from = sources[f][0];
    } else if (sources[f].size() > 1 && shared.count(f)) {
      // the source it shares the most boundary with, when that one is alone
      std::map<std::uint32_t, std::size_t> with_sources;
      for (const std::uint32_t s : sources[f]) {
        const auto it = shared.at(f).find(s);
        if (it != shared.at(f).end())
          with_sources.insert(*it);
      }
      from = detail::soleLargest(with_sources);
    }
    if (from != 0 && graph.node(from).cells > graph.node(f).cells)
      into[f] = from;
  }
  // a face joins a larger one only: no cycle
  for (std::uint32_t& target : into)
    while (into[target] != target)
      target = into[target];
  return into;
}

} // namespace

std::vector<std::uint32_t>
openFaceMerge(const TopologyGraph& graph)
{
  return mergeOpenFaces(graph, nullptr, nullptr);
}

std::vector<std::uint32_t>
openFaceMerge(const TopologyGraph& graph,
              const VoxelBand& band,
              const std::vector<std::uint32_t>& cell_labels)
{
  if (cell_labels.size() != band.size())
    throw Error("openFaceMerge: " + std::to_string(cell_labels.size()) +
                " cell labels for a band of " + std::to_string(band.size()) + " cells");
  return mergeOpenFaces(graph, &band, &cell_labels);
}

std::vector<std::uint32_t>
creaseInnerVertexMerge(const TopologyGraph& graph)
{
  std::vector<std::uint32_t> into = identityMerge(graph);
  const auto n = static_cast<std::uint32_t>(graph.size());
  std::vector<bool> taken(n + 1, false); // edges of a vertex merged already: no chain
  for (std::uint32_t v = 1; v <= n; ++v) {
    if (graph.node(v).feature_class != FeatureClass::kVertex)
      continue;
    const std::vector<std::uint32_t> edges = graph.neighbours(v, FeatureClass::kEdge);
    if (edges.size() != 2 || taken[edges[0]] || taken[edges[1]])
      continue;
    const std::vector<std::uint32_t> faces = graph.facesOfEdge(edges[0]);
    const std::uint32_t x = otherEnd(graph, edges[0], v);
    const std::uint32_t y = otherEnd(graph, edges[1], v);
    if (faces.size() != 2 || graph.facesOfEdge(edges[1]) != faces ||
        graph.neighbours(v, FeatureClass::kFace) != faces || x == 0 || y == 0 || x == y)
      continue;
    const bool first_larger = graph.node(edges[0]).cells >= graph.node(edges[1]).cells;
    const std::uint32_t kept = first_larger ? edges[0] : edges[1];
    into[v] = kept;
    into[first_larger ? edges[1] : edges[0]] = kept;
    taken[edges[0]] = taken[edges[1]] = true;
  }
  return into;
}

} // namespace visfeat
