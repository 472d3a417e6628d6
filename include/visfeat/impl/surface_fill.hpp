#pragma once

#include <visfeat/core/band/crease_fill.h>
#include <visfeat/core/band/crease_strips.h>
#include <visfeat/core/common/error.h>
#include <visfeat/core/common/threads.h>
#include <visfeat/surface_fill.h>

#include <pcl/common/point_tests.h>
#include <pcl/search/kdtree.h>

#include <algorithm>
#include <limits>
#include <memory>
#include <string>
#include <tuple>

namespace visfeat {

template <typename PointT>
pcl::PointCloud<PointT>
distinctSites(const pcl::PointCloud<PointT>& cloud, double radius)
{
  auto finite = std::make_shared<pcl::PointCloud<PointT>>();
  finite->reserve(cloud.size());
  for (const PointT& p : cloud.points)
    if (pcl::isXYZFinite(p))
      finite->push_back(p);
  const auto less = [](const PointT& a, const PointT& b) {
    return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
  };
  std::stable_sort(finite->begin(), finite->end(), less);
  pcl::PointCloud<PointT> sites;
  if (finite->empty())
    return sites;
  std::vector<char> removed(finite->size(), 0);
  pcl::search::KdTree<PointT> tree(false);
  tree.setInputCloud(finite);
  pcl::Indices found;
  std::vector<float> distances;
  for (std::size_t i = 0; i < finite->size(); ++i) {
    if (removed[i] || (i > 0 && !less((*finite)[i - 1], (*finite)[i])))
      continue; // a copy of a kept or removed point
    sites.push_back((*finite)[i]);
    if (radius > 0.0 && tree.radiusSearch((*finite)[i], radius, found, distances) > 0)
      for (const auto j : found)
        removed[static_cast<std::size_t>(j)] = 1;
  }
  sites.width = static_cast<std::uint32_t>(sites.size());
  sites.height = 1;
  sites.is_dense = true;
  return sites;
}

template <typename PointT>
std::vector<CellCoord>
localTriangleCells(const pcl::PointCloud<PointT>& cloud,
                   const GridSpec& grid,
                   const LocalTriangleParameters& parameters,
                   int threads,
                   FillReport* report)
{
  parameters.validate();
  // The finite points, their k nearest neighbours (the point itself comes first and
  // is skipped by umbrellaTriangles()).
  auto finite = std::make_shared<pcl::PointCloud<PointT>>();
  finite->reserve(cloud.size());
  for (const PointT& p : cloud.points)
    if (pcl::isXYZFinite(p))
      finite->push_back(p);
  std::vector<Eigen::Vector3d> points(finite->size());
  for (std::size_t i = 0; i < points.size(); ++i)
    points[i] = (*finite)[i].getVector3fMap().template cast<double>();
  const int k =
    std::min<int>(parameters.neighbours + 1,
                  static_cast<int>(std::max<std::size_t>(points.size(), 1)));
  std::vector<std::uint32_t> neighbours(points.size() * static_cast<std::size_t>(k),
                                        static_cast<std::uint32_t>(points.size()));
  if (points.size() >= 3) {
    pcl::search::KdTree<PointT> tree(false);
    tree.setInputCloud(finite);
    constexpr std::size_t kPointsPerChunk = 1024;
    parallelFor(points.size(), threads, kPointsPerChunk,
                [&](std::size_t begin, std::size_t end) {
                  pcl::Indices found;
                  std::vector<float> distances;
                  for (std::size_t i = begin; i < end; ++i) {
                    tree.nearestKSearch((*finite)[i], k, found, distances);
                    for (std::size_t j = 0; j < found.size(); ++j)
                      neighbours[i * static_cast<std::size_t>(k) + j] =
                        static_cast<std::uint32_t>(found[j]);
                  }
                });
  }
  const std::vector<TriangleIndices> triangles =
    umbrellaTriangles(points, neighbours, k, parameters, threads);
  if (report)
    *report = FillReport{triangles.size(), -1.0, -1.0, points.size()};
  if (parameters.crease_degrees >= 180.0)
    return rasterizeTriangles(grid, points, triangles, threads);
  const std::vector<TangentPlane> planes =
    tangentPlanes(points, neighbours, k, threads, report ? &report->noise : nullptr,
                  report ? &report->flat_share : nullptr);
  std::vector<CellCoord> cells = creaseFillCells(grid, points, planes, triangles,
                                                 parameters.crease_degrees, threads);
  const std::vector<CellCoord> strips = creaseStripCells(
    grid, points, planes, neighbours, k, parameters.crease_degrees, threads);
  std::vector<std::uint64_t> keys;
  keys.reserve(cells.size() + strips.size());
  for (const CellCoord& c : cells)
    keys.push_back(grid.linearKey(c));
  for (const CellCoord& c : strips)
    keys.push_back(grid.linearKey(c));
  return cellsOfKeys(grid, std::move(keys));
}

template <typename PointT>
std::vector<CellCoord>
organizedCells(const pcl::PointCloud<PointT>& cloud,
               const GridSpec& grid,
               const OrganizedTriangleParameters& parameters,
               int threads,
               FillReport* report)
{
  if (cloud.height <= 1 ||
      static_cast<std::size_t>(cloud.width) * cloud.height != cloud.size())
    throw Error("the fill 'grid' needs an organized cloud (height > 1), got " +
                std::to_string(cloud.width) + " x " + std::to_string(cloud.height));
  std::vector<Eigen::Vector3d> points(cloud.size());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t i = 0; i < cloud.size(); ++i)
    points[i] = pcl::isXYZFinite(cloud[i])
                  ? Eigen::Vector3d(cloud[i].x, cloud[i].y, cloud[i].z)
                  : Eigen::Vector3d(nan, nan, nan);
  const Eigen::Vector3d origin =
    cloud.sensor_origin_.template head<3>().template cast<double>();
  std::vector<TriangleIndices> triangles =
    organizedTriangles(points, static_cast<int>(cloud.width),
                       static_cast<int>(cloud.height), origin, parameters);
  if (report)
    *report = FillReport{triangles.size(), -1.0};
  // rasterizeTriangles() refuses non-finite vertices: the triangles use finite ones
  for (Eigen::Vector3d& p : points)
    if (!p.allFinite())
      p = origin;
  return rasterizeTriangles(grid, points, triangles, threads);
}

