// decomposeLatticeSegment against hand-derived cases and against the brute-force
// midpoint classification of the reference.

#include "band_fixtures.h"
#include "reference/brute_force.h"

#include <visfeat/core/visibility/lattice_segment.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace {

using visfeat::SegmentStretch;
using visfeat_test::toString;
using Vec3i = Eigen::Vector3i;

bool
lexLess(const Vec3i& a, const Vec3i& b)
{
  return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
}

std::vector<Vec3i>
sortedSubcells(const SegmentStretch& s)
{
  std::vector<Vec3i> out(s.subcells.begin(),
                         s.subcells.begin() + std::max(0, std::min(4, s.count)));
  std::sort(out.begin(), out.end(), lexLess);
  return out;
}

std::string
describe(const std::vector<Vec3i>& cells)
{
  std::ostringstream os;
  os << "{";
  for (const Vec3i& c : cells)
    os << toString(c);
  os << "}";
  return os.str();
}

std::vector<SegmentStretch>
sortedStretches(const Vec3i& d)
{
  std::vector<SegmentStretch> st = visfeat::decomposeLatticeSegment(d);
  std::sort(st.begin(), st.end(), [](const SegmentStretch& a, const SegmentStretch& b) {
    return a.t_mid < b.t_mid;
  });
  return st;
}

TEST(LatticeSegment, ZeroOffsetHasNoStretch)
{
  EXPECT_TRUE(visfeat::decomposeLatticeSegment(Vec3i::Zero()).empty());
}

// Along the x axis the segment runs on the edge shared by the four subcells
// (x, -1..0, -1..0); it crosses x = 1 and x = 2, so three stretches of length 1.
TEST(LatticeSegment, AxisSegmentRunsOnAnEdge)
{
  const std::vector<SegmentStretch> st = sortedStretches(Vec3i(3, 0, 0));
  ASSERT_EQ(st.size(), 3u);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(st[i].length, 1.0, 1e-12);
    EXPECT_NEAR(st[i].t_mid, (i + 0.5) / 3.0, 1e-12);
    ASSERT_EQ(st[i].count, 4);
    const std::vector<Vec3i> expected{Vec3i(i, -1, -1), Vec3i(i, -1, 0),
                                      Vec3i(i, 0, -1), Vec3i(i, 0, 0)};
    EXPECT_EQ(describe(sortedSubcells(st[i])), describe(expected));
  }
}

// Diagonal of the face z = 0 between subcells z = -1 and z = 0: one stretch, 2
// subcells.
TEST(LatticeSegment, FaceDiagonalRunsOnAFace)
{
  const std::vector<SegmentStretch> st = sortedStretches(Vec3i(1, -1, 0));
  ASSERT_EQ(st.size(), 1u);
  EXPECT_NEAR(st[0].length, std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(st[0].t_mid, 0.5, 1e-12);
  ASSERT_EQ(st[0].count, 2);
  EXPECT_EQ(describe(sortedSubcells(st[0])),
            describe({Vec3i(0, -1, -1), Vec3i(0, -1, 0)}));
}

// Space diagonal of one subcell: one stretch through its interior.
TEST(LatticeSegment, SpaceDiagonalCrossesOneSubcell)
{
  const std::vector<SegmentStretch> st = sortedStretches(Vec3i(-1, 1, -1));
  ASSERT_EQ(st.size(), 1u);
  EXPECT_NEAR(st[0].length, std::sqrt(3.0), 1e-12);
  ASSERT_EQ(st[0].count, 1);
  EXPECT_EQ(describe(sortedSubcells(st[0])), describe({Vec3i(-1, 0, -1)}));
}

// (2, 1, 0): crosses x = 1 at t = 1/2 where y = 1/2 is not an integer.
TEST(LatticeSegment, FaceSegmentCrossingOnePlane)
{
  const std::vector<SegmentStretch> st = sortedStretches(Vec3i(2, 1, 0));
  ASSERT_EQ(st.size(), 2u);
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(st[i].length, std::sqrt(5.0) / 2.0, 1e-12);
    ASSERT_EQ(st[i].count, 2);
    EXPECT_EQ(describe(sortedSubcells(st[i])),
              describe({Vec3i(i, 0, -1), Vec3i(i, 0, 0)}));
  }
}

