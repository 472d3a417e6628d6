#pragma once

// Helpers shared by the fill tests (test_surface_fill.cpp, test_crease_fill.cpp).

#include <visfeat/core/band/voxel_band.h>

#include <Eigen/Core>

#include <algorithm>
#include <cstdint>
#include <tuple>
#include <utility>
#include <vector>

namespace visfeat_test {
namespace fill {

using Key = std::tuple<int, int, int>;

inline Key
key(const visfeat::CellCoord& c)
{
  return {c.x(), c.y(), c.z()};
}

/** Brute-force k nearest neighbours (the point itself first). */
inline std::vector<std::uint32_t>
nearest(const std::vector<Eigen::Vector3d>& points, int k)
{
  std::vector<std::uint32_t> table;
  for (std::size_t i = 0; i < points.size(); ++i) {
    std::vector<std::pair<double, std::uint32_t>> d;
    for (std::size_t j = 0; j < points.size(); ++j)
      d.emplace_back((points[j] - points[i]).squaredNorm(),
                     static_cast<std::uint32_t>(j));
    std::partial_sort(d.begin(), d.begin() + k, d.end());
    for (int j = 0; j < k; ++j)
      table.push_back(d[static_cast<std::size_t>(j)].second);
  }
  return table;
}

} // namespace fill
} // namespace visfeat_test
