// The turn across a crease at one point of it, from planes fitted to the face points
// on its two sides (private to core/graph: the crease-angle measurement,
// crease_angles.h).
#pragma once

#include "face_point_index.h"

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <limits>
#include <vector>

namespace visfeat {
namespace detail {

/** One sample's measure: its two main faces (smaller label first) and their turn. */
struct SampleTurn
{
  std::array<std::uint32_t, 2> faces{{0, 0}};
  double degrees = std::numeric_limits<double>::quiet_NaN();
};

/** The turn at `at` between the two faces with most points within radius (world
 * units; each side needs CreaseAngleParameters::kMinSidePoints), less the turn the
 * surface repeats a window beside it; where that is below walk_below_degrees, the
 * sharpest turn so measured walking kContactScanWindows windows to both sides across
 * (measureCreaseAngles()). */
SampleTurn measureSample(const FacePointIndex& index,
                         const std::vector<Eigen::Vector3d>& points,
                         const std::vector<std::uint32_t>& labels,
                         const Eigen::Vector3d& at,
                         double radius,
                         double walk_below_degrees);

/** measureSample() at the middle between the centroids of the two faces with most
 * points within radius of `at` (each needs kMinSidePoints; else NaN): a sample point
 * of an edge region wider than the window lies beside the crease, its window holding
 * its own side around it and a sliver of the other (a 27.7-degree crease read 166
 * degrees there). */
SampleTurn measureSampleBetweenSides(const FacePointIndex& index,
                                     const std::vector<Eigen::Vector3d>& points,
                                     const std::vector<std::uint32_t>& labels,
                                     const Eigen::Vector3d& at,
                                     double radius,
                                     double walk_below_degrees);

/** The turn at `at` (degrees) across the contact of the two faces of `pair`, from their
 * points within radius split by geometry, not by label: the labels give only the
 * direction across (from one face's centroid to the other's, in the plane of both); the
 * points of both faces on either side of `at` along it are the two sides. Where the
 * watershed's boundary wanders off a crease each face holds points of both surfaces,
 * and planes fitted by label would both average them (a 90-degree crease read 4-13
 * degrees on the filleted box). The larger of it and the sharpest turn met walking
 * across, as measureSample(); NaN when a side holds too few points. */
double contactTurn(const FacePointIndex& index,
                   const std::vector<Eigen::Vector3d>& points,
                   const std::vector<std::uint32_t>& labels,
                   const Eigen::Vector3d& at,
                   double radius,
                   const std::array<std::uint32_t, 2>& pair);

/** The median of values (sorted in place); NaN when empty. */
double median(std::vector<double>& values);

} // namespace detail
} // namespace visfeat
