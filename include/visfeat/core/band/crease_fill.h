#pragma once

#include <visfeat/core/band/triangle_cells.h>
#include <visfeat/core/grid/grid_spec.h>

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace visfeat {

/** \brief Per point, the unit normal of its tangent plane (any sign), fitted so that a
 * point near a crease takes the plane of its own face.
 *
 * Least squares through the point and its kPlaneNeighbours nearest distinct neighbours
 * (rows of `neighbours`, k per point, nearest first, as umbrellaTriangles() reads
 * them), then again through those of them within kPlaneInlierShare of the distance to
 * the farthest of them from that first plane: the neighbours across a crease leave the
 * fit. Zero for a point with fewer than 2 usable neighbours or a non-finite point.
 * \throws visfeat::Error for a neighbour table of the wrong size. */
std::vector<Eigen::Vector3d>
tangentNormals(const std::vector<Eigen::Vector3d>& points,
               const std::vector<std::uint32_t>& neighbours,
               int k,
               int threads);

/** \brief The cells of the fill's triangles with their creases rebuilt sharp.
 *
 * A triangle whose corners' normals agree within crease_degrees lies on one face and is
 * rasterised exactly (rasterizeTriangles()). A triangle across a crease is a chord that
 * cuts the crease by up to about half a point spacing; it is sampled every
 * kCreaseSampleCells and each sample moves onto the nearest of its corners' tangent
 * planes (for a point inside a convex crease the nearest plane is that of the face it
 * belongs to, so the samples land on the two faces up to the crease line); the cells of
 * the moved samples join the band.
 *
 * \param[in] grid the grid
 * \param[in] points positions in world units (the triangles' corners)
 * \param[in] normals per point (tangentNormals()); a zero normal counts as agreeing
 * \param[in] triangles indices into points
 * \param[in] crease_degrees corners' normals further apart than this make a crease
 * triangle; 180 or more: no crease triangle (plain rasterisation)
 * \param[in] threads 0 = all available; the result does not depend on it
 * \return the cells, each once, in GridSpec::linearKey order.
 * \throws visfeat::Error as rasterizeTriangles(), or for sizes that do not match. */
std::vector<CellCoord> creaseFillCells(const GridSpec& grid,
                                       const std::vector<Eigen::Vector3d>& points,
                                       const std::vector<Eigen::Vector3d>& normals,
                                       const std::vector<TriangleIndices>& triangles,
                                       double crease_degrees,
                                       int threads);

} // namespace visfeat
