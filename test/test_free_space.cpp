// FreeSpace (subcell mask, blocked length, sees) and SegmentTable against the
// brute-force reference, on hand-made cases and on every pair of cells within reach in
// the small bands.

#include "band_fixtures.h"
#include "reference/brute_force.h"

#include <visfeat/core/band/voxel_band.h>
#include <visfeat/core/common/error.h>
#include <visfeat/core/visibility/band_tiles.h>
#include <visfeat/core/visibility/free_space.h>
#include <visfeat/core/visibility/free_space_window.h>
#include <visfeat/core/visibility/segment_table.h>

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

namespace {

namespace ref = visfeat_test::reference;
using visfeat::CellCoord;
using visfeat::FreeSpace;
using visfeat::SegmentTable;
using visfeat::VoxelBand;
using visfeat_test::cubeGrid;
using visfeat_test::NamedBand;
using visfeat_test::toString;
using Vec3i = Eigen::Vector3i;

constexpr double kLengthTolerance = 1e-5; // cell edges
const double kOpacities[] = {0.0, 1.5, 3.0};

VoxelBand
bandOf(const std::vector<CellCoord>& cells, int grid_size = 20)
{
  VoxelBand::Options options;
  options.repair = false;
  return VoxelBand::fromCells(cubeGrid(grid_size), cells, options);
}

// ---------------------------------------------------------------- hand-made cases

// One mixed cell: exactly the 4x4x4 block 2c-1 .. 2c+2 of subcells is free.
TEST(FreeSpace, SingleCellFreesItsDilatedSubcells)
{
  const CellCoord c(5, 6, 7);
  const VoxelBand band = bandOf({c});
  const FreeSpace fs(band);
  EXPECT_EQ(fs.dims(), Vec3i::Constant(40));
  int free_count = 0;
  for (int z = 0; z < 40; ++z)
    for (int y = 0; y < 40; ++y)
      for (int x = 0; x < 40; ++x) {
        const Vec3i s(x, y, z);
        const bool expected = (s.array() >= (2 * c).array() - 1).all() &&
                              (s.array() <= (2 * c).array() + 2).all();
        ASSERT_EQ(fs.isFree(s), expected) << "subcell " << toString(s);
        free_count += expected;
      }
  EXPECT_EQ(free_count, 64);
  EXPECT_FALSE(fs.isFree(Vec3i(-1, 0, 0)));
  EXPECT_FALSE(fs.isFree(Vec3i(0, 40, 0)));
}

// Cells (5,5,5) and (10,5,5) alone: the segment from subcell x = 11 to x = 21 runs on
// an edge; the subcells around it are free for x in [9, 13) and [19, 23), so the
// stretch x in [13, 19) -- 6 subcell edges = 3 cell edges -- is blocked.
TEST(FreeSpace, AxisSegmentBlockedLengthIsExact)
{
  const CellCoord a(5, 5, 5), b(10, 5, 5);
  const VoxelBand band = bandOf({a, b});
  const FreeSpace fs(band);
  const ref::FreeSubcells rfs(band.grid(), band.coords());
  EXPECT_NEAR(fs.blockedLength(a, b), 3.0, kLengthTolerance);
  EXPECT_NEAR(ref::blockedLength(rfs, a, b).length(), 3.0, 1e-12);
  EXPECT_FALSE(fs.sees(a, b));
  EXPECT_FALSE(fs.sees(a, b, 3.0)); // blocked length 3 is not below 3
  EXPECT_TRUE(fs.sees(a, b, 3.25));
  EXPECT_FALSE(ref::visible(ref::blockedLength(rfs, a, b), 3.0));
  EXPECT_TRUE(ref::visible(ref::blockedLength(rfs, a, b), 3.25));
}

// Same two cells, plus a row of cells at y = 6 over x = 6..9: their free subcells reach
// down to y = 11, one of the four subcells around the edge line y = z = 11, so the
// segment along that edge is no longer blocked anywhere (open-occluder rule).
TEST(FreeSpace, EdgeStretchIsBlockedOnlyIfAllFourSubcellsAreOccluded)
{
  const CellCoord a(5, 5, 5), b(10, 5, 5);
  const VoxelBand band = bandOf({a, b, CellCoord(6, 6, 5), CellCoord(7, 6, 5),
                                 CellCoord(8, 6, 5), CellCoord(9, 6, 5)});
  const FreeSpace fs(band);
  EXPECT_NEAR(fs.blockedLength(a, b), 0.0, kLengthTolerance);
  EXPECT_TRUE(fs.sees(a, b));
  // Moving the row one cell up (y = 7) frees subcells y >= 13 only: blocked again.
  const VoxelBand band2 = bandOf({a, b, CellCoord(6, 7, 5), CellCoord(7, 7, 5),
                                  CellCoord(8, 7, 5), CellCoord(9, 7, 5)});
  const FreeSpace fs2(band2);
  EXPECT_NEAR(fs2.blockedLength(a, b), 3.0, kLengthTolerance);
  EXPECT_FALSE(fs2.sees(a, b));
}

// (5,5,5) -> (8,8,5): the diagonal of the face z = 11 from (11,11) to (17,17); free
// around the ends for x, y in [9, 13) and [15, 19): blocked from 13 to 15, length
// 2 sqrt(2) subcell edges = sqrt(2) cell edges.
TEST(FreeSpace, FaceDiagonalBlockedLengthIsExact)
{
  const CellCoord a(5, 5, 5), b(8, 8, 5);
  const VoxelBand band = bandOf({a, b});
  const FreeSpace fs(band);
  const ref::FreeSubcells rfs(band.grid(), band.coords());
  EXPECT_NEAR(fs.blockedLength(a, b), std::sqrt(2.0), kLengthTolerance);
  EXPECT_NEAR(ref::blockedLength(rfs, a, b).length(), std::sqrt(2.0), 1e-12);
  EXPECT_FALSE(fs.sees(a, b, 1.4));
  EXPECT_TRUE(fs.sees(a, b, 1.5));
}

TEST(FreeSpace, NeighboursAndSelfAlwaysSeeEachOther)
{
  const VoxelBand band =
    bandOf({CellCoord(5, 5, 5), CellCoord(6, 6, 6), CellCoord(5, 6, 5)});
  const FreeSpace fs(band);
  for (const CellCoord& a : band.coords())
    for (const CellCoord& b : band.coords()) {
      EXPECT_EQ(fs.blockedLength(a, b), 0.0) << toString(a) << " " << toString(b);
      EXPECT_TRUE(fs.sees(a, b));
    }
}

// A window is a dense copy of the sparse mask: the same bit for every subcell it
// covers, bricks outside the grid occluded, and its cell index at its strides.
TEST(FreeSpaceWindow, CopiesTheMaskAroundABrick)
{
  const VoxelBand band =
    bandOf({CellCoord(3, 4, 5), CellCoord(9, 2, 7), CellCoord(15, 8, 1)}, 20);
  const FreeSpace fs(band);
  ASSERT_EQ(fs.dims(), Vec3i::Constant(40));
  ASSERT_EQ(fs.brickDims(), Vec3i::Constant(3));
  EXPECT_GT(fs.brickCount(), 1u);
  for (int bricks : {1, 3, 5}) {
    visfeat::FreeSpaceWindow window(bricks);
    EXPECT_EQ(window.side(), 8 * bricks);
    for (const Vec3i& centre : {Vec3i(0, 0, 0), Vec3i(1, 0, 0), Vec3i(1, 1, 1)}) {
      window.load(fs, centre);
      EXPECT_EQ(window.origin(), 8 * (centre - Vec3i::Constant(bricks / 2)));
      std::size_t covered = 0;
      for (int z = -48; z < 80; ++z)
        for (int y = -48; y < 80; ++y)
          for (int x = -48; x < 80; ++x) {
            const Vec3i s(x, y, z);
            const CellCoord c(x >> 1, y >> 1, z >> 1);
            ASSERT_EQ(window.isFree(s), window.contains(c) && fs.isFree(s))
              << toString(s) << " window " << bricks << " around " << toString(centre);
            if (!window.contains(c) || (x & 1) || (y & 1) || (z & 1))
              continue;
            ++covered;
            const Vec3i l = c - window.origin();
            ASSERT_EQ(window.cellIndex(c),
                      l.x() + window.strideY() * l.y() + window.strideZ() * l.z());
            int bits = 0;
            for (int i = 0; i < 8; ++i)
              bits |= fs.isFree(s + Vec3i(i & 1, (i >> 1) & 1, i >> 2)) << i;
            ASSERT_EQ(window.freeBits(window.cellIndex(c)), bits) << toString(c);
          }
      EXPECT_EQ(covered,
                static_cast<std::size_t>(8 * bricks) * 8 * bricks * 8 * bricks);
    }
  }
  EXPECT_THROW(visfeat::FreeSpaceWindow(2), visfeat::Error);
}

// Memory follows the band: a band in one corner of a large grid allocates a handful of
// bricks, and estimateBytes counts them exactly before building.
TEST(FreeSpace, MemoryFollowsTheBandNotTheGrid)
{
  const VoxelBand band = bandOf({CellCoord(3, 4, 5), CellCoord(4, 4, 5)}, 2000);
  const FreeSpace fs(band);
  EXPECT_EQ(fs.memoryBytes(), FreeSpace::estimateBytes(band));
  EXPECT_LE(fs.brickCount(), 8u);
  EXPECT_LT(fs.memoryBytes(), 8u * 1024u);
  EXPECT_TRUE(fs.isFree(FreeSpace::centre(CellCoord(3, 4, 5))));
  // The same count is offered before allocating, once; a refusal leaves nothing built.
  std::vector<std::uint64_t> offered;
  const FreeSpace checked(band, [&](std::uint64_t bytes) { offered.push_back(bytes); });
  EXPECT_EQ(offered, std::vector<std::uint64_t>{fs.memoryBytes()});
  EXPECT_EQ(checked.memoryBytes(), fs.memoryBytes());
  EXPECT_THROW(FreeSpace(band, [](std::uint64_t) { throw visfeat::Error("refused"); }),
               visfeat::Error);
  EXPECT_FALSE(fs.isFree(Vec3i(3000, 3000, 3000)));
}

// Offsets with |d|_inf <= 1 stay inside the always-free 4x4x4 blocks around the ends:
// nothing to check. A long axis offset has stretches outside both blocks.
TEST(SegmentTable, NoChecksForNeighbourOffsets)
{
  const VoxelBand band = bandOf({CellCoord(5, 5, 5)});
  const FreeSpace fs(band);
  const SegmentTable table(6);
  EXPECT_EQ(table.maxDistance(), 6);
  for (int z = -1; z <= 1; ++z)
    for (int y = -1; y <= 1; ++y)
      for (int x = -1; x <= 1; ++x)
        EXPECT_EQ(table.checksFor(Vec3i(x, y, z)), 0u) << toString(Vec3i(x, y, z));
  EXPECT_GT(table.checksFor(Vec3i(6, 0, 0)), 0u);
  EXPECT_GT(table.checksFor(Vec3i(-2, 3, 1)), 0u);
}

// ---------------------------------------------------------------- bands

class ReferenceBandTest : public ::testing::TestWithParam<std::size_t>
{
protected:
  void SetUp() override { named_ = visfeat_test::referenceBand(GetParam()); }
  const NamedBand& named() const { return named_; }

private:
  NamedBand named_;
};

// (a) isFree on every subcell of the grid (and a layer outside it) vs the reference
// set.
TEST_P(ReferenceBandTest, FreeSubcellsMatchReference)
{
  const VoxelBand& band = named().band;
  ASSERT_FALSE(band.empty());
  const FreeSpace fs(band);
  const ref::FreeSubcells rfs(band.grid(), band.coords());
  ASSERT_EQ(fs.dims(), 2 * band.grid().dims);
  const Vec3i dims = fs.dims();
  std::size_t mismatches = 0, free_count = 0;
  std::string first;
  for (int z = -1; z <= dims.z(); ++z)
    for (int y = -1; y <= dims.y(); ++y)
      for (int x = -1; x <= dims.x(); ++x) {
        const Vec3i s(x, y, z);
        const bool expected = rfs.isFree(s);
        free_count += expected;
        if (fs.isFree(s) != expected) {
          if (mismatches++ == 0)
            first =
              toString(s) + (expected ? " should be free" : " should be occluded");
        }
      }
  EXPECT_EQ(mismatches, 0u) << named().name << ": first mismatch " << first;
  EXPECT_EQ(free_count, rfs.freeCount());
  EXPECT_GT(free_count, 64u);
}

// (c), (d) Every pair within L1 distance kMaxDistance: blocked length (tolerance),
// visibility (exact) for opacity 0, 1.5, 3 through FreeSpace and SegmentTable,
// symmetry.
TEST_P(ReferenceBandTest, SegmentTestMatchesReferenceOnAllPairs)
{
  constexpr int kMaxDistance = 6;
  const VoxelBand& band = named().band;
  const FreeSpace fs(band);
  const SegmentTable table(kMaxDistance);
  visfeat::FreeSpaceWindow window(table.windowBricks());
  const ref::FreeSubcells rfs(band.grid(), band.coords());

  std::size_t pairs = 0, blocked_pairs = 0, mismatches = 0;
  std::ostringstream report;
  auto fail = [&](const std::string& what) {
    if (mismatches++ < 8)
      report << "\n  " << what;
  };
  for (const CellCoord& a : band.coords()) {
    window.load(fs, visfeat::BandTiles::brickOf(a));
    const std::int32_t base = window.cellIndex(a);
    for (int dz = -kMaxDistance; dz <= kMaxDistance; ++dz)
      for (int dy = -kMaxDistance; dy <= kMaxDistance; ++dy)
        for (int dx = -kMaxDistance; dx <= kMaxDistance; ++dx) {
          const Vec3i d(dx, dy, dz);
          const int dist = d.cwiseAbs().sum();
          if (dist == 0 || dist > kMaxDistance)
            continue;
          const CellCoord b = a + d;
          if (band.find(b) == visfeat::kNoCell)
            continue;
          ++pairs;
          const std::string pair = toString(a) + " -> " + toString(b);
          const ref::Blocked expected = ref::blockedLength(rfs, a, b);
          const double expected_length = expected.length();
          blocked_pairs += expected.blocked_intervals > 0;
          const double got = fs.blockedLength(a, b);
          if (std::abs(got - expected_length) > kLengthTolerance) {
            std::ostringstream os;
            os << pair << ": blockedLength " << got << ", reference "
               << expected_length;
            fail(os.str());
          }
          const double got_back = fs.blockedLength(b, a);
          if (std::abs(got_back - got) > kLengthTolerance) {
            std::ostringstream os;
            os << pair << ": blockedLength not symmetric: " << got << " vs "
               << got_back;
            fail(os.str());
          }
          if (!ref::visible(ref::blockedLength(rfs, b, a), 0.0) !=
              (expected.blocked_intervals > 0))
            fail(pair + ": REFERENCE not symmetric");
          for (double opacity : kOpacities) {
            const bool vis = ref::visible(expected, opacity);
            const std::string tag = pair + " opacity " + std::to_string(opacity) +
                                    " (reference blocked " +
                                    std::to_string(expected_length) + ", visible " +
                                    (vis ? "yes" : "no") + "): ";
            if (fs.sees(a, b, opacity) != vis)
              fail(tag + "FreeSpace::sees(a, b) differs");
            if (fs.sees(b, a, opacity) != vis)
              fail(tag + "FreeSpace::sees(b, a) differs");
            if (table.sees(fs, a, b, opacity) != vis)
              fail(tag + "SegmentTable::sees(a, b) differs");
            if (table.sees(fs, b, a, opacity) != vis)
              fail(tag + "SegmentTable::sees(b, a) differs");
            if (table.sees(window, base, d, opacity) != vis)
              fail(tag + "SegmentTable::sees(base, d) differs");
          }
        }
  }
  EXPECT_EQ(mismatches, 0u) << named().name << " (" << pairs
                            << " pairs), first:" << report.str();
  EXPECT_GT(pairs, band.size());
  // The bands are meant to exercise occlusion, not only free lines of sight (except
  // the flat digital planes, where nothing is hidden).
  if (named().name.rfind("digital_plane", 0) != 0) {
    EXPECT_GT(blocked_pairs, 0u) << named().name;
  }
}

std::string
bandName(const ::testing::TestParamInfo<std::size_t>& info)
{
  return visfeat_test::referenceBandNames().at(info.param);
}

INSTANTIATE_TEST_SUITE_P(
  SmallBands,
  ReferenceBandTest,
  ::testing::Range<std::size_t>(0, visfeat_test::referenceBandNames().size()),
  bandName);

// ---------------------------------------------------------------- thin plate

// The two large faces of a thin closed plate must not see each other (see
// visfeat_test::thinPlate for why the geometry guarantees a blocked length >= 1.25),
// although they are only ~5 cells apart.
TEST(FreeSpace, ThinPlateSidesDoNotSeeEachOther)
{
  for (std::uint64_t seed : {21u, 22u, 23u}) {
    const visfeat_test::ThinPlate plate = visfeat_test::thinPlate(seed, 6.0);
    SCOPED_TRACE(plate.band.name);
    VoxelBand::Options options;
    options.repair = false;
    const VoxelBand band =
      VoxelBand::fromCells(plate.band.grid, plate.band.cells, options);
    const FreeSpace fs(band);
    const int max_distance = 10;
    const SegmentTable table(max_distance);
    const ref::FreeSubcells rfs(band.grid(), band.coords());
    ASSERT_GT(plate.top_inner.size(), 20u);
    ASSERT_GT(plate.bottom_inner.size(), 20u);

    std::size_t near_pairs = 0, visible_pairs = 0;
    double closest = 1e9;
    std::string first;
    for (const CellCoord& a : plate.top_inner)
      for (const CellCoord& b : plate.bottom_inner) {
        const ref::Blocked r = ref::blockedLength(rfs, a, b);
        bool seen = !(r.length() >= 1.25 - 1e-9) || ref::visible(r, 1.0) ||
                    fs.sees(a, b, 0.0) || fs.sees(a, b, 1.0) || fs.sees(b, a, 1.0) ||
                    fs.blockedLength(a, b) < 1.25 - kLengthTolerance;
        if ((b - a).cwiseAbs().sum() <= max_distance) {
          ++near_pairs;
          seen = seen || table.sees(fs, a, b, 0.0) || table.sees(fs, a, b, 1.0) ||
                 table.sees(fs, b, a, 1.0);
        }
        closest = std::min(closest, (b - a).cast<double>().norm());
        if (seen && visible_pairs++ == 0)
          first = toString(a) + " -> " + toString(b) + ": reference blocked " +
                  std::to_string(r.length()) + ", FreeSpace blocked " +
                  std::to_string(fs.blockedLength(a, b));
      }
    EXPECT_EQ(visible_pairs, 0u) << "first: " << first;
    EXPECT_GT(near_pairs, 20u);
    EXPECT_LT(closest, plate.gap + 1.0); // the sides really are close
  }
}

} // namespace
