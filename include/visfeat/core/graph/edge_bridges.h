#pragma once

#include <visfeat/core/band/voxel_band.h>
#include <visfeat/core/graph/topology_graph.h>

#include <cstdint>
#include <vector>

namespace visfeat {

/** \brief Band cells that join an edge region that stops short of its corner to that
 * corner's region.
 *
 * On sparse clouds (4 cells a point spacing) the ridge that makes an edge core can end
 * 10-20 cells before a corner whose region formed from the other edges: the faces'
 * watershed fills the gap, the edge keeps one corner, and the corner lacks that edge
 * (measured on the generated models at 10,000 points, seeds 41-46: 7 of the 14 runs
 * that missed the true topology; the U prism seed 33 stops 12 cells short).
 */
struct EdgeBridge
{
  /** \brief The edge label and the vertex label it is bridged to. */
  std::uint32_t edge = 0, vertex = 0;
  /** \brief The face cells between them: a shortest 6-connected path, in order from
   * the edge's end. */
  std::vector<CellId> cells;
};

/** \brief A straight edge region has a spread across its line (standard deviation of
 * its cells, the square root of the scatter's second eigenvalue) of at most this
 * fraction of its spread along it plus kStraightEdgeWidth: 0.1. A straight edge 2-3
 * cells wide spreads 0.5-0.9 cells across at any length; a quarter circle of radius
 * 50 cells 5 cells across, 20 along. */
constexpr double kStraightEdgeSpread = 0.1;

/** \brief See kStraightEdgeSpread: 1 cell, the spread across of an edge region up to
 * 3 cells wide. */
constexpr double kStraightEdgeWidth = 1.0;

/** \brief The corner ahead of a free end lies within this distance of the edge's
 * line, cells, plus a quarter of its distance along the line: 3. */
constexpr double kBridgeLateralCells = 3.0;

/** \brief A corner off the edge's line is bridged to when it lies within this share
 * of max_reach of the edge's free end and is the only vertex region there joined to
 * both of the edge's faces: 0.5. On sparse clouds a corner's region may form a few
 * point spacings beside the true corner (measured on the generated models at 10,000
 * points, seeds 41-48, 4 cells a spacing: of the 6 edges left with one corner, 4 had
 * their corner 11-13 cells beside their line at 6-10 cells ahead and one 5 beside at 5
 * ahead, 7-16 cells from their end, each the only vertex of both faces within 24
 * cells; the sixth's lay 27 cells away, a corner misplaced between two). */
constexpr double kBridgeOffLineShare = 0.5;

/** \brief Bridges for the edges that stop short of their corner.
 *
 * An edge region qualifies when it is straight (kStraightEdgeSpread), joined to one
 * vertex region u and to two face regions f1, f2 (graph arcs), and has at least 8
 * cells. Its free end is the end of its cells along its line away from u. The corner
 * is the vertex region v != u joined to both f1 and f2 whose centroid lies ahead of
 * the free end, at most max_reach cells along the line and within
 * kBridgeLateralCells + a quarter of that of it (the nearest along the line when
 * several do); when none does, the one such v ahead of the free end whose centroid
 * lies within kBridgeOffLineShare x max_reach of it, if there is exactly one. The
 * bridge is the shortest path of 6-steps from the edge's end cells (within 2 cells of
 * the end along the line) to a cell of v through the cells of face regions only (f1,
 * f2, or a third face of v that leaked around the corner: U prism, seed 33), never
 * through an edge or vertex, at most sqrt(3) (max_reach + 3) + 3 steps, or to the
 * first face cell within reach_steps 6-steps of a cell of v (through any band cells):
 * the graph joins regions that close (TopologyGraphParameters::dilation_radius), and
 * a small corner region at a sharp tip may touch only its other edges (a
 * tetrahedron's 2-cell tip at 10,000 points, seed 52: faces 2 and 5 steps away); none
 * when there is no such path.
 *
 * \param[in] cell_labels per band cell, its region label (0: none)
 * \param[in] graph the regions' graph (labels 1..graph.size())
 * \param[in] max_reach cells (e.g. 2 x SegmentationParameters::vertex_reach)
 * \param[in] reach_steps 6-steps (e.g. the graph's dilation_radius; 0: the path
 *            reaches a cell of v itself)
 * \return the bridges, by ascending edge label, at most one per edge.
 * \throws visfeat::Error when cell_labels does not have one label per band cell or
 *         reach_steps is negative. */
std::vector<EdgeBridge> bridgesToCorners(const VoxelBand& band,
                                         const std::vector<std::uint32_t>& cell_labels,
                                         const TopologyGraph& graph,
                                         double max_reach,
                                         int reach_steps = 0);

} // namespace visfeat
