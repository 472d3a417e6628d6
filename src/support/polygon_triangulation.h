#pragma once

// Triangulation of a simple polygon with holes in the plane (ear clipping after
// bridging the holes to the outer boundary), used by the tessellation of the CAD
// models' planar faces.

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <vector>

namespace visfeat {
namespace synthetic {

/** \brief A polygon of the plane: its points in order (the last joins the first). */
using Polygon2 = std::vector<Eigen::Vector2d>;

/** \brief The triangles of a simple polygon with holes.
 *
 * Inputs:
 *   outer  the outer boundary, counter-clockwise (positive signed area), at least 3
 *          points, simple (no self-intersection, no repeated point), coordinates in any
 *          unit
 *   holes  each hole's boundary (either orientation, at least 3 points), strictly
 *          inside `outer` and disjoint from the other holes
 * Outputs:
 *   counter-clockwise triangles as indices into the points of `outer` followed by
 *   those of each hole in order: n + 2 h - 2 triangles for n points and h holes, whose
 *   areas add up to the area of the region. Every hole is bridged to the boundary
 *   found so far (Eberly's visible-vertex rule, holes in decreasing order of their
 *   largest x), then the bridged polygon is clipped ear by ear.
 * \throws visfeat::Error when `outer` has fewer than 3 points or is not
 *         counter-clockwise, a hole has fewer than 3 points, or no ear or no bridge is
 *         found (a polygon that is not simple or a hole that is not inside). */
std::vector<std::array<std::uint32_t, 3>>
triangulatePolygon(const Polygon2& outer, const std::vector<Polygon2>& holes);

/** \brief Twice the signed area of a polygon (positive: counter-clockwise). */
double twiceSignedArea(const Polygon2& polygon);

} // namespace synthetic
} // namespace visfeat
