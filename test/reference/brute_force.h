#pragma once

// Independent brute-force reference for the segment test and the visibility radius of
// DESIGN.md ("Free space and the segment test", "Visibility radius").
//
// Written from the definitions only, simple and slow on purpose. It shares no code with
// the library: it uses GridSpec / CellCoord as plain types (both header-only) and never
// calls FreeSpace, SegmentTable, decomposeLatticeSegment, VoxelBand or VisibilityMap.

#include <visfeat/core/grid/grid_spec.h>

#include <Eigen/Core>

#include <cstdint>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace visfeat_test {
namespace reference {

using visfeat::CellCoord;
using visfeat::GridSpec;
using Vec3i = Eigen::Vector3i;

/** \brief Hash of integer triples (coordinates within +-2^20). */
struct Vec3iHash
{
  std::size_t operator()(const Vec3i& v) const
  {
    const std::uint64_t x = static_cast<std::uint64_t>(v.x() + (1 << 20));
    const std::uint64_t y = static_cast<std::uint64_t>(v.y() + (1 << 20));
    const std::uint64_t z = static_cast<std::uint64_t>(v.z() + (1 << 20));
    std::uint64_t h = x | (y << 21) | (z << 42);
    h ^= h >> 33;
    h *= 0xff51afd7ed558ccdULL;
    h ^= h >> 33;
    return static_cast<std::size_t>(h);
  }
};

struct Vec3iEqual
{
  bool operator()(const Vec3i& a, const Vec3i& b) const
  {
    return a.x() == b.x() && a.y() == b.y() && a.z() == b.z();
  }
};

using CellSet = std::unordered_set<Vec3i, Vec3iHash, Vec3iEqual>;

/** \brief The free subcells: subcells of a mixed cell, or touching one by a face, an
 * edge or a corner (Chebyshev distance <= 1 in subcell units). Subcells outside the
 * subcell grid (2 * dims per axis) are occluded. */
class FreeSubcells
{
public:
  FreeSubcells(const GridSpec& grid, const std::vector<CellCoord>& mixed);

  /** \brief Subcells per axis. */
  const Vec3i& dims() const { return dims_; }

  bool isFree(const Vec3i& s) const;

  /** \brief Number of free subcells. */
  std::size_t freeCount() const { return free_.size(); }

private:
  Vec3i dims_{0, 0, 0};
  CellSet free_;
};

/** \brief Subcells around the point P + t D, t = (2m + 1) / (2N), i.e. the midpoint of
 * the m-th of N equal parameter intervals of the segment P -> P + D. Per axis: {x - 1,
 * x} when the coordinate x is an integer, {floor(x)} otherwise; the result is the
 * product set, sorted lexicographically (1, 2, 4 or 8 subcells). */
std::vector<Vec3i>
midpointSubcells(const Vec3i& p, const Vec3i& d, std::int64_t m, std::int64_t n);

/** \brief lcm of the nonzero |d_i| (0 for d = 0). Every crossing of an integer plane by
 * the segment P -> P + D (P a lattice point) happens at a parameter t = k / N. */
std::int64_t intervalCount(const Vec3i& d);

/** \brief Result of the brute-force segment test between two cell centres. */
struct Blocked
{
  std::int64_t intervals = 0;         // N
  std::int64_t blocked_intervals = 0; // intervals whose midpoint lies in the occluder
  std::int64_t d_norm2 = 0;           // |Q - P|^2, subcell units

  /** \brief Blocked length in cell edges: blocked * |D| / N / 2. */
  double length() const;
};

/** \brief Brute-force segment test between the centres of cells a and b. */
Blocked
blockedLength(const FreeSubcells& free_space, const CellCoord& a, const CellCoord& b);

/** \brief Visible iff nothing is blocked or the blocked length is < opacity; decided
 * exactly (squares of integers against the squared opacity). */
bool visible(const Blocked& blocked, double opacity);

/** \brief Brute-force visibility radius of every cell of `cells` (DESIGN.md): BFS rings
 * over 6-adjacent cells of `cells`, the number of successive rings all visible from the
 * cell, capped at max_radius; an empty ring counts as visible. */
std::vector<int> radii(const std::vector<CellCoord>& cells,
                       const FreeSubcells& free_space,
                       int max_radius,
                       double opacity);

/** \brief Radius of one cell (same definition). */
int radius(const CellSet& cells,
           const CellCoord& c,
           const FreeSubcells& free_space,
           int max_radius,
           double opacity);

} // namespace reference
} // namespace visfeat_test
