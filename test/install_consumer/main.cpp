// Compiled against an *installed* visfeat by test/install_consumer/run.cmake.
#include <visfeat/point_types.h>
#include <visfeat/visibility_feature_estimation.h>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <iostream>

int
main()
{
  pcl::PointCloud<visfeat::PointVisibility> cloud;
  visfeat::PointVisibility p;
  p.x = 1.0f;
  p.y = 2.0f;
  p.z = 3.0f;
  cloud.push_back(p);

  visfeat::VisibilityFeatureEstimation<pcl::PointXYZ, visfeat::PointVisibility> est;
  est.setResolution(64);

  std::cout << "visfeat consumer: cloud size " << cloud.size() << std::endl;
  return cloud.size() == 1 ? 0 : 1;
}
