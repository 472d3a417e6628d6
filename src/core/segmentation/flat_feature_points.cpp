#include <visfeat/core/common/error.h>
#include <visfeat/core/common/threads.h>
#include <visfeat/core/segmentation/flat_feature_points.h>

#include "../common/plane_sums.h"
#include "../grid/cell_members.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

namespace visfeat {

void
FlatPointParameters::validate() const
{
  checkRange("flat_point_variation", max_surface_variation, kMaxSurfaceVariationRange,
             "surface variation");
  checkRange("flat_point_min_points", min_points, kMinPointsRange, "points");
  checkRange("flat_point_radius", radius, kRadiusRange, "cells");
}

namespace {

bool
isFeature(FeatureClass c)
{
  return c == FeatureClass::kEdge || c == FeatureClass::kVertex;
}

} // namespace

double
surfaceVariation(const std::vector<Eigen::Vector3d>& points)
{
  detail::PlaneSums sums;
  for (const Eigen::Vector3d& p : points)
    sums.add(p - points.front()); // relative to a point of the set
  return sums.surfaceVariation();
}

namespace {

void
checkInputs(const VoxelBand& band,
            const std::vector<Eigen::Vector3f>& surface,
            const std::vector<CellId>& surface_cells,
            const std::vector<Eigen::Vector3f>& points,
            const std::vector<std::uint32_t>& labels,
            const std::vector<FeatureClass>& classes,
            const std::vector<std::uint32_t>& cell_labels,
            const std::vector<FeatureClass>& region_classes)
{
  const auto size = [](std::size_t n) { return std::to_string(n); };
  if (surface_cells.size() != surface.size())
    throw Error("flatFeaturePoints: " + size(surface.size()) + " surface points but " +
                size(surface_cells.size()) + " cells");
  if (labels.size() != points.size() || classes.size() != points.size())
    throw Error("flatFeaturePoints: " + size(points.size()) + " points but " +
                size(labels.size()) + " labels and " + size(classes.size()) +
                " classes");
  if (cell_labels.size() != band.size())
    throw Error("flatFeaturePoints: " + size(cell_labels.size()) +
                " cell labels for a band of " + size(band.size()) + " cells");
  for (const CellId c : surface_cells)
    if (c != kNoCell && (c < 0 || static_cast<std::size_t>(c) >= band.size()))
      throw Error("flatFeaturePoints: cell " + std::to_string(c) +
                  " is not a cell of the band (" + size(band.size()) + " cells)");
  for (const std::uint32_t l : cell_labels)
    if (l > region_classes.size())
      throw Error("flatFeaturePoints: cell label " + std::to_string(l) + " but " +
                  size(region_classes.size()) + " regions");
}

/** The feature points to judge (finite), grouped by the cell they fall in: group g is
 * queries[group_begin[g] .. group_begin[g + 1]), in increasing point order within
 * each group and in grid-key order of the cells. */
struct QueryGroups
{
  std::vector<std::size_t> queries;
  std::vector<std::size_t> group_begin;
  std::vector<CellCoord> group_cell;

  QueryGroups(const VoxelBand& band,
              const std::vector<Eigen::Vector3f>& points,
              const std::vector<FeatureClass>& classes)
  {
    std::vector<std::pair<std::uint64_t, std::size_t>> keyed;
    for (std::size_t i = 0; i < points.size(); ++i)
      if (isFeature(classes[i]) && points[i].allFinite()) {
        const CellCoord c = points[i].array().floor().cast<int>().matrix();
        if (band.grid().contains(c))
          keyed.emplace_back(band.grid().linearKey(c), i);
      }
    std::sort(keyed.begin(), keyed.end());
    for (std::size_t k = 0; k < keyed.size(); ++k) {
      if (k == 0 || keyed[k].first != keyed[k - 1].first) {
        group_begin.push_back(k);
        group_cell.push_back(band.grid().cellOfKey(keyed[k].first));
      }
      queries.push_back(keyed[k].second);
    }
    group_begin.push_back(keyed.size());
  }

