#include "brute_force.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numeric>
#include <stdexcept>

namespace visfeat_test {
namespace reference {

FreeSubcells::FreeSubcells(const GridSpec& grid, const std::vector<CellCoord>& mixed)
    : dims_(2 * grid.dims)
{
  // Subcell s of cell c: 2c <= s <= 2c + 1. Touching: Chebyshev distance 1, so every
  // subcell in 2c - 1 .. 2c + 2 per axis is free.
  for (const CellCoord& c : mixed)
    for (int z = 2 * c.z() - 1; z <= 2 * c.z() + 2; ++z)
      for (int y = 2 * c.y() - 1; y <= 2 * c.y() + 2; ++y)
        for (int x = 2 * c.x() - 1; x <= 2 * c.x() + 2; ++x) {
          const Vec3i s(x, y, z);
          if ((s.array() >= 0).all() && (s.array() < dims_.array()).all())
            free_.insert(s);
        }
}

bool
FreeSubcells::isFree(const Vec3i& s) const
{
  return free_.count(s) != 0;
}

namespace {

std::int64_t
floorDiv(std::int64_t a, std::int64_t b) // b > 0
{
  std::int64_t q = a / b;
  if ((a % b != 0) && (a < 0))
    --q;
  return q;
}

} // namespace

std::int64_t
intervalCount(const Vec3i& d)
{
  std::int64_t n = 0;
  for (int i = 0; i < 3; ++i) {
    const std::int64_t a = std::llabs(static_cast<long long>(d[i]));
    if (a == 0)
      continue;
    n = (n == 0) ? a : std::lcm(n, a);
  }
  return n;
}

std::vector<Vec3i>
midpointSubcells(const Vec3i& p, const Vec3i& d, std::int64_t m, std::int64_t n)
{
  // X = P + (2m+1)/(2N) D; scaled by 2N: 2N X = 2N P + (2m+1) D.
  const std::int64_t den = 2 * n;
  std::vector<int> options[3];
  for (int i = 0; i < 3; ++i) {
    const std::int64_t num = den * p[i] + (2 * m + 1) * static_cast<std::int64_t>(d[i]);
    if (num % den == 0) {
      const int x = static_cast<int>(num / den);
      options[i] = {x - 1, x};
    } else {
      options[i] = {static_cast<int>(floorDiv(num, den))};
    }
  }
  std::vector<Vec3i> out;
  for (int x : options[0])
    for (int y : options[1])
      for (int z : options[2])
        out.emplace_back(x, y, z);
  std::sort(out.begin(), out.end(), [](const Vec3i& a, const Vec3i& b) {
    return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
  });
  return out;
}

double
Blocked::length() const
{
  if (blocked_intervals == 0)
    return 0.0;
  return static_cast<double>(blocked_intervals) *
         std::sqrt(static_cast<double>(d_norm2)) / static_cast<double>(intervals) / 2.0;
}

Blocked
blockedLength(const FreeSubcells& free_space, const CellCoord& a, const CellCoord& b)
{
  const Vec3i p = 2 * a + Vec3i::Ones();
  const Vec3i q = 2 * b + Vec3i::Ones();
  const Vec3i d = q - p;
  Blocked out;
  out.d_norm2 = static_cast<std::int64_t>(d.x()) * d.x() +
                static_cast<std::int64_t>(d.y()) * d.y() +
                static_cast<std::int64_t>(d.z()) * d.z();
  out.intervals = intervalCount(d);
  for (std::int64_t m = 0; m < out.intervals; ++m) {
    const std::vector<Vec3i> around = midpointSubcells(p, d, m, out.intervals);
    if (around.size() == 8)
      throw std::logic_error("reference: midpoint on a lattice point");
    bool all_occluded = true;
    for (const Vec3i& s : around)
      if (free_space.isFree(s)) {
        all_occluded = false;
        break;
      }
    if (all_occluded)
      ++out.blocked_intervals;
  }
  return out;
}

bool
visible(const Blocked& blocked, double opacity)
{
  if (blocked.blocked_intervals == 0)
    return true;
  // k |D| / (2N) < opacity  <=>  k^2 |D|^2 < (2 N opacity)^2   (opacity > 0)
  if (!(opacity > 0.0))
    return false;
  const double lhs = static_cast<double>(blocked.blocked_intervals) *
                     static_cast<double>(blocked.blocked_intervals) *
                     static_cast<double>(blocked.d_norm2);
  const double r = 2.0 * static_cast<double>(blocked.intervals) * opacity;
  return lhs < r * r;
}

int
radius(const CellSet& cells,
       const CellCoord& c,
       const FreeSubcells& free_space,
       int max_radius,
       double opacity)
{
  static const Vec3i kDirs[6] = {Vec3i(-1, 0, 0), Vec3i(1, 0, 0),  Vec3i(0, -1, 0),
                                 Vec3i(0, 1, 0),  Vec3i(0, 0, -1), Vec3i(0, 0, 1)};
  CellSet seen;
  seen.insert(c);
  std::vector<CellCoord> ring{c};
  for (int k = 1; k <= max_radius; ++k) {
    std::vector<CellCoord> next;
    for (const CellCoord& r : ring)
      for (const Vec3i& dir : kDirs) {
        const CellCoord n = r + dir;
        if (cells.count(n) && seen.insert(n).second)
          next.push_back(n);
      }
    for (const CellCoord& n : next)
      if (!visible(blockedLength(free_space, c, n), opacity))
        return k - 1;
    ring.swap(next); // an empty ring is visible; later rings stay empty
  }
  return max_radius;
}

std::vector<int>
radii(const std::vector<CellCoord>& cells,
      const FreeSubcells& free_space,
      int max_radius,
      double opacity)
{
  CellSet set(cells.begin(), cells.end());
  std::vector<int> out;
  out.reserve(cells.size());
  for (const CellCoord& c : cells)
    out.push_back(radius(set, c, free_space, max_radius, opacity));
  return out;
}

} // namespace reference
} // namespace visfeat_test
