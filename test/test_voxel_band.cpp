// VoxelBand (ids, neighbours, find, point map, repair), CellIndex, and the PCL path
// (gridForCloud + buildVoxelBand).

#include "band_fixtures.h"
#include <support/cad_catalogue.h>
#include <support/cad_sampling.h>
#include <support/portable_random.h>
#include <support/synthetic_shapes.h>

#include <visfeat/core/band/voxel_band.h>
#include <visfeat/core/common/error.h>
#include <visfeat/core/grid/cell_index.h>
#include <visfeat/voxel_band_from_cloud.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <numeric>
#include <random>
#include <set>

namespace {

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

const Vec3i kFaceDirs[6] = {Vec3i(-1, 0, 0), Vec3i(1, 0, 0),  Vec3i(0, -1, 0),
                            Vec3i(0, 1, 0),  Vec3i(0, 0, -1), Vec3i(0, 0, 1)};

std::array<int, 3>
key(const CellCoord& c)
{
  return {c.x(), c.y(), c.z()};
}

CoordSet
toSet(const std::vector<CellCoord>& cells)
{
  CoordSet s;
  for (const CellCoord& c : cells)
    s.insert(key(c));
  return s;
}

VoxelBand::Options
withRepair(bool repair)
{
  VoxelBand::Options o;
  o.repair = repair;
  return o;
}

/** Structural invariants every band must satisfy. */
void
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
bool
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

/** Repair off: nothing added. Repair on: every original cell kept (repair cells hold no
 * point); every 26-adjacent pair of mixed cells -- repair cells included, since they
 * are mixed cells too (VoxelBand::size()) -- is face-connected inside its bounding box
 * (the 2x2x1 or 2x2x2 box of the pair); and every repair cell lies in the box of some
 * 26-adjacent pair of other band cells (it was added to join such a pair). */
void
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

// ---------------------------------------------------------------- PCL path

pcl::PointCloud<pcl::PointXYZ>
cloudWithNaNs(std::uint64_t seed)
{
  pcl::PointCloud<pcl::PointXYZ> cloud =
    visfeat_test::syntheticShapeCloud("octahedron", seed, 20);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  cloud.points.insert(cloud.points.begin() + 3, pcl::PointXYZ(nan, 0.f, 0.f));
  cloud.points.insert(cloud.points.begin() + 10, pcl::PointXYZ(0.f, 0.f, inf));
  cloud.push_back(pcl::PointXYZ(nan, nan, nan));
  cloud.width = static_cast<std::uint32_t>(cloud.points.size());
  cloud.height = 1;
  cloud.is_dense = false;
  return cloud;
}

TEST(BandFromCloud, GridFollowsTheDefinition)
{
  const pcl::PointCloud<pcl::PointXYZ> cloud = cloudWithNaNs(41);
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e30), hi = -lo;
  for (const pcl::PointXYZ& p : cloud.points) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      continue;
    const Eigen::Vector3d q(p.x, p.y, p.z);
    lo = lo.cwiseMin(q);
    hi = hi.cwiseMax(q);
  }
  const int resolution = 20;
  const GridSpec grid = visfeat::gridForCloud(cloud, resolution);
  const double extent = (hi - lo).maxCoeff();
  EXPECT_NEAR(grid.cell_size, extent / resolution, 1e-9 * extent);
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(grid.origin[i], lo[i] - 2.0 * grid.cell_size, 1e-6 * grid.cell_size);
  // Every finite point lies at least 2 cells inside the grid.
  for (const pcl::PointXYZ& p : cloud.points) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      continue;
    const Eigen::Vector3d f =
      ((Eigen::Vector3d(p.x, p.y, p.z) - grid.origin) / grid.cell_size).array().floor();
    EXPECT_TRUE((f.array() >= 2).all() &&
                (f.array() <= (grid.dims.cast<double>().array() - 3)).all())
      << "point cell " << f.transpose() << " dims " << grid.dims.transpose();
  }
}

