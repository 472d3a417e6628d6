#pragma once

#include <visfeat/core/band/voxel_band.h>
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
 * Where several such faces qualify (slivers on both sides of the edge: then the faces
 * of both ends are the two the crease divides), the graph cannot tell which one the
 * sliver was cut from, and it stays; the overload with the band says which.
 *
 * \return per label (index 0 unused, size graph.size() + 1), the label it joins. */
std::vector<std::uint32_t> openFaceMerge(const TopologyGraph& graph);

/** \brief openFaceMerge(), and where several faces qualify, the one the sliver shares
 * the most boundary with (6-neighbour pairs of cells; the graph joins no two faces),
 * when no other qualifying face shares as much. Measured on the public icosahedron
 * (lapy_icosahedron.off) sampled to 500,000 points, in its file's orientation, at 912
 * cells (the automatic choice): its creases at the extremes in y run in a grid plane,
 * where the band's top layer is a digital plane whose cells see each other along it
 * and peak at 15 rings (a narrow face's core); on one such crease the segmentation made
 * a strip face of 2,891-2,981 cells (4-5 cells wide, as long as the crease) on each
 * side of the crease's edge, each touching its edge, the edge's two corners, and the
 * face it was cut from (743-756 cell pairs; 0-14 with the other). 12/29/22 for
 * 12/30/20.
 * \param[in] band the band the graph was built from
 * \param[in] cell_labels per band cell, its region label (the graph's labels)
 * \throws visfeat::Error when cell_labels has another size than the band */
std::vector<std::uint32_t> openFaceMerge(const TopologyGraph& graph,
                                         const VoxelBand& band,
                                         const std::vector<std::uint32_t>& cell_labels);

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
