#include <visfeat/core/segmentation/flat_cores.h>

#include <Eigen/Eigenvalues>

#include <algorithm>

namespace visfeat {
namespace {

/** Patches fitted per core, at most. */
constexpr std::size_t kPatchesPerCore = 32;

/** Surface variation of the band cells within kFlatCoreRadius 6-steps of `centre`. */
double
patchVariation(const VoxelBand& band,
               CellId centre,
               std::vector<std::uint32_t>& stamp,
               std::uint32_t mark,
               std::vector<std::pair<CellId, int>>& queue)
{
  queue.assign(1, {centre, 0});
  stamp[static_cast<std::size_t>(centre)] = mark;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  Eigen::Matrix3d outer = Eigen::Matrix3d::Zero();
  const Eigen::Vector3d origin = band.coord(centre).cast<double>();
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const auto [cell, steps] = queue[head];
    const Eigen::Vector3d p = band.coord(cell).cast<double>() - origin;
    sum += p;
    outer += p * p.transpose();
    if (steps == kFlatCoreRadius)
      continue;
    for (const CellId nb : band.neighbours(cell))
      if (nb != kNoCell && stamp[static_cast<std::size_t>(nb)] != mark) {
        stamp[static_cast<std::size_t>(nb)] = mark;
        queue.emplace_back(nb, steps + 1);
      }
  }
  const double n = static_cast<double>(queue.size());
  const Eigen::Vector3d mean = sum / n;
  const Eigen::Matrix3d covariance = outer / n - mean * mean.transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(covariance,
                                                             Eigen::EigenvaluesOnly);
  const double total = eigen.eigenvalues().sum();
  return total > 0.0 ? eigen.eigenvalues()(0) / total : 1.0;
}

} // namespace

double
coreVariation(const VoxelBand& band,
              const std::vector<CellId>& members,
              std::vector<std::uint32_t>& stamp,
              std::uint32_t& next_stamp)
{
  const std::size_t stride = std::max<std::size_t>(1, members.size() / kPatchesPerCore);
  std::vector<double> variation;
  std::vector<std::pair<CellId, int>> queue;
  for (std::size_t i = 0; i < members.size() && variation.size() < kPatchesPerCore;
       i += stride)
    variation.push_back(patchVariation(band, members[i], stamp, ++next_stamp, queue));
  const auto middle =
    variation.begin() + static_cast<std::ptrdiff_t>(variation.size() / 2);
  std::nth_element(variation.begin(), middle, variation.end());
  return *middle;
}

bool
flatCore(const VoxelBand& band,
         const std::vector<CellId>& members,
         std::vector<std::uint32_t>& stamp,
         std::uint32_t& next_stamp)
{
  return coreVariation(band, members, stamp, next_stamp) < kFlatCoreVariation;
}

bool
fadingCreaseCore(const VoxelBand& band,
                 const std::vector<CellId>& members,
                 int min_radius,
                 std::vector<std::uint32_t>& stamp,
                 std::uint32_t& next_stamp)
{
  return members.size() >
           kFadingCreaseMinRadii * static_cast<std::size_t>(min_radius) &&
         coreVariation(band, members, stamp, next_stamp) >= kFadingCreaseVariation;
}

} // namespace visfeat
