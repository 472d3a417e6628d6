#include <visfeat/core/graph/graph_gaps.h>

#include "../common/angles.h"

#include <sstream>
#include <vector>

namespace visfeat {

namespace {

/** Whether two of the corner's edges leave it within kMergedCornerAngle of each other
 * (the corner has at least kMergedCornerEdges). */
bool
isMergedCorner(const TopologyGraph& graph, std::uint32_t vertex)
{
  const std::vector<std::uint32_t> edges =
    graph.neighbours(vertex, FeatureClass::kEdge);
  if (edges.size() < kMergedCornerEdges)
    return false;
  const Eigen::Vector3d& at = graph.node(vertex).centroid;
  std::vector<Eigen::Vector3d> directions;
  for (const std::uint32_t e : edges) {
    const Eigen::Vector3d d = graph.node(e).centroid - at;
    if (d.allFinite() && d.norm() > 0.0)
      directions.push_back(d.normalized());
  }
  const double cos_limit = detail::cosineOfDegrees(kMergedCornerAngle);
  for (std::size_t i = 0; i < directions.size(); ++i)
    for (std::size_t j = i + 1; j < directions.size(); ++j)
      if (directions[i].dot(directions[j]) > cos_limit)
        return true;
  return false;
}

} // namespace

GraphGaps
findGraphGaps(const TopologyGraph& graph)
{
  GraphGaps gaps;
  for (std::uint32_t id = 1; id <= graph.size(); ++id) {
    if (graph.size() > 1 && graph.neighbours(id).empty())
      ++gaps.lone_regions;
    if (graph.node(id).feature_class == FeatureClass::kVertex &&
        isMergedCorner(graph, id))
      ++gaps.merged_corners;
    if (graph.node(id).feature_class != FeatureClass::kEdge)
      continue;
    ++gaps.edges;
    const std::size_t faces = graph.facesOfEdge(id).size();
    const std::size_t corners = graph.verticesOfEdge(id).size();
    if (faces == 1 && corners < 2) { // a crease fading into its face: no corner where
      ++gaps.one_face;               // it fades
      continue;
    }
    gaps.one_corner += corners == 1 ? 1 : 0;
    gaps.no_corner += corners == 0 ? 1 : 0;
    gaps.not_two_faces += faces != 2 ? 1 : 0;
  }
  return gaps;
}

std::string
GraphGaps::describe() const
{
  if (!any())
    return "";
  std::ostringstream out;
  const char* sep = "";
  if (one_corner > 0) {
    out << one_corner << " of " << edges
        << (one_corner == 1 ? " edges ends" : " edges end")
        << " at a corner on one side only";
    if (no_corner > 0)
      out << " and " << no_corner << " more at neither";
    sep = ", ";
  }
  if (not_two_faces > 0) {
    out << sep << not_two_faces << (not_two_faces == 1 ? " edge does" : " edges do")
        << " not lie between two faces";
    sep = ", ";
  }
  if (lone_regions > 0) {
    out << sep << lone_regions
        << (lone_regions == 1 ? " region touches" : " regions touch") << " no other";
    sep = ", ";
  }
  if (merged_corners > 0)
    out << sep << merged_corners
        << (merged_corners == 1 ? " corner ends" : " corners end") << " "
        << kMergedCornerEdges << " or more edges, two leaving within "
        << kMergedCornerAngle << " degrees of each other (corners merged into one)";
  if (one_face > 0)
    out << " (" << one_face << " more " << (one_face == 1 ? "edge has" : "edges have")
        << " one face on both sides: " << (one_face == 1 ? "a crease" : "creases")
        << " fading into it)";
  return out.str();
}

} // namespace visfeat
