#pragma once

// Checks shared by the VoxelBand tests (test_voxel_band.cpp: structure, repair,
// CellIndex; test_voxel_band_from_cloud.cpp: the PCL path): a band's structural
// invariants and what the repair must give.

#include "band_fixtures.h"

#include <visfeat/core/band/voxel_band.h>

#include <gtest/gtest.h>

#include <array>
#include <functional>
#include <set>
#include <string>
#include <vector>

namespace visfeat_test {
namespace band_checks {

using visfeat::CellCoord;
using visfeat::CellId;
using visfeat::GridSpec;
using visfeat::kNoCell;
using visfeat::OccupiedCell;
using visfeat::VoxelBand;
using visfeat_test::cubeGrid;
using visfeat_test::toString;
using Vec3i = Eigen::Vector3i;
using CoordSet = std::set<std::array<int, 3>>;

inline const Vec3i kFaceDirs[6] = {Vec3i(-1, 0, 0), Vec3i(1, 0, 0),  Vec3i(0, -1, 0),
                                   Vec3i(0, 1, 0),  Vec3i(0, 0, -1), Vec3i(0, 0, 1)};

inline std::array<int, 3>
key(const CellCoord& c)
{
  return {c.x(), c.y(), c.z()};
}

inline CoordSet
toSet(const std::vector<CellCoord>& cells)
{
  CoordSet s;
  for (const CellCoord& c : cells)
    s.insert(key(c));
  return s;
}

inline VoxelBand::Options
withRepair(bool repair)
{
  VoxelBand::Options o;
  o.repair = repair;
  return o;
}

/** Structural invariants every band must satisfy. */
inline void
checkBandStructure(const VoxelBand& band, const std::string& name)
{
  SCOPED_TRACE(name);
  const GridSpec& grid = band.grid();
  ASSERT_EQ(band.coords().size(), band.size());
  // Ids sorted strictly by linear key; every cell inside the grid.
  for (std::size_t i = 0; i < band.size(); ++i) {
    ASSERT_TRUE(grid.contains(band.coord(static_cast<CellId>(i))))
      << toString(band.coord(static_cast<CellId>(i)));
    if (i > 0) {
      ASSERT_LT(grid.linearKey(band.coord(static_cast<CellId>(i - 1))),
                grid.linearKey(band.coord(static_cast<CellId>(i))))
        << "ids not sorted by linearKey at " << i;
    }
  }
  // find() agrees with coords, and neighbours are exactly the mixed face neighbours,
  // ordered -x, +x, -y, +y, -z, +z, and symmetric.
  for (std::size_t i = 0; i < band.size(); ++i) {
    const CellId id = static_cast<CellId>(i);
    const CellCoord& c = band.coord(id);
    ASSERT_EQ(band.find(c), id) << toString(c);
    const VoxelBand::Neighbours& nb = band.neighbours(id);
    for (int k = 0; k < 6; ++k) {
      const CellCoord n = c + kFaceDirs[k];
      const CellId expected = band.find(n);
      ASSERT_EQ(nb[k], expected) << "cell " << toString(c) << " direction " << k;
      if (expected != kNoCell) {
        ASSERT_EQ(band.coord(expected), n);
        ASSERT_EQ(band.neighbours(expected)[k ^ 1], id) << "asymmetric neighbours";
      }
    }
  }
}

/** Whether a and b are joined by a face path through cells of `cells` inside the
 * bounding box of a and b. */
inline bool
faceConnectedInBox(const CellCoord& a,
                   const CellCoord& b,
                   const std::function<bool(const CellCoord&)>& mixed)
{
  const Vec3i lo = a.cwiseMin(b), hi = a.cwiseMax(b);
  std::vector<CellCoord> stack{a};
  CoordSet seen{key(a)};
  while (!stack.empty()) {
    const CellCoord c = stack.back();
    stack.pop_back();
    if (c == b)
      return true;
    for (const Vec3i& d : kFaceDirs) {
      const CellCoord n = c + d;
      if ((n.array() < lo.array()).any() || (n.array() > hi.array()).any())
        continue;
      if (!mixed(n) || !seen.insert(key(n)).second)
        continue;
      stack.push_back(n);
    }
  }
  return false;
}

/** Repair off: nothing added. Repair on: every original cell kept (repair cells hold no
 * point); every 26-adjacent pair of mixed cells -- repair cells included, since they
 * are mixed cells too (VoxelBand::size()) -- is face-connected inside its bounding box
 * (the 2x2x1 or 2x2x2 box of the pair); and every repair cell lies in the box of some
 * 26-adjacent pair of other band cells (it was added to join such a pair). */
inline void
checkRepair(const GridSpec& grid,
            const std::vector<CellCoord>& cells,
            const std::string& name)
{
  SCOPED_TRACE(name);
  const CoordSet original = toSet(cells);
  const VoxelBand off = VoxelBand::fromCells(grid, cells, withRepair(false));
  EXPECT_EQ(toSet(off.coords()), original);
  EXPECT_EQ(off.repairCellCount(), 0u);

  const VoxelBand band = VoxelBand::fromCells(grid, cells, withRepair(true));
  checkBandStructure(band, name + " repaired");
  const CoordSet repaired = toSet(band.coords());
  for (const auto& k : original)
    ASSERT_TRUE(repaired.count(k)) << "original cell lost";
  EXPECT_EQ(band.repairCellCount(), band.size() - original.size());

  auto in_original = [&](const CellCoord& c) { return original.count(key(c)) != 0; };
  auto in_band = [&](const CellCoord& c) { return band.find(c) != kNoCell; };
  std::size_t broken_before = 0, broken_after = 0;
  std::string first_broken;
  for (const CellCoord& a : band.coords())
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const Vec3i d(dx, dy, dz);
          if ((d.array() != 0).count() < 2)
            continue;
          const CellCoord b = a + d;
          if (!in_band(b) || !std::lexicographical_compare(a.data(), a.data() + 3,
                                                           b.data(), b.data() + 3))
            continue;
          if (in_original(a) && in_original(b) &&
              !faceConnectedInBox(a, b, in_original))
            ++broken_before;
          if (!faceConnectedInBox(a, b, in_band) && broken_after++ == 0)
            first_broken = toString(a) + " and " + toString(b);
        }
  EXPECT_EQ(broken_after, 0u)
    << "26-adjacent cells not face-connected in their box after "
       "repair, first: "
    << first_broken;
  for (std::size_t i = 0; i < band.size(); ++i) {
    const CellCoord& c = band.coord(static_cast<CellId>(i));
    if (in_original(c)) {
      EXPECT_GT(band.pointCount(static_cast<CellId>(i)), 0u);
      continue;
    }
    EXPECT_EQ(band.pointCount(static_cast<CellId>(i)), 0u);
    // Some pair p, q of other band cells, 26-adjacent, with c in their box.
    bool justified = false;
    for (int dz = -1; dz <= 1 && !justified; ++dz)
      for (int dy = -1; dy <= 1 && !justified; ++dy)
        for (int dx = -1; dx <= 1 && !justified; ++dx) {
          const CellCoord p = c + Vec3i(dx, dy, dz);
          if (p == c || !in_band(p))
            continue;
          for (int ez = -1; ez <= 1 && !justified; ++ez)
            for (int ey = -1; ey <= 1 && !justified; ++ey)
              for (int ex = -1; ex <= 1 && !justified; ++ex) {
                const CellCoord q = c + Vec3i(ex, ey, ez);
                const Vec3i pq = q - p;
                if (q == c || !in_band(q) || (pq.array() != 0).count() < 2 ||
                    pq.cwiseAbs().maxCoeff() != 1)
                  continue;
                const Vec3i lo = p.cwiseMin(q), hi = p.cwiseMax(q);
                justified =
                  (c.array() >= lo.array()).all() && (c.array() <= hi.array()).all();
              }
        }
    EXPECT_TRUE(justified) << "repair cell " << toString(c)
                           << " lies in the box of no 26-adjacent pair";
  }
  if (name.rfind("sparse", 0) == 0) {
    EXPECT_GT(broken_before, 0u) << "fixture should need repair";
    EXPECT_GT(band.repairCellCount(), 0u);
  }
}

} // namespace band_checks
} // namespace visfeat_test
