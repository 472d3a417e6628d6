#include <visfeat/core/visibility/lattice_segment.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numeric>

namespace visfeat {
namespace {

std::int64_t
floorDiv(std::int64_t a, std::int64_t b) // b > 0
{
  return a >= 0 ? a / b : -((-a + b - 1) / b);
}

} // namespace

std::vector<SegmentStretch>
decomposeLatticeSegment(const Eigen::Vector3i& d)
{
  std::vector<SegmentStretch> stretches;
  if (d.isZero())
    return stretches;

  // Every crossing of an integer plane happens at t = n / L, L = lcm of the nonzero
  // |d_a|.
  std::int64_t L = 1;
  for (int a = 0; a < 3; ++a)
    if (d[a] != 0)
      L = std::lcm(L, static_cast<std::int64_t>(std::abs(d[a])));

  std::vector<std::int64_t> breaks;
  for (int a = 0; a < 3; ++a) {
    const std::int64_t n = std::abs(d[a]);
    for (std::int64_t m = 0; n > 0 && m <= n; ++m)
      breaks.push_back(m * (L / n));
  }
  std::sort(breaks.begin(), breaks.end());
  breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());

  const double norm = d.cast<double>().norm();
  for (std::size_t b = 0; b + 1 < breaks.size(); ++b) {
    const std::int64_t n0 = breaks[b], n1 = breaks[b + 1];
    // Midpoint x_a = d_a (n0 + n1) / (2L): not an integer unless d_a = 0.
    std::array<std::int64_t, 3> lo{}, count{};
    for (int a = 0; a < 3; ++a) {
      if (d[a] == 0) {
        lo[a] = -1; // on the plane x_a = 0: subcells -1 and 0
        count[a] = 2;
      } else {
        lo[a] = floorDiv(static_cast<std::int64_t>(d[a]) * (n0 + n1), 2 * L);
        count[a] = 1;
      }
    }
    SegmentStretch s;
    s.length = norm * static_cast<double>(n1 - n0) / static_cast<double>(L);
    s.t_mid = static_cast<double>(n0 + n1) / static_cast<double>(2 * L);
    for (std::int64_t z = 0; z < count[2]; ++z)
      for (std::int64_t y = 0; y < count[1]; ++y)
        for (std::int64_t x = 0; x < count[0]; ++x)
          s.subcells[static_cast<std::size_t>(s.count++)] =
            Eigen::Vector3i(static_cast<int>(lo[0] + x), static_cast<int>(lo[1] + y),
                            static_cast<int>(lo[2] + z));
    stretches.push_back(s);
  }
  return stretches;
}

} // namespace visfeat
