// Clouds with x y z as FLOAT64 fields (not installed, not public API): the output of
// voxels and survey coordinates in the input's frame, and the tests' survey clouds.
#pragma once

#include <pcl/PCLPointCloud2.h>

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

namespace visfeat_tools {

/** \brief A cloud of points.size() points (height 1, dense) whose only fields are x, y,
 * z as FLOAT64 (point_step 24), each point `points[i] + shift`, in double. */
inline pcl::PCLPointCloud2
doubleXYZCloud(const std::vector<Eigen::Vector3d>& points,
               const Eigen::Vector3d& shift = Eigen::Vector3d::Zero())
{
  pcl::PCLPointCloud2 c;
  for (const char* name : {"x", "y", "z"}) {
    pcl::PCLPointField f;
    f.name = name;
    f.offset = static_cast<std::uint32_t>(8 * c.fields.size());
    f.datatype = pcl::PCLPointField::FLOAT64;
    f.count = 1;
    c.fields.push_back(f);
  }
  c.point_step = 24;
  c.width = static_cast<std::uint32_t>(points.size());
  c.height = 1;
  c.row_step = c.point_step * c.width;
  c.is_dense = true;
  c.data.resize(points.size() * 24);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3d p = points[i] + shift;
    std::memcpy(c.data.data() + 24 * i, p.data(), 24);
  }
  return c;
}

} // namespace visfeat_tools
