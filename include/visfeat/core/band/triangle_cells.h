#pragma once

#include <visfeat/core/grid/grid_spec.h>

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <vector>

namespace visfeat {

/** \brief Whether triangle (a, b, c) and cell `cell` overlap (all in cell units: cell
 * (i, j, k) is the box [i, i + 1) x [j, j + 1) x [k, k + 1)).
 *
 * The separating-axis test of Akenine-Moller ("Fast 3D triangle-box overlap testing",
 * 2001): the 3 box axes, the triangle's normal and the 9 cross products of edges and
 * axes. The box axes are tested exactly and half-open, so a triangle lying on the plane
 * between two cells touches the upper one only and a plane at a cell boundary gives
 * one layer of cells, as points on it would; the other axes use the closed box widened
 * by 1e-9 cells, so rounding never loses a cell. Degenerate triangles (segments,
 * points) are handled. */
bool triangleTouchesCell(const Eigen::Vector3d& a,
                         const Eigen::Vector3d& b,
                         const Eigen::Vector3d& c,
                         const CellCoord& cell);

/** \brief Appends the cells of a grid of `dims` cells that triangle (a, b, c) (cell
 * units) touches (triangleTouchesCell); cells outside the grid are left out. */
void appendTriangleCells(const Eigen::Vector3d& a,
                         const Eigen::Vector3d& b,
                         const Eigen::Vector3d& c,
                         const Eigen::Vector3i& dims,
                         std::vector<CellCoord>& out);

/** \brief The cells of linear keys (GridSpec::linearKey), each once, in key order:
 * the keys sorted and made unique, then decoded. */
std::vector<CellCoord> cellsOfKeys(const GridSpec& grid,
                                   std::vector<std::uint64_t> keys);

/** \brief A triangle as three indices into a vertex array. */
using TriangleIndices = std::array<std::uint32_t, 3>;

/** \brief The cells of `grid` touched by a triangle soup: the exact rasterisation of
 * DESIGN.md's "band from the surface".
 *
 * \param[in] grid the grid
 * \param[in] vertices positions in world units
 * \param[in] triangles indices into vertices
 * \param[in] threads 0 = all available; the result does not depend on it
 * \return the cells, each once, in GridSpec::linearKey order. Triangles or parts of
 * them outside the grid add nothing.
 * \throws visfeat::Error for an index out of range or a non-finite vertex. */
std::vector<CellCoord> rasterizeTriangles(const GridSpec& grid,
                                          const std::vector<Eigen::Vector3d>& vertices,
                                          const std::vector<TriangleIndices>& triangles,
                                          int threads);

} // namespace visfeat
