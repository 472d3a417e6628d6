#pragma once

// Tessellation of a CAD model: a triangle mesh of its faces, watertight where the
// model is closed, with the id of the face each triangle comes from.

#include <support/cad_model.h>
#include <visfeat/core/mesh/mesh_sampling.h>

#include <vector>

namespace visfeat {
namespace synthetic {

/** \brief A triangle mesh of a CadModel and, per triangle, the face it comes from. */
struct CadMesh
{
  /** Vertices (world units) and counter-clockwise triangles (seen from outside). */
  SurfaceMesh mesh;
  /** Per triangle of mesh.triangles, the id of its CadFace. */
  std::vector<int> face;
};

/** \brief The number of segments of the polygon inscribed in a circle of `radius`
 * whose chords stay within `chord_tolerance` of the circle (both in world units):
 * ceil(pi / acos(1 - chord_tolerance / radius)), at least 8.
 * \throws visfeat::Error for a radius or tolerance that is not positive and finite, or
 *         more than 2^20 segments. */
int circleSegments(double radius, double chord_tolerance);

/** \brief A triangle mesh of the model's faces.
 *
 * Inputs:
 *   model            the CAD model (checkCadModel() holds)
 *   chord_tolerance  the largest distance between a circle (or a cylinder) and its
 *                    polygonal approximation (world units, > 0)
 * Outputs:
 *   the mesh: its first vertices are the model's vertices (same ids), then each circle
 *   as circleSegments(radius, chord_tolerance) points on it, shared by the two faces it
 *   separates, so that the mesh is watertight where the model is closed (every edge in
 *   two triangles of opposite orientations). Planar faces are triangulated in their
 *   plane (triangulatePolygon(): holes bridged, ear clipping); cylinders as strips
 *   between their two circles. Triangles are counter-clockwise seen from outside (their
 *   normal is the face's outward normal, away from a cylinder's axis or towards it for
 *   a hole's wall). Every vertex lies on the exact surface; the area differs from
 *   model.area() by less than chord_tolerance times the length of the circles on
 *   planar faces (once per face) plus 2 pi chord_tolerance per unit of cylinder
 *   height.
 * \throws visfeat::Error for a bad tolerance (see circleSegments()) or a face that
 *         cannot be triangulated. */
CadMesh tessellateCadModel(const CadModel& model, double chord_tolerance);

} // namespace synthetic
} // namespace visfeat
