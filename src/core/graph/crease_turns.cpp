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

/** A window of the walk across (or beside) a crease: the pair's points within radius
 * of `position`. */
struct Window
{
  std::vector<Eigen::Vector3d> local; // relative to the position before the move
  PlaneSums all;
};

/** The turn at `position` across `direction` over the pair's points within radius:
 * the position moves onto the plane of those points and the direction turns into it;
 * the points before and after the plane through it across the direction are the two
 * halves (turnOfHalves(), the line being normal x direction), their sums relative to
 * the moved position returned in before and after. Returns false (the walk ends)
 * where the window holds fewer than 2 kMinSidePoints or kScanMinWindowShare of
 * first_count points (the faces' border: another face, a hole, the cloud's end) or
 * the direction vanishes; `turn` is NaN where a half is a sliver (fewer than
 * kMinSidePoints or kScanMinSideShare of the window). Only the points on the side
 * of half_normal of the plane through half_origin count (a zero normal: all). */
bool
turnInWindow(const FacePointIndex& index,
             const std::vector<Eigen::Vector3d>& points,
             const std::vector<std::uint32_t>& labels,
             Eigen::Vector3d& position,
             Eigen::Vector3d& direction,
             double radius,
             const std::array<std::uint32_t, 2>& pair,
             std::size_t first_count,
             const Eigen::Vector3d& half_origin,
             const Eigen::Vector3d& half_normal,
             Window& window,
             PlaneSums& before,
             PlaneSums& after,
             double& turn)
{
  turn = std::numeric_limits<double>::quiet_NaN();
  window.local.clear();
  window.all = PlaneSums();
  index.forEachWithin(position, radius, [&](std::uint32_t i) {
    if ((labels[i] != pair[0] && labels[i] != pair[1]) ||
        (points[i] - half_origin).dot(half_normal) < 0.0)
      return;
    window.local.push_back(points[i] - position);
    window.all.add(window.local.back());
  });
  const PlaneSums& all = window.all;
  if (all.count < 2 * CreaseAngleParameters::kMinSidePoints ||
      double(all.count) < kScanMinWindowShare * double(first_count))
    return false;
  const Eigen::Vector3d n = all.normal();
  const Eigen::Vector3d offset = all.mean().dot(n) * n; // onto the local plane
  position += offset;
  direction -= direction.dot(n) * n;
  if (!(direction.norm() > 0.0))
    return false;
  direction.normalize();
  before = PlaneSums();
  after = PlaneSums();
  splitAcross(window.local, offset, direction, before, after);
  if (before.count < CreaseAngleParameters::kMinSidePoints ||
      after.count < CreaseAngleParameters::kMinSidePoints ||
      double(std::min(before.count, after.count)) <
        kScanMinSideShare * double(all.count))
    return true;
  turn = turnOfHalves(before, after, n.cross(direction).normalized());
  return true;
}

/** The part of `turn`, measured at `origin` on a crease between sides a and b (sums
 * relative to origin), that the surface does not repeat one window into each side:
 * turn minus the smaller of the turns there, at least 0. The turn into a side is
 * turnInWindow() at the window one radius from origin along sideDirection(), over the
 * pair's points; a side where it cannot be measured (the face ends: a corner, a hole)
 * repeats nothing. A crease between flat faces keeps its turn (less the noise of a flat
 * window's halves); a cylinder or a fillet wider than the window turns alike beside
 * the sample and reads about 0 (the box with hole at 10,000 points, 4 cells a spacing,
 * its window 16 cells: the hole's wall, radius 42 cells, read 20-23 degrees at the
 * watershed's cuts across it and 15-21 a window beside them; its 90-degree rims 90 and
 * 0-5). */
double
concentratedTurn(double turn,
                 const FacePointIndex& index,
                 const std::vector<Eigen::Vector3d>& points,
                 const std::vector<std::uint32_t>& labels,
                 const Eigen::Vector3d& origin,
                 const PlaneSums& a,
                 const PlaneSums& b,
                 double radius,
                 const std::array<std::uint32_t, 2>& pair,
                 std::size_t first_count)
{
  if (!std::isfinite(turn))
    return turn;
  Eigen::Vector3d foot_a, away_a, foot_b, away_b;
  if (!sideDirection(a, b, foot_a, away_a) || !sideDirection(b, a, foot_b, away_b))
    return turn;
  // Each side's window keeps the points nearer its side than the other's (beyond the
  // plane bisecting the two directions): where the faces fold back (a turn above 90
  // degrees) the other face passes within a window of it.
  const Eigen::Vector3d bisector_normal = away_a - away_b;
  const double separation = (a.mean() - b.mean()).norm();
  double repeated = std::numeric_limits<double>::infinity();
  Window window;
  PlaneSums before, after;
  for (const bool side_a : {true, false}) {
    Eigen::Vector3d away = side_a ? away_a : away_b;
    Eigen::Vector3d position = origin + (side_a ? foot_a : foot_b) + radius * away;
    double beside = 0.0;
    if (turnInWindow(index, points, labels, position, away, radius, pair, first_count,
                     origin,
                     side_a ? bisector_normal : Eigen::Vector3d(-bisector_normal),
                     window, before, after, beside) &&
        std::isfinite(beside))
      // as much as the surface turns there between points as far apart as the
      // sides at origin (a bend's turn grows with the distance between the centroids
      // of the planes compared, and the sides at origin lie beyond the edge region's
      // points, a window beside they do not)
      repeated =
        std::min(repeated, beside * separation / (before.mean() - after.mean()).norm());
    if (repeated <= 0.0)
      break;
  }
  return std::isfinite(repeated) ? std::max(0.0, turn - repeated) : turn;
}

