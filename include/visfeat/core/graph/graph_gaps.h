#pragma once

#include <visfeat/core/graph/topology_graph.h>

#include <cstddef>
#include <string>

namespace visfeat {

/** \brief Where a topology graph departs from that of a closed B-rep (every edge
 * between two faces and ending at a corner at each end or closing on itself, every
 * region touching another).
 *
 * On the clouds of a closed part these gaps mean features the segmentation did not
 * separate (closer than about 2 min_radius cells): an edge that stops short of its
 * corner, a corner that was never made, a narrow face swallowed by its neighbours. A
 * scan's border (an open surface) leaves edges without their outer corner too.
 *
 * An edge with one face on both sides is a crease fading into its face (the
 * segmentation keeps such an edge only when it bends like one, kFadingCreaseVariation
 * in flat_cores.h: a fin sinking into a face, a crease turning shallow towards one end;
 * the public fandisk has two): its faded end has no corner. It is counted apart
 * (one_face) and is no gap. An edge with one face and a corner at both ends has no
 * faded end: the face on its other side merged into that one (the generated thin plate
 * with a hole at 510 cells, rotation 1: four such edges along its rims, 5/6/4 for
 * 8/14/7, where the graph looked closed). It does not lie between two faces.
 *
 * Corners closer than the separation merge into one, and the short edges between them
 * vanish: the graph stays closed, but the merged corner ends the edges of both, at
 * least 4, and two of them leave it side by side (merged_corners): the generated
 * parallel creases at 512 (corners 20 cells apart: two corners of 5 edges, 10.8 and
 * 13.5 degrees between two of them; 10/17/9 for 14/21/9), the stepped block at 512
 * (rotation 23: two of 4 edges, 13 degrees; 14/22/10 for 16/24/10), the chamfered box
 * at 1024 (corners of 4 edges, 4.6-5.7 degrees; 14/22/10 for 16/24/10). */
struct GraphGaps
{
  std::size_t edges = 0;          // edge regions in all
  std::size_t one_corner = 0;     // edges touching exactly one vertex (one_face aside)
  std::size_t no_corner = 0;      // edges touching none (a closed loop needs none)
  std::size_t not_two_faces = 0;  // edges touching no face, more than two, or one face
                                  // with a corner at both ends
  std::size_t one_face = 0;       // edges touching one face and at most one corner:
                                  // creases fading into it
  std::size_t lone_regions = 0;   // regions touching no other (with other regions)
  std::size_t merged_corners = 0; // vertices of >= 4 edges, two of them leaving within
                                  // kMergedCornerAngle of each other

  /** \brief Whether a gap that a closed part never has is there: an edge with one
   * corner or not between two faces, a lone region or a merged corner (edges without
   * any corner are
   * left out: a circular rim is one; so are creases fading into their face). */
  bool any() const
  {
    return one_corner > 0 || not_two_faces > 0 || lone_regions > 0 ||
           merged_corners > 0;
  }

  /** \brief One line for the user, e.g. "11 of 28 edges end at a corner on one side
   * only and 3 more at neither, 2 edges do not lie between two faces, 1 region touches
   * no other (2 more edges have one face on both sides: creases fading into it)";
   * empty when !any(). */
  std::string describe() const;
};

/** \brief Two edges that leave a corner of at least kMergedCornerEdges edges within
 * this angle of each other (degrees; directions from the corner's centroid to the
 * edges' centroids) say that corners merged. Measured 2026-12-07: merged corners
 * 4.6-19.6 degrees (see GraphGaps); on the generated models at 256 and the
 * small-feature models where their corners are all found, corners of 3 edges down to 31
 * degrees (the chamfered box) and the icosahedron's corners of 5 edges 58-60 degrees.
 */
constexpr double kMergedCornerAngle = 25.0;

/** \brief Fewest edges at a merged corner: two corners of 3 edges merged end 4. */
constexpr std::size_t kMergedCornerEdges = 4;

/** \brief The gaps of a graph (GraphGaps). */
GraphGaps findGraphGaps(const TopologyGraph& graph);

} // namespace visfeat
