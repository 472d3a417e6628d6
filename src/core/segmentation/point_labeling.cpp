#include <visfeat/core/common/error.h>
#include <visfeat/core/segmentation/point_labeling.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <utility>

namespace visfeat {

PointLabeling::PointLabeling(const VoxelBand& band,
                             const FeatureSegmentation& segmentation,
                             double point_feature_distance)
    : PointLabeling(band,
                    segmentation.cellLabels(),
                    segmentation.regionClasses(),
                    segmentation.skeleton(),
                    segmentation.skeletonCentres(),
                    segmentation.skeletonTangents(),
                    point_feature_distance)
{}

PointLabeling::PointLabeling(const VoxelBand& band,
                             const std::vector<std::uint32_t>& cell_labels,
                             std::vector<FeatureClass> region_classes,
                             const std::vector<char>& skeleton,
                             const std::vector<Eigen::Vector3f>& skeleton_centres,
                             const std::vector<Eigen::Vector3f>& skeleton_tangents,
                             double point_feature_distance)
    : band_(band)
    , labels_(cell_labels)
    , classes_(std::move(region_classes))
    , skeleton_(skeleton)
    , centres_(skeleton_centres)
    , tangents_(skeleton_tangents)
    , distance_(point_feature_distance)
{
  if (!(std::isfinite(distance_) && distance_ >= 0.0)) {
    std::ostringstream msg;
    msg << "point_feature_distance " << distance_
        << " must be finite and >= 0 (cells; 0 = off)";
    throw Error(msg.str());
  }
  if (labels_.size() != band.size() ||
      (!skeleton_.empty() &&
       (skeleton_.size() != band.size() || centres_.size() != band.size() ||
        tangents_.size() != band.size())))
    throw Error("PointLabeling: the labels or the skeleton do not match the band");
  for (const std::uint32_t label : labels_)
    if (label > classes_.size())
      throw Error("PointLabeling: cell label " + std::to_string(label) +
                  " exceeds the " + std::to_string(classes_.size()) + " regions");
  if (distance_ <= 0.0 || skeleton_.empty())
    return;
  reach_ = std::max(kSkeletonReach, static_cast<int>(std::ceil(distance_)));
  listSkeletonAround();
}

void
PointLabeling::listSkeletonAround()
{
  // Scatter: every skeleton cell s, in increasing id, adds itself to the list of each
  // band cell n within reach_. Band ids increase with GridSpec::linearKey, that is in
  // z, y, x order, so each list comes out in the scan order around its cell.
  std::vector<std::pair<CellId, CellId>> pairs; // (n, s)
  const std::size_t n_cells = skeleton_.size();
  for (std::size_t c = 0; c < n_cells; ++c) {
    if (!skeleton_[c])
      continue;
    const CellCoord at = band_.coord(static_cast<CellId>(c));
    for (int dz = -reach_; dz <= reach_; ++dz)
      for (int dy = -reach_; dy <= reach_; ++dy)
        for (int dx = -reach_; dx <= reach_; ++dx) {
          const CellId n = band_.find(at + CellCoord(dx, dy, dz));
          if (n != kNoCell)
            pairs.emplace_back(n, static_cast<CellId>(c));
        }
  }
  around_begin_.assign(n_cells + 1, 0);
  for (const auto& p : pairs)
    ++around_begin_[static_cast<std::size_t>(p.first) + 1];
  for (std::size_t c = 0; c < n_cells; ++c)
    around_begin_[c + 1] += around_begin_[c];
  around_.resize(pairs.size());
  std::vector<std::uint32_t> next(around_begin_.begin(), around_begin_.end() - 1);
  for (const auto& p : pairs)
    around_[next[static_cast<std::size_t>(p.first)]++] = p.second;
  near_skeleton_.assign(n_cells, 0);
  for (std::size_t c = 0; c < n_cells; ++c)
    near_skeleton_[c] = around_begin_[c + 1] > around_begin_[c] ? 1 : 0;
}

std::uint32_t
PointLabeling::nearestFace(const Eigen::Vector3d& q, const CellCoord& c) const
{
  double near_face = std::numeric_limits<double>::infinity();
  std::uint32_t face = 0;
  for (int dz = -kFaceReach; dz <= kFaceReach; ++dz)
    for (int dy = -kFaceReach; dy <= kFaceReach; ++dy)
      for (int dx = -kFaceReach; dx <= kFaceReach; ++dx) {
        const CellId n = band_.find(c + CellCoord(dx, dy, dz));
        if (n == kNoCell || cellClass(n) != FeatureClass::kFace)
          continue;
        const double d =
          (band_.coord(n).cast<double>() + Eigen::Vector3d::Constant(0.5) - q).norm();
        if (d < near_face) {
          near_face = d;
          face = labels_[static_cast<std::size_t>(n)];
        }
      }
  return face;
}

PointLabel
PointLabeling::labelOf(const Eigen::Vector3d& q, CellId cell) const
{
  PointLabel result;
  if (cell == kNoCell)
    return result;
  result.label = labels_[static_cast<std::size_t>(cell)];
  result.feature_class = cellClass(cell);
  if (near_skeleton_.empty() || !near_skeleton_[static_cast<std::size_t>(cell)])
    return result;

  double near_skeleton = std::numeric_limits<double>::infinity();
  CellId nearest_skeleton = kNoCell;
  double near_vertex = std::numeric_limits<double>::infinity();
  CellId nearest_vertex = kNoCell;
  const auto [first, last] = skeletonAround(cell);
  for (const CellId* it = first; it != last; ++it) {
    const CellId n = *it;
    const auto s = static_cast<std::size_t>(n);
    // Distance to the piece of middle line the skeleton cell stands for.
    const Eigen::Vector3d d = q - centres_[s].cast<double>();
    const Eigen::Vector3d u = tangents_[s].cast<double>();
    const double along = std::clamp(d.dot(u), -kHalfPiece, kHalfPiece);
    const double distance = (d - along * u).norm();
    if (distance < near_skeleton) {
      near_skeleton = distance;
      nearest_skeleton = n;
    }
    if (distance < near_vertex && cellClass(n) == FeatureClass::kVertex) {
      near_vertex = distance;
      nearest_vertex = n;
    }
  }
  if (near_vertex <= distance_)
    nearest_skeleton = nearest_vertex;
  if (near_skeleton <= distance_) {
    result.label = labels_[static_cast<std::size_t>(nearest_skeleton)];
    result.feature_class = cellClass(nearest_skeleton);
  } else if (result.feature_class == FeatureClass::kEdge ||
             result.feature_class == FeatureClass::kVertex) {
    const std::uint32_t face = nearestFace(q, band_.coord(cell));
    if (face != 0) {
      result.label = face;
      result.feature_class = FeatureClass::kFace;
    }
  }
  return result;
}

std::vector<std::pair<std::uint32_t, std::vector<CellId>>>
pointlessVertices(const std::vector<std::uint32_t>& cell_labels,
                  const std::vector<FeatureClass>& region_classes,
                  const std::vector<std::uint64_t>& points_per_label)
{
  const auto pointless = [&](std::size_t l) {
    return region_classes[l - 1] == FeatureClass::kVertex &&
           (l >= points_per_label.size() || points_per_label[l] == 0);
  };
  std::vector<std::pair<std::uint32_t, std::vector<CellId>>> vertices;
  bool any = false;
  for (std::size_t l = 1; l <= region_classes.size(); ++l)
    any = any || pointless(l);
  if (!any)
    return vertices;
  std::vector<std::vector<CellId>> cells(region_classes.size() + 1);
  for (std::size_t c = 0; c < cell_labels.size(); ++c) {
    const std::uint32_t l = cell_labels[c];
    if (l > region_classes.size())
      throw Error("pointlessVertices: cell label " + std::to_string(l) +
                  " exceeds the " + std::to_string(region_classes.size()) + " regions");
    if (l != 0 && pointless(l))
      cells[l].push_back(static_cast<CellId>(c));
  }
  for (std::size_t l = 1; l < cells.size(); ++l)
    if (!cells[l].empty())
      vertices.emplace_back(static_cast<std::uint32_t>(l), std::move(cells[l]));
  return vertices;
}

RegionPointGeometry::RegionPointGeometry(std::size_t regions)
{
  Sum empty;
  empty.min = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  empty.max = -empty.min;
  sums_.assign(regions, empty);
}

void
RegionPointGeometry::add(std::uint32_t label, const Eigen::Vector3d& p)
{
  if (label == 0 || label > sums_.size() || !p.allFinite())
    return;
  Sum& s = sums_[label - 1];
  ++s.n;
  s.sum += p;
  s.min = s.min.cwiseMin(p);
  s.max = s.max.cwiseMax(p);
}

void
RegionPointGeometry::applyTo(TopologyGraph& graph) const
{
  for (std::size_t r = 0; r < sums_.size(); ++r)
    if (sums_[r].n > 0)
      graph.setPointGeometry(static_cast<std::uint32_t>(r + 1), sums_[r].n,
                             sums_[r].sum / static_cast<double>(sums_[r].n),
                             sums_[r].min, sums_[r].max);
}

} // namespace visfeat
