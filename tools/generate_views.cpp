#include "generate_views.h"

#include "common/arguments.h"
#include "common/output_files.h"
#include "common/tool_main.h"

#include <pcl/conversions.h>
#include <pcl/io/ply_io.h>

#include <cmath>
#include <cstdint>
#include <limits>

namespace visfeat_tools {

namespace syn = visfeat::synthetic;

bool
parseImageSize(const std::string& text, int& width, int& height, std::string& error)
{
  constexpr long long kMaxSide = 16384;
  const std::size_t x = text.find_first_of("xX");
  long long w = 0, h = 0;
  if (x == std::string::npos || !parseInteger(text.substr(0, x), w) ||
      !parseInteger(text.substr(x + 1), h) || w < 1 || h < 1 || w > kMaxSide ||
      h > kMaxSide) {
    error = "-organized expects WIDTHxHEIGHT with each in [1, " +
            std::to_string(kMaxSide) + "], got '" + text + "'";
    return false;
  }
  width = static_cast<int>(w);
  height = static_cast<int>(h);
  return true;
}

bool
parseDirection(const std::string& text, Eigen::Vector3d& direction, std::string& error)
{
  const std::vector<std::string> items = splitList(text);
  Eigen::Vector3d v;
  bool ok = items.size() == 3;
  for (std::size_t i = 0; ok && i < 3; ++i)
    ok = parseReal(items[i], v[static_cast<Eigen::Index>(i)]);
  if (!ok || !(v.norm() > 0.0)) {
    error = "-view expects a non-zero direction X,Y,Z, got '" + text + "'";
    return false;
  }
  direction = v;
  return true;
}

pcl::PolygonMesh
toPolygonMesh(const syn::CadMesh& mesh)
{
  pcl::PointCloud<pcl::PointXYZ> vertices;
  vertices.reserve(mesh.mesh.vertices.size());
  for (const Eigen::Vector3d& v : mesh.mesh.vertices)
    vertices.push_back(pcl::PointXYZ(
      static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z())));
  pcl::PolygonMesh out;
  pcl::toPCLPointCloud2(vertices, out.cloud);
  out.polygons.reserve(mesh.mesh.triangles.size());
  for (const auto& t : mesh.mesh.triangles) {
    pcl::Vertices polygon;
    polygon.vertices.assign(t.begin(), t.end());
    out.polygons.push_back(polygon);
  }
  return out;
}

void
toOrganizedCloud(const syn::OrganizedView& view, pcl::PointCloud<PointGenerated>& cloud)
{
  cloud.resize(view.points.size());
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (std::size_t i = 0; i < view.points.size(); ++i) {
    PointGenerated& p = cloud[i];
    p.x = view.points[i].x();
    p.y = view.points[i].y();
    p.z = view.points[i].z();
    p.data[3] = 1.0f;
    const bool hit = view.face[i] >= 0;
    p.curve_distance = hit ? static_cast<float>(view.curve_distance[i]) : nan;
    p.face_id = hit ? static_cast<std::uint32_t>(view.face[i])
                    : std::numeric_limits<std::uint32_t>::max();
  }
  cloud.width = static_cast<std::uint32_t>(view.width);
  cloud.height = static_cast<std::uint32_t>(view.height);
  cloud.is_dense = false;
  // The camera's position in the points' own frame, as PCL's normal estimation reads
  // sensor_origin_ (useSensorOriginAsViewPoint) and visfeat's grid fill does; the
  // orientation stays the identity: the points are not in the camera's frame.
  cloud.sensor_origin_ =
    Eigen::Vector4f(static_cast<float>(view.camera_position.x()),
                    static_cast<float>(view.camera_position.y()),
                    static_cast<float>(view.camera_position.z()), 0.0f);
}

bool
writeMeshPly(const std::string& path, const pcl::PolygonMesh& mesh, std::string& error)
{
  const int rc =
    quietly([&] { return pcl::io::savePLYFileBinary(temporaryPath(path), mesh); });
  if (rc >= 0)
    return true;
  discardOutput(path);
  error = "cannot write '" + path + "' (disk full or not writable?)";
  return false;
}

} // namespace visfeat_tools
