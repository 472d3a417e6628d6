// VoxelBand (ids, neighbours, find, point map, repair) and CellIndex; the PCL path
// (gridForCloud + buildVoxelBand) is test_voxel_band_from_cloud.cpp.

#include "band_fixtures.h"
#include "voxel_band_checks.h"
#include <support/portable_random.h>

#include <visfeat/core/band/voxel_band.h>
#include <visfeat/core/common/error.h>
#include <visfeat/core/grid/cell_index.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <random>
#include <set>

namespace {

using namespace visfeat_test::band_checks;

// ---------------------------------------------------------------- structure

TEST(VoxelBand, FromCellsWithoutRepairKeepsExactlyTheCells)
{
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    std::mt19937_64 rng(seed);
    visfeat::synthetic::UniformInt coord(0, 15);
    CoordSet wanted;
    std::vector<CellCoord> cells;
    while (cells.size() < 600) {
      const CellCoord c(coord(rng), coord(rng), coord(rng));
      if (wanted.insert(key(c)).second)
        cells.push_back(c);
    }
    const VoxelBand band = VoxelBand::fromCells(cubeGrid(16), cells, withRepair(false));
    checkBandStructure(band, "random cells " + std::to_string(seed));
    EXPECT_EQ(band.repairCellCount(), 0u);
    EXPECT_EQ(toSet(band.coords()), wanted);
    // find() over the whole grid and a layer outside it.
    for (int z = -1; z <= 16; ++z)
      for (int y = -1; y <= 16; ++y)
        for (int x = -1; x <= 16; ++x) {
          const CellCoord c(x, y, z);
          const CellId id = band.find(c);
          if (wanted.count(key(c))) {
            ASSERT_NE(id, kNoCell) << toString(c);
            ASSERT_EQ(band.coord(id), c);
          } else {
            ASSERT_EQ(id, kNoCell) << toString(c);
          }
        }
    for (std::size_t i = 0; i < band.size(); ++i)
      EXPECT_EQ(band.pointCount(static_cast<CellId>(i)), 1u);
  }
}

TEST(VoxelBand, IdsDoNotDependOnInputOrder)
{
  const visfeat_test::CellBand shells = visfeat_test::ballShells(5);
  std::vector<CellCoord> shuffled = shells.cells;
  std::mt19937_64 rng(7);
  visfeat::synthetic::shuffle(shuffled, rng);
  for (bool repair : {false, true}) {
    const VoxelBand a =
      VoxelBand::fromCells(shells.grid, shells.cells, withRepair(repair));
    const VoxelBand b = VoxelBand::fromCells(shells.grid, shuffled, withRepair(repair));
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i)
      ASSERT_EQ(a.coord(static_cast<CellId>(i)), b.coord(static_cast<CellId>(i)));
    checkBandStructure(a, shells.name);
  }
}

TEST(VoxelBand, BuildRenumbersPointCells)
{
  const GridSpec grid = cubeGrid(10);
  // Occupied cells in reverse key order; points refer to entries of `occupied`.
  std::vector<OccupiedCell> occupied(3);
  occupied[0].coord = CellCoord(7, 7, 7);
  occupied[0].point_count = 2;
  occupied[1].coord = CellCoord(3, 3, 3);
  occupied[1].point_count = 1;
  occupied[2].coord = CellCoord(3, 4, 3);
  occupied[2].point_count = 4;
  const std::vector<std::int32_t> point_occupied{0, 1, -1, 2, 0, 2, 2, 2};
  const VoxelBand band =
    VoxelBand::build(grid, occupied, point_occupied, withRepair(false));
  checkBandStructure(band, "build");
  ASSERT_EQ(band.size(), 3u);
  EXPECT_EQ(band.coord(0), CellCoord(3, 3, 3));
  EXPECT_EQ(band.coord(1), CellCoord(3, 4, 3));
  EXPECT_EQ(band.coord(2), CellCoord(7, 7, 7));
  EXPECT_EQ(band.pointCount(0), 1u);
  EXPECT_EQ(band.pointCount(1), 4u);
  EXPECT_EQ(band.pointCount(2), 2u);
  const std::vector<CellId> expected{2, 0, kNoCell, 1, 2, 1, 1, 1};
  EXPECT_EQ(band.pointCell(), expected);
}

