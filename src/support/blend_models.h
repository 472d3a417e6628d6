#pragma once

// Models with blends and shallow facets (issue 14, "sharp versus smooth"): a triangle
// mesh of the surface and the truth a CAD user expects, which is not the mesh's own
// edges (a fillet or a tessellated cylinder is a face, not a row of creases).

#include <support/synthetic_shapes.h>

#include <string>
#include <vector>

namespace visfeat {
namespace synthetic {

/** \brief A model given by a triangle mesh and its expected topology.
 *
 * The truth counts regions and arcs only (no per-point geometry): vertices (corners),
 * curves (creases, a closed loop being one curve without corners), faces, and the arcs
 * of the topology graph (vertex-edge + edge-face + vertex-face). */
struct BlendModel
{
  std::string name;
  TriangleMesh mesh;
  int vertices = 0;
  int curves = 0;
  int faces = 0;
  int arcs = 0;
  /** \brief The turn of every true crease (degrees; 90 on both models). */
  double crease_turn = 90.0;
  /** \brief The largest turn between two neighbouring triangles that is not a crease
   * (degrees): the fillet's tessellation step, or the cylinder's facet step. */
  double blend_step = 0.0;
  /** \brief The truth in words. */
  std::string truth;
};

/** \brief "filleted_box": a box 40 x 30 x 20 whose four vertical edges are rounded
 * with radius 3 (each quarter cylinder tessellated into kFilletSegments facets, 3.75
 * degrees apart: a smooth blend at any resolution up to ~2000). Truth 0/2/3: the top
 * and bottom rims are the creases (closed loops, 90 degrees all round, no corner); the
 * faces are the top, the bottom and the side wall, four planes and four fillets being
 * one smooth face; arcs 4 (each rim to the top or bottom and to the wall). At 256 the
 * fillets have a radius of 19.2 cells.
 *
 * "faceted_boss": a block 40 x 40 x 10 carrying a cylinder of radius 10 and height 10
 * tessellated into 36 facets 10 degrees apart (vertices on the circle, the first at 5
 * degrees from the x axis). Truth 8/14/8: the block's 8 corners, 12 edges and 6 faces;
 * the cylinder's wall (36 facets, one face) and its top (one face); its top rim and
 * its base, where it meets the block, are two closed creases without corners (each
 * 36 segments turning 90 degrees). Arcs 76: 24 vertex-edge, 24 + 4 edge-face, 24
 * vertex-face. At 256 a facet is 11 cells wide. */
std::vector<std::string> blendModelNames();

/** \brief Quarter-cylinder facets of each fillet of "filleted_box". */
constexpr int kFilletSegments = 24;
/** \brief Facets of the cylinder of "faceted_boss". */
constexpr int kBossFacets = 36;

/** \brief The model of a name of blendModelNames(), axis-aligned, centred on its
 * bounding box. \throws visfeat::Error for an unknown name. */
BlendModel blendModelByName(const std::string& name);

} // namespace synthetic
} // namespace visfeat
