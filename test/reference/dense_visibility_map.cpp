#include "reference/dense_visibility_map.h"

#include <visfeat/core/visibility/lattice_segment.h>

#include <cstdint>
#include <cstdlib>
#include <thread>

namespace visfeat_test {
namespace reference {
namespace {

using visfeat::CellCoord;
using visfeat::CellId;

struct DenseMask
{
  explicit DenseMask(const visfeat::VoxelBand& band)
      : dims(2 * band.grid().dims)
      , bits(static_cast<std::size_t>(dims.x()) * dims.y() * dims.z(), false)
  {
    for (const CellCoord& c : band.coords())
      for (int z = 2 * c.z() - 1; z <= 2 * c.z() + 2; ++z)
        for (int y = 2 * c.y() - 1; y <= 2 * c.y() + 2; ++y)
          for (int x = 2 * c.x() - 1; x <= 2 * c.x() + 2; ++x)
            if (inside(Eigen::Vector3i(x, y, z)))
              bits[index(Eigen::Vector3i(x, y, z))] = true;
  }
  bool inside(const Eigen::Vector3i& s) const
  {
    return (s.array() >= 0).all() && (s.array() < dims.array()).all();
  }
  std::size_t index(const Eigen::Vector3i& s) const
  {
    return static_cast<std::size_t>(s.x()) +
           static_cast<std::size_t>(dims.x()) *
             (static_cast<std::size_t>(s.y()) +
              static_cast<std::size_t>(dims.y()) * static_cast<std::size_t>(s.z()));
  }
  bool isFree(const Eigen::Vector3i& s) const { return inside(s) && bits[index(s)]; }

  Eigen::Vector3i dims;
  std::vector<bool> bits;
};

} // namespace

std::vector<int>
denseRadii(const visfeat::VoxelBand& band, int max_radius, double opacity)
{
  const DenseMask mask(band);
  const int w = 2 * max_radius + 1;
  std::vector<std::vector<visfeat::SegmentStretch>> stretches(
    static_cast<std::size_t>(w) * w * w);
  auto slot = [&](const Eigen::Vector3i& d) {
    return static_cast<std::size_t>(
      (d.x() + max_radius) + w * ((d.y() + max_radius) + w * (d.z() + max_radius)));
  };
  for (int z = -max_radius; z <= max_radius; ++z)
    for (int y = -max_radius; y <= max_radius; ++y)
      for (int x = -max_radius; x <= max_radius; ++x)
        if (std::abs(x) + std::abs(y) + std::abs(z) <= max_radius)
          stretches[slot(Eigen::Vector3i(x, y, z))] =
            visfeat::decomposeLatticeSegment(2 * Eigen::Vector3i(x, y, z));

  auto sees = [&](const CellCoord& a, const CellCoord& b) {
    const Eigen::Vector3i start = 2 * a + Eigen::Vector3i::Ones();
    double blocked = 0.0; // subcell edges
    for (const visfeat::SegmentStretch& s : stretches[slot(b - a)]) {
      bool occluded = true;
      for (int i = 0; i < s.count && occluded; ++i)
        occluded = !mask.isFree(start + s.subcells[static_cast<std::size_t>(i)]);
      if (occluded)
        blocked += s.length;
    }
    blocked *= 0.5; // cell edges
    return blocked <= 0.0 || blocked < opacity;
  };

  // Cells are independent: two threads, each its own BFS scratch.
  std::vector<int> radii(band.size(), 0);
  auto radiiOf = [&](std::size_t first, std::size_t last) {
    std::vector<std::uint32_t> mark(band.size(), 0);
    std::vector<CellId> ring, next;
    for (std::size_t c = first; c < last; ++c) {
      const auto stamp = static_cast<std::uint32_t>(c + 1);
      const CellCoord origin = band.coord(static_cast<CellId>(c));
      ring.assign(1, static_cast<CellId>(c));
      mark[c] = stamp;
      int radius = max_radius;
      for (int k = 1; k <= max_radius && radius == max_radius; ++k) {
        next.clear();
        for (const CellId r : ring)
          for (const CellId n : band.neighbours(r))
            if (n != visfeat::kNoCell && mark[static_cast<std::size_t>(n)] != stamp) {
              mark[static_cast<std::size_t>(n)] = stamp;
              next.push_back(n);
            }
        if (next.empty())
          break;
        for (const CellId n : next)
          if (!sees(origin, band.coord(n))) {
            radius = k - 1;
            break;
          }
        ring.swap(next);
      }
      radii[c] = radius;
    }
  };
  const std::size_t half = band.size() / 2;
  std::thread second(radiiOf, half, band.size());
  radiiOf(0, half);
  second.join();
  return radii;
}

} // namespace reference
} // namespace visfeat_test
