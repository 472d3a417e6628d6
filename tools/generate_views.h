// visfeat_generate's other products (not installed, not public API): the model's
// tessellation as a PLY mesh and an organized depth view as an organized cloud.
#pragma once

#include "generated_point.h"

#include <support/cad_models.h>

#include <pcl/PolygonMesh.h>
#include <pcl/point_cloud.h>

#include <string>

namespace visfeat_tools {

/** \brief "WxH" (e.g. "640x480") -> width and height in pixels, each in [1, 16384].
 * False and a one-line `error` otherwise. */
bool
parseImageSize(const std::string& text, int& width, int& height, std::string& error);

/** \brief "x,y,z" -> a non-zero finite vector. False and a one-line `error` otherwise.
 */
bool
parseDirection(const std::string& text, Eigen::Vector3d& direction, std::string& error);

/** \brief The tessellation as a PCL mesh: vertices as float x y z (world units),
 * triangles counter-clockwise seen from outside. */
pcl::PolygonMesh toPolygonMesh(const visfeat::synthetic::CadMesh& mesh);

/** \brief The view as an organized cloud: width x height points, row-major; an empty
 * pixel has NaN x y z and curve_distance and face_id 4294967295; is_dense false. The
 * points are in the model's (world) frame; sensor_origin_ (the PCD VIEWPOINT) is the
 * camera's position in that frame, its orientation the identity. */
void toOrganizedCloud(const visfeat::synthetic::OrganizedView& view,
                      pcl::PointCloud<PointGenerated>& cloud);

/** \brief Write the mesh as binary PLY to the temporary name of `path` (see
 * output_files.h). False and a one-line `error` when it cannot. */
bool
writeMeshPly(const std::string& path, const pcl::PolygonMesh& mesh, std::string& error);

} // namespace visfeat_tools
