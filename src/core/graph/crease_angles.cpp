// Sharp versus smooth (crease_angles.h): the turn across each edge region from planes
// fitted to its two sides, and the merge of the edges that turn less than the minimum.

#include <visfeat/core/graph/crease_angles.h>

#include <visfeat/core/band/voxel_band.h>
#include <visfeat/core/common/threads.h>

#include "../common/angles.h"
#include "face_point_index.h"
#include "plane_sums.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>
#include <set>

namespace visfeat {

void
CreaseAngleParameters::validate() const
{
  checkRange("min_crease_angle", min_crease_angle, kMinCreaseAngleRange, "degrees");
  checkRange("crease_window", window_cells, kWindowCellsRange, "cells");
}

namespace {

using detail::acrossDirection;
using detail::FacePointIndex;
using detail::PlaneSums;
using detail::splitAcross;
using detail::turnOfSides;

/** One sample's measure: its two main faces (smaller label first) and their turn. */
struct SampleTurn
{
  std::array<std::uint32_t, 2> faces{{0, 0}};
  double degrees = std::numeric_limits<double>::quiet_NaN();
};

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

/** The turn at `at` between the two faces with most points within radius. */
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

/** The turn at `at` across the contact of the two faces of `pair`, from their points
 * within radius split by geometry, not by label: the labels give only the direction
 * across (from one face's centroid to the other's, in the plane of both); the points
 * of both faces on either side of `at` along it are the two sides. Where the
 * watershed's boundary wanders off a crease each face holds points of both surfaces,
 * and planes fitted by label would both average them (a 90-degree crease read 4-13
 * degrees on the filleted box). */
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

/** The median of values (sorted in place); NaN when empty. */
double
median(std::vector<double>& values)
{
  if (values.empty())
    return std::numeric_limits<double>::quiet_NaN();
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

} // namespace

double
sideTurnDegrees(const std::vector<Eigen::Vector3d>& side_a,
                const std::vector<Eigen::Vector3d>& side_b,
                const Eigen::Vector3d& at)
{
  PlaneSums a, b;
  for (const Eigen::Vector3d& p : side_a)
    a.add(p - at);
  for (const Eigen::Vector3d& p : side_b)
    b.add(p - at);
  return turnOfSides(a, b);
}

namespace {

/** measureCreaseAngles() for one edge from its points (indices into points). */
CreaseAngle
measureEdge(const FacePointIndex& index,
            const std::vector<Eigen::Vector3d>& points,
            const std::vector<std::uint32_t>& labels,
            const std::vector<std::uint32_t>& mine,
            double radius,
            double walk_below_degrees)
{
  CreaseAngle angle;
  if (mine.empty())
    return angle;
  const std::size_t samples =
    std::min(mine.size(), CreaseAngleParameters::kMaxSamplesPerEdge);
  std::map<std::array<std::uint32_t, 2>, std::vector<double>> by_pair;
  for (std::size_t s = 0; s < samples; ++s) {
    // evenly spread: the middle of the s-th of `samples` equal parts
    const std::size_t i = mine[(2 * s + 1) * mine.size() / (2 * samples)];
    const SampleTurn turn =
      measureSample(index, points, labels, points[i], radius, walk_below_degrees);
    if (std::isfinite(turn.degrees))
      by_pair[turn.faces].push_back(turn.degrees);
  }
  // The pair most samples saw (the smaller pair among equals).
  const std::vector<double>* best = nullptr;
  for (const auto& [pair, turns] : by_pair) {
    if (best == nullptr || turns.size() > best->size()) {
      best = &turns;
      angle.faces = pair;
    }
  }
  if (best != nullptr) {
    std::vector<double> turns = *best;
    angle.samples = static_cast<std::uint32_t>(turns.size());
    angle.degrees = median(turns);
  }
  return angle;
}

} // namespace

std::vector<CreaseAngle>
measureCreaseAngles(const std::vector<Eigen::Vector3d>& points,
                    const std::vector<std::uint32_t>& labels,
                    const std::vector<FeatureClass>& classes,
                    double cell_size,
                    double window_cells,
                    double walk_below_degrees,
                    int threads)
{
  std::vector<CreaseAngle> angles(classes.size());
  const double radius = window_cells * cell_size;
  if (!(radius > 0.0) || points.size() != labels.size())
    return angles;
  // Per edge, its points.
  std::vector<std::vector<std::uint32_t>> edge_points(classes.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::uint32_t l = labels[i];
    if (l != 0 && l <= classes.size() && classes[l - 1] == FeatureClass::kEdge &&
        points[i].allFinite())
      edge_points[l - 1].push_back(static_cast<std::uint32_t>(i));
  }
  const FacePointIndex index(points, labels, classes, radius);
  // Edges are independent: one at a time on the threads (each writes its own entry).
  parallelFor(classes.size(), threads, 1, [&](std::size_t first, std::size_t last) {
    for (std::size_t r = first; r < last; ++r)
      angles[r] =
        measureEdge(index, points, labels, edge_points[r], radius, walk_below_degrees);
  });
  return angles;
}

std::vector<CreaseAngle>
measureFaceContacts(const VoxelBand& band,
                    const std::vector<std::uint32_t>& cell_labels,
                    const std::vector<Eigen::Vector3d>& points,
                    const std::vector<std::uint32_t>& labels,
                    const std::vector<FeatureClass>& classes,
                    double window_cells,
                    int threads)
{
  std::vector<CreaseAngle> contacts;
  const double cell = band.grid().cell_size, radius = window_cells * cell;
  if (!(radius > 0.0) || points.size() != labels.size() ||
      cell_labels.size() != band.size())
    return contacts;
  const auto isFace = [&](std::uint32_t l) {
    return l != 0 && l <= classes.size() && classes[l - 1] == FeatureClass::kFace;
  };
  // Per pair of touching faces, the cells of the smaller label along the contact.
  std::map<std::array<std::uint32_t, 2>, std::vector<CellId>> cells_of;
  for (std::size_t c = 0; c < band.size(); ++c) {
    const std::uint32_t a = cell_labels[c];
    if (!isFace(a))
      continue;
    std::uint32_t last = 0; // a cell counts once a pair
    for (const CellId n : band.neighbours(static_cast<CellId>(c))) {
      const std::uint32_t b =
        n == kNoCell ? 0 : cell_labels[static_cast<std::size_t>(n)];
      if (b > a && b != last && isFace(b)) {
        cells_of[{{a, b}}].push_back(static_cast<CellId>(c));
        last = b;
      }
    }
  }
  const FacePointIndex index(points, labels, classes, radius);
  const double clearance = CreaseAngleParameters::kContactClearanceCells * cell;
  const FacePointIndex features(points, labels, classes, clearance, false);
  // Pairs are independent: one at a time on the threads, each into its own slot,
  // kept in the pairs' order.
  std::vector<std::pair<std::array<std::uint32_t, 2>, std::vector<CellId>>> pairs(
    std::make_move_iterator(cells_of.begin()), std::make_move_iterator(cells_of.end()));
  std::vector<CreaseAngle> measured(pairs.size());
  parallelFor(pairs.size(), threads, 1, [&](std::size_t first, std::size_t last) {
    for (std::size_t p = first; p < last; ++p) {
      const std::array<std::uint32_t, 2>& pair = pairs[p].first;
      std::vector<CellId>& cells = pairs[p].second;
      // only the contact away from edges and vertices
      const auto near = [&](CellId c) {
        return features.anyWithin(band.grid().cellCenter(band.coord(c)), clearance);
      };
      cells.erase(std::remove_if(cells.begin(), cells.end(), near), cells.end());
      if (cells.empty())
        continue;
      const std::size_t samples =
        std::min(cells.size(), CreaseAngleParameters::kMaxSamplesPerEdge);
      std::vector<double> turns;
      for (std::size_t s = 0; s < samples; ++s) {
        const CellId c = cells[(2 * s + 1) * cells.size() / (2 * samples)];
        const Eigen::Vector3d at = band.grid().cellCenter(band.coord(c));
        const double turn = contactTurn(index, points, labels, at, radius, pair);
        if (std::isfinite(turn))
          turns.push_back(turn);
      }
      if (turns.size() < CreaseAngleParameters::kMinContactSamples)
        continue;
      measured[p].faces = pair;
      measured[p].samples = static_cast<std::uint32_t>(turns.size());
      measured[p].degrees = median(turns);
    }
  });
  for (const CreaseAngle& contact : measured)
    if (contact.samples > 0)
      contacts.push_back(contact);
  return contacts;
}

namespace {

/** Union-find whose root is chosen by the caller (attach b's set under a's root). */
struct Joined
{
  std::vector<std::uint32_t> parent;

