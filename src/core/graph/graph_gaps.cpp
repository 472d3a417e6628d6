#include <visfeat/core/graph/graph_gaps.h>

#include <sstream>
#include <vector>

namespace visfeat {

GraphGaps
findGraphGaps(const TopologyGraph& graph)
{
  GraphGaps gaps;
  for (std::uint32_t id = 1; id <= graph.size(); ++id) {
    if (graph.size() > 1 && graph.neighbours(id).empty())
      ++gaps.lone_regions;
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
  if (lone_regions > 0)
    out << sep << lone_regions
        << (lone_regions == 1 ? " region touches" : " regions touch") << " no other";
  if (one_face > 0)
    out << " (" << one_face << " more " << (one_face == 1 ? "edge has" : "edges have")
        << " one face on both sides: " << (one_face == 1 ? "a crease" : "creases")
        << " fading into it)";
  return out.str();
}

} // namespace visfeat