TEST(BandFromCloud, PointCellsFollowTheFloorFormula)
{
  const pcl::PointCloud<pcl::PointXYZ> cloud = cloudWithNaNs(42);
  for (bool repair : {false, true}) {
    const VoxelBand band = visfeat_test::bandFromCloud(cloud, 20, repair);
    checkBandStructure(band, repair ? "cloud, repair" : "cloud, no repair");
    const GridSpec& grid = band.grid();
    ASSERT_EQ(band.pointCell().size(), cloud.size());
    std::vector<std::uint32_t> counts(band.size(), 0);
    CoordSet occupied;
    for (std::size_t i = 0; i < cloud.size(); ++i) {
      const pcl::PointXYZ& p = cloud.points[i];
      const CellId id = band.pointCell()[i];
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
        EXPECT_EQ(id, kNoCell) << "point " << i;
        continue;
      }
      ASSERT_NE(id, kNoCell) << "point " << i;
      ASSERT_LT(static_cast<std::size_t>(id), band.size());
      ++counts[static_cast<std::size_t>(id)];
      const CellCoord& c = band.coord(id);
      occupied.insert(key(c));
      // Position inside the cell, in cell units: within [0, 1) up to rounding.
      const Eigen::Vector3d local =
        (Eigen::Vector3d(p.x, p.y, p.z) - grid.origin) / grid.cell_size -
        c.cast<double>();
      EXPECT_TRUE((local.array() >= -1e-6).all() && (local.array() < 1.0 + 1e-6).all())
        << "point " << i << " at " << local.transpose() << " inside cell "
        << toString(c);
    }
    for (std::size_t i = 0; i < band.size(); ++i)
      EXPECT_EQ(band.pointCount(static_cast<CellId>(i)), counts[i]);
    if (!repair) {
      EXPECT_EQ(toSet(band.coords()), occupied);
    } else {
      EXPECT_EQ(band.size(), occupied.size() + band.repairCellCount());
    }
  }
}

TEST(BandFromCloud, ShuffledPointsGiveTheSameBand)
{
  pcl::PointCloud<pcl::PointXYZ> cloud = cloudWithNaNs(43);
  std::vector<std::size_t> perm(cloud.size());
  std::iota(perm.begin(), perm.end(), 0);
  std::mt19937_64 rng(17);
  visfeat::synthetic::shuffle(perm, rng);
  pcl::PointCloud<pcl::PointXYZ> shuffled;
  for (std::size_t i : perm)
    shuffled.push_back(cloud.points[i]);
  shuffled.is_dense = false;

  const GridSpec g1 = visfeat::gridForCloud(cloud, 20),
                 g2 = visfeat::gridForCloud(shuffled, 20);
  EXPECT_EQ(g1.origin, g2.origin);
  EXPECT_EQ(g1.cell_size, g2.cell_size);
  EXPECT_EQ(g1.dims, g2.dims);
  for (bool repair : {false, true}) {
    const VoxelBand a = visfeat::buildVoxelBand(cloud, g1, withRepair(repair));
    const VoxelBand b = visfeat::buildVoxelBand(shuffled, g2, withRepair(repair));
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
      ASSERT_EQ(a.coord(static_cast<CellId>(i)), b.coord(static_cast<CellId>(i)));
      ASSERT_EQ(a.pointCount(static_cast<CellId>(i)),
                b.pointCount(static_cast<CellId>(i)));
    }
    for (std::size_t j = 0; j < perm.size(); ++j)
      ASSERT_EQ(b.pointCell()[j], a.pointCell()[perm[j]]);
  }
}

