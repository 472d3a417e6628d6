// visfeat_eval's PCL peer: surface variation from pcl::NormalEstimationOMP.

#include "peers.h"

#include <pcl/features/normal_3d_omp.h>
#include <pcl/search/kdtree.h>

#include <chrono>
#include <limits>
#include <memory>

namespace visfeat_tools {

PeerScore
pclSurfaceVariation(const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& cloud,
                    int k,
                    unsigned int threads)
{
  PeerScore result;
  pcl::NormalEstimationOMP<pcl::PointXYZ, pcl::Normal> ne(threads);
  ne.setInputCloud(cloud);
  ne.setSearchMethod(std::make_shared<pcl::search::KdTree<pcl::PointXYZ>>());
  ne.setKSearch(k);
  pcl::PointCloud<pcl::Normal> normals;
  const auto t0 = std::chrono::steady_clock::now(); // the kd-tree is built in compute()
  ne.compute(normals);
  result.seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (normals.size() != cloud->size()) {
    result.error = "NormalEstimationOMP failed";
    return result;
  }
  result.score.resize(normals.size());
  for (std::size_t i = 0; i < normals.size(); ++i)
    result.score[i] = normals[i].curvature; // NaN where the estimate failed
  return result;
}

} // namespace visfeat_tools
