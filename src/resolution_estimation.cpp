#include <visfeat/resolution_estimation.h>

#ifndef PCL_NO_PRECOMPILE
#include <visfeat/impl/resolution_estimation.hpp>

#include <pcl/impl/instantiate.hpp>
#include <pcl/point_types.h>

PCL_INSTANTIATE(VisfeatResolutionEstimation, PCL_XYZ_POINT_TYPES)
#endif
