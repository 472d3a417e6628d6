#include <visfeat/core/graph/open_faces.h>

#include <algorithm>
#include <iterator>
#include <numeric>

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

} // namespace

std::vector<std::uint32_t>
openFaceMerge(const TopologyGraph& graph)
{
  std::vector<std::uint32_t> into = identityMerge(graph);
  const auto n = static_cast<std::uint32_t>(graph.size());
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
    std::vector<std::uint32_t> both, others;
    std::set_intersection(a.begin(), a.end(), b.begin(), b.end(),
                          std::back_inserter(both));
    std::set_difference(both.begin(), both.end(), faces.begin(), faces.end(),
                        std::back_inserter(others));
    if (others.size() == 1 && graph.node(others[0]).cells > graph.node(f).cells)
      into[f] = others[0];
  }
  // a face joins a larger one only: no cycle
  for (std::uint32_t& target : into)
    while (into[target] != target)
      target = into[target];
  return into;
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
