#pragma once

#include <visfeat/core/common/error.h>
#include <visfeat/core/common/memory_budget.h>
#include <visfeat/impl/voxel_band_from_cloud.hpp>
#include <visfeat/visibility_feature_estimation.h>
#include <visfeat/voxel_band_from_cloud.h>

#include <pcl/common/point_tests.h>

#include <visfeat/core/common/threads.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <new>

namespace visfeat {
namespace detail {

inline double
millisecondsSince(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() -
                                                   start)
    .count();
}

} // namespace detail

template <typename PointInT, typename PointOutT>
bool
VisibilityFeatureEstimation<PointInT, PointOutT>::fail(const std::string& message)
{
  error_ = message;
  PCL_ERROR("[visfeat::%s::compute] %s\n", getClassName().c_str(), message.c_str());
  return false;
}

template <typename PointInT, typename PointOutT>
bool
VisibilityFeatureEstimation<PointInT, PointOutT>::initCompute()
{
  error_.clear();
  times_ = PhaseTimes{};
  if (!input_)
    return fail("no input cloud: call setInputCloud() first");
  if (!pcl::PCLBase<PointInT>::initCompute())
    return fail("the input cloud or its indices are invalid");
  if (input_->empty()) {
    this->deinitCompute();
    return fail("the input cloud is empty");
  }
  if (!surface_) {
    fake_surface_ = true;
    surface_ = input_;
  }
  try {
    const auto start = std::chrono::steady_clock::now();
    VisibilityMap::validate(visibility_);
    FeatureSegmentation::validate(segmentation_parameters_, visibility_.max_radius);
    if (!(smoothing_.radius >= 0.0 && smoothing_.radius <= 8.0))
      throw Error("smoothing radius " + std::to_string(smoothing_.radius) +
                  " is out of range [0, 8] (cells; 0 = off)");
    grid_ = gridForCloud(*surface_, resolution_);
    // Refuse before allocating: the subcell mask dominates; cells are at most the
    // points.
    const std::size_t points = surface_->size();
    const std::size_t cells =
      static_cast<std::size_t>(std::min<std::uint64_t>(points, grid_.cellCount()));
    const int threads = resolveThreads(visibility_.threads);
    const std::uint64_t octree_bytes = std::uint64_t{160} * cells + 4 * points;
    const std::uint64_t estimate =
      FreeSpace::estimateBytes(grid_) + VoxelBand::estimateBytes(grid_, cells, points) +
      octree_bytes + std::uint64_t{4} * cells * static_cast<std::uint64_t>(threads) +
      (smoothing_.radius > 0.0 ? (sizeof(PointInT) + 40) * std::uint64_t{points} : 0);
    checkMemory(estimate, memory_limit_,
                "a grid of " + std::to_string(grid_.dims.x()) + "x" +
                  std::to_string(grid_.dims.y()) + "x" +
                  std::to_string(grid_.dims.z()) + " cells");
    times_.grid_ms = detail::millisecondsSince(start);
  } catch (const Error& e) {
    this->deinitCompute();
    return fail(e.what());
  }
  return true;
}

template <typename PointInT, typename PointOutT>
void
VisibilityFeatureEstimation<PointInT, PointOutT>::markCellsNearSkeleton()
{
  const std::vector<char>& skeleton = segmentation_.skeleton();
  near_skeleton_.assign(skeleton.size(), 0);
  for (std::size_t c = 0; c < skeleton.size(); ++c) {
    if (!skeleton[c])
      continue;
    const CellCoord at = band_.coord(static_cast<CellId>(c));
    for (int dz = -2; dz <= 2; ++dz)
      for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx) {
          const CellId n = band_.find(at + CellCoord(dx, dy, dz));
          if (n != kNoCell)
            near_skeleton_[static_cast<std::size_t>(n)] = 1;
        }
  }
}

