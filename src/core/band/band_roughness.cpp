#include <visfeat/core/band/band_roughness.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace visfeat {

double
bandRoughness(const GridSpec& grid,
              const std::vector<CellCoord>& coords,
              const std::vector<std::uint32_t>& counts,
              const std::vector<Eigen::Vector3d>& sums)
{
  const std::size_t n = coords.size();
  std::vector<std::uint64_t> keys(n);
  for (std::size_t i = 0; i < n; ++i)
    keys[i] = grid.linearKey(coords[i]);
  const std::size_t stride = std::max<std::size_t>(1, n / kRoughnessSamples);
  std::vector<double> rms;
  std::vector<Eigen::Vector3d> block;
  for (std::size_t i = 0; i < n; i += stride) {
    if (counts[i] == 0)
      continue;
    block.clear();
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const CellCoord c = coords[i] + CellCoord(dx, dy, dz);
          if (!grid.contains(c))
            continue;
          const auto it = std::lower_bound(keys.begin(), keys.end(), grid.linearKey(c));
          if (it == keys.end() || *it != grid.linearKey(c))
            continue;
          const auto j = static_cast<std::size_t>(it - keys.begin());
          if (counts[j] > 0)
            block.push_back(sums[j] / static_cast<double>(counts[j]));
        }
    if (block.size() < static_cast<std::size_t>(kMinRoughnessCentroids))
      continue;
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (const Eigen::Vector3d& p : block)
      mean += p;
    mean /= static_cast<double>(block.size());
    Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
    for (const Eigen::Vector3d& p : block)
      covariance += (p - mean) * (p - mean).transpose();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
    solver.computeDirect(covariance / static_cast<double>(block.size()),
                         Eigen::EigenvaluesOnly);
    rms.push_back(std::sqrt(std::max(0.0, solver.eigenvalues()[0])));
  }
  if (rms.size() < kMinRoughnessBlocks)
    return -1.0;
  auto middle = rms.begin() + static_cast<std::ptrdiff_t>(rms.size() / 2);
  std::nth_element(rms.begin(), middle, rms.end());
  return *middle;
}

} // namespace visfeat
