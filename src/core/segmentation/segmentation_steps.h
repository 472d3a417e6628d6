#pragma once

// Internal to the segmentation (not installed): the steps of
// FeatureSegmentation::compute() in the default mode, in the order it runs them (see
// the class documentation in feature_segmentation.h). Each works on the shared state
// of segmentation_state.h; each group lives in the .cpp named above it.

#include "segmentation_state.h"

namespace visfeat {
namespace segmentation {

// --- core_classification.cpp: step 2 and 3 ------------------------------------------

/** \brief Step 2: every band cell joins a core by the watershed on the radius
 * (growRegions from the seeds); also the label contacts of the result and each core's
 * seed cells. */
void growCoresIntoRegions(SegmentationState& state);

/** \brief Step 3, by faces: a non-face region touching two or more face regions is an
 * edge between its two main faces (most shared boundary; `signature`); one touching at
 * most one face is a speck (class kNone, `speck_into` = its neighbour with the most
 * shared boundary), unless findVertices() claims it, or it touches one face and is a
 * crease fading into it (an edge core of more than kFadingCreaseMinRadii min_radius
 * cells across which the band turns, kFadingCreaseVariation): an edge with that face on
 * both sides (signature (f, f)). Faces stay faces. */
void classifyByFaces(SegmentationState& state);

/** \brief Step 3, the vertex test (the paper's geodesic dilation): a small core (<=
 * vertex_max_cells, not a face) is a vertex candidate when, within vertex_reach steps
 * through the band, it meets edges of two different face pairs (its own included), or
 * it or what it meets touches three faces; but never when pieces of its own edge lie
 * on opposite sides of it (insideAnEdge). An accepted candidate absorbs the small cores
 * it reaches; all become vertices, and candidates within reach of each other are one
 * set (one corner). Also finds the edges' joining reach (edge_reach, read by
 * joinEdgeFragments()): both dilations run core by core on parameters.threads. */
void findVertices(SegmentationState& state);

/** \brief Step 3, specks: each speck joins its neighbour's set; sets left of specks
 * only go to their classified neighbour with the most shared boundary, until none
 * touches one. From here on classes are read at set roots only. */
void mergeSpecks(SegmentationState& state);

// --- fragment_joining.cpp: step 4 ---------------------------------------------------

/** \brief Step 4, fragments of one edge: edge sets with the same two faces join when
 * they touch, when their cores are within join_distance cells (and sqrt(3) times as
 * many 6-steps through the band), when they touch the same vertex, or, when nothing
 * else joins, when both are straight and on one line (any gap; join_distance 0 turns
 * this off too). Touching vertex sets join. Repeats until nothing changes. Runs after
 * findVertices() (its edge_reach). */
void joinEdgeFragments(SegmentationState& state);

/** \brief How far the joining searches the band from an edge's cores: sqrt(3) x
 * join_distance 6-steps, rounded up (a path of 6-steps is up to sqrt(3) times longer
 * than the straight gap it spans). */
std::uint32_t joinSteps(const SegmentationParameters& parameters);

/** \brief Step 4, corners: two corners share at most one edge, so vertex candidates
 * whose reached edges share two or more are one vertex. Repeats until nothing changes.
 */
void joinCornersSharingEdges(SegmentationState& state);

// --- feature_segmentation.cpp -------------------------------------------------------

/** \brief Every labelled cell takes its set's root; without complete regions, cells
 * outside the cores are dropped (label 0). */
void applyUnion(SegmentationState& state);

// --- vertex_edge_pairs.cpp: step 5, which vertex ends which edge ---------------------

/** \brief The vertex-edge pairs: regions that touch, and each end of an edge's cores
 * (its farthest pair of core cells) with the vertex whose core cell is nearest, within
 * vertex_reach cells; failing that, for a straight edge, the vertex ahead on its line
 * (vertexAhead). Fills `pairs` and `ends`. */
void findVertexEdgePairs(ThinningState& state);

/** \brief Two corners merged into one vertex (noise can join the candidates at both
 * ends of a short edge): an edge whose two ends, more than kMergedCornerSpan *
 * vertex_reach apart, both link to the same vertex. The vertex is split across the
 * middle of that edge; the far half takes the smallest label of its own cores.
 * \return whether a vertex was split (the pairs must then be found again). */
bool splitMergedCorners(ThinningState& state);

// --- corner_drawing.cpp: step 5, corners from edge lines -----------------------------

/** \brief A corner without a region: where the free ends (linked to no vertex) of
 * kMinFreeCornerEdges or more straight edges lie within vertex_reach of each other
 * and of their lines' meeting point, a new vertex (a label after the cores') takes the
 * band cell nearest to that point, and those ends link to it; drawCorners then draws
 * them to it. */
void cornersAtFreeEnds(ThinningState& state);

/** \brief On a straight edge (>= kMinLineCells core cells, narrow), the middle of the
 * skeleton is its line: each core cell's centre is its projection on the line. */
void centreStraightEdges(ThinningState& state);

/** \brief A vertex with two or more straight edges becomes the point nearest to their
 * lines (least squares, if they are not nearly parallel and it lies within
 * vertex_reach of the vertex's cores); each of those edges is drawn as a segment from
 * its core's end to that corner (`drawn`), and the vertex's own cores leave the
 * skeleton. */
void drawCorners(ThinningState& state);

// --- ridge_paths.cpp ----------------------------------------------------------------

/** \brief For each vertex-edge pair not drawn: the cheapest path from the vertex's
 * cores to the edge's skeleton through the two regions and the faces (never through
 * other features), a step costing 1 + (max_radius - radius), so it follows the ridge.
 * Its cells join the skeleton and the edge (the vertex's keep their label). */
void traceRidgePaths(ThinningState& state);

// --- skeleton_bridging.cpp ----------------------------------------------------------

/** \brief Gaps in an edge's skeleton: each end of a 26-connected piece is joined by a
 * straight segment to the nearest skeleton cell of another piece of the same edge
 * within join_distance cells. */
void bridgeSkeletonGaps(ThinningState& state);

// --- skeleton_width.cpp -------------------------------------------------------------

/** \brief Edge and vertex regions keep the cells within feature_width 6-steps of
 * their skeleton (through their own region); the rest go to the nearest face region
 * (breadth-first from the faces), or keep their label where no face reaches them. */
void cutToSkeletonWidth(ThinningState& state);

/** \brief A vertex-edge pair (`pairs`) whose regions no longer touch after the cut
 * is joined again: the cells of the shortest band path (at most kMaxRejoinSteps
 * 6-steps, through no other feature) from the edge to the vertex join the edge. */
void rejoinCutPairs(ThinningState& state);

// --- skeleton_centres.cpp -----------------------------------------------------------

/** \brief For each skeleton cell without a centre: the mean of its region's skeleton
 * cells within kSkeletonCentreRadius cells, and the main axis of those cells as its
 * tangent where they are elongated (kElongation). */
void middleOfSkeleton(ThinningState& state);

} // namespace segmentation
} // namespace visfeat
