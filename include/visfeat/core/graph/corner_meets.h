#pragma once

#include <visfeat/core/graph/topology_graph.h>

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace visfeat {

/** \brief Where a corner's creases meet: the parameters (all distances in cells). */
struct CornerMeetParameters
{
  /** \brief An edge's points within this distance of its vertex's point centroid fit
   * the edge's line there. Default kDefaultLineRadius. */
  double line_radius = kDefaultLineRadius;
  /** \brief The point a corner claims lies within this distance of the meet (the
   * estimator passes kCornerClaimDistances x point_feature_distance, as for the
   * corners that hold no point). */
  double max_point_distance = 2.0;

  /** \brief 48 cells, 3 x min_radius: far enough along each crease to leave the few
   * spacings around a sharp tip where the segmentation fuses the creases (the
   * tetrahedron at 10,000 points, seed 31: its tip's edge region runs 21 cells past
   * the vertex region), near enough that the short straight creases of the generated
   * models stay straight within it. On the three corners misplaced down a tip (see
   * cornerMeets), 64 cells moved their meets by under 0.5 cells (32 cells: the
   * tetrahedron's by 0.2). */
  static constexpr double kDefaultLineRadius = 48.0;
  /** \brief Fewer points of an edge within line_radius give no line. */
  static constexpr std::size_t kMinLinePoints = 5;
  /** \brief The meet of the lines (the point nearest all of them, least squares) is
   * well posed when the smallest eigenvalue of sum(I - d d^T) over the lines'
   * directions d reaches this: for two lines it is 1 - |cos| of their angle, so 0.25
   * asks for two lines 41 degrees apart or more (parallel ones have no meet). */
  static constexpr double kMinConditioning = 0.25;
};

/** \brief A corner's meet and the point nearest it. */
struct CornerMeet
{
  std::uint32_t vertex = 0;     ///< the vertex region (graph id)
  Eigen::Vector3d meet;         ///< where its edges' lines meet, cell units
  std::size_t point = kNoPoint; ///< the point nearest the meet, or kNoPoint
  static constexpr std::size_t kNoPoint = static_cast<std::size_t>(-1);
};

/** \brief Where each corner's creases meet, and the point nearest that place.
 *
 * The segmentation places a vertex region where the creases' regions come within
 * reach of each other; at a sharp tip (a tetrahedron's, a wedge's) the faces narrow
 * below the cores' width for several point spacings and one edge region runs on to
 * the tip, so the vertex region lies that far down the spike (the tetrahedron at
 * 10,000 points, seed 31: 21 cells; a triangular prism, seed 48: 24 cells; the
 * icosahedron, seed 56: 27 cells, each farther than the 3 point spacings within which
 * the evaluation wants a corner). The creases themselves stay straight up to the tip:
 * for each vertex region with two edge regions or more, a line (principal axis) is
 * fitted to each edge's points within line_radius of the vertex's point centroid, and
 * the meet is the point nearest all lines in the least-squares sense. Measured on the
 * seven generated models at 10,000 points (the tetrahedron seed 31, the prism seeds
 * 48 and 49, the U prism seeds 41 and 55, the icosahedron seed 56, the cube seed 41;
 * 66 corners): the meet lay 0.7-6.5 cells from the true corner (median 1.9) where the
 * vertex regions' point centroids lay 1.1-27 cells from it (median 3.3).
 *
 * A meet is given for a vertex when at least two lines have kMinLinePoints points,
 * they are well posed (kMinConditioning), and the meet lies within line_radius of the
 * vertex's centroid. Its point is the nearest within max_point_distance whose label is
 * the vertex or one of its neighbours in the graph (edges and faces), the first by
 * index on a tie; kNoPoint when there is none.
 *
 * \param[in] graph the topology graph of the labels
 * \param[in] points the points in cell units (GridSpec::toCellUnits)
 * \param[in] labels per point its region (graph id), 0 for none; same size as points
 * \return one entry per vertex region with a meet, by ascending vertex id.
 * \throws visfeat::Error when the sizes differ or a distance is not positive. */
std::vector<CornerMeet> cornerMeets(const TopologyGraph& graph,
                                    const std::vector<Eigen::Vector3d>& points,
                                    const std::vector<std::uint32_t>& labels,
                                    const CornerMeetParameters& parameters);

} // namespace visfeat
