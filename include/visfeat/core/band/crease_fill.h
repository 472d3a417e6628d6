#pragma once

#include <visfeat/core/band/tangent_planes.h>
#include <visfeat/core/band/triangle_cells.h>
#include <visfeat/core/grid/grid_spec.h>

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace visfeat {

/** \brief The cells of the fill's triangles with their creases rebuilt sharp.
 *
 * A triangle whose corners' normals agree within crease_degrees lies on one face and is
 * rasterised exactly (rasterizeTriangles()). A triangle across a crease is a chord that
 * cuts the crease by up to about half a point spacing; it is sampled every
 * kCreaseSampleCells and each sample is lifted onto the wedge of its corners' tangent
 * planes (each plane oriented so that the other corners lie below it; the sample moves
 * along the sum of the normals until it leaves the wedge, so a sample on the chord's
 * middle reaches the crease line itself). Where the planes make no wedge (a saddle, a
 * side that cannot be told, a lift longer than the triangle), the sample moves onto the
 * nearest corner plane instead. The cells of the moved samples join the band.
 * creaseStripCells() adds the strips between the chords and the crease line.
 *
 * \param[in] grid the grid
 * \param[in] points positions in world units (the triangles' corners)
 * \param[in] planes per point (tangentPlanes()); a zero normal counts as agreeing
 * \param[in] triangles indices into points
 * \param[in] crease_degrees corners' normals further apart than this make a crease
 * triangle; 180 or more: no crease triangle (plain rasterisation)
 * \param[in] threads 0 = all available; the result does not depend on it
 * \return the cells, each once, in GridSpec::linearKey order.
 * \throws visfeat::Error as rasterizeTriangles(), or for sizes that do not match. */
std::vector<CellCoord> creaseFillCells(const GridSpec& grid,
                                       const std::vector<Eigen::Vector3d>& points,
                                       const std::vector<TangentPlane>& planes,
                                       const std::vector<TriangleIndices>& triangles,
                                       double crease_degrees,
                                       int threads);

} // namespace visfeat
