#include <visfeat/visibility_feature_estimation.h>

#ifndef PCL_NO_PRECOMPILE
#include <visfeat/impl/visibility_feature_estimation.hpp>

#include <pcl/impl/instantiate.hpp>
#include <pcl/point_types.h>

// Every PCL point type with x y z (PCL_XYZ_POINT_TYPES: PointXYZ, PointXYZI, PointXYZL,
// PointXYZRGB(A), PointNormal, PointXYZRGBNormal, PointXYZINormal, PointSurfel, ...)
// with PointVisibility as output; test_estimator_api links PointXYZI and PointNormal.
PCL_INSTANTIATE_PRODUCT(VisibilityFeatureEstimation,
                        (PCL_XYZ_POINT_TYPES)((visfeat::PointVisibility)))
#endif
