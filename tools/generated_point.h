// The point type of visfeat_generate's clouds (not installed, not public API).
#pragma once

#include <pcl/point_types.h>
#include <pcl/register_point_struct.h>

#include <cstdint>

namespace visfeat_tools {

/** \brief A generated point: x y z, the distance of its noise-free position to the
 * nearest true sharp curve (world units) and the id of the face it was sampled from
 * (in an organized view: NaN coordinates and distance, and the largest uint32 as the
 * face, for an empty pixel). */
struct EIGEN_ALIGN16 PointGenerated
{
  PCL_ADD_POINT4D;
  float curve_distance;
  std::uint32_t face_id;

  PCL_MAKE_ALIGNED_OPERATOR_NEW
};

} // namespace visfeat_tools

POINT_CLOUD_REGISTER_POINT_STRUCT(visfeat_tools::PointGenerated,
                                  (float, x, x)(float, y, y)(float, z, z)(
                                    float,
                                    curve_distance,
                                    curve_distance)(std::uint32_t, face_id, face_id))
