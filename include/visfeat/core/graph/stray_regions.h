#pragma once

#include <visfeat/core/graph/topology_graph.h>

#include <cstdint>
#include <limits>
#include <vector>

namespace visfeat {

/** \brief Regions that break the incidences of a B-rep, and the regions they join:
 * vertices that end none of their edges, corners split in two, face specks at a
 * corner, and pieces of a broken rim.
 *
 * **Stray vertices.** A B-rep vertex ends at least one of the edges it is joined to
 * (all of them at a corner; the ending crease where one crease ends on another, a T).
 * Vertex region v does not end edge region e when
 * - e is joined to more than two vertex regions and v is not one of its two ends (an
 *   edge has two ends, and the segmentation splits edges where creases meet): the two
 *   whose centroids lie farthest apart, or among pairs nearly as far apart (within 5%)
 *   the one whose smaller region is largest; or
 * - v is the only vertex region of e and e the only edge region of v: a corner joins
 *   two edges or more, and an edge with a single vertex is a closed loop (a hole's
 *   rim), which has none.
 * A vertex region that ends none of its edges (and has at least one) is a blob beside
 * a crease, a broken tip of a face's core near a corner, or a piece of a rim: it joins
 * its edge when it has one; with more, the one face joined to all of them (whose core
 * tip broke off), else the one vertex that most of them (two or more) are joined to
 * (the corner it lies beside); it is kept when there is none.
 *
 * **Split corners.** Two vertex regions that each end an edge, joined to two or more
 * of the same edge regions, one of which goes on to a third vertex, are one corner
 * split in two (two
 * distinct B-rep vertices share at most one edge; two that share two would be the
 * ends of a lens, and then no shared edge goes on). Measured on sparse clouds (the
 * icosahedron at 10,000 points, 4 cells a point spacing, seeds 31 and 32): a corner
 * of 14-24 cells 8-19 cells from the true one, a piece of 2-14 cells beside it, and
 * a crease piece of 34-50 cells between them. The smaller joins the larger, and so
 * does every shared edge region joined to no other vertex (the piece between them).
 * Such regions are not tested as stray vertices. Only regions whose centroids lie
 * within max_split_distance are pieces of one corner: where creases broke into
 * several edge regions, two corners a whole edge apart shared two of them (the public
 * icosahedron in its file's orientation at 400 cells: three pairs of corners 200
 * cells apart merged, 9 vertices for 12).
 *
 * **Corner specks.** A face region joined to no edge and to one vertex region, smaller
 * (in cells) than every face of that vertex's edges, is a speck at the corner's tip,
 * not a face (a B-rep face is bounded by edges, or by none at all on a closed smooth
 * surface): it joins the vertex (or what the vertex joins).
 *
 * **Broken rims.** Edge regions without a corner (no vertex region, or only stray
 * ones; a piece of a split corner counts as its corner) joined to the same two faces
 * are pieces of one closed crease broken where the band lost its core (a hole's rim:
 * the box with hole at 10,000 points, seed 43, a rim of 781 and 176 cells): they join
 * the smallest label. Two faces that meet along two closed curves (surfaces crossing
 * twice, rare in machined parts) would have their two rims made one edge too.
 *
 * Measured on the generated models at 20,000 points (the band filled between the
 * points at 256 cells), rotations 4000-4020: 14 of 147 runs had such regions (the
 * icosahedron 11 of 21: 1-3 stray vertices; a tetrahedron a speck); every one was an
 * extra region and no true corner or face was one.
 *
 * \param[in] max_split_distance the farthest apart (world units, between the regions'
 *            centroids) two vertex regions are taken for one split corner; the
 *            estimator passes splitCornerDistance(): 2 vertex_reach cells
 * \return per label (index 0 unused, size graph.size() + 1), the label it joins:
 *         itself when kept; for FeatureSegmentation::mergeRegions.
 */
std::vector<std::uint32_t>
strayRegionMerge(const TopologyGraph& graph,
                 double max_split_distance = std::numeric_limits<double>::infinity());

/** \brief The split-corner rule of strayRegionMerge alone, for graphs that gained
 * corners since (contact creases' corners beside the corner their crease runs to).
 * \param[in] max_split_distance as strayRegionMerge's (world units, the centroids')
 * \return per label (index 0 unused, size graph.size() + 1), the label it joins. */
std::vector<std::uint32_t>
splitCornerMerge(const TopologyGraph& graph,
                 double max_split_distance = std::numeric_limits<double>::infinity());

/** \brief Corner spurs: edge regions that are a few cells of ridge at a corner.
 *
 * An edge region joined to exactly one vertex region, whose turn was not measured
 * (GraphNode::crease_angle NaN: no sample of it found two faces with enough points)
 * and which holds fewer than min_points points, is not a crease: it joins its vertex.
 * A crease between two corners holds points along its whole length and its turn is
 * measured; a closed rim has no vertex. Measured on sparse clouds (the icosahedron at
 * 10,000 points, 4 cells a point spacing, seeds 41-56): 3 of 16 runs had one, 42-57
 * cells with 0-2 points, at a 5-valent corner between two faces that meet only there,
 * each the one extra edge of its run; no other edge of the seven generated models
 * (seeds 41-56, 112 runs) had an unmeasured turn and a single corner.
 *
 * \param[in] min_points fewest points of an edge that stays (e.g.
 *            CreaseAngleParameters::kMinSidePoints, what one side of a sample needs)
 * \return per label (index 0 unused, size graph.size() + 1), the label it joins. */
std::vector<std::uint32_t> cornerSpurMerge(const TopologyGraph& graph,
                                           std::uint64_t min_points);

/** \brief Dead-end corners: vertex regions at the end of one edge only.
 *
 * A vertex region joined to a single edge region and to no face but that edge's two
 * is no B-rep corner (a corner joins two edges or more; a crease fading into its face
 * or ending at an open scan's border has no vertex at that end): the edge stopped
 * short of its corner and the segmentation drew one at its end. Where the edge's other
 * end is a corner (two edges or more) and another such corner, not on the edge, is
 * joined to both faces (the corner the edge runs to), the dead end joins its edge,
 * whose free end bridgesToCorners() then takes to that corner. Measured on sparse
 * clouds (the icosahedron at 10,000 points, 4 cells a point spacing, seed 31): a
 * 26-cell region 30 cells from its true corner, whose region lay 11 cells from it.
 *
 * \return per label (index 0 unused, size graph.size() + 1), the label it joins. */
std::vector<std::uint32_t> deadEndCornerMerge(const TopologyGraph& graph);

} // namespace visfeat
