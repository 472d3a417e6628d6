// Mesh input of the visfeat tools (not installed, not public API): .ply files with
// faces, .obj and .off files read into a visfeat::SurfaceMesh and sampled to a cloud.
#pragma once

#include "common/ply_check.h"

#include <visfeat/core/mesh/mesh_sampling.h>

#include <pcl/PCLPointCloud2.h>
#include <pcl/PolygonMesh.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

namespace visfeat_tools {

/** \brief Seed of the mesh sampling: fixed, so a mesh always gives the same cloud. */
constexpr std::uint64_t kMeshSeed = 1;

/** \brief The most points a mesh is sampled to. */
constexpr std::size_t kMaxMeshPoints = 1000000000;

/** \brief How densely to sample a mesh: a point count, or a mean spacing (world units)
 * when spacing > 0. */
struct MeshDensity
{
  std::size_t points = 1000000;
  double spacing = 0.0;
};

/** \brief Binary STL layout: header bytes before the triangle count, bytes a
 * triangle (normal, 3 vertices, attribute count). */
constexpr std::uint64_t kStlHeaderBytes = 80;
constexpr std::uint64_t kStlTriangleBytes = 50;

/** \brief What is wrong with an STL file, empty when it looks valid: a binary STL
 * whose size matches its triangle count, or an ASCII one from 'solid' to 'endsolid'
 * with 3 finite vertices a facet. VTK's STL reader (pcl::io::loadPolygonFileSTL) has
 * no error path and must only see files that pass. */
std::string stlProblem(const std::string& path);

/** \brief True when `path` is a mesh to sample: .obj, .off, .stl, or a .ply whose
 * header declares at least one face. A .ply that cannot be read stays a "cloud", so the
 * cloud reader reports what is wrong with it. */
bool isMeshFile(const std::string& path);

/** \brief A pcl::PolygonMesh as a visfeat::SurfaceMesh: vertex coordinates whatever
 * their numeric type, polygons fanned from their first vertex. False + `error` (without
 * the file name) for vertices without x y z, truncated vertex data, a polygon of fewer
 * than 3 vertices or a vertex index out of range. */
bool toSurfaceMesh(const pcl::PolygonMesh& in,
                   visfeat::SurfaceMesh& out,
                   std::string& error);

/** \brief Read a mesh file (.off by visfeat::readOff, .ply by PCL, .obj by PCL after
 * objProblem(), .stl by PCL's VTK reader after stlProblem()), after checkInputFile().
 * On failure `error` is one line naming the file. */
bool loadMesh(const std::string& path, visfeat::SurfaceMesh& mesh, std::string& error);

/** \brief Load a mesh and sample it (area-weighted, seed kMeshSeed) into an x y z
 * cloud, keeping the mesh (for the band: VisibilityFeatureEstimation::setInputMesh).
 * `summary` says what was done, for the tool to print.
 *
 * Survey coordinates: `offset` is recentringOffset() of the vertices' bounding box
 * (zero near the origin). The kept mesh is the recentred one (vertices minus offset,
 * in double) and is sampled there, so the float samples keep their precision; the
 * cloud holds the samples in the input's frame (samples plus offset, FLOAT64 x y z
 * when the offset is not zero, FLOAT32 otherwise): the tool subtracts the same offset
 * (toXYZ) and gets the recentred samples back, on the recentred mesh. */
bool loadMeshAsCloud(const std::string& path,
                     const MeshDensity& density,
                     pcl::PCLPointCloud2& cloud,
                     std::shared_ptr<const visfeat::SurfaceMesh>& mesh,
                     Eigen::Vector3d& offset,
                     std::string& summary,
                     std::string& error);

} // namespace visfeat_tools
