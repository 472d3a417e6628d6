#pragma once

// An organized depth view of a CAD model, as a structured-light or time-of-flight
// camera takes it: one pinhole view ray cast against the exact faces, with
// depth-dependent noise and the shadows of a projector beside the camera.

#include <support/cad_model.h>

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace visfeat {
namespace synthetic {

/** \brief The camera of an organized view. The camera sits at target + distance *
 * camera_direction and looks at target; image x runs to the right, image y down, and
 * the optical axis z forward (x cross y = z). */
struct OrganizedViewOptions
{
  /** Image size (pixels), >= 1 each. */
  int width = 640;
  int height = 480;
  /** Horizontal field of view (degrees, in (0, 180)); pixels are square. */
  double horizontal_fov = 60.0;
  /** Unit vector from the target to the camera; the default sees a corner of the cube
   * (three faces, three edges, one vertex). */
  Eigen::Vector3d camera_direction = Eigen::Vector3d(1.0, 1.0, 1.0).normalized();
  /** The world direction that appears upwards in the image (-y); any vector not
   * parallel to camera_direction (when it is, another axis is taken). */
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  /** The point looked at (world units): the origin is the centre of every catalogue
   * model and of its rotations. */
  Eigen::Vector3d target = Eigen::Vector3d::Zero();
  /** Camera distance from the target (world units); 0: automatic, the sphere about
   * the target that holds the model fills 90% of the smaller field of view. */
  double distance = 0.0;
  /** Depth noise: a Gaussian displacement along the pixel's ray whose standard
   * deviation is noise_a + noise_b * depth^2 (depth: distance along the optical axis;
   * noise_a in world units, noise_b in 1 / world units). */
  double noise_a = 0.0;
  double noise_b = 0.0;
  /** Projector offset from the camera along image x (world units, may be negative): a
   * pixel whose surface point the projector does not see is empty (a shadow). 0: no
   * shadows. */
  double baseline = 0.0;
  /** Seed of the noise (one draw per pixel in row-major order, so a pixel's noise does
   * not depend on the baseline or on which other pixels hit). */
  std::uint64_t seed = 1;
};

/** \brief An organized view: width x height pixels, row-major (index = row * width +
 * column), with the camera that took it. Empty pixels (no surface, or a shadow) have
 * NaN coordinates, face -1 and a NaN curve distance. */
struct OrganizedView
{
  int width = 0;
  int height = 0;
  /** Per pixel: the surface point (world units), noise added along the ray. */
  std::vector<Eigen::Vector3f> points;
  /** Per pixel: the id of the face the ray hit, -1 for none. */
  std::vector<int> face;
  /** Per pixel: the distance from the noise-free point to the nearest true sharp
   * curve (world units). */
  std::vector<double> curve_distance;
  /** Camera centre and axes (columns: image x, image y, optical axis; world units). */
  Eigen::Vector3d camera_position = Eigen::Vector3d::Zero();
  Eigen::Matrix3d camera_axes = Eigen::Matrix3d::Identity();
  Eigen::Vector3d projector_position = Eigen::Vector3d::Zero();
  /** Focal length (pixels): pixel (column c, row r) looks along camera_axes * ((c +
   * 0.5 - width / 2) / focal, (r + 0.5 - height / 2) / focal, 1). */
  double focal = 0.0;
};

/** \brief One organized depth view of the model.
 *
 * Inputs:
 *   model    the CAD model (checkCadModel() holds), seen from outside
 *   options  image size, field of view, camera placement, noise, baseline, seed
 * Outputs:
 *   per pixel the nearest intersection of its ray with the exact faces (planes
 *   clipped to their boundaries and holes, finite cylinders), not with a
 *   tessellation; a pixel is empty when its ray misses the model or, with a baseline,
 *   when the segment from the projector to its point meets the surface first.
 * \throws visfeat::Error for a bad size, field of view, direction, distance, noise or
 *         a camera inside the model's bounding sphere. */
OrganizedView renderOrganizedView(const CadModel& model,
                                  const OrganizedViewOptions& options);

} // namespace synthetic
} // namespace visfeat
