#pragma once

#include <visfeat/core/band/voxel_band.h>

#include <pcl/point_cloud.h>

namespace visfeat {

/** \brief The grid of DESIGN.md for the finite points of a cloud.
 *
 * Bounding box of the points whose x, y, z are all finite (the others are skipped),
 * cell_size = largest side / resolution, 2 cells of padding. The origin is then read
 * back from a pcl::octree given that box, so that octree keys are cell coordinates.
 * \throws visfeat::Error when the cloud has no finite point, all finite points
 *         coincide, or the resolution is out of range.
 */
template <typename PointT>
GridSpec gridForCloud(const pcl::PointCloud<PointT>& cloud, int resolution);

/** \brief Build the band of a cloud through pcl::octree with an explicit bounding box,
 * so the cells do not depend on the order of the points.
 * \param[in] cloud the points (NaN / infinite points are skipped: pointCell() =
 * kNoCell) \param[in] grid from gridForCloud() \param[in] options VoxelBand::Options
 */
template <typename PointT>
VoxelBand buildVoxelBand(const pcl::PointCloud<PointT>& cloud,
                         const GridSpec& grid,
                         const VoxelBand::Options& options,
                         const std::vector<CellCoord>& fill = {});

} // namespace visfeat

#ifdef PCL_NO_PRECOMPILE
#include <visfeat/impl/voxel_band_from_cloud.hpp>
#endif