template <typename PointInT, typename PointOutT>
void
VisibilityFeatureEstimation<PointInT, PointOutT>::refinePointLabel(
  const PointInT& p, CellId cell, std::uint32_t& label, FeatureClass& cls) const
{
  // Cells are coarser than the points, and the cores of obtuse edges are several cells
  // wide: a point is a feature point when it lies within point_feature_distance of the
  // middle line of a skeleton around it (the nearest one names its region); otherwise
  // it belongs to its face cell, or to the closest face cell around it.
  const std::vector<char>& skeleton = segmentation_.skeleton();
  const double limit = segmentation_parameters_.point_feature_distance;
  if (limit <= 0.0 || skeleton.empty() || near_skeleton_.empty() ||
      !near_skeleton_[static_cast<std::size_t>(cell)])
    return;
  const GridSpec& grid = band_.grid();
  const Eigen::Vector3d q =
    (Eigen::Vector3d(p.x, p.y, p.z) - grid.origin) / grid.cell_size; // cell units
  const CellCoord c = band_.coord(cell);
  const std::vector<Eigen::Vector3f>& centres = segmentation_.skeletonCentres();
  const std::vector<Eigen::Vector3f>& tangents = segmentation_.skeletonTangents();
  // Each skeleton cell stands for a short piece of its middle line (its centre, +-1.5
  // cells along its direction), so points in a gap of up to 3 cells between skeleton
  // cells (noise thins the ridge) still find the line.
  constexpr double kHalfPiece = 1.5;
  // A vertex's skeleton is a few cells at its corner, where the line pieces of its
  // edges end too: a point within reach of both goes to the vertex, or the corner might
  // keep no point at all.
  double near_skeleton = std::numeric_limits<double>::infinity();
  CellId nearest_skeleton = kNoCell;
  double near_vertex = std::numeric_limits<double>::infinity();
  CellId nearest_vertex = kNoCell;
  double near_face = std::numeric_limits<double>::infinity();
  std::uint32_t face = 0;
  for (int dz = -2; dz <= 2; ++dz)
    for (int dy = -2; dy <= 2; ++dy)
      for (int dx = -2; dx <= 2; ++dx) {
        const CellId n = band_.find(c + CellCoord(dx, dy, dz));
        if (n == kNoCell)
          continue;
        if (skeleton[static_cast<std::size_t>(n)]) {
          const Eigen::Vector3d d =
            q - centres[static_cast<std::size_t>(n)].template cast<double>();
          const Eigen::Vector3d u =
            tangents[static_cast<std::size_t>(n)].template cast<double>();
          const double along = std::clamp(d.dot(u), -kHalfPiece, kHalfPiece);
          const double distance = (d - along * u).norm();
          if (distance < near_skeleton) {
            near_skeleton = distance;
            nearest_skeleton = n;
          }
          if (distance < near_vertex &&
              segmentation_.cellClass(n) == FeatureClass::kVertex) {
            near_vertex = distance;
            nearest_vertex = n;
          }
        }
        if (std::abs(dx) <= 1 && std::abs(dy) <= 1 && std::abs(dz) <= 1 &&
            segmentation_.cellClass(n) == FeatureClass::kFace) {
          const double d = (band_.coord(n).template cast<double>() +
                            Eigen::Vector3d::Constant(0.5) - q)
                             .norm();
          if (d < near_face) {
            near_face = d;
            face = segmentation_.cellLabels()[static_cast<std::size_t>(n)];
          }
        }
      }
  if (near_vertex <= limit)
    nearest_skeleton = nearest_vertex;
  if (near_skeleton <= limit) {
    label = segmentation_.cellLabels()[static_cast<std::size_t>(nearest_skeleton)];
    cls = segmentation_.cellClass(nearest_skeleton);
  } else if ((cls == FeatureClass::kEdge || cls == FeatureClass::kVertex) &&
             face != 0) {
    label = face;
    cls = FeatureClass::kFace;
  }
}

template <typename PointInT, typename PointOutT>
void
VisibilityFeatureEstimation<PointInT, PointOutT>::buildGraph(
  const PointCloudOut& output)
{
  const std::vector<Region>& regions = segmentation_.regions();
  std::vector<FeatureClass> classes(regions.size());
  for (std::size_t r = 0; r < regions.size(); ++r)
    classes[r] = regions[r].feature_class;
  TopologyGraphParameters parameters;
  const bool touching =
    !segmentation_parameters_.raw && segmentation_parameters_.complete_regions;
  parameters.dilation_radius =
    graph_dilation_ >= 0
      ? graph_dilation_
      : (touching ? 2 : segmentation_parameters_.components.min_radius);
  graph_ = TopologyGraph::build(band_, segmentation_.cellLabels(), classes, parameters);

  // Node geometry from the labeled output points themselves.
  struct Sum
  {
    std::uint64_t n = 0;
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    Eigen::Vector3d min =
      Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
    Eigen::Vector3d max =
      -Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  };
  std::vector<Sum> sums(regions.size());
  for (const PointOutT& p : output.points) {
    if (p.label == 0 || p.label > regions.size() || !pcl::isXYZFinite(p))
      continue;
    Sum& s = sums[p.label - 1];
    const Eigen::Vector3d v(p.x, p.y, p.z);
    ++s.n;
    s.sum += v;
    s.min = s.min.cwiseMin(v);
    s.max = s.max.cwiseMax(v);
  }
  for (std::size_t r = 0; r < regions.size(); ++r)
    if (sums[r].n > 0)
      graph_.setPointGeometry(static_cast<std::uint32_t>(r + 1), sums[r].n,
                              sums[r].sum / static_cast<double>(sums[r].n), sums[r].min,
                              sums[r].max);
}

