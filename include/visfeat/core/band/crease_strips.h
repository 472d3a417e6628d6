#pragma once

#include <visfeat/core/band/tangent_planes.h>
#include <visfeat/core/band/triangle_cells.h>
#include <visfeat/core/grid/grid_spec.h>

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace visfeat {

/** \brief The cells of the crease strips: the faces rebuilt up to the crease line
 * between neighbours on either side of it.
 *
 * For each point p and each of its kStripNeighbours nearest neighbours q whose
 * tangent planes differ by more than crease_degrees and straddle one crease (each
 * point clearly on one side of the other's plane, the planes' intersection line
 * between them), the two triangles (p, p', q') on p's plane and (q, q', p') on q's
 * plane, p' and q' the feet of p and q on that line, are rasterised exactly (p and q
 * moved onto their own planes first). Where the points stay a spacing away from a
 * crease the local triangles' chords miss its apex; the strips put it back (exact when
 * the planes are).
 *
 * Corners: for p and two such neighbours q and r on a third plane, where the three
 * planes meet at a point v near them and each point lies in the convex corner of its
 * face between the two crease lines through v (not at a face's reflex corner), each
 * point's quadrilateral (point, its foot on one line, v, its foot on the other) on its
 * own plane, as two triangles.
 *
 * \param[in] grid the grid
 * \param[in] points positions in world units
 * \param[in] planes per point (tangentPlanes()); a zero normal pairs with nothing
 * \param[in] neighbours k indices per point, nearest first, as umbrellaTriangles()
 * \param[in] k neighbours per point in `neighbours`
 * \param[in] crease_degrees planes further apart than this make a crease; 180 or
 * more: no strip
 * \param[in] threads 0 = all available; the result does not depend on it
 * \return the cells, each once, in GridSpec::linearKey order.
 * \throws visfeat::Error for sizes that do not match. */
std::vector<CellCoord> creaseStripCells(const GridSpec& grid,
                                        const std::vector<Eigen::Vector3d>& points,
                                        const std::vector<TangentPlane>& planes,
                                        const std::vector<std::uint32_t>& neighbours,
                                        int k,
                                        double crease_degrees,
                                        int threads);

} // namespace visfeat
