#pragma once

#include <visfeat/core/common/error.h>
#include <visfeat/core/common/threads.h>
#include <visfeat/voxel_band_from_cloud.h>

#include <pcl/common/point_tests.h>
#include <pcl/octree/octree_pointcloud.h>
#include <pcl/octree/octree_pointcloud_pointvector.h>
// the members of OctreePointCloud<PointT, OctreeContainerPointIndex> that PCL does
// not instantiate for every point type
#include <pcl/octree/impl/octree_base.hpp>
#include <pcl/octree/impl/octree_pointcloud.hpp>

#include <algorithm>
#include <array>
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

/** Fewer points than this per octree are not worth a thread (measured on the 2-core
 * test machine: octree insertion costs 20-30 ms per 100,000 points, a thread's start
 * well under 1 ms; the generated icosahedron at 256, 656,000 points, builds its band
 * in 0.44 s on 2 threads instead of 0.52 s). */
constexpr std::size_t kMinPointsPerOctree = 100000;

/** The band's octree: a pcl::octree over the grid's box whose leaves are the occupied
 * cells. Each leaf holds the number of its cell in cells (numbered as the leaves are
 * made; VoxelBand::build renumbers them by key), and each point adds itself to its
 * cell's sums as it is inserted, under the key the octree computes for it: no list of
 * point indices per leaf, no second walk over the leaves and their points. Measured
 * 2026-12-07 (2 cores, generated icosahedron at 256, 656,000 points, 1 thread):
 * buildVoxelBand() took 0.26-0.28 s with OctreePointCloudPointVector (a vector of
 * indices per leaf, their frees, the walk), 0.22-0.23 s so, 0.14-0.15 s with
 * addPoints()' read-ahead and the repair's and sorts' changes of that date. */
template <typename PointT>
class BandOctree final
    : public pcl::octree::OctreePointCloud<PointT,
                                           pcl::octree::OctreeContainerPointIndex>
{
public:
  /** point_occupied gets, for each inserted point, the slab-local number of its cell
   * in cells. */
  BandOctree(const GridSpec& grid,
             std::vector<OccupiedCell>& cells,
             std::vector<std::int32_t>& point_occupied)
      : pcl::octree::OctreePointCloud<PointT, pcl::octree::OctreeContainerPointIndex>(
          grid.cell_size)
      , grid_(grid)
      , scale_(OccupiedCell::kOffsetScale / grid.cell_size)
      , cells_(cells)
      , point_occupied_(point_occupied)
  {
    defineOctreeBox(*this, grid);
  }

  /** Inserts the points of these indices, as addPointsFromInputCloud() would (points
   * pcl::isFinite() rejects are left out), each point read a few points ahead of its
   * insertion: the indices run brick by brick, so the points are read out of order,
   * and a read that waited for memory took 70% of the insertion's time (perf,
   * 2026-12-07). */
  void addPoints(const pcl::index_t* first, const pcl::index_t* last)
  {
    constexpr std::ptrdiff_t kAhead = 16;
    const pcl::PointCloud<PointT>& cloud = *this->input_;
    for (const pcl::index_t* it = first; it != last; ++it) {
      if (last - it > kAhead)
        __builtin_prefetch(&cloud[static_cast<std::size_t>(it[kAhead])]);
      if (pcl::isFinite(cloud[static_cast<std::size_t>(*it)]))
        addPointIdx(static_cast<pcl::uindex_t>(*it));
    }
  }

protected:
  void addPointIdx(const pcl::uindex_t index) override
  {
    const PointT& p = (*this->input_)[index];
    this->adoptBoundingBoxToPoint(p);
    pcl::octree::OctreeKey key;
    this->genOctreeKeyforPoint(p, key);
    pcl::octree::OctreeContainerPointIndex* leaf = this->createLeaf(key);
    if (leaf->getSize() == 0) {
      // The octree computes its keys as GridSpec::cellOf does (same origin and cell
      // size, truncation of (p - origin) / cell_size in double): a key is the cell of
      // its points.
      OccupiedCell cell;
      cell.coord = CellCoord(static_cast<int>(key.x), static_cast<int>(key.y),
                             static_cast<int>(key.z));
      leaf->addPointIndex(static_cast<pcl::index_t>(cells_.size()));
      cells_.push_back(cell);
    }
    const pcl::index_t entry = leaf->getPointIndex();
    OccupiedCell& cell = cells_[static_cast<std::size_t>(entry)];
    const Eigen::Vector3d cell_min =
      grid_.origin + grid_.cell_size * cell.coord.template cast<double>();
    // offsets are >= 0: adding 0.5 and truncating rounds them
    const Eigen::Vector3d offset = (Eigen::Vector3d(p.x, p.y, p.z) - cell_min) * scale_;
    cell.offset_sum += (offset.array() + 0.5).template cast<std::int64_t>().matrix();
    ++cell.point_count;
    point_occupied_[index] = entry; // slab-local
  }

private:
  const GridSpec& grid_;
  const double scale_;
  std::vector<OccupiedCell>& cells_;
  std::vector<std::int32_t>& point_occupied_;
};

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
  // Axis-aligned faces on the box's sides go to cell centres (withSidesAtCellCentres):
  // a side holds a face when more than kMinSidePoints points (and a thousandth of
  // them) lie on it; a rotated part touches its box at a few points only.
  constexpr std::size_t kMinSidePoints = 16;
  const double on_side = 1e-6 * (hi - lo).maxCoeff();
  std::array<std::size_t, 3> side_points{0, 0, 0};
  for (const PointT& p : cloud.points) {
    if (!pcl::isXYZFinite(p))
      continue;
    const Eigen::Vector3d v(p.x, p.y, p.z);
    for (int a = 0; a < 3; ++a)
      if (v[a] - lo[a] <= on_side || hi[a] - v[a] <= on_side)
        ++side_points[static_cast<std::size_t>(a)];
  }
  std::array<bool, 3> aligned{false, false, false};
  for (std::size_t a = 0; a < 3; ++a)
    aligned[a] = side_points[a] > std::max(kMinSidePoints, finite / 1000);
  grid = grid.withSidesAtCellCentres(aligned);
  pcl::octree::OctreePointCloudPointVector<PointT> octree(grid.cell_size);
  grid.origin = detail::defineOctreeBox(octree, grid);
  return grid;
}