  explicit Joined(std::size_t n)
      : parent(n + 1)
  {
    for (std::size_t l = 0; l <= n; ++l)
      parent[l] = static_cast<std::uint32_t>(l);
  }
  std::uint32_t find(std::uint32_t a)
  {
    while (parent[a] != a)
      a = parent[a] = parent[parent[a]];
    return a;
  }
  /** b's set joins a's; a's root stays the root. */
  void attach(std::uint32_t a, std::uint32_t b)
  {
    const std::uint32_t ra = find(a), rb = find(b);
    if (ra != rb)
      parent[rb] = ra;
  }
};

/** Each remaining edge of vertex v as the set of its faces' roots; the distinct sets.
 */
std::set<std::vector<std::uint32_t>>
facePairsAt(const TopologyGraph& graph,
            std::uint32_t v,
            const std::vector<char>& removed,
            Joined& joined,
            std::vector<std::uint32_t>& remaining)
{
  std::set<std::vector<std::uint32_t>> pairs;
  for (const std::uint32_t e : graph.neighbours(v, FeatureClass::kEdge)) {
    if (removed[e])
      continue;
    remaining.push_back(e);
    std::vector<std::uint32_t> faces;
    for (const std::uint32_t f : graph.facesOfEdge(e))
      faces.push_back(joined.find(f));
    std::sort(faces.begin(), faces.end());
    faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
    pairs.insert(faces);
  }
  return pairs;
}

/** For a vertex whose creases' face pairs (two faces each) do not close around it,
 * the face every pair holds; 0 otherwise.
 *
 * Around a corner the faces and creases alternate in a cycle, so each face bounds two
 * of its creases (or more). Where one face bounds only one, no crease separates it
 * from the next: the creases pass the vertex by rather than meet at it. Measured on
 * the generated filleted box (rotation 2, thin face cores on): a 3,460-cell vertex
 * region on a fillet bounded top-side, side-bottom, bottom-side' and side'-top; once
 * side and side' were one face, the pairs were top-side and side-bottom, the top and
 * bottom rims passing it by. */
std::uint32_t
sharedFaceOfOpenFan(const std::set<std::vector<std::uint32_t>>& pairs)
{
  std::map<std::uint32_t, std::size_t> bounds;
  for (const std::vector<std::uint32_t>& faces : pairs) {
    if (faces.size() != 2)
      return 0;
    for (const std::uint32_t f : faces)
      ++bounds[f];
  }
  const bool open = std::any_of(bounds.begin(), bounds.end(),
                                [](const auto& fc) { return fc.second == 1; });
  if (!open)
    return 0;
  for (const auto& [face, count] : bounds)
    if (count == pairs.size())
      return face;
  return 0;
}

} // namespace

std::vector<std::uint32_t>
shallowCreaseMerge(const TopologyGraph& graph,
                   const std::vector<CreaseAngle>& angles,
                   const std::vector<CreaseAngle>& contacts,
                   double min_crease_angle)
{
  const std::size_t n = graph.size();
  Joined joined(n);
  std::vector<char> removed(n + 1, 0);
  if (min_crease_angle > 0.0) {
    // 1. Shallow edges: their two faces become one (the smaller label the root).
    for (std::uint32_t e = 1; e <= n && e <= angles.size(); ++e) {
      const CreaseAngle& a = angles[e - 1];
      if (graph.node(e).feature_class != FeatureClass::kEdge ||
          !std::isfinite(a.degrees) || a.degrees >= min_crease_angle ||
          a.faces[0] == 0 || !graph.contains(a.faces[1]))
        continue;
      removed[e] = 1;
      const std::uint32_t fa = joined.find(a.faces[0]), fb = joined.find(a.faces[1]);
      joined.attach(std::min(fa, fb), std::max(fa, fb));
    }
    // 2. Faces touching without an edge between them, at a shallow turn, unless a
    // crease kept separates them elsewhere (then the contact is a spill of the
    // watershed across that crease, not a blend).
    const auto creaseBetween = [&](std::uint32_t fa, std::uint32_t fb) {
      for (std::uint32_t e = 1; e <= n && e <= angles.size(); ++e) {
        const CreaseAngle& a = angles[e - 1];
        if (graph.node(e).feature_class != FeatureClass::kEdge || removed[e] ||
            !std::isfinite(a.degrees) || a.faces[0] == 0)
          continue;
        const std::uint32_t x = joined.find(a.faces[0]), y = joined.find(a.faces[1]);
        if ((x == fa && y == fb) || (x == fb && y == fa))
          return true;
      }
      return false;
    };
    for (const CreaseAngle& c : contacts) {
      if (!std::isfinite(c.degrees) || c.degrees >= min_crease_angle ||
          c.faces[0] == 0 || !graph.contains(c.faces[1]))
        continue;
      const std::uint32_t fa = joined.find(c.faces[0]), fb = joined.find(c.faces[1]);
      if (!creaseBetween(fa, fb))
        joined.attach(std::min(fa, fb), std::max(fa, fb));
    }
    for (std::uint32_t e = 1; e <= n; ++e)
      if (removed[e])
        joined.attach(angles[e - 1].faces[0], e);
  }
  // Faces in a set with others: their edges' face pairs may have changed.
  std::vector<std::uint32_t> set_size(n + 1, 0);
  for (std::uint32_t f = 1; f <= n; ++f)
    if (graph.node(f).feature_class == FeatureClass::kFace)
      ++set_size[joined.find(f)];
  const auto mergedFace = [&](std::uint32_t f) { return set_size[joined.find(f)] > 1; };
  // An edge that could not be measured (no two faces around it) whose faces all
  // merged into one lies inside a blend: it joins that face.
  for (std::uint32_t e = 1; e <= n && e <= angles.size(); ++e) {
    if (graph.node(e).feature_class != FeatureClass::kEdge || removed[e] ||
        std::isfinite(angles[e - 1].degrees))
      continue;
    const std::vector<std::uint32_t> faces = graph.facesOfEdge(e);
    if (faces.empty() || !std::all_of(faces.begin(), faces.end(), mergedFace) ||
        std::any_of(faces.begin(), faces.end(), [&](std::uint32_t f) {
          return joined.find(f) != joined.find(faces.front());
        }))
      continue;
    removed[e] = 1;
    joined.attach(faces.front(), e);
  }
  // 3. Vertices of removed edges or of merged faces' edges that no longer end two
  // different creases.
  for (std::uint32_t v = 1; v <= n; ++v) {
    if (graph.node(v).feature_class != FeatureClass::kVertex)
      continue;
    const std::vector<std::uint32_t> edges = graph.neighbours(v, FeatureClass::kEdge);
    const auto changed = [&](std::uint32_t e) {
      const std::vector<std::uint32_t> faces = graph.facesOfEdge(e);
      return removed[e] != 0 || std::any_of(faces.begin(), faces.end(), mergedFace);
    };
    if (std::none_of(edges.begin(), edges.end(), changed))
      continue;
    std::vector<std::uint32_t> remaining;
    const std::set<std::vector<std::uint32_t>> pairs =
      facePairsAt(graph, v, removed, joined, remaining);
    if (pairs.size() >= 2) {
      // Creases passing by: the vertex joins the one face they all bound.
      const std::uint32_t shared = sharedFaceOfOpenFan(pairs);
      if (shared != 0)
        joined.attach(shared, v);
      continue;
    }
    if (!remaining.empty()) {
      for (const std::uint32_t e : remaining)
        joined.attach(remaining.front(), e);
      joined.attach(remaining.front(), v);
    } else {
      const std::vector<std::uint32_t> faces = graph.neighbours(v, FeatureClass::kFace);
      if (!faces.empty())
        joined.attach(faces.front(), v);
    }
  }
  // 4. Pieces of one crease: kept edges whose faces were merged and now separate the
  // same two faces (before, they separated different pairs, so the segmentation
  // never joined them; e.g. a rim cut where the fillets were) are one edge.
  std::map<std::vector<std::uint32_t>, std::uint32_t> edge_of_pair;
  for (std::uint32_t e = 1; e <= n; ++e) {
    if (graph.node(e).feature_class != FeatureClass::kEdge || removed[e])
      continue;
    const std::vector<std::uint32_t> faces = graph.facesOfEdge(e);
    if (std::none_of(faces.begin(), faces.end(), mergedFace))
      continue;
    std::vector<std::uint32_t> roots;
    for (const std::uint32_t f : faces)
      roots.push_back(joined.find(f));
    std::sort(roots.begin(), roots.end());
    roots.erase(std::unique(roots.begin(), roots.end()), roots.end());
    if (roots.size() != 2)
      continue;
    const auto [it, first] = edge_of_pair.emplace(roots, e);
    if (!first)
      joined.attach(it->second, e);
  }
  std::vector<std::uint32_t> into(n + 1, 0);
  for (std::uint32_t l = 1; l <= n; ++l)
    into[l] = joined.find(l);
  return into;
}

} // namespace visfeat