  std::size_t size() const { return group_cell.size(); }
};

/** The band cells of the block of cells within `reach` of c (Chebyshev). */
void
blockCells(const VoxelBand& band,
           const CellCoord& c,
           int reach,
           std::vector<std::pair<CellId, CellCoord>>& out)
{
  out.clear();
  for (int dz = -reach; dz <= reach; ++dz)
    for (int dy = -reach; dy <= reach; ++dy)
      for (int dx = -reach; dx <= reach; ++dx) {
        const CellCoord at = c + CellCoord(dx, dy, dz);
        const CellId id = band.find(at);
        if (id != kNoCell)
          out.emplace_back(id, at);
      }
}

/** Squared distance from q to the box of cell c (0 inside). */
double
boxDistance2(const Eigen::Vector3d& q, const CellCoord& c)
{
  const Eigen::Array3d lo = c.cast<double>().array();
  const Eigen::Array3d gap =
    (lo - q.array()).max(q.array() - (lo + 1.0)).max(Eigen::Array3d::Zero());
  return gap.matrix().squaredNorm();
}

/** Per labelled point, the face label it moves to (0: stays), and in `variation` the
 * surface variation of its ball where it moves. The points of one cell share the band
 * cells of the block around it (one lookup per cell, not per point); each point reads
 * the cells its ball reaches. */
std::vector<std::uint32_t>
flatTargets(const VoxelBand& band,
            const std::vector<Eigen::Vector3f>& surface,
            const detail::CellMembers& by_cell,
            const std::vector<Eigen::Vector3f>& points,
            const std::vector<FeatureClass>& classes,
            const std::vector<std::uint32_t>& cell_labels,
            const std::vector<FeatureClass>& region_classes,
            const FlatPointParameters& parameters,
            std::vector<double>& variation,
            FlatPointStats& stats)
{
  variation.assign(points.size(), 0.0);
  const double r = parameters.radius;
  const double r2 = r * r;
  const int reach = static_cast<int>(std::ceil(r));
  std::vector<std::uint32_t> target(points.size(), 0);
  const QueryGroups groups(band, points, classes);
  stats.feature_points = groups.queries.size();
  std::atomic<std::size_t> judged{0};
  constexpr std::size_t kCellsPerChunk = 64;
  parallelFor(
    groups.size(), parameters.threads, kCellsPerChunk,
    [&](std::size_t first, std::size_t last) {
      std::vector<std::pair<CellId, CellCoord>> block;
      std::size_t chunk_judged = 0;
      for (std::size_t g = first; g < last; ++g) {
        blockCells(band, groups.group_cell[g], reach, block);
        for (std::size_t k = groups.group_begin[g]; k < groups.group_begin[g + 1];
             ++k) {
          const std::size_t i = groups.queries[k];
          const Eigen::Vector3d q = points[i].cast<double>();
          detail::PlaneSums scatter;
          double nearest_face = std::numeric_limits<double>::infinity();
          std::uint32_t face = 0;
          for (const auto& [id, at] : block) {
            if (boxDistance2(q, at) > r2)
              continue; // the ball does not reach the cell
            const auto cell = static_cast<std::size_t>(id);
            const std::uint32_t label = cell_labels[cell];
            if (label != 0 && region_classes[label - 1] == FeatureClass::kFace) {
              const double d2 =
                (at.cast<double>().array() + 0.5 - q.array()).square().sum();
              if (d2 < nearest_face || (d2 == nearest_face && label < face)) {
                nearest_face = d2;
                face = label;
              }
            }
            for (std::size_t j = by_cell.start[cell]; j < by_cell.start[cell + 1];
                 ++j) {
              const Eigen::Vector3d d = surface[by_cell.members[j]].cast<double>() - q;
              if (d.squaredNorm() <= r2)
                scatter.add(d);
            }
          }
          if (face == 0 ||
              scatter.count < static_cast<std::size_t>(parameters.min_points))
            continue;
          ++chunk_judged;
          const double v = scatter.surfaceVariation();
          if (v <= parameters.max_surface_variation) {
            target[i] = face;
            variation[i] = v;
          }
        }
      }
      judged += chunk_judged;
    });
  stats.judged = judged;
  return target;
}

} // namespace

std::vector<FlatPointMove>
flatFeaturePoints(const VoxelBand& band,
                  const std::vector<Eigen::Vector3f>& surface,
                  const std::vector<CellId>& surface_cells,
                  const std::vector<Eigen::Vector3f>& points,
                  const std::vector<std::uint32_t>& labels,
                  const std::vector<FeatureClass>& classes,
                  const std::vector<std::uint32_t>& cell_labels,
                  const std::vector<FeatureClass>& region_classes,
                  const FlatPointParameters& parameters,
                  FlatPointStats* stats)
{
  parameters.validate();
  checkInputs(band, surface, surface_cells, points, labels, classes, cell_labels,
              region_classes);
  FlatPointStats counted;
  if (stats)
    *stats = counted;
  if (parameters.max_surface_variation <= 0.0)
    return {};
  std::vector<double> variation;
  std::vector<std::uint32_t> target =
    flatTargets(band, surface, detail::CellMembers(band.size(), surface_cells), points,
                classes, cell_labels, region_classes, parameters, variation, counted);
  // a region all of whose points would move keeps its least flat one (the first on
  // ties)
  std::uint32_t max_label = 0;
  for (const std::uint32_t l : labels)
    max_label = std::max(max_label, l);
  std::vector<std::size_t> total(static_cast<std::size_t>(max_label) + 1, 0);
  std::vector<std::size_t> moving(total.size(), 0);
  for (std::size_t i = 0; i < points.size(); ++i) {
    ++total[labels[i]];
    if (target[i] != 0)
      ++moving[labels[i]];
  }
  const std::size_t none = points.size();
  std::vector<std::size_t> keep(total.size(), none);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::uint32_t l = labels[i];
    if (l != 0 && target[i] != 0 && moving[l] == total[l] &&
        (keep[l] == none || variation[i] > variation[keep[l]]))
      keep[l] = i;
  }
  for (const std::size_t i : keep)
    if (i != none)
      target[i] = 0;
  std::vector<FlatPointMove> moves;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (target[i] != 0)
      moves.push_back({i, target[i]});
  counted.moved = moves.size();
  if (stats)
    *stats = counted;
  return moves;
}

} // namespace visfeat