TEST(VoxelBand, BuildRejectsBadInput)
{
  const GridSpec grid = cubeGrid(8);
  EXPECT_THROW(VoxelBand::build(grid, {}, {}, withRepair(true)), visfeat::Error);
  EXPECT_THROW(VoxelBand::fromCells(grid, {}, withRepair(true)), visfeat::Error);
  EXPECT_THROW(VoxelBand::fromCells(grid, {CellCoord(1, 2, 3), CellCoord(1, 2, 3)},
                                    withRepair(false)),
               visfeat::Error);
  EXPECT_THROW(VoxelBand::fromCells(grid, {CellCoord(1, 2, 3), CellCoord(8, 2, 3)},
                                    withRepair(false)),
               visfeat::Error);
  EXPECT_THROW(VoxelBand::fromCells(grid, {CellCoord(-1, 2, 3)}, withRepair(false)),
               visfeat::Error);
}

// ---------------------------------------------------------------- repair

// An edge pair needs exactly one cell, a corner pair exactly two: the fewest cells of
// their box that join them.
TEST(VoxelBandRepair, EdgePairGetsOneCellCornerPairTwo)
{
  const GridSpec grid = cubeGrid(12);
  for (int axis = 0; axis < 3; ++axis) {
    Vec3i d = Vec3i::Ones();
    d[axis] = 0;
    const CellCoord a(5, 5, 5), b = a + d;
    const VoxelBand band = VoxelBand::fromCells(grid, {a, b}, withRepair(true));
    checkBandStructure(band, "edge pair");
    EXPECT_EQ(band.size(), 3u);
    EXPECT_EQ(band.repairCellCount(), 1u);
    EXPECT_TRUE(faceConnectedInBox(
      a, b, [&](const CellCoord& c) { return band.find(c) != kNoCell; }));
  }
  for (const Vec3i& d :
       {Vec3i(1, 1, 1), Vec3i(1, -1, 1), Vec3i(-1, 1, 1), Vec3i(1, 1, -1)}) {
    const CellCoord a(5, 5, 5), b = a + d;
    const VoxelBand band = VoxelBand::fromCells(grid, {a, b}, withRepair(true));
    checkBandStructure(band, "corner pair");
    EXPECT_EQ(band.size(), 4u);
    EXPECT_EQ(band.repairCellCount(), 2u);
    EXPECT_TRUE(faceConnectedInBox(
      a, b, [&](const CellCoord& c) { return band.find(c) != kNoCell; }));
  }
}

// Already face-connected pairs get nothing.
TEST(VoxelBandRepair, ConnectedPairsGetNothing)
{
  const GridSpec grid = cubeGrid(12);
  const std::vector<CellCoord> cells{CellCoord(5, 5, 5), CellCoord(6, 5, 5),
                                     CellCoord(6, 6, 5), CellCoord(6, 6, 6)};
  const VoxelBand band = VoxelBand::fromCells(grid, cells, withRepair(true));
  EXPECT_EQ(band.size(), 4u);
  EXPECT_EQ(band.repairCellCount(), 0u);
}

