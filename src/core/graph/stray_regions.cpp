#include <visfeat/core/graph/stray_regions.h>

#include <algorithm>
#include <numeric>

namespace visfeat {
namespace {

/** The two vertices of `vertices` (more than two) whose centroids lie farthest apart;
 * the first such pair in order on ties. */
std::pair<std::uint32_t, std::uint32_t>
farthestPair(const TopologyGraph& graph, const std::vector<std::uint32_t>& vertices)
{
  std::pair<std::uint32_t, std::uint32_t> best{vertices[0], vertices[1]};
  double best_distance = -1.0;
  for (std::size_t i = 0; i < vertices.size(); ++i)
    for (std::size_t j = i + 1; j < vertices.size(); ++j) {
      const double d =
        (graph.node(vertices[i]).centroid - graph.node(vertices[j]).centroid)
          .squaredNorm();
      if (d > best_distance) {
        best_distance = d;
        best = {vertices[i], vertices[j]};
      }
    }
  return best;
}

/** The single face joined to every edge of `edges`, or 0 when there is none or more
 * than one. */
std::uint32_t
faceOfAllEdges(const TopologyGraph& graph, const std::vector<std::uint32_t>& edges)
{
  std::vector<std::uint32_t> common = graph.facesOfEdge(edges[0]);
  for (std::size_t i = 1; i < edges.size() && !common.empty(); ++i) {
    const std::vector<std::uint32_t> faces = graph.facesOfEdge(edges[i]);
    common.erase(std::remove_if(common.begin(), common.end(),
                                [&](std::uint32_t f) {
                                  return std::find(faces.begin(), faces.end(), f) ==
                                         faces.end();
                                }),
                 common.end());
  }
  return common.size() == 1 ? common[0] : 0;
}

/** Per vertex: whether it ends at least one of its edges (see strayRegionMerge). */
std::vector<bool>
vertexEnds(const TopologyGraph& graph)
{
  const std::size_t n = graph.size();
  std::vector<bool> ends(n + 1, false);
  for (std::uint32_t e = 1; e <= n; ++e) {
    if (graph.node(e).feature_class != FeatureClass::kEdge)
      continue;
    const std::vector<std::uint32_t> vertices = graph.verticesOfEdge(e);
    if (vertices.size() == 1) {
      const std::uint32_t v = vertices[0];
      ends[v] = ends[v] || graph.neighbours(v, FeatureClass::kEdge).size() > 1;
    } else if (vertices.size() == 2) {
      ends[vertices[0]] = ends[vertices[1]] = true;
    } else if (vertices.size() > 2) {
      const auto [a, b] = farthestPair(graph, vertices);
      ends[a] = ends[b] = true;
    }
  }
  return ends;
}

/** Whether face f is a speck at the tip of vertex v: smaller than every face of v's
 * edges (v has at least one edge). */
bool
isCornerSpeck(const TopologyGraph& graph, std::uint32_t f, std::uint32_t v)
{
  const std::vector<std::uint32_t> edges = graph.neighbours(v, FeatureClass::kEdge);
  if (edges.empty())
    return false;
  for (const std::uint32_t e : edges)
    for (const std::uint32_t other : graph.facesOfEdge(e))
      if (graph.node(other).cells <= graph.node(f).cells)
        return false;
  return true;
}

} // namespace

std::vector<std::uint32_t>
strayRegionMerge(const TopologyGraph& graph)
{
  const std::size_t n = graph.size();
  std::vector<std::uint32_t> into(n + 1);
  std::iota(into.begin(), into.end(), 0u);
  const std::vector<bool> ends = vertexEnds(graph);
  for (std::uint32_t v = 1; v <= n; ++v) {
    if (graph.node(v).feature_class != FeatureClass::kVertex || ends[v])
      continue;
    const std::vector<std::uint32_t> edges = graph.neighbours(v, FeatureClass::kEdge);
    if (edges.empty())
      continue;
    into[v] = edges.size() == 1 ? edges[0] : faceOfAllEdges(graph, edges);
    if (into[v] == 0)
      into[v] = v;
  }
  for (std::uint32_t f = 1; f <= n; ++f) {
    if (graph.node(f).feature_class != FeatureClass::kFace ||
        !graph.neighbours(f, FeatureClass::kEdge).empty())
      continue;
    const std::vector<std::uint32_t> vertices =
      graph.neighbours(f, FeatureClass::kVertex);
    if (vertices.size() == 1 && isCornerSpeck(graph, f, vertices[0]))
      into[f] = into[vertices[0]];
  }
  return into;
}

} // namespace visfeat