template <typename PointT>
void
pointsOnCells(const pcl::PointCloud<PointT>& cloud,
              const GridSpec& grid,
              const std::vector<CellCoord>& cells,
              std::vector<OccupiedCell>& occupied,
              std::vector<std::int32_t>& point_occupied,
              int threads)
{
  std::vector<std::uint64_t> keys(cells.size());
  for (std::size_t i = 0; i < cells.size(); ++i)
    keys[i] = grid.linearKey(cells[i]);
  auto find = [&](const CellCoord& c) -> std::int64_t {
    if (!grid.contains(c))
      return -1;
    const auto it = std::lower_bound(keys.begin(), keys.end(), grid.linearKey(c));
    return it != keys.end() && *it == grid.linearKey(c) ? it - keys.begin() : -1;
  };
  // Each point's cell (an index into cells, -1 none) on threads: the binary searches
  // are the cost (about 0.3 s for a million points on 355,000 cells).
  std::vector<std::int32_t> cell_of(cloud.size(), -1);
  constexpr std::size_t kPointsPerChunk = 16384;
  parallelFor(cloud.size(), threads, kPointsPerChunk,
              [&](std::size_t begin, std::size_t end) {
                for (std::size_t i = begin; i < end; ++i) {
                  const PointT& p = cloud[i];
                  if (!pcl::isXYZFinite(p))
                    continue;
                  const Eigen::Vector3d q(p.x, p.y, p.z);
                  const CellCoord home = grid.cellOf(q);
                  std::int64_t found = find(home);
                  if (found < 0) { // the nearest cell centre among the 26 neighbours
                    double best = std::numeric_limits<double>::infinity();
                    for (int dz = -1; dz <= 1; ++dz)
                      for (int dy = -1; dy <= 1; ++dy)
                        for (int dx = -1; dx <= 1; ++dx) {
                          const CellCoord c = home + CellCoord(dx, dy, dz);
                          const std::int64_t at = find(c);
                          const double d = (grid.cellCenter(c) - q).squaredNorm();
                          if (at >= 0 && d < best) {
                            best = d;
                            found = at;
                          }
                        }
                  }
                  cell_of[i] = static_cast<std::int32_t>(found);
                }
              });
  // The entries in the order of their first point, as one thread would make them.
  std::vector<std::int32_t> entry_of(cells.size(), -1);
  occupied.clear();
  point_occupied.assign(cloud.size(), -1);
  const double scale = OccupiedCell::kOffsetScale / grid.cell_size;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const std::int32_t found = cell_of[i];
    if (found < 0)
      continue;
    std::int32_t& entry = entry_of[static_cast<std::size_t>(found)];
    if (entry < 0) {
      entry = static_cast<std::int32_t>(occupied.size());
      OccupiedCell cell;
      cell.coord = cells[static_cast<std::size_t>(found)];
      occupied.push_back(cell);
    }
    OccupiedCell& cell = occupied[static_cast<std::size_t>(entry)];
    const PointT& p = cloud[i];
    const Eigen::Vector3d q(p.x, p.y, p.z);
    const Eigen::Vector3d cell_min =
      grid.origin + grid.cell_size * cell.coord.template cast<double>();
    const Eigen::Vector3d offset =
      ((q - cell_min) * scale).cwiseMax(0.0).cwiseMin(OccupiedCell::kOffsetScale);
    cell.offset_sum += (offset.array() + 0.5).template cast<std::int64_t>().matrix();
    ++cell.point_count;
    point_occupied[i] = entry;
  }
}

} // namespace visfeat

#define PCL_INSTANTIATE_VisfeatSurfaceFill(T)                                          \
  template pcl::PointCloud<T> visfeat::distinctSites<T>(const pcl::PointCloud<T>&,     \
                                                        double);                       \
  template std::vector<visfeat::CellCoord> visfeat::localTriangleCells<T>(             \
    const pcl::PointCloud<T>&, const visfeat::GridSpec&,                               \
    const visfeat::LocalTriangleParameters&, int, visfeat::FillReport*);               \
  template std::vector<visfeat::CellCoord> visfeat::organizedCells<T>(                 \
    const pcl::PointCloud<T>&, const visfeat::GridSpec&,                               \
    const visfeat::OrganizedTriangleParameters&, int, visfeat::FillReport*);           \
  template void visfeat::pointsOnCells<T>(                                             \
    const pcl::PointCloud<T>&, const visfeat::GridSpec&,                               \
    const std::vector<visfeat::CellCoord>&, std::vector<visfeat::OccupiedCell>&,       \
    std::vector<std::int32_t>&, int);