template <typename PointT>
VoxelBand
buildVoxelBand(const pcl::PointCloud<PointT>& cloud,
               const GridSpec& grid,
               const VoxelBand::Options& options,
               const std::vector<CellCoord>& fill)
{
  {
    pcl::octree::OctreePointCloudPointVector<PointT> probe(grid.cell_size);
    if (detail::defineOctreeBox(probe, grid) != grid.origin)
      throw Error(
        "the octree moved the grid's origin: use gridForCloud() to make the grid");
  }
  // Non-owning pointer: the octrees read the cloud only during this call.
  const typename pcl::PointCloud<PointT>::ConstPtr input(
    &cloud, [](const pcl::PointCloud<PointT>*) {});
  // Finite points only (pcl::isFinite may also look at other fields), sorted brick by
  // brick (8^3 cells, counting sort, z-major): descents then stay in cache, and the
  // points split into slabs of whole bricks, one octree each, built in parallel (no
  // cell spans two slabs). The order changes no result: cells are renumbered by key
  // and point sums are integers.
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
  pcl::Indices finite(start.back());
  for (std::size_t i = 0; i < cloud.size(); ++i)
    if (pcl::isXYZFinite(cloud[i]))
      finite[start[brickOf(cloud[i])]++] = static_cast<pcl::index_t>(i);

  // Slabs of about equal point counts, cut between bricks: after the scatter, start[b]
  // is where brick b ends (and brick b + 1 begins).
  const int threads = resolveThreads(options.threads);
  const std::size_t slabs = std::max<std::size_t>(
    1, std::min<std::size_t>(static_cast<std::size_t>(threads),
                             finite.size() / detail::kMinPointsPerOctree));
  std::vector<std::size_t> cut(slabs + 1, finite.size());
  cut[0] = 0;
  for (std::size_t s = 1; s < slabs; ++s) {
    const auto target = static_cast<std::uint32_t>(finite.size() * s / slabs);
    cut[s] = *std::lower_bound(start.begin(), start.end(), target);
  }

  std::vector<std::vector<OccupiedCell>> slab_cells(slabs);
  std::vector<std::int32_t> point_occupied(cloud.size(), -1);
  parallelFor(slabs, threads, 1, [&](std::size_t first, std::size_t last) {
    for (std::size_t s = first; s < last; ++s) {
      detail::BandOctree<PointT> octree(grid, slab_cells[s], point_occupied);
      octree.setInputCloud(input);
      octree.addPoints(finite.data() + cut[s], finite.data() + cut[s + 1]);
    }
  });
  // One list of occupied cells; slab-local entries become global.
  std::vector<OccupiedCell> occupied;
  for (std::size_t s = 0; s < slabs; ++s) {
    const auto offset = static_cast<std::int32_t>(occupied.size());
    if (offset > 0)
      for (std::size_t i = cut[s]; i < cut[s + 1]; ++i)
        point_occupied[static_cast<std::size_t>(finite[i])] += offset;
    occupied.insert(occupied.end(), slab_cells[s].begin(), slab_cells[s].end());
    slab_cells[s] = {};
  }
  if (occupied.empty() && fill.empty())
    throw Error("the cloud has no finite point");
  return VoxelBand::build(grid, std::move(occupied), point_occupied, options, fill);
}

} // namespace visfeat

#define PCL_INSTANTIATE_VisfeatVoxelBandFromCloud(T)                                   \
  template visfeat::GridSpec visfeat::gridForCloud<T>(const pcl::PointCloud<T>&, int); \
  template visfeat::VoxelBand visfeat::buildVoxelBand<T>(                              \
    const pcl::PointCloud<T>&, const visfeat::GridSpec&,                               \
    const visfeat::VoxelBand::Options&, const std::vector<visfeat::CellCoord>&);
