// VisibilityFeatureEstimation (not for inclusion on its own): the per-point output,
// each point labelled from the band cell it falls in (PointLabeling), and the corner
// points that vertex regions no point falls in claim; last, the feature points on flat
// ground go to a face.
#pragma once

#include <visfeat/core/common/threads.h>
#include <visfeat/core/segmentation/flat_feature_points.h>
#include <visfeat/core/segmentation/point_labeling.h>
#include <visfeat/impl/visibility_feature_estimation.hpp>

#include <pcl/common/point_tests.h>

#include <algorithm>
#include <atomic>
#include <iomanip>
#include <limits>
#include <sstream>

namespace visfeat {
template <typename PointInT, typename PointOutT>
void
VisibilityFeatureEstimation<PointInT, PointOutT>::labelPoints(
  const Results& results,
  const Run& run,
  const PointCloudIn& surface,
  PointCloudOut& output) const
{
  const PointLabeling labeling(results.band, results.segmentation,
                               run.segmentation.point_feature_distance);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const GridSpec& grid = results.band.grid();
  std::atomic<bool> dense{true};
  // Points are independent: chunks of them on the map's threads.
  constexpr std::size_t kPointsPerChunk = 4096;
  parallelFor(indices_->size(), run.visibility.threads, kPointsPerChunk,
              [&](std::size_t begin, std::size_t end) {
                bool chunk_dense = true;
                for (std::size_t i = begin; i < end; ++i) {
                  const auto index = static_cast<std::size_t>((*indices_)[i]);
                  const PointInT& p = (*input_)[index];
                  // The point as the band saw it (smoothed in noise mode) and its cell:
                  // the band's own record for points of the band's cloud, else the cell
                  // it falls in.
                  const PointInT& seen = fake_surface_ ? surface[index] : p;
                  const CellId cell = bandCellOf(results.band, index);
                  PointOutT& out = output[i];
                  out.x = p.x;
                  out.y = p.y;
                  out.z = p.z;
                  out.visibility_radius =
                    cell == kNoCell ? nan
                                    : static_cast<float>(results.map.radius(cell));
                  const PointLabel label = labeling.labelOf(
                    grid.toCellUnits(Eigen::Vector3d(seen.x, seen.y, seen.z)), cell);
                  out.label = label.label;
                  out.feature_class = static_cast<std::uint8_t>(label.feature_class);
                  chunk_dense = chunk_dense && cell != kNoCell;
                }
                if (!chunk_dense)
                  dense = false;
              });
  output.is_dense = dense;
}

template <typename PointInT, typename PointOutT>
CellId
VisibilityFeatureEstimation<PointInT, PointOutT>::bandCellOf(const VoxelBand& band,
                                                             std::size_t index) const
{
  const PointInT& p = (*input_)[index];
  if (!pcl::isXYZFinite(p))
    return kNoCell;
  return fake_surface_ ? band.pointCell()[index]
                       : band.find(band.grid().cellOf(Eigen::Vector3d(p.x, p.y, p.z)));
}

template <typename PointInT, typename PointOutT>
void
VisibilityFeatureEstimation<PointInT, PointOutT>::claimCornerPoints(
  Results& results,
  const Run& run,
  const PointCloudIn& surface,
  PointCloudOut& output) const
{
  const double limit = kCornerClaimDistances * run.segmentation.point_feature_distance;
  if (!(limit > 0.0) || run.segmentation.raw)
    return;
  std::vector<std::uint64_t> points_per_label(results.segmentation.regions().size() + 1,
                                              0);
  for (const PointOutT& p : output.points)
    if (p.label < points_per_label.size())
      ++points_per_label[p.label];
  const auto vertices =
    pointlessVertices(results.segmentation.cellLabels(),
                      results.segmentation.regionClasses(), points_per_label);
  if (vertices.empty())
    return;
  // The band cells within the claim distance of a pointless vertex's cells, and which
  // vertices (few: a claim is the exception).
  const VoxelBand& band = results.band;
  const int reach = static_cast<int>(std::ceil(limit));
  std::multimap<CellId, std::size_t> vertices_near;
  for (std::size_t k = 0; k < vertices.size(); ++k) {
    std::vector<CellId> near;
    for (const CellId v : vertices[k].second)
      for (int dz = -reach; dz <= reach; ++dz)
        for (int dy = -reach; dy <= reach; ++dy)
          for (int dx = -reach; dx <= reach; ++dx) {
            const CellId c = band.find(band.coord(v) + CellCoord(dx, dy, dz));
            if (c != kNoCell)
              near.push_back(c);
          }
    std::sort(near.begin(), near.end());
    near.erase(std::unique(near.begin(), near.end()), near.end());
    for (const CellId c : near)
      vertices_near.emplace(c, k);
  }
  const auto vertex = static_cast<std::uint8_t>(FeatureClass::kVertex);
  std::vector<double> best(vertices.size(), limit * limit);
  std::vector<std::size_t> best_point(vertices.size(), output.size());
  const GridSpec& grid = band.grid();
  for (std::size_t i = 0; i < output.size(); ++i) {
    if (output[i].feature_class == vertex)
      continue; // another vertex's point stays its own
    // the point as the band saw it, and its cell (as in labelPoints)
    const auto index = static_cast<std::size_t>((*indices_)[i]);
    const CellId cell = bandCellOf(band, index);
    const PointInT& p = fake_surface_ ? surface[index] : (*input_)[index];
    const auto [first, last] = vertices_near.equal_range(cell);
    if (cell == kNoCell || first == last)
      continue;
    const Eigen::Vector3d q = grid.toCellUnits(Eigen::Vector3d(p.x, p.y, p.z));
    for (auto it = first; it != last; ++it) {
      const std::size_t k = it->second;
      for (const CellId v : vertices[k].second) {
        const double d2 =
          (q - band.coord(v).cast<double>() - Eigen::Vector3d::Constant(0.5))
            .squaredNorm();
        if (d2 < best[k] || (d2 == best[k] && best_point[k] == output.size())) {
          best[k] = d2;
          best_point[k] = i;
        }
      }
    }
  }
  bool claimed = false;
  for (std::size_t k = 0; k < vertices.size(); ++k) {
    const std::size_t i = best_point[k];
    if (i == output.size() || output[i].feature_class == vertex)
      continue; // none near, or the nearest of two vertices: the first keeps it
    output[i].label = vertices[k].first;
    output[i].feature_class = vertex;
    claimed = true;
  }
  if (claimed)
    detail::refreshPointGeometry(results.segmentation.regions().size(), output,
                                 results.graph);
}

template <typename PointInT, typename PointOutT>
void
VisibilityFeatureEstimation<PointInT, PointOutT>::moveFlatFeaturePoints(
  Results& results, Run& run, const PointCloudIn& surface, PointCloudOut& output) const
{
  if (run.segmentation.raw || !(run.flat_points.max_surface_variation > 0.0))
    return;
  FlatPointParameters parameters = run.flat_points;
  parameters.radius =
    run.segmentation.point_feature_distance + FlatPointParameters::kMargin;
  // the labelled points as the band saw them (smoothed in noise mode), as in
  // labelPoints(); their balls hold the points the band was built from, in the cells
  // the band recorded for them (pointCell(): kNoCell for skipped points)
  const GridSpec& grid = results.band.grid();
  const auto cellUnits = [&](const PointInT& p) -> Eigen::Vector3f {
    return grid.toCellUnits(Eigen::Vector3d(p.x, p.y, p.z)).template cast<float>();
  };
  std::vector<Eigen::Vector3f> ground(surface.size());
  for (std::size_t j = 0; j < surface.size(); ++j)
    ground[j] = cellUnits(surface[j]);
  std::vector<Eigen::Vector3f> points(output.size());
  std::vector<std::uint32_t> labels(output.size());
  std::vector<FeatureClass> classes(output.size());
  for (std::size_t i = 0; i < output.size(); ++i) {
    const auto index = static_cast<std::size_t>((*indices_)[i]);
    points[i] = cellUnits(fake_surface_ ? surface[index] : (*input_)[index]);
    labels[i] = output[i].label;
    classes[i] = static_cast<FeatureClass>(output[i].feature_class);
  }
  FlatPointStats stats;
  const std::vector<FlatPointMove> moves =
    flatFeaturePoints(results.band, ground, results.band.pointCell(), points, labels,
                      classes, results.segmentation.cellLabels(),
                      results.segmentation.regionClasses(), parameters, &stats);
  std::ostringstream note;
  note << std::setprecision(3);
  if (stats.judged * 2 < stats.feature_points) {
    note
      << "feature points on flat ground: " << stats.feature_points - stats.judged
      << " of " << stats.feature_points << " edge and vertex points have fewer than "
      << parameters.min_points << " points within " << parameters.radius
      << " cells, too few to tell flat ground, and keep their labels (the step needs "
         "about 2 points a cell squared: sample denser";
    const double spacing = run.resolution.spacing / grid.cell_size;
    if (run.fill != SurfaceFill::kPoints && spacing > 1.0) // finer than the points
      note << "; here the points lie " << std::fixed << std::setprecision(1) << spacing
           << " cells apart, the band filled between them)";
    else
      note << ", or lower the resolution)";
    run.notes.push_back(note.str());
  } else if (!moves.empty()) {
    note << "feature points on flat ground: " << moves.size() << " of "
         << stats.feature_points
         << " edge and vertex points lie on one plane with their neighbours "
            "(flat_point_variation "
         << parameters.max_surface_variation << ") and went to their faces";
    run.notes.push_back(note.str());
  }
  if (moves.empty())
    return;
  for (const FlatPointMove& m : moves) {
    output[m.point].label = m.label;
    output[m.point].feature_class = static_cast<std::uint8_t>(FeatureClass::kFace);
  }
  detail::refreshPointGeometry(results.segmentation.regions().size(), output,
                               results.graph);
}

} // namespace visfeat
