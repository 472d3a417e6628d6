// The turn across a crease at one point of it (crease_turns.h): planes fitted to the
// two faces' points, and the walk across a blend for the sharpest turn.

#include "crease_turns.h"

#include <visfeat/core/graph/crease_angles.h>

#include "plane_sums.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace visfeat {
namespace detail {

namespace {

/** The walk across a blend stops where its window holds fewer than this share of the
 * points of its first window (measured on two half-planes 12 cells wide: windows at
 * their outer border read turns of 20-70 degrees for a 10-degree crease). */
constexpr double kScanMinWindowShare = 0.75;
/** A position of the walk is measured only when each side holds this share of the
 * window's points: a sliver's plane is noise. */
constexpr double kScanMinSideShare = 0.3;

/** Walking from `at` along `direction` over the two faces' points (steps of half the
 * window, kContactScanWindows windows far, each position moved onto the plane of the
 * points around it and the direction turned into that plane), the largest turn
 * between the points before and after a position (sideTurnDegrees() of the window);
 * 0 when no position holds kMinSidePoints a side. first_count: the two faces' points
 * within the window at `at` (the caller's own query there). */
double
sharpestTurnAlong(const FacePointIndex& index,
                  const std::vector<Eigen::Vector3d>& points,
                  const std::vector<std::uint32_t>& labels,
                  const Eigen::Vector3d& at,
                  Eigen::Vector3d direction,
                  double radius,
                  const std::array<std::uint32_t, 2>& pair,
                  std::size_t first_count)
{
  double sharpest = 0.0;
  Eigen::Vector3d position = at;
  const int steps = static_cast<int>(2.0 * CreaseAngleParameters::kContactScanWindows);
  std::vector<Eigen::Vector3d> local;
  // a window that holds much fewer points than the first reaches the faces' border
  // (another face, a hole, the cloud's end), where a side is a sliver whose plane is
  // noise: the walk ends there
  for (int k = 1; k <= steps; ++k) {
    position += 0.5 * radius * direction;
    local.clear();
    PlaneSums all;
    index.forEachWithin(position, radius, [&](std::uint32_t i) {
      if (labels[i] != pair[0] && labels[i] != pair[1])
        return;
      local.push_back(points[i] - position);
      all.add(local.back());
    });
    if (all.count < 2 * CreaseAngleParameters::kMinSidePoints ||
        double(all.count) < kScanMinWindowShare * double(first_count))
      break;
    const Eigen::Vector3d n = all.normal();
    const Eigen::Vector3d offset = all.mean().dot(n) * n; // onto the local plane
    position += offset;
    direction -= direction.dot(n) * n;
    if (!(direction.norm() > 0.0))
      break;
    direction.normalize();
    PlaneSums before, after;
    splitAcross(local, offset, direction, before, after);
    if (before.count < CreaseAngleParameters::kMinSidePoints ||
        after.count < CreaseAngleParameters::kMinSidePoints ||
        double(std::min(before.count, after.count)) <
          kScanMinSideShare * double(all.count))
      continue;
    const double turn = turnOfSides(before, after);
    if (std::isfinite(turn))
      sharpest = std::max(sharpest, turn);
  }
  return sharpest;
}

} // namespace

SampleTurn
measureSample(const FacePointIndex& index,
              const std::vector<Eigen::Vector3d>& points,
              const std::vector<std::uint32_t>& labels,
              const Eigen::Vector3d& at,
              double radius,
              double walk_below_degrees)
{
  std::map<std::uint32_t, PlaneSums> sides;
  index.forEachWithin(at, radius,
                      [&](std::uint32_t i) { sides[labels[i]].add(points[i] - at); });
  // The two faces with most points (the smaller label first among equals).
  std::uint32_t first = 0, second = 0;
  std::size_t n_first = 0, n_second = 0;
  for (const auto& [label, sums] : sides) {
    if (sums.count > n_first) {
      second = first;
      n_second = n_first;
      first = label;
      n_first = sums.count;
    } else if (sums.count > n_second) {
      second = label;
      n_second = sums.count;
    }
  }
  SampleTurn turn;
  if (n_second < CreaseAngleParameters::kMinSidePoints)
    return turn;
  turn.faces = {{std::min(first, second), std::max(first, second)}};
  turn.degrees = turnOfSides(sides[first], sides[second]);
  if (!std::isfinite(turn.degrees) || turn.degrees >= walk_below_degrees)
    return turn;
  // the sharpest turn across: an edge region on a chamfer narrower than the
  // separation has both faces' points on the chamfer beside it (a 45-degree chamfer
  // crease read 15 degrees), its creases lie a few cells away
  const Eigen::Vector3d across = acrossDirection(sides[first], sides[second]);
  if (across.isZero())
    return turn;
  for (const double way : {1.0, -1.0})
    turn.degrees = std::max(
      turn.degrees, sharpestTurnAlong(index, points, labels, at, way * across, radius,
                                      {{first, second}}, n_first + n_second));
  return turn;
}

double
contactTurn(const FacePointIndex& index,
            const std::vector<Eigen::Vector3d>& points,
            const std::vector<std::uint32_t>& labels,
            const Eigen::Vector3d& at,
            double radius,
            const std::array<std::uint32_t, 2>& pair)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<Eigen::Vector3d> local;
  PlaneSums a, b;
  index.forEachWithin(at, radius, [&](std::uint32_t i) {
    const Eigen::Vector3d p = points[i] - at;
    if (labels[i] == pair[0])
      a.add(p);
    else if (labels[i] == pair[1])
      b.add(p);
    else
      return;
    local.push_back(p);
  });
  if (a.count < CreaseAngleParameters::kMinSidePoints ||
      b.count < CreaseAngleParameters::kMinSidePoints)
    return nan;
  const Eigen::Vector3d across = acrossDirection(a, b);
  if (across.isZero())
    return nan;
  PlaneSums side_a, side_b;
  splitAcross(local, Eigen::Vector3d::Zero(), across, side_b, side_a);
  if (side_a.count < CreaseAngleParameters::kMinSidePoints ||
      side_b.count < CreaseAngleParameters::kMinSidePoints)
    return nan;
  const double here = turnOfSides(side_a, side_b);
  if (!std::isfinite(here))
    return nan;
  // The sharpest turn across the blend: a chamfer narrower than the separation is
  // split between its two faces like a fillet, but its middle is flat and its turns
  // are sharp a few cells away.
  double sharpest = here;
  for (const double way : {1.0, -1.0})
    sharpest =
      std::max(sharpest, sharpestTurnAlong(index, points, labels, at, way * across,
                                           radius, pair, local.size()));
  return sharpest;
}

double
median(std::vector<double>& values)
{
  if (values.empty())
    return std::numeric_limits<double>::quiet_NaN();
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

} // namespace detail
} // namespace visfeat
