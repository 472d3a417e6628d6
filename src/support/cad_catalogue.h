#pragma once

// The catalogue of named CAD models, and polyhedral models from closed polygon meshes.

#include <support/cad_model.h>
#include <support/synthetic_shapes.h>

#include <string>
#include <vector>

namespace visfeat {
namespace synthetic {

/** \brief Names accepted by cadModelByName(): "cube", "tetrahedron", "icosahedron",
 * "triangular_prism", "u_prism", "box_with_hole", "cylinder". */
std::vector<std::string> cadModelNames();

/** \brief Models with features closer than 2 min_radius cells at 256 (the small
 * features of real machined parts), also accepted by cadModelByName():
 * "stepped_block" 16/24/10 (a staircase of three treads 0.6 deep, risers 0.15 high,
 * extruded by 1.2: at 256 cells along its 1.8 length a riser is 21 cells high);
 * "chamfered_box" 16/24/10 (a 2 x 1.5 x 1 box, its four edges along z chamfered at 45
 * degrees, chamfer faces 6, 10, 14 and 20 cells wide at 256 along its 2-unit side);
 * "thin_plate_with_hole" 8/14/7 (a 2 x 1.5 plate 12 cells thick at 256, a hole of
 * radius 0.3 through its middle); "parallel_creases" 14/21/9 (a 2 x 0.6 block, 1 deep,
 * whose top turns by 30, 60 and 30 degrees at three parallel creases 10 cells apart at
 * 256). Unrotated: a random rotation lengthens the bounding box, so at 256 the cells
 * grow by up to sqrt(3) and the features shrink in cells. */
std::vector<std::string> smallFeatureModelNames();

/** \brief cadModelNames() then smallFeatureModelNames(). */
std::vector<std::string> allCadModelNames();

/** \brief The model of a name of allCadModelNames(), centred at the origin,
 * axis-aligned.
 *
 * Truth counts (vertices / curves / faces): cube 8/12/6, tetrahedron 4/6/4,
 * icosahedron 12/30/20 (the Platonic solids of platonicSolid(), circumradius 1);
 * triangular_prism 6/9/5 (equilateral triangle of side 2, length 2); u_prism 16/24/10
 * (a U of 3 x 3 with arms and base 1 thick and a 1-wide notch, extruded by 1.5);
 * box_with_hole 8/14/7 (a 2 x 2 x 1.5 box, a through-hole of radius 0.5 along its short
 * side: 12 segments + 2 circles, 6 planar faces of which two have a hole + the hole's
 * wall); cylinder 0/2/3 (radius 1, height 2: 2 discs + the lateral face).
 * \throws visfeat::Error for an unknown name, listing the known ones. */
CadModel cadModelByName(const std::string& name);

/** \brief A polyhedral model from a closed polygon mesh (faces may be non-convex).
 *
 * Inputs:
 *   name  the model's name
 *   mesh  closed, consistently oriented (counter-clockwise seen from outside), planar
 *         faces; every edge shared by exactly two faces that are not coplanar
 * Outputs:
 *   the model: the mesh's vertices, one kSegment curve per mesh edge (in the order of
 *   first appearance along the faces), one kPlanar face per mesh face (same ids).
 * \throws visfeat::Error when the mesh breaks one of these conditions. */
CadModel polyhedralModel(const std::string& name, const PolygonMesh& mesh);

} // namespace synthetic
} // namespace visfeat
