#pragma once

#include <visfeat/core/graph/topology_graph.h>

#include <cstdint>
#include <vector>

namespace visfeat {

/** \brief Open faces: face regions bounded by one edge that is no loop.
 *
 * A B-rep face is bounded by closed loops of edges (or by none on a closed smooth
 * surface). A face region whose only edge region runs between two distinct vertex
 * regions, and which touches no other vertex, has an open boundary: it is a sliver of
 * a larger face that the segmentation cut off along that edge, where a sharp tip
 * narrows the faces below the cores' width. It joins the one face, other than the
 * edge's two, joined to both of the edge's vertices (the face it was cut from), when
 * that face is larger; otherwise it stays. Measured on sparse clouds (the tetrahedron
 * at 10,000 points, 4 cells a point spacing, seed 32): a 419-cell sliver with 3 points
 * beside a 6-cell tip corner, along a 146-cell piece of crease that ended at a 46-cell
 * vertex region, where the true face has 54,000 cells.
 *
 * \return per label (index 0 unused, size graph.size() + 1), the label it joins. */
std::vector<std::uint32_t> openFaceMerge(const TopologyGraph& graph);

/** \brief Vertices inside one crease: a vertex region joined to exactly two edge
 * regions that run between the same two faces, to no other face, and on to two
 * different vertex regions, is a point along one crease (a B-rep vertex ends edges
 * where three faces or more meet, or where a crease ends); it and the smaller edge
 * join the larger edge (by cells). Two edges between the same two faces that meet at
 * both ends (a lens) keep their corners. Such a vertex is what an open face leaves
 * (openFaceMerge): the crease it was cut along ended at a vertex of the cut.
 *
 * \return per label (index 0 unused, size graph.size() + 1), the label it joins. */
std::vector<std::uint32_t> creaseInnerVertexMerge(const TopologyGraph& graph);

} // namespace visfeat
