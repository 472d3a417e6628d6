#pragma once

#include <visfeat/core/common/error.h>
#include <visfeat/voxel_band_from_cloud.h>

#include <pcl/common/point_tests.h>
#include <pcl/octree/octree_pointcloud_pointvector.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <string>

namespace visfeat {
namespace detail {

/** Gives the octree the grid's box with a power-of-two side, so it neither grows nor
 * recentres it: octree keys are then the grid's cell coordinates. Returns the origin
 * the octree actually uses. */
template <typename Octree>
Eigen::Vector3d
defineOctreeBox(Octree& octree, const GridSpec& grid)
{
  double side = grid.cell_size;
  while (side < grid.cell_size * grid.dims.maxCoeff())
    side *= 2.0;
  octree.defineBoundingBox(grid.origin.x(), grid.origin.y(), grid.origin.z(),
                           grid.origin.x() + side, grid.origin.y() + side,
                           grid.origin.z() + side);
  Eigen::Vector3d min, max;
  octree.getBoundingBox(min.x(), min.y(), min.z(), max.x(), max.y(), max.z());
  return min;
}

} // namespace detail

template <typename PointT>
GridSpec
gridForCloud(const pcl::PointCloud<PointT>& cloud, int resolution)
{
  if (cloud.empty())
    throw Error("the cloud is empty");
  Eigen::Vector3d lo =
    Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d hi = -lo;
  std::size_t finite = 0;
  for (const PointT& p : cloud.points) {
    if (!pcl::isXYZFinite(p))
      continue;
    const Eigen::Vector3d v(p.x, p.y, p.z);
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
    ++finite;
  }
  if (finite == 0)
    throw Error("the cloud has no finite point: all " + std::to_string(cloud.size()) +
                " points have a NaN or infinite coordinate");
  if (finite == 1)
    throw Error("the cloud has a single finite point: there is no surface to analyse");
  GridSpec grid = GridSpec::fromBounds(lo, hi, resolution);
  pcl::octree::OctreePointCloudPointVector<PointT> octree(grid.cell_size);
  grid.origin = detail::defineOctreeBox(octree, grid);
  return grid;
}

template <typename PointT>
VoxelBand
buildVoxelBand(const pcl::PointCloud<PointT>& cloud,
               const GridSpec& grid,
               const VoxelBand::Options& options)
{
  pcl::octree::OctreePointCloudPointVector<PointT> octree(grid.cell_size);
  if (detail::defineOctreeBox(octree, grid) != grid.origin)
    throw Error(
      "the octree moved the grid's origin: use gridForCloud() to make the grid");
  // Non-owning pointer: the octree reads the cloud only during this call.
  const typename pcl::PointCloud<PointT>::ConstPtr input(
    &cloud, [](const pcl::PointCloud<PointT>*) {});
  // Finite points only (pcl::isFinite may also look at other fields), handed to the
  // octree brick by brick (8^3 cells, counting sort): descents then stay in cache. The
  // order changes no result: cells are renumbered and point sums are integers.
  constexpr int kBrickShift = 3;
  const Eigen::Vector3i bricks = (grid.dims.array() + 7) / 8;
  auto brickOf = [&](const PointT& p) {
    const CellCoord c = grid.cellOf(Eigen::Vector3d(p.x, p.y, p.z));
    std::size_t key = 0;
    for (int a = 2; a >= 0; --a) {
      const int b = std::clamp(c[a], 0, grid.dims[a] - 1) >> kBrickShift;
      key = key * static_cast<std::size_t>(bricks[a]) + static_cast<std::size_t>(b);
    }
    return key;
  };
  std::vector<std::uint32_t> start(static_cast<std::size_t>(bricks.prod()) + 1, 0);
  for (const PointT& p : cloud.points)
    if (pcl::isXYZFinite(p))
      ++start[brickOf(p) + 1];
  for (std::size_t b = 1; b < start.size(); ++b)
    start[b] += start[b - 1];
  const auto finite = std::make_shared<pcl::Indices>(start.back());
  for (std::size_t i = 0; i < cloud.size(); ++i)
    if (pcl::isXYZFinite(cloud[i]))
      (*finite)[start[brickOf(cloud[i])]++] = static_cast<pcl::index_t>(i);
  octree.setInputCloud(input, finite);
  octree.addPointsFromInputCloud();

  std::vector<OccupiedCell> occupied;
  occupied.reserve(octree.getLeafCount());
  std::vector<std::int32_t> point_occupied(cloud.size(), -1);
  const double scale = OccupiedCell::kOffsetScale / grid.cell_size;
  for (auto it = octree.leaf_depth_begin(); it != octree.leaf_depth_end(); ++it) {
    // The octree computes its keys as GridSpec::cellOf does (same origin and cell
    // size, truncation of (p - origin) / cell_size in double): a key is the cell of
    // its points.
    const pcl::octree::OctreeKey& key = it.getCurrentOctreeKey();
    OccupiedCell cell;
    cell.coord = CellCoord(static_cast<int>(key.x), static_cast<int>(key.y),
                           static_cast<int>(key.z));
    const Eigen::Vector3d cell_min =
      grid.origin + grid.cell_size * cell.coord.template cast<double>();
    const auto entry = static_cast<std::int32_t>(occupied.size());
    for (const auto index : it.getLeafContainer().getPointIndicesVector()) {
      const PointT& p = cloud[static_cast<std::size_t>(index)];
      // offsets are >= 0: adding 0.5 and truncating rounds them
      const Eigen::Vector3d offset =
        (Eigen::Vector3d(p.x, p.y, p.z) - cell_min) * scale;
      cell.offset_sum += (offset.array() + 0.5).template cast<std::int64_t>().matrix();
      ++cell.point_count;
      point_occupied[static_cast<std::size_t>(index)] = entry;
    }
    occupied.push_back(cell);
  }
  if (occupied.empty())
    throw Error("the cloud has no finite point");
  return VoxelBand::build(grid, std::move(occupied), point_occupied, options);
}

} // namespace visfeat

#define PCL_INSTANTIATE_VisfeatVoxelBandFromCloud(T)                                   \
  template visfeat::GridSpec visfeat::gridForCloud<T>(const pcl::PointCloud<T>&, int); \
  template visfeat::VoxelBand visfeat::buildVoxelBand<T>(                              \
    const pcl::PointCloud<T>&, const visfeat::GridSpec&,                               \
    const visfeat::VoxelBand::Options&);