/** Walking from `at` along `direction` over the two faces' points (steps of half the
 * window, kContactScanWindows windows far, turnInWindow() at each position), the
 * largest concentratedTurn() between the points before and after a position; 0 when
 * no position holds kMinSidePoints a side. first_count: the two faces' points within
 * the window at `at` (the caller's own query there). */
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
  Window window;
  PlaneSums before, after;
  for (int k = 1; k <= steps; ++k) {
    position += 0.5 * radius * direction;
    double turn = 0.0;
    if (!turnInWindow(index, points, labels, position, direction, radius, pair,
                      first_count, position, Eigen::Vector3d::Zero(), window, before,
                      after, turn))
      break;
    if (!std::isfinite(turn) || turn <= sharpest) // the discount only lowers it
      continue;
    sharpest =
      std::max(sharpest, concentratedTurn(turn, index, points, labels, position, before,
                                          after, radius, pair, first_count));
  }
  return sharpest;
}

/** The face points within radius of a point, per face label (sums relative to the
 * point), and the two faces with most of them (the smaller label first among equals)
 * with their counts. */
struct MainSides
{
  std::map<std::uint32_t, PlaneSums> sides;
  std::uint32_t first = 0, second = 0;
  std::size_t n_first = 0, n_second = 0;
};

MainSides
mainSidesAround(const FacePointIndex& index,
                const std::vector<Eigen::Vector3d>& points,
                const std::vector<std::uint32_t>& labels,
                const Eigen::Vector3d& at,
                double radius)
{
  MainSides main;
  index.forEachWithin(
    at, radius, [&](std::uint32_t i) { main.sides[labels[i]].add(points[i] - at); });
  for (const auto& [label, sums] : main.sides) {
    if (sums.count > main.n_first) {
      main.second = main.first;
      main.n_second = main.n_first;
      main.first = label;
      main.n_first = sums.count;
    } else if (sums.count > main.n_second) {
      main.second = label;
      main.n_second = sums.count;
    }
  }
  return main;
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
  MainSides main = mainSidesAround(index, points, labels, at, radius);
  auto& sides = main.sides;
  const std::uint32_t first = main.first, second = main.second;
  const std::size_t n_first = main.n_first, n_second = main.n_second;
  SampleTurn turn;
  if (n_second < CreaseAngleParameters::kMinSidePoints)
    return turn;
  turn.faces = {{std::min(first, second), std::max(first, second)}};
  const std::array<std::uint32_t, 2> pair{{first, second}};
  turn.degrees =
    concentratedTurn(turnOfSides(sides[first], sides[second]), index, points, labels,
                     at, sides[first], sides[second], radius, pair, n_first + n_second);
  if (!std::isfinite(turn.degrees) || turn.degrees >= walk_below_degrees)
    return turn;
  // the sharpest turn across: an edge region on a chamfer narrower than the
  // separation has both faces' points on the chamfer beside it (a 45-degree chamfer
  // crease read 15 degrees), its creases lie a few cells away
  const Eigen::Vector3d across = acrossDirection(sides[first], sides[second]);
  if (across.isZero())
    return turn;
  for (const double way : {1.0, -1.0})
    turn.degrees =
      std::max(turn.degrees, sharpestTurnAlong(index, points, labels, at, way * across,
                                               radius, pair, n_first + n_second));
  return turn;
}

SampleTurn
measureSampleBetweenSides(const FacePointIndex& index,
                          const std::vector<Eigen::Vector3d>& points,
                          const std::vector<std::uint32_t>& labels,
                          const Eigen::Vector3d& at,
                          double radius,
                          double walk_below_degrees)
{
  const MainSides main = mainSidesAround(index, points, labels, at, radius);
  if (main.n_second < CreaseAngleParameters::kMinSidePoints)
    return SampleTurn{};
  const Eigen::Vector3d middle =
    at + 0.5 * (main.sides.at(main.first).mean() + main.sides.at(main.second).mean());
  return measureSample(index, points, labels, middle, radius, walk_below_degrees);
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
  const double here =
    concentratedTurn(turnOfSides(side_a, side_b), index, points, labels, at, side_a,
                     side_b, radius, pair, local.size());
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
