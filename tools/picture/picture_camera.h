// Where the visfeat tool's pictures look from (not installed, not public API): the view
// direction that shows the most surface, a camera fitted to the points, and a point
// size that makes the surfaces look closed. Eigen only: no VTK here.
#pragma once

#include <visfeat/point_types.h>

#include <pcl/point_cloud.h>

#include <Eigen/Core>

#include <cstddef>

namespace visfeat_tools {

/** \brief The direction to look from (from the object towards the camera): the one
 * that shows the most faces, then the most planar surface.
 *
 * Each face region's normal (its points' smallest covariance eigenvector) is turned
 * outward, away from the centroid of all points (right for convex parts; a hole's
 * walls come out inward). A direction sees the faces whose outward normal lies within
 * about 72 degrees of it; among the directions that see the most faces, the planar
 * ones facing it (smallest eigenvalue below 1% of the middle one) add their point
 * count times the cosine (their projected area): a cube is seen from a corner, three
 * faces at once, and a part with one large flat back and a detailed front (the
 * fandisk) from the front. Among the directions within 3% of the best area, the one
 * closest to the default wins (deterministic, and never exactly along a diagonal).
 * Without a planar face (raw mode, smooth objects): the default, the bounding-box
 * diagonal (1,1,1) tilted a little so that opposite corners of a box do not project
 * onto each other. Unit length. */
Eigen::Vector3d chooseDirection(const pcl::PointCloud<visfeat::PointVisibility>& cloud);

/** \brief The camera: perspective, looking from `direction`; the longer axis of the
 * object on screen horizontal (the frame is wider than high) unless the object looks
 * round from there (then world z is up); centred on the object's projected box, at the
 * distance where every point is inside `fill` of the frame. */
struct View
{
  Eigen::Vector3d focal, position, up;
  double view_angle_deg = 30.0;
  double pixels_per_unit = 1.0; // at the focal point
  /** \brief vtkCamera::SetWindowCenter x: shifts the object left of the frame's
   * centre when the right side is reserved (for the scalar bar). */
  double window_center_x = 0.0;
};

/** \brief The View of the finite points of `cloud` (bounding box lo-hi) from
 * `direction` in a width x height frame whose right `right_reserve` (a fraction of the
 * half width) is kept free. With `up` (not parallel to `direction`), the screen's up
 * is that direction (an organized cloud: its sensor's up) instead of the choice
 * above. */
View fitView(const pcl::PointCloud<visfeat::PointVisibility>& cloud,
             const Eigen::Vector3d& lo,
             const Eigen::Vector3d& hi,
             const Eigen::Vector3d& direction,
             int width,
             int height,
             double right_reserve,
             const Eigen::Vector3d* up = nullptr);

/** \brief For an organized cloud (height > 1), its sensor's view: the direction from
 * the scene towards the sensor (the sensor looks along its +z, sensor_orientation_)
 * and the sensor's up (its -y: image rows run down +y). False for an unorganized
 * cloud. */
bool sensorView(const pcl::PointCloud<visfeat::PointVisibility>& cloud,
                Eigen::Vector3d& direction,
                Eigen::Vector3d& up);

/** \brief Point size in pixels: about 2.2 times the estimated point spacing on screen,
 * so that the surfaces look closed, 2-10. Spacing: sqrt(area / points), the area
 * estimated as band cells x cell size^2; 2 when any of them is 0. */
float pointSize(double cell_size,
                std::size_t band_cells,
                std::size_t points,
                const View& view);

} // namespace visfeat_tools
