#pragma once

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <cstdint>
#include <istream>
#include <vector>

namespace visfeat {

/** \brief A triangle mesh as plain arrays: vertex positions and, per triangle, three
 * vertex indices. No connectivity is assumed (a soup is fine). */
struct SurfaceMesh
{
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;
};

/** \brief Area of triangle (a, b, c). */
double triangleArea(const Eigen::Vector3d& a,
                    const Eigen::Vector3d& b,
                    const Eigen::Vector3d& c);

/** \brief Check a mesh before sampling it.
 * \throws visfeat::Error naming the first problem: a vertex with a NaN or infinite
 *         coordinate, or a triangle index out of range. */
void validateMesh(const SurfaceMesh& mesh);

/** \brief Whether the mesh is closed: every edge (a pair of vertex indices) is shared
 * by two triangles or more, so it bounds a solid and the features of its surface form a
 * closed B-rep. Triangles with a repeated index are left out; coincident vertices
 * with different indices are not merged (a mesh stored as a triangle soup reads as
 * open). Call validateMesh() first. */
bool meshIsClosed(const SurfaceMesh& mesh);

/** \brief Total area of the triangles (degenerate ones add 0). Call validateMesh()
 * first. */
double meshArea(const SurfaceMesh& mesh);

/** \brief Number of uniform samples with a mean spacing of `spacing` (world units):
 * ceil(area / spacing^2), the definition visfeat_generate uses.
 * \throws visfeat::Error if spacing or area is not positive and finite, or the count
 *         exceeds max_count. */
std::size_t samplesForSpacing(double area, double spacing, std::size_t max_count);

/** \brief One sample: its position and the triangle it lies on. */
struct MeshSample
{
  Eigen::Vector3f position;
  std::uint32_t triangle = 0;
};

/** \brief Area-weighted uniform random samples of a triangle mesh.
 *
 * Inputs:
 *   mesh   vertices and triangles (validated: see validateMesh())
 *   count  number of samples
 *   seed   the same seed gives the same samples on every platform (a 64-bit Mersenne
 *          twister with its own conversion to [0, 1), not std's distributions)
 * Outputs:
 *   count samples; triangle t receives each sample with probability area(t) / total
 *   area (so zero-area triangles receive none) and places it uniformly on t
 *   (barycentric coordinates (1 - sqrt(u), sqrt(u) (1 - v), sqrt(u) v)). Positions
 *   are computed in double and rounded to float.
 * \throws visfeat::Error for an invalid mesh, no triangles, or zero total area. */
std::vector<MeshSample>
sampleMesh(const SurfaceMesh& mesh, std::size_t count, std::uint64_t seed);

/** \brief Read an OFF file (Object File Format, as written by Geomview, CGAL, meshlab).
 *
 * Accepted: a first line "OFF" (optionally followed by the counts on the same line),
 * then "vertices faces edges", one line "x y z" per vertex and one line
 * "n i_1 ... i_n [colour]" per face with n >= 3 indices from 0. '#' starts a comment;
 * blank lines are skipped. Polygons are fanned from their first vertex (exact for
 * convex polygons). Anything else (another header such as COFF or NOFF, a missing or
 * extra value, a short file, an index out of range, data after the last face) is
 * refused.
 * \throws visfeat::Error with one line naming the problem and the line number. */
SurfaceMesh readOff(std::istream& in);

} // namespace visfeat