template <typename PointInT, typename PointOutT>
void
VisibilityFeatureEstimation<PointInT, PointOutT>::computeFeature(PointCloudOut& output)
{
  using Clock = std::chrono::steady_clock;
  try {
    auto start = Clock::now();
    // Noise mode: the band (and the per-point decision) use the smoothed surface.
    typename PointCloudIn::ConstPtr surface = surface_;
    if (smoothing_.radius > 0.0) {
      std::vector<Eigen::Vector3f> points(surface_->size());
      for (std::size_t i = 0; i < points.size(); ++i)
        points[i] = (*surface_)[i].getVector3fMap();
      SmoothingParameters smoothing = smoothing_;
      smoothing.threads = visibility_.threads;
      points = smoothPoints(points, grid_, smoothing);
      auto smoothed = std::make_shared<pcl::PointCloud<PointInT>>(*surface_);
      for (std::size_t i = 0; i < points.size(); ++i)
        (*smoothed)[i].getVector3fMap() = points[i];
      surface = smoothed;
      times_.smoothing_ms = detail::millisecondsSince(start);
      start = Clock::now();
    }
    band_ = buildVoxelBand(*surface, grid_, band_options_);
    times_.band_ms = detail::millisecondsSince(start);

    start = Clock::now();
    free_space_ = FreeSpace(band_);
    times_.free_space_ms = detail::millisecondsSince(start);

    start = Clock::now();
    map_ = VisibilityMap::compute(band_, free_space_, visibility_, progress_);
    times_.visibility_ms = detail::millisecondsSince(start);

    start = Clock::now();
    segmentation_ = FeatureSegmentation::compute(band_, map_, segmentation_parameters_);
    times_.segmentation_ms = detail::millisecondsSince(start);

    start = Clock::now();
    markCellsNearSkeleton();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const GridSpec& grid = band_.grid();
    auto cellOf = [&](std::size_t index, const PointInT& p) -> CellId {
      if (fake_surface_)
        return band_.pointCell()[index];
      // Same arithmetic as the octree's keys, so a point of the surface finds its cell.
      CellCoord c;
      for (int a = 0; a < 3; ++a) {
        const double u =
          (static_cast<double>(p.data[a]) - grid.origin[a]) / grid.cell_size;
        if (!(u >= 0.0 && u < grid.dims[a]))
          return kNoCell;
        c[a] = static_cast<int>(u);
      }
      return band_.find(c);
    };
    bool dense = true;
    for (std::size_t i = 0; i < indices_->size(); ++i) {
      const auto index = static_cast<std::size_t>((*indices_)[i]);
      const PointInT& p = (*input_)[index];
      // The point as the band saw it (smoothed in noise mode).
      const PointInT& seen = fake_surface_ ? (*surface)[index] : p;
      PointOutT& out = output[i];
      out.x = p.x;
      out.y = p.y;
      out.z = p.z;
      const CellId cell = pcl::isXYZFinite(p) ? cellOf(index, p) : kNoCell;
      out.visibility_radius =
        cell == kNoCell ? nan : static_cast<float>(map_.radius(cell));
      std::uint32_t label =
        cell == kNoCell ? 0u
                        : segmentation_.cellLabels()[static_cast<std::size_t>(cell)];
      FeatureClass cls =
        cell == kNoCell ? FeatureClass::kNone : segmentation_.cellClass(cell);
      if (cell != kNoCell)
        refinePointLabel(seen, cell, label, cls);
      out.label = label;
      out.feature_class = static_cast<std::uint8_t>(cls);
      dense = dense && cell != kNoCell;
    }
    output.is_dense = dense;
    times_.output_ms = detail::millisecondsSince(start);

    start = Clock::now();
    buildGraph(output);
    times_.graph_ms = detail::millisecondsSince(start);
  } catch (const Error& e) {
    fail(e.what());
    output.width = output.height = 0;
    output.clear();
  } catch (const std::bad_alloc&) {
    fail("out of memory: lower the resolution");
    output.width = output.height = 0;
    output.clear();
  }
}

} // namespace visfeat

#define PCL_INSTANTIATE_VisibilityFeatureEstimation(T, OUTT)                           \
  template class visfeat::VisibilityFeatureEstimation<T, OUTT>;
