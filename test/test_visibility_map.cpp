// VisibilityMap: parameter checks, radii against the brute-force reference on every
// cell of the small bands, determinism (threads, point order), and the geometry of a
// flat square and of a 90-degree crease.

#include "band_fixtures.h"
#include "reference/brute_force.h"
#include "shuffled_cloud.h"
#include <support/portable_random.h>

#include <visfeat/core/band/voxel_band.h>
#include <visfeat/core/common/error.h>
#include <visfeat/core/visibility/free_space.h>
#include <visfeat/core/visibility/visibility_map.h>
#include <visfeat/voxel_band_from_cloud.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <numeric>
#include <sstream>

namespace {

namespace ref = visfeat_test::reference;
using visfeat::CellCoord;
using visfeat::CellId;
using visfeat::FreeSpace;
using visfeat::VisibilityMap;
using visfeat::VoxelBand;
using visfeat_test::cubeGrid;
using visfeat_test::NamedBand;
using visfeat_test::toString;

std::string
lower(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

VisibilityMap::Parameters
params(int max_radius, double opacity, int threads)
{
  VisibilityMap::Parameters p;
  p.max_radius = max_radius;
  p.opacity = opacity;
  p.threads = threads;
  return p;
}

std::vector<int>
radiiOf(const VisibilityMap& map)
{
  return std::vector<int>(map.radii().begin(), map.radii().end());
}

// ---------------------------------------------------------------- parameters

void
expectRejected(const VisibilityMap::Parameters& p, const std::string& word)
{
  try {
    VisibilityMap::validate(p);
    ADD_FAILURE() << "accepted parameters that should mention '" << word << "'";
  } catch (const visfeat::Error& e) {
    EXPECT_NE(lower(e.what()).find(word), std::string::npos) << e.what();
  }
}

TEST(VisibilityMapParameters, OutOfRangeIsRejectedByName)
{
  EXPECT_NO_THROW(VisibilityMap::validate(VisibilityMap::Parameters{}));
  EXPECT_NO_THROW(VisibilityMap::validate(params(1, 0.0, 0)));
  EXPECT_NO_THROW(VisibilityMap::validate(params(VisibilityMap::kMaxRadius,
                                                 VisibilityMap::kMaxOpacity,
                                                 VisibilityMap::kMaxThreads)));
  expectRejected(params(0, 0.0, 0), "radius");
  expectRejected(params(-3, 0.0, 0), "radius");
  expectRejected(params(VisibilityMap::kMaxRadius + 1, 0.0, 0), "radius");
  expectRejected(params(5, -0.5, 0), "opacity");
  expectRejected(params(5, VisibilityMap::kMaxOpacity + 1.0, 0), "opacity");
  expectRejected(params(5, std::nan(""), 0), "opacity");
  expectRejected(params(5, 0.0, -1), "thread");
  expectRejected(params(5, 0.0, VisibilityMap::kMaxThreads + 1), "thread");
}

TEST(VisibilityMapParameters, ComputeRejectsBadParameters)
{
  const VoxelBand band = VoxelBand::fromCells(cubeGrid(8), {CellCoord(3, 3, 3)}, {});
  const FreeSpace fs(band);
  EXPECT_THROW(VisibilityMap::compute(band, fs, params(0, 0.0, 1)), visfeat::Error);
  EXPECT_THROW(VisibilityMap::compute(band, fs, params(4, -1.0, 1)), visfeat::Error);
}

// ---------------------------------------------------------------- small cases

// Empty rings count as visible: an isolated cell and a short bar reach the cap.
TEST(VisibilityMap, RunningOutOfCellsReachesTheCap)
{
  VoxelBand::Options no_repair;
  no_repair.repair = false;
  const VoxelBand single =
    VoxelBand::fromCells(cubeGrid(8), {CellCoord(3, 3, 3)}, no_repair);
  const VisibilityMap m1 =
    VisibilityMap::compute(single, FreeSpace(single), params(7, 0.0, 1));
  ASSERT_EQ(m1.radii().size(), 1u);
  EXPECT_EQ(m1.radius(0), 7);
  EXPECT_EQ(m1.parameters().max_radius, 7);

  std::vector<CellCoord> bar;
  for (int x = 3; x < 9; ++x)
    bar.emplace_back(x, 5, 5);
  const VoxelBand b = VoxelBand::fromCells(cubeGrid(12), bar, no_repair);
  const FreeSpace fs(b);
  const VisibilityMap m2 = VisibilityMap::compute(b, fs, params(11, 0.0, 2));
  for (std::size_t i = 0; i < b.size(); ++i)
    EXPECT_EQ(m2.radius(static_cast<CellId>(i)), 11);
}

// Two parallel bars joined at one end (a U of width 5): a cell of one arm sees the
// other arm only near the bend. The radius of the far end of an arm is decided by the
// first ring reaching the opposite arm; check against the reference and that it is
// below the cap.
TEST(VisibilityMap, HairpinStopsAtTheOppositeArm)
{
  std::vector<CellCoord> cells;
  for (int x = 3; x <= 14; ++x) {
    cells.emplace_back(x, 3, 5);
    cells.emplace_back(x, 9, 5);
  }
  for (int y = 4; y <= 8; ++y)
    cells.emplace_back(14, y, 5);
  VoxelBand::Options no_repair;
  no_repair.repair = false;
  const VoxelBand band = VoxelBand::fromCells(cubeGrid(18), cells, no_repair);
  const FreeSpace fs(band);
  const VisibilityMap map = VisibilityMap::compute(band, fs, params(30, 0.0, 1));
  const ref::FreeSubcells rfs(band.grid(), band.coords());
  const std::vector<int> expected = ref::radii(band.coords(), rfs, 30, 0.0);
  EXPECT_EQ(radiiOf(map), expected);
  // (3,3,5) and (3,9,5) are 6 apart and separated by occluded space: (3,3,5) cannot see
  // (3,9,5), which its BFS reaches at ring 11 + 6 + 11 = 28 at the latest.
  const ref::Blocked b =
    ref::blockedLength(rfs, CellCoord(3, 3, 5), CellCoord(3, 9, 5));
  EXPECT_GT(b.blocked_intervals, 0);
  EXPECT_FALSE(fs.sees(CellCoord(3, 3, 5), CellCoord(3, 9, 5)));
  EXPECT_LT(map.radius(band.find(CellCoord(3, 3, 5))), 28);
}

// ---------------------------------------------------------------- reference bands

class RadiusReferenceTest : public ::testing::TestWithParam<std::size_t>
{};

TEST_P(RadiusReferenceTest, RadiiMatchReferenceOnEveryCell)
{
  const NamedBand named = visfeat_test::referenceBand(GetParam());
  const VoxelBand& band = named.band;
  const FreeSpace fs(band);
  const ref::FreeSubcells rfs(band.grid(), band.coords());
  constexpr int kMaxRadius = 8;
  for (double opacity : {0.0, 1.5, 3.0}) {
    const std::vector<int> expected =
      ref::radii(band.coords(), rfs, kMaxRadius, opacity);
    const VisibilityMap map =
      VisibilityMap::compute(band, fs, params(kMaxRadius, opacity, 2));
    ASSERT_EQ(map.radii().size(), band.size());
    std::size_t mismatches = 0, below_cap = 0;
    std::ostringstream first;
    for (std::size_t i = 0; i < band.size(); ++i) {
      below_cap += expected[i] < kMaxRadius;
      const int got = map.radius(static_cast<CellId>(i));
      if (got != expected[i] && mismatches++ < 8)
        first << "\n  cell " << toString(band.coord(static_cast<CellId>(i)))
              << ": radius " << got << ", reference " << expected[i];
    }
    EXPECT_EQ(mismatches, 0u) << named.name << " opacity " << opacity << " ("
                              << band.size() << " cells):" << first.str();
    if (opacity == 0.0 && named.name.rfind("digital_plane", 0) != 0) {
      EXPECT_GT(below_cap, 0u) << named.name << ": fixture should limit some radii";
    }
  }
}

// The map works a brick (8^3 cells) at a time, 64 sources at once, inside a window of
// 1 + 2 ceil(cap / 8) bricks a side: a folded slab fills its bricks (up to 256 sources
// a brick, four batches) and caps 1 to 64 change the window from 3 to 17 bricks a side.
// Every radius against the brute-force reference, with and without an opacity.
TEST(VisibilityMap, BatchesAndWindowsOfEveryCapMatchReference)
{
  std::vector<CellCoord> cells;
  for (int z = 3; z < 7; ++z) // a slab 4 cells thick, 14 x 14 ...
    for (int y = 3; y < 17; ++y)
      for (int x = 3; x < 17; ++x)
        cells.emplace_back(x, y, z);
  for (int z = 7; z < 13; ++z) // ... with a wall on one side, 2 cells thick ...
    for (int y = 3; y < 17; ++y)
      for (int x = 3; x < 5; ++x)
        cells.emplace_back(x, y, z);
  for (int z = 7; z < 11; ++z) // ... and a post that hides part of the slab
    for (int y = 9; y < 11; ++y)
      for (int x = 10; x < 12; ++x)
        cells.emplace_back(x, y, z);
  VoxelBand::Options no_repair;
  no_repair.repair = false;
  const VoxelBand band = VoxelBand::fromCells(cubeGrid(20), cells, no_repair);
  const FreeSpace fs(band);
  const ref::FreeSubcells rfs(band.grid(), band.coords());
  for (const int cap : {1, 9, 17, VisibilityMap::kMaxRadius})
    for (const double opacity : {0.0, 2.0}) {
      if (cap == VisibilityMap::kMaxRadius && opacity > 0.0)
        continue; // the reference's time grows with the cap
      const std::vector<int> expected = ref::radii(band.coords(), rfs, cap, opacity);
      const VisibilityMap map =
        VisibilityMap::compute(band, fs, params(cap, opacity, 2));
      std::size_t mismatches = 0, below_cap = 0;
      for (std::size_t i = 0; i < band.size(); ++i) {
        below_cap += expected[i] < cap;
        if (map.radius(static_cast<CellId>(i)) != expected[i] && mismatches++ < 3)
          ADD_FAILURE() << "cap " << cap << " opacity " << opacity << ": cell "
                        << toString(band.coord(static_cast<CellId>(i))) << " radius "
                        << int(map.radius(static_cast<CellId>(i))) << ", reference "
                        << expected[i];
      }
      EXPECT_EQ(mismatches, 0u) << "cap " << cap << " opacity " << opacity;
      if (cap > 3 && opacity == 0.0) {
        EXPECT_GT(below_cap, 0u) << "cap " << cap << ": the wall and post hide nothing";
      }
    }
}

std::string
bandName(const ::testing::TestParamInfo<std::size_t>& info)
{
  return visfeat_test::referenceBandNames().at(info.param);
}

INSTANTIATE_TEST_SUITE_P(
  SmallBands,
  RadiusReferenceTest,
  ::testing::Range<std::size_t>(0, visfeat_test::referenceBandNames().size()),
  bandName);

// ---------------------------------------------------------------- determinism

TEST(VisibilityMap, SameRadiiForOneAndTwoThreads)
{
  const pcl::PointCloud<pcl::PointXYZ> cloud =
    visfeat_test::syntheticShapeCloud("icosahedron", 51, 32);
  const VoxelBand band = visfeat_test::bandFromCloud(cloud, 32);
  const FreeSpace fs(band);
  for (double opacity : {0.0, 3.0}) {
    const VisibilityMap one = VisibilityMap::compute(band, fs, params(11, opacity, 1));
    const VisibilityMap two = VisibilityMap::compute(band, fs, params(11, opacity, 2));
    const VisibilityMap all = VisibilityMap::compute(band, fs, params(11, opacity, 0));
    EXPECT_EQ(radiiOf(one), radiiOf(two));
    EXPECT_EQ(radiiOf(one), radiiOf(all));
    const std::vector<int> r = radiiOf(one);
    EXPECT_LT(*std::min_element(r.begin(), r.end()),
              11); // not trivially all at the cap
    EXPECT_EQ(*std::max_element(r.begin(), r.end()), 11);
  }
}

TEST(VisibilityMap, SameRadiiForShuffledPoints)
{
  const pcl::PointCloud<pcl::PointXYZ> cloud =
    visfeat_test::syntheticShapeCloud("cube", 52, 24);
  const auto [shuffled, perm] = visfeat_test::shuffledCloud(cloud, 3);
  const VoxelBand a = visfeat_test::bandFromCloud(cloud, 24);
  const VoxelBand b = visfeat_test::bandFromCloud(shuffled, 24);
  ASSERT_EQ(a.coords(), b.coords());
  const VisibilityMap ma = VisibilityMap::compute(a, FreeSpace(a), params(8, 0.0, 2));
  const VisibilityMap mb = VisibilityMap::compute(b, FreeSpace(b), params(8, 0.0, 1));
  EXPECT_EQ(radiiOf(ma), radiiOf(mb));
  // Per point: the same radius whatever the order.
  for (std::size_t j = 0; j < perm.size(); ++j)
    ASSERT_EQ(mb.radius(b.pointCell()[j]), ma.radius(a.pointCell()[perm[j]]));
}

// ---------------------------------------------------------------- geometry

struct CloudMap
{
  VoxelBand band;
  VisibilityMap map;
};

CloudMap
mapOfCloud(const pcl::PointCloud<pcl::PointXYZ>& cloud, int resolution, int max_radius)
{
  CloudMap out{visfeat_test::bandFromCloud(cloud, resolution), VisibilityMap()};
  const FreeSpace fs(out.band);
  out.map = VisibilityMap::compute(out.band, fs, params(max_radius, 0.0, 2));
  return out;
}

/** Points per unit area for a mean spacing of about 0.35 cells. */
std::size_t
pointsPerUnitArea(double cell_size)
{
  return static_cast<std::size_t>(std::ceil(1.0 / std::pow(0.35 * cell_size, 2)));
}

/** Reference radii of some cells of a big band (the full reference would be slow). */
void
expectReferenceRadii(const VoxelBand& band,
                     const VisibilityMap& map,
                     const std::vector<CellId>& ids,
                     int max_radius)
{
  const ref::FreeSubcells rfs(band.grid(), band.coords());
  const ref::CellSet cells(band.coords().begin(), band.coords().end());
  for (CellId id : ids)
    EXPECT_EQ(map.radius(id), ref::radius(cells, band.coord(id), rfs, max_radius, 0.0))
      << "cell " << toString(band.coord(id));
}

// A flat square is convex and flat: every cell sees every other one, up to the holes
// that random sampling leaves in the digital plane. At least 95% of the cells away from
// the border reach the cap.
TEST(VisibilityMapGeometry, RotatedFlatSquareReachesTheCap)
{
  constexpr int kRes = 64, kCap = 16;
  for (std::uint64_t seed : {101u, 102u, 103u}) {
    std::mt19937_64 rng(seed);
    const Eigen::Matrix3d r = visfeat_test::randomRotationMatrix(rng);
    const Eigen::Vector3d u = r.col(0), v = r.col(1);
    const double cell =
      (u.cwiseAbs() + v.cwiseAbs()).maxCoeff() / kRes; // bbox extent / res
    const pcl::PointCloud<pcl::PointXYZ> cloud =
      visfeat_test::squareCloud(u, v, pointsPerUnitArea(cell), rng);
    const CloudMap m = mapOfCloud(cloud, kRes, kCap);
    std::size_t interior = 0, at_cap = 0;
    std::vector<CellId> check;
    for (std::size_t i = 0; i < m.band.size(); ++i) {
      const CellId id = static_cast<CellId>(i);
      const Eigen::Vector3d c = m.band.grid().cellCenter(m.band.coord(id));
      const double border = 0.5 - std::max(std::abs(u.dot(c)), std::abs(v.dot(c)));
      // (cell below is the estimate used for the sampling density; the grid's own cell
      // size is m.band.grid().cell_size)
      if (m.map.radius(id) < kCap || i % 97 == 0)
        check.push_back(id);
      if (border < 3.0 * m.band.grid().cell_size)
        continue;
      ++interior;
      at_cap += m.map.radius(id) == kCap;
    }
    SCOPED_TRACE("seed " + std::to_string(seed));
    ASSERT_GT(interior, 1000u);
    EXPECT_GE(at_cap, 0.95 * interior) << at_cap << " of " << interior << " at the cap";
    // The cells below the cap (and a sample of the others) agree with the reference.
    if (check.size() > 80)
      check.resize(80);
    expectReferenceRadii(m.band, m.map, check, kCap);
  }
}

// Two unit squares meeting at a 90-degree crease (an L). With e the distance of a cell
// from the crease line, in cells, along the face it lies on:
//  - cells on the crease line see both faces along them: median radius at the cap;
//  - valley cells (2 <= e < 4) see the other face's near cells but not those a few
//  cells
//    up, whose segment crosses the empty inside of the L deeper than the free layer:
//    all below the cap, median at most half the cap;
//  - the radius rises again away from the crease: the BFS reaches the other face
//    (centres within ~1 cell of its plane) no sooner than ring e - 2, and a flat face
//    sees itself up to the rare holes of the sampling (see the flat square), so the
//    median radius of the cells at distance floor(e) = k is >= min(cap, k - 2);
//  - far face cells (e >= cap + 2) never reach the other face: at least 95% at the cap
//    (as on the flat square).
TEST(VisibilityMapGeometry, RotatedCreaseHasALowValleyBetweenHighRidgeAndFaces)
{
  constexpr int kRes = 64, kCap = 16;
  for (std::uint64_t seed : {201u, 202u, 203u}) {
    std::mt19937_64 rng(seed);
    const Eigen::Matrix3d frame = visfeat_test::randomRotationMatrix(rng);
    const Eigen::Vector3d u = frame.col(0), v = frame.col(1), w = frame.col(2);
    // Bounding box of the L: s u + t v or s u + t w, s in [-1/2, 1/2], t in [0, 1].
    const Eigen::Vector3d lo = -0.5 * u.cwiseAbs() + v.cwiseMin(w).cwiseMin(0.0);
    const Eigen::Vector3d hi = 0.5 * u.cwiseAbs() + v.cwiseMax(w).cwiseMax(0.0);
    const pcl::PointCloud<pcl::PointXYZ> cloud = visfeat_test::creaseCloud(
      frame, pointsPerUnitArea((hi - lo).maxCoeff() / kRes), rng);
    const CloudMap m = mapOfCloud(cloud, kRes, kCap);
    const double cell = m.band.grid().cell_size;
    SCOPED_TRACE("seed " + std::to_string(seed));

    std::vector<int> ridge, valley;
    std::vector<CellId> valley_ids;
    std::size_t far = 0, far_at_cap = 0;
    std::map<int, std::vector<int>> by_distance;
    for (std::size_t i = 0; i < m.band.size(); ++i) {
      const CellId id = static_cast<CellId>(i);
      const Eigen::Vector3d c = m.band.grid().cellCenter(m.band.coord(id));
      const double s = u.dot(c) / cell, a = v.dot(c) / cell, b = w.dot(c) / cell;
      if (std::abs(s) > 0.5 / cell - 3.0) // keep away from the ends of the crease
        continue;
      const double e = std::max(a, b);
      const int radius = m.map.radius(id);
      if (e < 0.75)
        ridge.push_back(radius);
      if (e >= 2.0 && e < 4.0) {
        valley.push_back(radius);
        valley_ids.push_back(id);
      }
      if (e >= kCap + 2.0) {
        ++far;
        far_at_cap += radius == kCap;
      }
      if (e >= 4.0 && e < kCap + 2.0)
        by_distance[static_cast<int>(std::floor(e))].push_back(radius);
    }
    ASSERT_GT(ridge.size(), 10u);
    ASSERT_GT(valley.size(), 40u);
    ASSERT_GT(far, 1000u);
    auto median = [](std::vector<int> x) {
      std::nth_element(x.begin(), x.begin() + static_cast<std::ptrdiff_t>(x.size() / 2),
                       x.end());
      return x[x.size() / 2];
    };
    EXPECT_EQ(median(ridge), kCap) << "crease-line cells should see both faces";
    EXPECT_LT(*std::max_element(valley.begin(), valley.end()), kCap);
    EXPECT_LE(median(valley), kCap / 2) << "valley should fall well below the cap";
    ASSERT_EQ(by_distance.size(), static_cast<std::size_t>(kCap - 2));
    for (const auto& kv : by_distance) {
      ASSERT_GT(kv.second.size(), 10u);
      EXPECT_GE(median(kv.second), std::min(kCap, kv.first - 2))
        << "cells at distance " << kv.first << " from the crease";
    }
    EXPECT_GE(far_at_cap, 0.95 * far) << far_at_cap << " of " << far;
    expectReferenceRadii(m.band, m.map, valley_ids, kCap);
  }
}

} // namespace
