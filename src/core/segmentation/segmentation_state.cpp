#include "segmentation_state.h"

#include <visfeat/core/band/band_pieces.h>
#include <visfeat/core/common/threads.h>

#include <limits>
#include <mutex>

namespace visfeat {
namespace segmentation {

SegmentationState::SegmentationState(const VoxelBand& band_,
                                     const VisibilityMap& map_,
                                     const SegmentationParameters& parameters_,
                                     const ComponentSet& cores_)
    : band(band_)
    , map(map_)
    , parameters(parameters_)
    , cores(cores_.components())
    , core_of(cores_.cellLabels())
    , seeds(core_of)
    , cls(cores.size() + 1, FeatureClass::kNone)
    , sets(cores.size())
    , face_count(cores.size() + 1, 0)
    , speck_into(cores.size() + 1, 0)
    , speck(cores.size() + 1, 0)
{
  // Outlier clusters: small band pieces get no label at all.
  const std::vector<std::uint32_t> piece = bandPieceSizes(band);
  for (std::size_t c = 0; c < seeds.size(); ++c)
    if (piece[c] < static_cast<std::uint32_t>(parameters.min_piece_cells))
      seeds[c] = 0;
  for (std::size_t l = 0; l < cores.size(); ++l)
    cls[l + 1] = cores[l].feature_class;
}

std::vector<std::set<std::uint32_t>>
SegmentationState::coresWithin(const std::vector<std::uint32_t>& labels,
                               const std::vector<std::uint32_t>& steps)
{
  std::vector<std::set<std::uint32_t>> met(labels.size());
  std::mutex mutex; // guards `dilations`: a chunk takes one, then gives it back
  parallelFor(labels.size(), parameters.threads, 1,
              [&](std::size_t begin, std::size_t end) {
                std::unique_ptr<BandDilation> dilation;
                {
                  const std::lock_guard<std::mutex> lock(mutex);
                  if (!dilations.empty()) {
                    dilation = std::move(dilations.back());
                    dilations.pop_back();
                  }
                }
                if (!dilation)
                  dilation = std::make_unique<BandDilation>(band);
                for (std::size_t i = begin; i < end; ++i) {
                  const std::uint32_t l = labels[i];
                  dilation->run(core_cells[l], steps[i], [&](CellId c) {
                    const std::uint32_t other = core_of[static_cast<std::size_t>(c)];
                    if (other != 0 && other != l)
                      met[i].insert(other);
                  });
                }
                const std::lock_guard<std::mutex> lock(mutex);
                dilations.push_back(std::move(dilation));
              });
  return met;
}

ThinningState::ThinningState(SegmentationState& state)
    : band(state.band)
    , map(state.map)
    , parameters(state.parameters)
    , core_of(state.core_of)
    , speck(state.speck)
    , labels(state.labels)
    , cls(state.cls)
    , skeleton(state.band.size(), 0)
    , centres(state.band.size(),
              Eigen::Vector3f::Constant(std::numeric_limits<float>::quiet_NaN()))
    , tangents(state.band.size(), Eigen::Vector3f::Zero())
{
  for (std::size_t c = 0; c < band.size(); ++c) {
    skeleton[c] = isFeature(labels[c]) && core_of[c] != 0 && !speck[core_of[c]];
    if (skeleton[c])
      (cls[labels[c]] == FeatureClass::kVertex ? vertex_cores : edge_cores)[labels[c]]
        .push_back(static_cast<CellId>(c));
  }
  for (const auto& [edge, cells] : edge_cores)
    core_line[edge] = fitCoreLine(band, cells);
}

void
ThinningState::setCentre(CellId c,
                         const Eigen::Vector3d& x,
                         const Eigen::Vector3d& direction)
{
  centres[static_cast<std::size_t>(c)] =
    (x + Eigen::Vector3d::Constant(0.5)).cast<float>();
  tangents[static_cast<std::size_t>(c)] = direction.cast<float>();
}

double
ThinningState::distance(CellId a, CellId b) const
{
  return (band.coord(a) - band.coord(b)).cast<double>().norm();
}

CellId
ThinningState::farthestFrom(CellId from, const std::vector<CellId>& cells) const
{
  CellId best = from;
  double best_distance = -1.0;
  for (const CellId c : cells)
    if (const double d = distance(from, c); d > best_distance) {
      best_distance = d;
      best = c;
    }
  return best;
}

namespace {

/** The band cell among those within `radius` (Chebyshev) of round(x) nearest to x and
 * no farther than max_distance, the first in z, y, x order among equals; kNoCell if
 * none. */
CellId
nearestInCube(const VoxelBand& band,
              const Eigen::Vector3d& x,
              int radius,
              double max_distance)
{
  const CellCoord at = x.array().round().cast<int>().matrix();
  CellId best = kNoCell;
  double best_distance = std::numeric_limits<double>::infinity();
  for (int dz = -radius; dz <= radius; ++dz)
    for (int dy = -radius; dy <= radius; ++dy)
      for (int dx = -radius; dx <= radius; ++dx) {
        const CellId c = band.find(at + CellCoord(dx, dy, dz));
        if (c == kNoCell)
          continue;
        const double d = (band.coord(c).cast<double>() - x).norm();
        if (d < best_distance && d <= max_distance) {
          best_distance = d;
          best = c;
        }
      }
  return best;
}

} // namespace

CellId
ThinningState::nearestCell(const Eigen::Vector3d& x) const
{
  return nearestInCube(band, x, 1, std::numeric_limits<double>::infinity());
}

CellId
ThinningState::nearestCellWithin(const Eigen::Vector3d& x, int radius) const
{
  return nearestInCube(band, x, radius, static_cast<double>(radius));
}

} // namespace segmentation
} // namespace visfeat