// (2, 2, 1): crosses x = 1 and y = 1 at the same parameter t = 1/2 (z = 1/2): the
// crossing of the edge has zero length and is not listed.
TEST(LatticeSegment, CrossingAnEdgeAtAPointIsNotListed)
{
  const std::vector<SegmentStretch> st = sortedStretches(Vec3i(2, 2, 1));
  ASSERT_EQ(st.size(), 2u);
  EXPECT_EQ(st[0].count, 1);
  EXPECT_EQ(st[1].count, 1);
  EXPECT_EQ(describe(sortedSubcells(st[0])), describe({Vec3i(0, 0, 0)}));
  EXPECT_EQ(describe(sortedSubcells(st[1])), describe({Vec3i(1, 1, 0)}));
}

// Every offset in a box: lengths add up to |d|, counts are 1, 2 or 4 with distinct
// subcells, the stretches tile [0, 1] with boundaries at plane crossings, and every
// midpoint interval of the reference lies in one stretch with the same subcells.
TEST(LatticeSegment, AgreesWithReferenceOnABoxOfOffsets)
{
  namespace ref = visfeat_test::reference;
  const int r = 6;
  int failures = 0;
  for (int z = -r; z <= r; ++z)
    for (int y = -r; y <= r; ++y)
      for (int x = -r; x <= r; ++x) {
        const Vec3i d(x, y, z);
        if (d.isZero())
          continue;
        if (failures > 10)
          return;
        const std::vector<SegmentStretch> st = sortedStretches(d);
        const double norm = d.cast<double>().norm();
        SCOPED_TRACE("d = " + toString(d));
        ASSERT_FALSE(st.empty());

        double sum = 0.0;
        for (const SegmentStretch& s : st) {
          sum += s.length;
          EXPECT_GT(s.length, 0.0);
          EXPECT_GT(s.t_mid, 0.0);
          EXPECT_LT(s.t_mid, 1.0);
          const bool count_ok = s.count == 1 || s.count == 2 || s.count == 4;
          EXPECT_TRUE(count_ok) << "count " << s.count;
          if (!count_ok) {
            ++failures;
            continue;
          }
          std::vector<Vec3i> cells = sortedSubcells(s);
          EXPECT_TRUE(std::adjacent_find(cells.begin(), cells.end(),
                                         [](const Vec3i& a, const Vec3i& b) {
                                           return a == b;
                                         }) == cells.end())
            << "repeated subcell in " << describe(cells);
        }
        EXPECT_NEAR(sum, norm, 1e-9 * norm);

        // Tiling of [0, 1]; every boundary is a crossing of an integer plane.
        const std::int64_t n = ref::intervalCount(d);
        double prev_hi = 0.0;
        for (std::size_t i = 0; i < st.size(); ++i) {
          const double half = st[i].length / norm / 2.0;
          const double lo = st[i].t_mid - half, hi = st[i].t_mid + half;
          EXPECT_NEAR(lo, prev_hi, 1e-9) << "stretch " << i;
          prev_hi = hi;
          bool crossing = false;
          for (int a = 0; a < 3; ++a)
            if (d[a] != 0) {
              const double k = hi * std::abs(d[a]);
              crossing = crossing || std::abs(k - std::round(k)) < 1e-9;
            }
          EXPECT_TRUE(crossing) << "stretch " << i << " ends at t = " << hi
                                << ", which crosses no integer plane";
        }
        EXPECT_NEAR(prev_hi, 1.0, 1e-9);

        for (std::int64_t m = 0; m < n; ++m) {
          const double t = (2.0 * m + 1.0) / (2.0 * n);
          const std::vector<Vec3i> expected =
            ref::midpointSubcells(Vec3i::Zero(), d, m, n);
          const SegmentStretch* hit = nullptr;
          for (const SegmentStretch& s : st) {
            const double half = s.length / norm / 2.0;
            if (t > s.t_mid - half && t < s.t_mid + half)
              hit = &s;
          }
          if (hit == nullptr) {
            ADD_FAILURE() << "no stretch contains t = " << t;
            ++failures;
            continue;
          }
          if (describe(sortedSubcells(*hit)) != describe(expected)) {
            ADD_FAILURE() << "at t = " << t << ": stretch subcells "
                          << describe(sortedSubcells(*hit)) << ", reference "
                          << describe(expected);
            ++failures;
          }
        }
      }
}

} // namespace
