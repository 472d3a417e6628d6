// Sharp versus smooth (crease_angles.h): the turn across each edge region and each
// contact of two faces, the median over samples measured by crease_turns.h (the merge
// of the shallow ones: shallow_crease_merge.cpp).

#include <visfeat/core/graph/crease_angles.h>

#include <visfeat/core/band/voxel_band.h>
#include <visfeat/core/common/error.h>
#include <visfeat/core/common/threads.h>

#include "crease_turns.h"
#include "face_point_index.h"
#include "plane_sums.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <map>
#include <optional>
#include <string>

namespace visfeat {

void
CreaseAngleParameters::validate() const
{
  checkRange("min_crease_angle", min_crease_angle, kMinCreaseAngleRange, "degrees");
  checkRange("crease_window", window_cells, kWindowCellsRange, "cells");
}

namespace {

using detail::FacePointIndex;
using detail::measureSample;
using detail::median;
using detail::PlaneSums;
using detail::SampleTurn;
using detail::splitAcross;
using detail::turnOfHalves;

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

/** measureCreaseAngles() for one edge from its points (indices into points); each
 * sample between the sides around its point (measureSampleBetweenSides()) where
 * between_sides. */
CreaseAngle
measureEdge(const FacePointIndex& index,
            const std::vector<Eigen::Vector3d>& points,
            const std::vector<std::uint32_t>& labels,
            const std::vector<std::uint32_t>& mine,
            double radius,
            double walk_below_degrees,
            bool between_sides = false)
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
      between_sides
        ? measureSampleBetweenSides(index, points, labels, points[i], radius,
                                    walk_below_degrees)
        : measureSample(index, points, labels, points[i], radius, walk_below_degrees);
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

namespace {

/** measureCreaseAngles() with the face points' index (bucket: the window). */
std::vector<CreaseAngle>
measureEdges(const FacePointIndex& index,
             const std::vector<Eigen::Vector3d>& points,
             const std::vector<std::uint32_t>& labels,
             const std::vector<FeatureClass>& classes,
             double radius,
             double walk_below_degrees,
             int threads)
{
  std::vector<CreaseAngle> angles(classes.size());
  // Per edge, its points.
  std::vector<std::vector<std::uint32_t>> edge_points(classes.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::uint32_t l = labels[i];
    if (l != 0 && l <= classes.size() && classes[l - 1] == FeatureClass::kEdge &&
        points[i].allFinite())
      edge_points[l - 1].push_back(static_cast<std::uint32_t>(i));
  }
  // Edges are independent: one at a time on the threads (each writes its own entry).
  parallelFor(classes.size(), threads, 1, [&](std::size_t first, std::size_t last) {
    for (std::size_t r = first; r < last; ++r)
      angles[r] =
        measureEdge(index, points, labels, edge_points[r], radius, walk_below_degrees);
  });
  // Edges wider than the window, where most samples measured nothing: again with a
  // wider one (kWideWindowFactor), each sample between the two sides its window
  // holds; the measure more samples made stands.
  std::vector<std::size_t> wide;
  for (std::size_t r = 0; r < classes.size(); ++r) {
    const std::size_t taken =
      std::min(edge_points[r].size(), CreaseAngleParameters::kMaxSamplesPerEdge);
    if (edge_points[r].size() >= CreaseAngleParameters::kMinWideEdgePoints &&
        2 * std::size_t(angles[r].samples) < taken)
      wide.push_back(r);
  }
  if (wide.empty())
    return angles;
  const double wide_radius = CreaseAngleParameters::kWideWindowFactor * radius;
  const FacePointIndex wide_index(points, labels, classes, wide_radius);
  parallelFor(wide.size(), threads, 1, [&](std::size_t first, std::size_t last) {
    for (std::size_t k = first; k < last; ++k) {
      const CreaseAngle again =
        measureEdge(wide_index, points, labels, edge_points[wide[k]], wide_radius,
                    walk_below_degrees, true);
      if (again.samples > angles[wide[k]].samples)
        angles[wide[k]] = again;
    }
  });
  return angles;
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
  const double radius = window_cells * cell_size;
  if (!(radius > 0.0) || points.size() != labels.size())
    return std::vector<CreaseAngle>(classes.size());
  const FacePointIndex index(points, labels, classes, radius);
  return measureEdges(index, points, labels, classes, radius, walk_below_degrees,
                      threads);
}

namespace {

/** measureFadingCreases() at the sample point `at` of edge `edge`: NaN where the
 * edge's points or a side are too few. */
double
fadingSampleTurn(const FacePointIndex& faces,
                 const FacePointIndex& features,
                 const std::vector<Eigen::Vector3d>& points,
                 const std::vector<std::uint32_t>& labels,
                 std::uint32_t edge,
                 const Eigen::Vector3d& at,
                 double radius,
                 std::uint32_t& face)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  PlaneSums line_points;
  features.forEachWithin(at, radius, [&](std::uint32_t i) {
    if (labels[i] == edge)
      line_points.add(points[i] - at);
  });
  if (line_points.count < 3)
    return nan;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(line_points.covariance());
  const Eigen::Vector3d line = solver.eigenvectors().col(2); // the principal axis
  std::map<std::uint32_t, std::vector<Eigen::Vector3d>> around;
  faces.forEachWithin(
    at, radius, [&](std::uint32_t i) { around[labels[i]].push_back(points[i] - at); });
  const std::vector<Eigen::Vector3d>* local = nullptr;
  for (const auto& [label, list] : around)
    if (local == nullptr || list.size() > local->size()) {
      local = &list;
      face = label;
    }
  if (local == nullptr || local->size() < 2 * CreaseAngleParameters::kMinSidePoints)
    return nan;
  PlaneSums all;
  for (const Eigen::Vector3d& p : *local)
    all.add(p);
  const Eigen::Vector3d across = all.normal().cross(line);
  if (!(across.norm() > 0.0))
    return nan;
  PlaneSums before, after;
  splitAcross(*local, Eigen::Vector3d::Zero(), across.normalized(), before, after);
  if (before.count < CreaseAngleParameters::kMinSidePoints ||
      after.count < CreaseAngleParameters::kMinSidePoints)
    return nan;
  return turnOfHalves(before, after, line);
}

} // namespace

std::vector<CreaseAngle>
measureFadingCreases(const std::vector<Eigen::Vector3d>& points,
                     const std::vector<std::uint32_t>& labels,
                     const std::vector<FeatureClass>& classes,
                     const std::vector<std::uint32_t>& edges,
                     double cell_size,
                     double window_cells,
                     int threads)
{
  std::vector<CreaseAngle> angles(classes.size());
  const double radius = window_cells * cell_size;
  if (edges.empty() || !(radius > 0.0) || points.size() != labels.size())
    return angles;
  std::vector<std::vector<std::uint32_t>> edge_points(classes.size());
  for (const std::uint32_t e : edges)
    if (e == 0 || e > classes.size() || classes[e - 1] != FeatureClass::kEdge)
      throw Error("measureFadingCreases: label " + std::to_string(e) +
                  " is not an edge region");
  std::vector<char> wanted(classes.size() + 1, 0);
  for (const std::uint32_t e : edges)
    wanted[e] = 1;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (labels[i] <= classes.size() && wanted[labels[i]] && points[i].allFinite())
      edge_points[labels[i] - 1].push_back(static_cast<std::uint32_t>(i));
  const FacePointIndex faces(points, labels, classes, radius);
  const FacePointIndex features(points, labels, classes, radius, false);
  parallelFor(edges.size(), threads, 1, [&](std::size_t first, std::size_t last) {
    for (std::size_t k = first; k < last; ++k) {
      const std::uint32_t e = edges[k];
      const std::vector<std::uint32_t>& mine = edge_points[e - 1];
      const std::size_t samples =
        std::min(mine.size(), CreaseAngleParameters::kMaxSamplesPerEdge);
      std::map<std::uint32_t, std::vector<double>> by_face;
      for (std::size_t s = 0; s < samples; ++s) {
        const std::size_t i = mine[(2 * s + 1) * mine.size() / (2 * samples)];
        std::uint32_t face = 0;
        const double turn =
          fadingSampleTurn(faces, features, points, labels, e, points[i], radius, face);
        if (std::isfinite(turn))
          by_face[face].push_back(turn);
      }
      std::vector<double>* best = nullptr; // the face most samples saw
      for (auto& [face, turns] : by_face)
        if (best == nullptr || turns.size() > best->size()) {
          best = &turns;
          angles[e - 1].faces = {{face, face}};
        }
      if (best != nullptr) {
        angles[e - 1].samples = static_cast<std::uint32_t>(best->size());
        angles[e - 1].degrees = median(*best);
      }
    }
  });
  return angles;
}

namespace {

/** measureFaceContacts() with the face points' index, which `indexOf()` gives only
 * where two faces touch (the clean parts need none). */
template <typename IndexOf>
std::vector<CreaseAngle>
measureContacts(const VoxelBand& band,
                const std::vector<std::uint32_t>& cell_labels,
                const std::vector<Eigen::Vector3d>& points,
                const std::vector<std::uint32_t>& labels,
                const std::vector<FeatureClass>& classes,
                double window_cells,
                int threads,
                IndexOf&& indexOf)
{
  std::vector<CreaseAngle> contacts;
  const double cell = band.grid().cell_size, radius = window_cells * cell;
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
  if (cells_of.empty())
    return contacts; // no two faces touch: nothing to index (clean parts)
  const FacePointIndex& index = indexOf();
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
        const double turn =
          detail::contactTurn(index, points, labels, at, radius, pair);
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

} // namespace

std::vector<CreaseAngle>
measureFaceContacts(const VoxelBand& band,
                    const std::vector<std::uint32_t>& cell_labels,
                    const std::vector<Eigen::Vector3d>& points,
                    const std::vector<std::uint32_t>& labels,
                    const std::vector<FeatureClass>& classes,
                    double window_cells,
                    int threads)
{
  const double radius = window_cells * band.grid().cell_size;
  if (!(radius > 0.0) || points.size() != labels.size() ||
      cell_labels.size() != band.size())
    return {};
  std::optional<FacePointIndex> index;
  return measureContacts(band, cell_labels, points, labels, classes, window_cells,
                         threads, [&]() -> const FacePointIndex& {
                           index.emplace(points, labels, classes, radius);
                           return *index;
                         });
}

CreaseMeasures
measureCreasesAndContacts(const VoxelBand& band,
                          const std::vector<std::uint32_t>& cell_labels,
                          const std::vector<Eigen::Vector3d>& points,
                          const std::vector<std::uint32_t>& labels,
                          const std::vector<FeatureClass>& classes,
                          double window_cells,
                          double walk_below_degrees,
                          int threads)
{
  const double radius = window_cells * band.grid().cell_size;
  if (!(radius > 0.0) || points.size() != labels.size())
    return {std::vector<CreaseAngle>(classes.size()), {}};
  const FacePointIndex index(points, labels, classes, radius);
  CreaseMeasures measures;
  measures.angles =
    measureEdges(index, points, labels, classes, radius, walk_below_degrees, threads);
  if (cell_labels.size() == band.size())
    measures.contacts =
      measureContacts(band, cell_labels, points, labels, classes, window_cells, threads,
                      [&]() -> const FacePointIndex& { return index; });
  return measures;
}

} // namespace visfeat