// The candidate closest to the centroid of the pair's points is chosen.
TEST(VoxelBandRepair, ChoosesCandidateClosestToCentroid)
{
  const GridSpec grid = cubeGrid(12);
  const double s = OccupiedCell::kOffsetScale;
  auto cell = [&](const CellCoord& c, double ox, double oy, double oz) {
    OccupiedCell o;
    o.coord = c;
    o.point_count = 1;
    o.offset_sum = Eigen::Matrix<std::int64_t, 3, 1>(
      std::llround(ox * s), std::llround(oy * s), std::llround(oz * s));
    return o;
  };
  // a = (5,5,5) with its point at (5.1, 5.9, 5.5); b = (6,6,5) with (6.1, 6.1, 5.5):
  // centroid (5.6, 6.0, 5.5); candidate (5,6,5) has centre (5.5, 6.5, 5.5), distance^2
  // 0.26; candidate (6,5,5) has (6.5, 5.5, 5.5), distance^2 1.06.
  {
    const VoxelBand band = VoxelBand::build(grid,
                                            {cell(CellCoord(5, 5, 5), 0.1, 0.9, 0.5),
                                             cell(CellCoord(6, 6, 5), 0.1, 0.1, 0.5)},
                                            {0, 1}, withRepair(true));
    ASSERT_EQ(band.size(), 3u);
    EXPECT_NE(band.find(CellCoord(5, 6, 5)), kNoCell);
    EXPECT_EQ(band.find(CellCoord(6, 5, 5)), kNoCell);
    EXPECT_EQ(band.pointCount(band.find(CellCoord(5, 6, 5))), 0u);
  }
  // Mirrored: a's point at (5.9, 5.1, 5.5), b's at (6.1, 6.1, 5.5): centroid
  // (6.0, 5.6, 5.5) -> (6,5,5).
  {
    const VoxelBand band = VoxelBand::build(grid,
                                            {cell(CellCoord(5, 5, 5), 0.9, 0.1, 0.5),
                                             cell(CellCoord(6, 6, 5), 0.1, 0.1, 0.5)},
                                            {0, 1}, withRepair(true));
    ASSERT_EQ(band.size(), 3u);
    EXPECT_NE(band.find(CellCoord(6, 5, 5)), kNoCell);
    EXPECT_EQ(band.find(CellCoord(5, 6, 5)), kNoCell);
  }
}

TEST(VoxelBandRepair, RandomSparseCells)
{
  for (std::uint64_t seed : {11u, 12u, 13u, 14u}) {
    std::mt19937_64 rng(seed);
    visfeat::synthetic::UniformInt coord(1, 14);
    CoordSet set;
    std::vector<CellCoord> cells;
    while (cells.size() < 350) {
      const CellCoord c(coord(rng), coord(rng), coord(rng));
      if (set.insert(key(c)).second)
        cells.push_back(c);
    }
    checkRepair(cubeGrid(16), cells, "sparse " + std::to_string(seed));
  }
}

// Thin digital planes (centre within |n|_inf / 2 of the plane: 26-connected but not
// 6-connected) get repaired.
TEST(VoxelBandRepair, NaiveDigitalPlanes)
{
  for (std::uint64_t seed : {31u, 32u, 33u}) {
    std::mt19937_64 rng(seed);
    const Eigen::Matrix3d r = visfeat_test::randomRotationMatrix(rng);
    const Eigen::Vector3d n = r.col(2);
    const Eigen::Vector3d c0(10.3, 9.8, 10.1);
    const double half = n.cwiseAbs().maxCoeff() / 2.0;
    std::vector<CellCoord> cells;
    for (int z = 2; z < 18; ++z)
      for (int y = 2; y < 18; ++y)
        for (int x = 2; x < 18; ++x) {
          const Eigen::Vector3d p =
            Eigen::Vector3d(x, y, z) + Eigen::Vector3d::Constant(0.5) - c0;
          const double h = n.dot(p);
          if (h > -half && h <= half && (p - h * n).norm() < 7.0)
            cells.push_back(CellCoord(x, y, z));
        }
    checkRepair(cubeGrid(20), cells, "sparse naive plane " + std::to_string(seed));
  }
}

// ---------------------------------------------------------------- CellIndex

TEST(CellIndex, FindsInsertedCellsOnly)
{
  const Vec3i dims(19, 9, 23); // not multiples of the brick size
  visfeat::CellIndex index(dims);
  std::mt19937_64 rng(5);
  std::map<std::array<int, 3>, CellId> inserted;
  for (int i = 0; i < 300; ++i) {
    const CellCoord c(static_cast<int>(rng() % 19), static_cast<int>(rng() % 9),
                      static_cast<int>(rng() % 23));
    if (inserted.count(key(c)))
      continue;
    const CellId id = static_cast<CellId>(inserted.size());
    inserted[key(c)] = id;
    index.insert(c, id);
  }
  for (int z = -2; z < 25; ++z)
    for (int y = -2; y < 11; ++y)
      for (int x = -2; x < 21; ++x) {
        const auto it = inserted.find({x, y, z});
        ASSERT_EQ(index.find(CellCoord(x, y, z)),
                  it == inserted.end() ? kNoCell : it->second)
          << toString(CellCoord(x, y, z));
      }
}

} // namespace