// Large clouds are split into slabs of bricks, one pcl::octree each, built on several
// threads: the band (cells, ids, counts, adjacency, repair, point cells) is the same
// for any thread count. 360,000 points make 3 slabs of more than 100,000.
TEST(BandFromCloud, SlabOctreesOnThreadsGiveTheSameBand)
{
  const visfeat::synthetic::CadModel model =
    visfeat::synthetic::rotated(visfeat::synthetic::cadModelByName("box_with_hole"),
                                visfeat::synthetic::randomRotation(5));
  visfeat::synthetic::SamplingOptions sampling;
  sampling.count = 360000;
  sampling.seed = 5;
  const std::vector<Eigen::Vector3f> samples =
    visfeat::synthetic::sampleCadModel(model, sampling).points;
  pcl::PointCloud<pcl::PointXYZ> cloud;
  for (const Eigen::Vector3f& p : samples)
    cloud.push_back(pcl::PointXYZ(p.x(), p.y(), p.z()));
  cloud[7].x = std::numeric_limits<float>::quiet_NaN(); // skipped on every thread count
  cloud.is_dense = false;
  const GridSpec grid = visfeat::gridForCloud(cloud, 200);
  VoxelBand::Options one;
  one.threads = 1;
  const VoxelBand a = visfeat::buildVoxelBand(cloud, grid, one);
  EXPECT_GT(a.repairCellCount(), 0u);
  for (int threads : {2, 3, 5}) {
    VoxelBand::Options many;
    many.threads = threads;
    const VoxelBand b = visfeat::buildVoxelBand(cloud, grid, many);
    ASSERT_EQ(a.size(), b.size()) << threads << " threads";
    EXPECT_EQ(a.repairCellCount(), b.repairCellCount());
    for (std::size_t i = 0; i < a.size(); ++i) {
      const auto id = static_cast<CellId>(i);
      ASSERT_EQ(a.coord(id), b.coord(id)) << threads << " threads, cell " << i;
      ASSERT_EQ(a.pointCount(id), b.pointCount(id));
      ASSERT_EQ(a.neighbours(id), b.neighbours(id));
    }
    EXPECT_EQ(a.pointCell(), b.pointCell());
  }
  EXPECT_EQ(a.pointCell()[7], visfeat::kNoCell);
}

TEST(BandFromCloud, RepairMakesSparseCloudBandsFaceConnected)
{
  // A sparsely sampled rotated cube: its band is 26- but not 6-connected in places.
  const pcl::PointCloud<pcl::PointXYZ> cloud =
    visfeat_test::syntheticShapeCloud("cube", 44, 24, 1.2);
  const VoxelBand off = visfeat_test::bandFromCloud(cloud, 24, false);
  std::vector<CellCoord> cells = off.coords();
  checkRepair(off.grid(), cells, "sparse cube cloud");
  const VoxelBand on = visfeat_test::bandFromCloud(cloud, 24, true);
  CoordSet with = toSet(on.coords());
  for (const CellCoord& c : cells)
    EXPECT_TRUE(with.count(key(c)));
  EXPECT_EQ(on.repairCellCount(), on.size() - cells.size());
}

TEST(BandFromCloud, BadInputThrows)
{
  pcl::PointCloud<pcl::PointXYZ> empty;
  EXPECT_THROW(visfeat::gridForCloud(empty, 32), visfeat::Error);
  pcl::PointCloud<pcl::PointXYZ> nans;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  nans.push_back(pcl::PointXYZ(nan, nan, nan));
  nans.push_back(pcl::PointXYZ(1.f, nan, 0.f));
  EXPECT_THROW(visfeat::gridForCloud(nans, 32), visfeat::Error);
  pcl::PointCloud<pcl::PointXYZ> same;
  same.push_back(pcl::PointXYZ(1.f, 2.f, 3.f));
  same.push_back(pcl::PointXYZ(1.f, 2.f, 3.f));
  EXPECT_THROW(visfeat::gridForCloud(same, 32), visfeat::Error);
  const pcl::PointCloud<pcl::PointXYZ> ok =
    visfeat_test::syntheticShapeCloud("cube", 45, 8);
  EXPECT_THROW(visfeat::gridForCloud(ok, 0), visfeat::Error);
  EXPECT_THROW(visfeat::gridForCloud(ok, GridSpec::kMinResolution - 1), visfeat::Error);
  EXPECT_THROW(visfeat::gridForCloud(ok, GridSpec::kMaxResolution + 1), visfeat::Error);
  EXPECT_NO_THROW(visfeat::gridForCloud(ok, GridSpec::kMinResolution));
}

} // namespace
