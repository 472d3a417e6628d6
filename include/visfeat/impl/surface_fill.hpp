#pragma once

#include <visfeat/core/common/threads.h>
#include <visfeat/surface_fill.h>

#include <pcl/common/point_tests.h>
#include <pcl/search/kdtree.h>

#include <algorithm>
#include <memory>

namespace visfeat {

template <typename PointT>
std::vector<CellCoord>
localTriangleCells(const pcl::PointCloud<PointT>& cloud,
                   const GridSpec& grid,
                   const LocalTriangleParameters& parameters,
                   int threads,
                   std::size_t* triangle_count)
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
  if (triangle_count)
    *triangle_count = triangles.size();
  return rasterizeTriangles(grid, points, triangles, threads);
}

} // namespace visfeat

#define PCL_INSTANTIATE_VisfeatSurfaceFill(T)                                          \
  template std::vector<visfeat::CellCoord> visfeat::localTriangleCells<T>(             \
    const pcl::PointCloud<T>&, const visfeat::GridSpec&,                               \
    const visfeat::LocalTriangleParameters&, int, std::size_t*);
