// Unit tests of the pictures' camera direction (picture_camera.h): labelled clouds made
// here, with known outward face normals.

#include "picture/picture_camera.h"

#include <visfeat/core/common/feature_class.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

namespace {

using Cloud = pcl::PointCloud<visfeat::PointVisibility>;

/** Face points on an n x n grid of the square [0, 1]^2 mapped by origin + u s + v t. */
void
addFace(Cloud& cloud,
        std::uint32_t label,
        const Eigen::Vector3d& origin,
        const Eigen::Vector3d& u,
        const Eigen::Vector3d& v,
        int n)
{
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const Eigen::Vector3d p = origin + u * (i + 0.5) / n + v * (j + 0.5) / n;
      visfeat::PointVisibility q;
      q.x = static_cast<float>(p.x());
      q.y = static_cast<float>(p.y());
      q.z = static_cast<float>(p.z());
      q.label = label;
      q.feature_class = static_cast<std::uint8_t>(visfeat::FeatureClass::kFace);
      cloud.push_back(q);
    }
}

/** A flat slab 4 x 4 x 0.2 (big bottom face at z = 0, its sides) carrying a roof of
 * four planar faces rising to a ridge on top: one large face seen from below, five
 * smaller ones seen from above. */
Cloud
roofOnASlab()
{
  Cloud cloud;
  const double w = 4.0, h = 0.2;
  addFace(cloud, 1, {0, 0, 0}, {w, 0, 0}, {0, w, 0}, 60); // the flat bottom
  addFace(cloud, 2, {0, 0, 0}, {w, 0, 0}, {0, 0, h}, 20);
  addFace(cloud, 3, {0, w, 0}, {w, 0, 0}, {0, 0, h}, 20);
  addFace(cloud, 4, {0, 0, 0}, {0, w, 0}, {0, 0, h}, 20);
  addFace(cloud, 5, {w, 0, 0}, {0, w, 0}, {0, 0, h}, 20);
  // the roof: two slopes up to a ridge along x at y = 2, z = h + 1, and two gables
  addFace(cloud, 6, {0, 0, h}, {w, 0, 0}, {0, 2, 1}, 30);
  addFace(cloud, 7, {0, w, h}, {w, 0, 0}, {0, -2, 1}, 30);
  addFace(cloud, 8, {0.5, 0.5, h + 0.3}, {0, 3, 0}, {0.5, 0, 0.4}, 15);
  addFace(cloud, 9, {3.5, 0.5, h + 0.3}, {0, 3, 0}, {-0.5, 0, 0.4}, 15);
  return cloud;
}

TEST(PictureCamera, SeesTheDetailedSideNotTheLargeFlatBack)
{
  const Eigen::Vector3d d = visfeat_tools::chooseDirection(roofOnASlab());
  EXPECT_NEAR(d.norm(), 1.0, 1e-9);
  // from above: the roof's slopes face +z, the bottom -z
  EXPECT_GT(d.z(), 0.3) << d.transpose();
  // and upside down: from below
  Cloud flipped = roofOnASlab();
  for (auto& p : flipped)
    p.z = -p.z;
  EXPECT_LT(visfeat_tools::chooseDirection(flipped).z(), -0.3);
}

TEST(PictureCamera, SeesThreeFacesOfABox)
{
  Cloud cloud;
  const double a = 2.0;
  std::uint32_t label = 1;
  for (int axis = 0; axis < 3; ++axis)
    for (const double at : {0.0, a}) {
      Eigen::Vector3d origin = Eigen::Vector3d::Zero(), u = Eigen::Vector3d::Zero(),
                      v = Eigen::Vector3d::Zero();
      origin[axis] = at;
      u[(axis + 1) % 3] = a;
      v[(axis + 2) % 3] = a;
      addFace(cloud, label++, origin, u, v, 25);
    }
  const Eigen::Vector3d d = visfeat_tools::chooseDirection(cloud);
  for (int axis = 0; axis < 3; ++axis)
    EXPECT_GT(std::abs(d[axis]), 0.3) << d.transpose();
}

TEST(PictureCamera, WithoutPlanarFacesTheDefault)
{
  Cloud cloud; // points of a sphere, one face region: not planar
  for (int i = 0; i < 2000; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / 2000, r = std::sqrt(1.0 - z * z);
    const double phi = i * M_PI * (3.0 - std::sqrt(5.0));
    visfeat::PointVisibility q;
    q.x = static_cast<float>(r * std::cos(phi));
    q.y = static_cast<float>(r * std::sin(phi));
    q.z = static_cast<float>(z);
    q.label = 1;
    q.feature_class = static_cast<std::uint8_t>(visfeat::FeatureClass::kFace);
    cloud.push_back(q);
  }
  const Eigen::Vector3d d = visfeat_tools::chooseDirection(cloud);
  EXPECT_TRUE(d.isApprox(Eigen::Vector3d(1.0, 0.78, 0.62).normalized(), 1e-12))
    << d.transpose();
}

TEST(PictureCamera, AnOrganizedCloudIsSeenFromItsSensor)
{
  // a 40 x 30 depth image of a wall 2 units ahead of a sensor at the origin, turned
  // 90 degrees about its z axis (its image rows then run along world -x)
  Cloud cloud;
  cloud.width = 40;
  cloud.height = 30;
  for (int row = 0; row < 30; ++row)
    for (int col = 0; col < 40; ++col) {
      visfeat::PointVisibility q;
      q.x = static_cast<float>(0.05 * (col - 20));
      q.y = static_cast<float>(0.05 * (row - 15));
      q.z = 2.0f;
      q.label = 1;
      q.feature_class = static_cast<std::uint8_t>(visfeat::FeatureClass::kFace);
      cloud.push_back(q);
    }
  cloud.width = 40;
  cloud.height = 30;
  cloud.sensor_orientation_ =
    Eigen::Quaternionf(Eigen::AngleAxisf(float(M_PI / 2), Eigen::Vector3f::UnitZ()));
  Eigen::Vector3d direction, up;
  ASSERT_TRUE(visfeat_tools::sensorView(cloud, direction, up));
  EXPECT_TRUE(direction.isApprox(Eigen::Vector3d(0, 0, -1), 1e-6)) << direction;
  EXPECT_TRUE(up.isApprox(Eigen::Vector3d(1, 0, 0), 1e-6)) << up; // -(turned y)
  const Eigen::Vector3d lo(-1, -0.75, 2), hi(0.95, 0.7, 2);
  const visfeat_tools::View view =
    visfeat_tools::fitView(cloud, lo, hi, direction, 800, 600, 0.0, &up);
  EXPECT_TRUE(view.up.isApprox(up, 1e-6)) << view.up;
  EXPECT_LT(view.position.z(), 2.0); // on the sensor's side of the wall
  // without the hint, the major axis is horizontal and up points to +z or sideways
  const visfeat_tools::View free_view =
    visfeat_tools::fitView(cloud, lo, hi, direction, 800, 600, 0.0);
  EXPECT_FALSE(free_view.up.isApprox(up, 1e-3)) << free_view.up;
  // an unorganized cloud has no sensor view
  Cloud flat = cloud;
  flat.width = static_cast<std::uint32_t>(flat.size());
  flat.height = 1;
  EXPECT_FALSE(visfeat_tools::sensorView(flat, direction, up));
}

} // namespace
