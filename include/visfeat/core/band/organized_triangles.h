#pragma once

#include <visfeat/core/band/triangle_cells.h>
#include <visfeat/core/common/parameters.h>

#include <Eigen/Core>

#include <vector>

namespace visfeat {

/** \brief Where the pixel grid of an organized cloud is cut (organizedTriangles).
 *
 * Both limits are measured in the cloud's own pixel footprint (its range times the
 * angular pixel pitch, estimated from the data), so they hold at every depth and
 * resolution. The defaults were measured on the one-view depth images of the generated
 * CAD models (support's renderOrganizedView, test_organized_triangles.cpp); see each.
 */
struct OrganizedTriangleParameters
{
  /** \brief An edge longer than this many expected pixel footprints (at the nearer of
   * its two ends; sqrt(2) footprints for a diagonal on square pixels) is a depth jump:
   * no triangle uses it (footprints, [1, 1000]; 1000: practically no limit).
   *
   * A surface seen at angle phi from its normal has edges of about 1 / cos(phi)
   * footprints; independent depth noise of sigma footprints lengthens them. Measured on
   * the corner view of the cube (640 x 480, faces seen at up to 75 degrees, noise-free
   * edges under 3 footprints), with this limit alone: at noise sigma = 0.5 / 1 / 1.5
   * footprints (at depth 2.2, mid-cube; 0.8-1.4 times that over the cube), 7 keeps both
   * triangles of 100 / 99.6 / 95% of the quads inside the faces (5 keeps 99.9 / 92 /
   * 75%, 8 keeps 100 / 99.9 / 98%). A step of d footprints along a row or a column is
   * cut when d > 7 (the tests cut 7.5, which max_view_angle_degrees lets through).
   * Raise it for noisier data, lower it to cut smaller jumps. */
  double max_edge_ratio = 7.0;
  static constexpr ParameterRange<double> kMaxEdgeRatioRange{1.0, 1000.0};
  /** \brief A triangle whose normal makes more than this angle (degrees, [1, 90]; 90:
   * no limit) with the sensor's ray to its centroid is seen edge-on: the wall of a
   * depth jump or a shadow border (mixed pixels), not a surface. No triangle is made.
   *
   * The triangles across a step of d footprints are seen at about atan(d) degrees
   * along a row or a column, atan(d sqrt 2) along the image diagonal: 83 cuts steps of
   * more than 8 footprints along rows and columns (max_edge_ratio cuts them from 7) and
   * of more than 5.8 along diagonals (which the edge limit lets through up to 7; the
   * tests cut 6.2). Measured on the same cube view, this limit alone: noise-free faces
   * need 75 (70 keeps 97%); at sigma = 0.5 / 1 / 1.5 footprints 83 keeps 100 / 99.5 /
   * 94% of the quads (80 keeps 99.8 / 91 / 72%, 85 keeps 100 / 100 / 99.6%). Both
   * defaults together keep 99.4% at sigma = 1 footprint, 93% at 1.5. */
  double max_view_angle_degrees = 83.0;
  static constexpr ParameterRange<double> kMaxViewAngleRange{1.0, 90.0};

  /** \throws visfeat::Error for a value out of its range (one line). */
  void validate() const;
};

/** \brief The triangles of an organized cloud's pixel grid, cut at depth jumps and at
 * surfaces seen edge-on, so that jumps and shadow borders never join two surfaces.
 *
 * The same job as PCL's pcl::OrganizedFastMesh (its max edge length and angle
 * tolerance), kept in the PCL-free core so that the estimator can use it without a
 * dependency on PCL's surface module; the thresholds here need no camera intrinsics.
 *
 * Inputs:
 *   points         width x height positions (world units), row-major: pixel (row,
 *                  column) is points[row * width + column]; a non-finite point or one
 *                  at sensor_origin is a pixel without a return
 *   width, height  the image size (pixels), >= 1 each
 *   sensor_origin  where the rays start (world units), e.g. PCL's sensor_origin_
 *   parameters     see OrganizedTriangleParameters (validated)
 * Outputs:
 *   triangles as indices into points, row-major by quad. Each quad of 2 x 2 pixels
 *   with 4 returns gives the two triangles of its shorter diagonal (the one from its
 *   top-left corner on a tie), with 3 returns the one triangle of those; a triangle is
 *   kept when each of its edges is at most max_edge_ratio expected footprints and its
 *   view angle at most max_view_angle_degrees (degenerate triangles are dropped).
 *   Every triangle is counter-clockwise seen from sensor_origin (its normal points
 *   towards the sensor).
 *
 * The expected footprint of an edge is the range (distance to sensor_origin) of its
 * nearer end times the angular pixel pitch along the edge. The pitch is estimated
 * from the data: the median angle, seen from sensor_origin, between the rays of
 * horizontally (and apart, vertically) neighbouring returns; a diagonal combines the
 * two. On a surface facing the sensor that angle is |p - q| / range; unlike that
 * ratio it does not grow on oblique surfaces or across jumps, so the median needs no
 * filtering. The result is deterministic (one thread, fixed order).
 *
 * \throws visfeat::Error for width or height < 1, points.size() != width * height, more
 *         points than 32-bit indices address, a non-finite sensor_origin or bad
 *         parameters (one-line messages). */
std::vector<TriangleIndices>
organizedTriangles(const std::vector<Eigen::Vector3d>& points,
                   int width,
                   int height,
                   const Eigen::Vector3d& sensor_origin,
                   const OrganizedTriangleParameters& parameters);

} // namespace visfeat
