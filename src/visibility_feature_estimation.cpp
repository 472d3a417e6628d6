#include <visfeat/visibility_feature_estimation.h>

#ifndef PCL_NO_PRECOMPILE
#include <visfeat/impl/visibility_feature_estimation.hpp>

#include <pcl/impl/instantiate.hpp>
#include <pcl/point_types.h>

PCL_INSTANTIATE_PRODUCT(VisibilityFeatureEstimation,
                        (PCL_XYZ_POINT_TYPES)((visfeat::PointVisibility)))
#endif
