#pragma once

#include <support/portable_random.h>

#include <pcl/point_cloud.h>

#include <cstdint>
#include <numeric>
#include <random>
#include <vector>

namespace visfeat_test {

/** \brief A cloud's points in a shuffled order: shuffled.points[j] is
 * cloud.points[order[j]] (visfeat::synthetic::shuffle, the same on every platform),
 * with the cloud's is_dense. */
template <typename PointT>
struct ShuffledCloud
{
  pcl::PointCloud<PointT> cloud;
  std::vector<std::size_t> order;
};

template <typename PointT>
ShuffledCloud<PointT>
shuffledCloud(const pcl::PointCloud<PointT>& cloud, std::uint64_t seed)
{
  ShuffledCloud<PointT> shuffled;
  shuffled.order.resize(cloud.size());
  std::iota(shuffled.order.begin(), shuffled.order.end(), 0);
  std::mt19937_64 rng(seed);
  visfeat::synthetic::shuffle(shuffled.order, rng);
  for (const std::size_t i : shuffled.order)
    shuffled.cloud.push_back(cloud.points[i]);
  shuffled.cloud.is_dense = cloud.is_dense;
  return shuffled;
}

} // namespace visfeat_test
