#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace visfeat {
namespace synthetic {

/** \brief A closed triangle mesh to sample clouds from. */
struct TriangleMesh
{
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 3>> triangles;

  double area() const;

  Eigen::AlignedBox3d bounds() const;
};

/** \brief A closed polyhedron with planar polygonal faces.
 *
 * faces[f] lists the vertex ids of face f in counter-clockwise order seen from outside
 * (right-hand rule: the outward normal). A face may be non-convex; it has no holes. */
struct PolygonMesh
{
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::vector<int>> faces;
};

/** \brief The convex hull of a small vertex set (brute force, O(n^4)).
 *
 * Inputs:
 *   vertices  points spanning a volume (a vertex inside the hull or inside a face is
 *             kept in the output's vertices but belongs to no face)
 * Outputs:
 *   the hull: every supporting plane through three vertices is one face (coplanar
 *   triangles merged into one polygon), its vertices sorted counter-clockwise seen from
 *   outside; vertex ids are the input's. Tolerance 1e-9 (absolute). */
PolygonMesh convexHull(const std::vector<Eigen::Vector3d>& vertices);

/** \brief A triangle mesh of a polygon mesh: every face fanned from its first vertex
 * (correct for convex faces only). */
TriangleMesh fanTriangulation(const PolygonMesh& mesh);

/** \brief The Platonic solid of a name of shapeNames(), centred at the origin with
 * circumradius 1, as polygons (squares for the cube).
 * \throws visfeat::Error for an unknown name, listing the known ones. */
PolygonMesh platonicSolid(const std::string& name);

/** \brief Platonic solids centred at the origin with circumradius 1 (fanTriangulation
 * of platonicSolid()). */
TriangleMesh tetrahedron();
TriangleMesh cube();
TriangleMesh octahedron();
TriangleMesh icosahedron();

/** \brief The mesh of a named shape (the names of shapeNames()).
 * \throws visfeat::Error for an unknown name, listing the known ones. */
TriangleMesh shapeByName(const std::string& name);

/** \brief Names accepted by shapeByName(). */
std::vector<std::string> shapeNames();

/** \brief A uniformly random rotation, reproducible from the seed. */
Eigen::Matrix3d randomRotation(std::uint64_t seed);

/** \brief The mesh with every vertex rotated. */
TriangleMesh rotated(const TriangleMesh& mesh, const Eigen::Matrix3d& rotation);

/** \brief How many uniform samples give a mean spacing of about spacing_cells cells on
 * a grid of `resolution` cells along the mesh's longest bounding-box side. */
std::size_t
samplesForSpacing(const TriangleMesh& mesh, int resolution, double spacing_cells);

/** \brief count points uniformly distributed over the surface (by area), reproducible
 * from the seed. */
std::vector<Eigen::Vector3f>
sampleSurface(const TriangleMesh& mesh, std::size_t count, std::uint64_t seed);

} // namespace synthetic
} // namespace visfeat
