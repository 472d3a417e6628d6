// cornerMeets: the point where a corner's creases meet, from lines fitted to its
// edges' points, and the point nearest it among the corner and its neighbours; no meet
// for parallel creases or a single one; bad input refused.

#include "graph_sheet.h"

#include <visfeat/core/common/error.h>
#include <visfeat/core/common/feature_class.h>
#include <visfeat/core/graph/corner_meets.h>

#include <gtest/gtest.h>

#include <cmath>

namespace {

using visfeat::CornerMeet;
using visfeat::CornerMeetParameters;
using visfeat::FeatureClass;
using visfeat_test::in;
using visfeat_test::LabelledSheet;

constexpr FeatureClass kV = FeatureClass::kVertex;
constexpr FeatureClass kE = FeatureClass::kEdge;
constexpr FeatureClass kF = FeatureClass::kFace;

/** One point at each cell's centre, cell units, with the cell's label. */
struct SheetPoints
{
  std::vector<Eigen::Vector3d> points;
  std::vector<std::uint32_t> labels;

  explicit SheetPoints(const LabelledSheet& sheet)
  {
    for (std::size_t i = 0; i < sheet.band.size(); ++i) {
      points.push_back(
        sheet.band.coord(static_cast<visfeat::CellId>(i)).cast<double>() +
        Eigen::Vector3d::Constant(0.5));
      labels.push_back(sheet.labels[i]);
    }
  }
};

/** A wedge with its tip at cell corner (10, 10): crease E2 along y = 10 (cells y
 * 9..10, x >= 10) and crease E3 along y = x (cells |x - y| <= 1, x >= 24), the faces F1
 * (between) and F5 (outside). The corner region V4 (x 20..23, y 8..25) lies 10 cells
 * and more down the wedge from the tip, where the segmentation of a sharp tip puts it;
 * the diagonal crease's cells before it are lost in F1. */
std::uint32_t
wedge(int x, int y)
{
  if (in(x, 20, 23) && in(y, 8, 25))
    return 4;
  if (in(y, 9, 10) && x >= 10)
    return 2;
  if (std::abs(x - y) <= 1 && x >= 24)
    return 3;
  return x >= 10 && y > 10 && y < x ? 1 : 5;
}

const std::vector<FeatureClass> kWedgeClasses{kF, kE, kE, kV, kF};

TEST(CornerMeets, ACornerDownASharpTipMeetsItsCreasesAtTheTip)
{
  const LabelledSheet sheet(kWedgeClasses, wedge);
  ASSERT_EQ(sheet.graph.neighbours(4, kE), (visfeat_test::Labels{2, 3}));
  const SheetPoints cloud(sheet);
  CornerMeetParameters parameters;
  parameters.max_point_distance = 2.0;
  const std::vector<CornerMeet> meets =
    visfeat::cornerMeets(sheet.graph, cloud.points, cloud.labels, parameters);
  ASSERT_EQ(meets.size(), 1u);
  EXPECT_EQ(meets[0].vertex, 4u);
  const Eigen::Vector3d tip(10.0, 10.0, 2.5);
  EXPECT_LT((meets[0].meet - tip).norm(), 0.5) << meets[0].meet.transpose();
  ASSERT_NE(meets[0].point, CornerMeet::kNoPoint);
  // a point beside the tip (cell centres lie 0.71 cells from it), of V4's neighbours
  EXPECT_LT((cloud.points[meets[0].point] - tip).norm(), 0.8);
  const std::uint32_t label = cloud.labels[meets[0].point];
  EXPECT_TRUE(label == 4 || sheet.graph.adjacent(4, label)) << label;
  // no point within a tenth of a cell of the tip: the meet stays, with no point
  parameters.max_point_distance = 0.1;
  const std::vector<CornerMeet> far =
    visfeat::cornerMeets(sheet.graph, cloud.points, cloud.labels, parameters);
  ASSERT_EQ(far.size(), 1u);
  EXPECT_EQ(far[0].point, CornerMeet::kNoPoint);
}

TEST(CornerMeets, ParallelCreasesOrOneCreaseHaveNoMeet)
{
  // V4 (x 20..23) between E2 (y 9..10) and E3 (y 19..20), both along x
  const LabelledSheet parallel(kWedgeClasses, [](int x, int y) -> std::uint32_t {
    if (in(x, 20, 23) && in(y, 8, 21))
      return 4;
    if (in(y, 9, 10))
      return 2;
    if (in(y, 19, 20))
      return 3;
    return in(y, 11, 18) ? 1 : 5;
  });
  ASSERT_EQ(parallel.graph.neighbours(4, kE), (visfeat_test::Labels{2, 3}));
  const SheetPoints a(parallel);
  EXPECT_TRUE(
    visfeat::cornerMeets(parallel.graph, a.points, a.labels, CornerMeetParameters())
      .empty());
  // the wedge without its diagonal crease: V4 ends E2 only
  const LabelledSheet single(kWedgeClasses, [](int x, int y) {
    const std::uint32_t label = wedge(x, y);
    return label == 3 ? 1u : label;
  });
  ASSERT_EQ(single.graph.neighbours(4, kE), (visfeat_test::Labels{2}));
  const SheetPoints b(single);
  EXPECT_TRUE(
    visfeat::cornerMeets(single.graph, b.points, b.labels, CornerMeetParameters())
      .empty());
}

TEST(CornerMeets, BadInputIsRefused)
{
  const LabelledSheet sheet(kWedgeClasses, wedge);
  SheetPoints cloud(sheet);
  cloud.labels.pop_back();
  EXPECT_THROW(visfeat::cornerMeets(sheet.graph, cloud.points, cloud.labels,
                                    CornerMeetParameters()),
               visfeat::Error);
  cloud.labels.push_back(1);
  CornerMeetParameters parameters;
  parameters.line_radius = 0.0;
  EXPECT_THROW(
    visfeat::cornerMeets(sheet.graph, cloud.points, cloud.labels, parameters),
    visfeat::Error);
}

} // namespace
