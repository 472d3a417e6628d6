#include <visfeat/core/graph/stray_regions.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <map>
#include <numeric>

namespace visfeat {
namespace {

/** Pairs of candidate ends less than this fraction shorter than the farthest pair
 * are a tie, which the larger regions win: a blob a few cells from a corner lies
 * about as far from the other end as the corner does (the icosahedron at 40,000
 * points, seed 2: a 2-cell blob 2 cells from a corner, on an edge of about 130
 * cells). */
constexpr double kEndPairTie = 0.05;

/** The two of `vertices` (more than two) that pass for the ends of their edge: the
 * pair whose centroids lie farthest apart, or, among pairs within kEndPairTie of that
 * distance, the one whose smaller region has the most cells (the first in order on
 * equal counts). */
std::pair<std::uint32_t, std::uint32_t>
endPair(const TopologyGraph& graph, const std::vector<std::uint32_t>& vertices)
{
  struct Candidate
  {
    double distance;
    std::uint32_t cells; // of the smaller region
    std::pair<std::uint32_t, std::uint32_t> pair;
  };
  std::vector<Candidate> candidates;
  double farthest = 0.0;
  for (std::size_t i = 0; i < vertices.size(); ++i)
    for (std::size_t j = i + 1; j < vertices.size(); ++j) {
      const GraphNode& a = graph.node(vertices[i]);
      const GraphNode& b = graph.node(vertices[j]);
      const double distance = (a.centroid - b.centroid).norm();
      candidates.push_back(
        {distance, std::min(a.cells, b.cells), {vertices[i], vertices[j]}});
      farthest = std::max(farthest, distance);
    }
  const Candidate* best = nullptr;
  for (const Candidate& c : candidates)
    if (c.distance >= (1.0 - kEndPairTie) * farthest &&
        (best == nullptr || c.cells > best->cells))
      best = &c;
  return best->pair;
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

/** The vertex that ends an edge (`ends`) and that the most of `edges` are joined to,
 * when at least two are and no other such vertex ties with it (the corner that a
 * stray vertex beside several of its edges lies near); 0 otherwise. Being an end, it
 * is never stray itself. */
std::uint32_t
cornerOfEdges(const TopologyGraph& graph,
              const std::vector<bool>& ends,
              const std::vector<std::uint32_t>& edges)
{
  std::vector<std::pair<std::uint32_t, int>> count; // (vertex, edges joined to it)
  for (const std::uint32_t e : edges)
    for (const std::uint32_t u : graph.verticesOfEdge(e)) {
      if (!ends[u])
        continue;
      auto it = std::find_if(count.begin(), count.end(),
                             [u](const auto& c) { return c.first == u; });
      if (it == count.end())
        count.emplace_back(u, 1);
      else
        ++it->second;
    }
  std::uint32_t best = 0;
  int most = 1;
  bool tie = false;
  for (const auto& [u, n] : count)
    if (n > most) {
      best = u;
      most = n;
      tie = false;
    } else if (n == most && best != 0) {
      tie = true;
    }
  return tie ? 0 : best;
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
      const auto [a, b] = endPair(graph, vertices);
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

/** Whether edge e is joined to a vertex other than u and v. */
bool
reachesOtherVertex(const TopologyGraph& graph,
                   std::uint32_t e,
                   std::uint32_t u,
                   std::uint32_t v)
{
  for (const std::uint32_t w : graph.verticesOfEdge(e))
    if (w != u && w != v)
      return true;
  return false;
}

/** Split corners (see strayRegionMerge) among the vertices that end an edge (`ends`;
 * the others are stray): into[piece] = corner, and the pieces of crease between them
 * join the corner too. Returns, per label, whether the region is
 * such a corner or piece (the stray-vertex rule leaves them alone). */
std::vector<bool>
mergeSplitCorners(const TopologyGraph& graph,
                  const std::vector<bool>& ends,
                  double max_distance,
                  std::vector<std::uint32_t>& into)
{
  const std::size_t n = graph.size();
  std::vector<bool> split(n + 1, false);
  for (std::uint32_t u = 1; u <= n; ++u) {
    if (graph.node(u).feature_class != FeatureClass::kVertex || !ends[u] ||
        into[u] != u)
      continue;
    const std::vector<std::uint32_t> edges = graph.neighbours(u, FeatureClass::kEdge);
    for (std::uint32_t v = u + 1; v <= n; ++v) {
      if (graph.node(v).feature_class != FeatureClass::kVertex || !ends[v] ||
          into[v] != v ||
          !((graph.node(u).centroid - graph.node(v).centroid).norm() <= max_distance))
        continue;
      std::vector<std::uint32_t> shared;
      bool leaves = false; // a shared edge goes on to a third vertex
      for (const std::uint32_t e : graph.neighbours(v, FeatureClass::kEdge))
        if (std::find(edges.begin(), edges.end(), e) != edges.end()) {
          shared.push_back(e);
          leaves = leaves || reachesOtherVertex(graph, e, u, v);
        }
      if (shared.size() < 2 || !leaves)
        continue;
      const bool u_larger = graph.node(u).cells >= graph.node(v).cells;
      const std::uint32_t corner = u_larger ? u : v;
      into[u_larger ? v : u] = corner;
      split[u] = split[v] = true;
      for (const std::uint32_t e : shared)
        if (!reachesOtherVertex(graph, e, u, v))
          into[e] = corner;
      if (!u_larger)
        break; // u joined v
    }
  }
  return split;
}

} // namespace

std::vector<std::uint32_t>
splitCornerMerge(const TopologyGraph& graph, double max_split_distance)
{
  std::vector<std::uint32_t> into(graph.size() + 1);
  std::iota(into.begin(), into.end(), 0u);
  mergeSplitCorners(graph, vertexEnds(graph), max_split_distance, into);
  for (std::uint32_t& target : into) // pieces join the corner that stays
    while (into[target] != target)
      target = into[target];
  return into;
}

std::vector<std::uint32_t>
strayRegionMerge(const TopologyGraph& graph, double max_split_distance)
{
  const std::size_t n = graph.size();
  std::vector<std::uint32_t> into(n + 1);
  std::iota(into.begin(), into.end(), 0u);
  const std::vector<bool> ends = vertexEnds(graph);
  const std::vector<bool> split =
    mergeSplitCorners(graph, ends, max_split_distance, into);
  for (std::uint32_t v = 1; v <= n; ++v) {
    if (graph.node(v).feature_class != FeatureClass::kVertex || ends[v] || split[v])
      continue;
    const std::vector<std::uint32_t> edges = graph.neighbours(v, FeatureClass::kEdge);
    if (edges.empty())
      continue;
    into[v] = edges.size() == 1 ? edges[0] : faceOfAllEdges(graph, edges);
    if (into[v] == 0)
      into[v] = cornerOfEdges(graph, ends, edges);
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
  // Pieces of a broken rim: edges without a corner kept (their vertices, if any,
  // stray; a piece of a split corner is that corner) between the same two faces are
  // one edge (the smallest label).
  std::map<std::vector<std::uint32_t>, std::uint32_t> rim_of_pair;
  for (std::uint32_t e = 1; e <= n; ++e) {
    if (graph.node(e).feature_class != FeatureClass::kEdge)
      continue;
    const std::vector<std::uint32_t> vertices =
      graph.neighbours(e, FeatureClass::kVertex);
    if (std::any_of(vertices.begin(), vertices.end(),
                    [&](std::uint32_t v) { return into[v] == v || split[v]; }))
      continue;
    const std::vector<std::uint32_t> faces = graph.facesOfEdge(e);
    if (faces.size() != 2)
      continue;
    const auto [it, first] = rim_of_pair.emplace(faces, e);
    if (!first)
      into[e] = it->second;
  }
  // a stray vertex or speck that joined a corner piece or a piece of crease between
  // two, or a piece of a broken rim (corners never join anything: no cycle)
  for (std::uint32_t r = 1; r <= n; ++r)
    while (into[into[r]] != into[r])
      into[r] = into[into[r]];
  return into;
}

std::vector<std::uint32_t>
cornerSpurMerge(const TopologyGraph& graph, std::uint64_t min_points)
{
  const std::size_t n = graph.size();
  std::vector<std::uint32_t> into(n + 1);
  std::iota(into.begin(), into.end(), 0u);
  for (std::uint32_t e = 1; e <= n; ++e) {
    const GraphNode& node = graph.node(e);
    if (node.feature_class != FeatureClass::kEdge || std::isfinite(node.crease_angle) ||
        node.points >= min_points)
      continue;
    const std::vector<std::uint32_t> vertices = graph.verticesOfEdge(e);
    if (vertices.size() == 1)
      into[e] = vertices[0]; // vertices join nothing here: no chain
  }
  return into;
}

std::vector<std::uint32_t>
deadEndCornerMerge(const TopologyGraph& graph)
{
  const std::size_t n = graph.size();
  std::vector<std::uint32_t> into(n + 1);
  std::iota(into.begin(), into.end(), 0u);
  for (std::uint32_t v = 1; v <= n; ++v) {
    if (graph.node(v).feature_class != FeatureClass::kVertex)
      continue;
    const std::vector<std::uint32_t> edges = graph.neighbours(v, FeatureClass::kEdge);
    if (edges.size() != 1)
      continue;
    const std::uint32_t e = edges[0];
    const std::vector<std::uint32_t> faces = graph.facesOfEdge(e);
    const std::vector<std::uint32_t> ends = graph.verticesOfEdge(e);
    const auto isCorner = [&](std::uint32_t w) {
      return graph.neighbours(w, FeatureClass::kEdge).size() >= 2;
    };
    // the edge's other end a corner: one dead end, not a crease between two such
    // (both face lists ascending, as TopologyGraph::neighbours promises)
    if (faces.size() != 2 || graph.neighbours(v, FeatureClass::kFace) != faces ||
        std::none_of(ends.begin(), ends.end(), isCorner))
      continue;
    // the corner of both faces, not on the edge
    const std::vector<std::uint32_t> a =
      graph.neighbours(faces[0], FeatureClass::kVertex);
    const std::vector<std::uint32_t> b =
      graph.neighbours(faces[1], FeatureClass::kVertex);
    std::vector<std::uint32_t> both;
    std::set_intersection(a.begin(), a.end(), b.begin(), b.end(),
                          std::back_inserter(both));
    const bool corner = std::any_of(both.begin(), both.end(), [&](std::uint32_t w) {
      return std::find(ends.begin(), ends.end(), w) == ends.end() && isCorner(w);
    });
    if (corner)
      into[v] = e; // edges join nothing here: no chain
  }
  return into;
}

} // namespace visfeat
