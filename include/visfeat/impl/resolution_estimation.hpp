#pragma once

#include <visfeat/core/common/error.h>
#include <visfeat/resolution_estimation.h>

#include <pcl/common/point_tests.h>
#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

namespace visfeat {

template <typename PointT>
CloudShape
cloudShapeOf(const pcl::PointCloud<PointT>& cloud)
{
  return cloudShape([&cloud](const auto& visit) {
    for (const PointT& p : cloud.points)
      if (pcl::isXYZFinite(p))
        visit(Eigen::Vector3d(p.x, p.y, p.z));
  });
}

template <typename PointT>
ResolutionEstimate
estimateResolution(const pcl::PointCloud<PointT>& cloud)
{
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::max());
  Eigen::Vector3d hi = -lo;
  for (const PointT& p : cloud.points)
    if (pcl::isXYZFinite(p)) {
      lo = lo.cwiseMin(Eigen::Vector3d(p.x, p.y, p.z));
      hi = hi.cwiseMax(Eigen::Vector3d(p.x, p.y, p.z));
    }
  return estimateResolution(cloud, (hi - lo).maxCoeff());
}

template <typename PointT>
ResolutionEstimate
estimateResolution(const pcl::PointCloud<PointT>& cloud, double extent)
{
  // x y z only, in a PointXYZ cloud: the tree sees no other field, whatever PointT is.
  auto finite = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  finite->reserve(cloud.size());
  for (const PointT& p : cloud.points)
    if (pcl::isXYZFinite(p))
      finite->push_back(pcl::PointXYZ(p.x, p.y, p.z));
  const std::size_t n = finite->size();
  if (n < 2)
    throw Error("too few finite points to estimate the point spacing");
  const int k = static_cast<int>(std::min<std::size_t>(kSpacingNeighbour, n - 1));
  // k sites of up to kMaxCopies points each: copies are recognised, not counted
  const std::size_t per_query = std::min<std::size_t>(
    static_cast<std::size_t>(k) * static_cast<std::size_t>(kMaxCopies), n - 1);
  pcl::KdTreeFLANN<pcl::PointXYZ> tree;
  tree.setInputCloud(finite);
  const std::size_t stride = std::max<std::size_t>(1, n / kSpacingQueries);
  NeighbourDistanceTable table;
  table.per_query = per_query;
  table.values.reserve(std::min(n, kSpacingQueries) * per_query);
  pcl::Indices indices;
  std::vector<float> sqr_distances;
  for (std::size_t i = 0, rows = 0; i < n && rows < kSpacingQueries; i += stride) {
    // per_query + 1: the query point itself comes back too (first, at distance 0).
    const int found = tree.nearestKSearch((*finite)[i], static_cast<int>(per_query + 1),
                                          indices, sqr_distances);
    if (found != static_cast<int>(per_query + 1))
      continue;
    for (std::size_t r = 1; r <= per_query; ++r)
      table.values.push_back(std::sqrt(static_cast<double>(sqr_distances[r])));
    ++rows;
  }
  return resolutionFromNeighbourTable(table, k, extent);
}

} // namespace visfeat

#define PCL_INSTANTIATE_VisfeatResolutionEstimation(T)                                 \
  template visfeat::CloudShape visfeat::cloudShapeOf<T>(const pcl::PointCloud<T>&);    \
  template visfeat::ResolutionEstimate visfeat::estimateResolution<T>(                 \
    const pcl::PointCloud<T>&);                                                        \
  template visfeat::ResolutionEstimate visfeat::estimateResolution<T>(                 \
    const pcl::PointCloud<T>&, double);
