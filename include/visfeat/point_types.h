#pragma once

#include <visfeat/core/common/feature_class.h>

#include <pcl/point_types.h>
#include <pcl/register_point_struct.h>

#include <cstdint>

namespace visfeat {

/** \brief Per-point output of VisibilityFeatureEstimation.
 *
 * - visibility_radius: the visibility radius of the point's cell (NaN for NaN input)
 * - label: the component (region) id, 0 = none; pcl_viewer colours by it by default
 * - feature_class: a FeatureClass value (0 none, 1 vertex, 2 edge, 3 face)
 */
struct EIGEN_ALIGN16 PointVisibility
{
  PCL_ADD_POINT4D;
  float visibility_radius;
  std::uint32_t label;
  std::uint8_t feature_class;

  inline PointVisibility()
      : PointVisibility(0.f, 0.f, 0.f)
  {}

  inline PointVisibility(float _x,
                         float _y,
                         float _z,
                         float _radius = 0.f,
                         std::uint32_t _label = 0,
                         std::uint8_t _class = 0)
  {
    x = _x;
    y = _y;
    z = _z;
    data[3] = 1.0f;
    visibility_radius = _radius;
    label = _label;
    feature_class = _class;
  }

  PCL_MAKE_ALIGNED_OPERATOR_NEW
};

/** \brief One mixed cell of the band, at the cell's centre (the tool's -voxels dump).
 * i, j, k are the cell's integer grid coordinates. */
struct EIGEN_ALIGN16 PointVoxel
{
  PCL_ADD_POINT4D;
  std::int32_t i;
  std::int32_t j;
  std::int32_t k;
  float visibility_radius;
  std::uint32_t label;
  std::uint8_t feature_class;

  inline PointVoxel()
  {
    x = y = z = 0.f;
    data[3] = 1.0f;
    i = j = k = 0;
    visibility_radius = 0.f;
    label = 0;
    feature_class = 0;
  }

  PCL_MAKE_ALIGNED_OPERATOR_NEW
};

} // namespace visfeat

// clang-format off
POINT_CLOUD_REGISTER_POINT_STRUCT(visfeat::PointVisibility,
                                  (float, x, x)
                                  (float, y, y)
                                  (float, z, z)
                                  (float, visibility_radius, visibility_radius)
                                  (std::uint32_t, label, label)
                                  (std::uint8_t, feature_class, feature_class))

POINT_CLOUD_REGISTER_POINT_STRUCT(visfeat::PointVoxel,
                                  (float, x, x)
                                  (float, y, y)
                                  (float, z, z)
                                  (std::int32_t, i, i)
                                  (std::int32_t, j, j)
                                  (std::int32_t, k, k)
                                  (float, visibility_radius, visibility_radius)
                                  (std::uint32_t, label, label)
                                  (std::uint8_t, feature_class, feature_class))
// clang-format on
