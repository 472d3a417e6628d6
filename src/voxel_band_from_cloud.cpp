#include <visfeat/voxel_band_from_cloud.h>

#ifndef PCL_NO_PRECOMPILE
#include <visfeat/impl/voxel_band_from_cloud.hpp>

#include <pcl/impl/instantiate.hpp>
#include <pcl/point_types.h>

PCL_INSTANTIATE(VisfeatVoxelBandFromCloud, PCL_XYZ_POINT_TYPES)
#endif
