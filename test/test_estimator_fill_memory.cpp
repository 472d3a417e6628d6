// The memory check before a fill: the band filled between points or from a mesh's
// triangles is refused before it allocates anything when its cells (the surface's area
// in cells, kFillBytesPerCell) and, between points, the points themselves
// (kFillBytesPerPoint) would pass the memory limit.

#include "estimator_fixtures.h"

#include <support/cad_models.h>
#include <visfeat/point_types.h>
#include <visfeat/surface_fill.h>
#include <visfeat/visibility_feature_estimation.h>

#include <gtest/gtest.h>

#include <cstdint>
#include <string>

namespace {

using namespace visfeat_test::estimator;

TEST(EstimatorFill, AFillBeyondTheMemoryLimitIsRefusedBeforeItStarts)
{
  // 10,000 points of a cube at 1024 cells are about 13 cells apart: the band is filled
  // between them, some 2 million cells of surface (about 400 MB), over a 64 MiB limit.
  // The refusal comes before the fill; the points alone (10,000 cells) would pass, and
  // the band's own check came only after the fill had been built (a cloud of 562,000
  // points at 8192 cells rose past 15 GB in the fill).
  const syn::CadModel model =
    syn::rotated(syn::cadModelByName("cube"), syn::randomRotation(3));
  Estimator est;
  est.setInputCloud(sparseCloud(model, 10000, 3));
  est.setResolution(1024);
  est.setMemoryLimit(std::uint64_t{64} << 20);
  Output out;
  est.compute(out);
  EXPECT_TRUE(out.empty());
  const std::string& message = est.getErrorMessage();
  EXPECT_EQ(message.rfind("filling the band between the points at resolution 1024 "
                          "(at least ",
                          0),
            0u)
    << message;
  EXPECT_NE(message.find("more than the limit of 64.0 MiB"), std::string::npos)
    << message;
}

TEST(EstimatorFill, AFillBetweenPointsCountsItsPoints)
{
  // 300,000 points of a cube at 400 cells lie about 1.07 cells apart: the band is
  // filled between them. Their area is about 345,000 cells (66 MiB at
  // kFillBytesPerCell), but the fill also holds each point's neighbours and triangles
  // (kFillBytesPerPoint: 129 MiB). Under a 120 MiB limit the fill is refused; counted
  // by its area alone it passed (the box with hole at 2048, 0.7 cells apart, peaked at
  // 13.4 GB where the area counted 2.0).
  const syn::CadModel model =
    syn::rotated(syn::cadModelByName("cube"), syn::randomRotation(4));
  Estimator est;
  est.setInputCloud(sparseCloud(model, 300000, 4));
  est.setResolution(400);
  est.setMemoryLimit(std::uint64_t{120} << 20);
  Output out;
  est.compute(out);
  EXPECT_TRUE(out.empty());
  const std::string& message = est.getErrorMessage();
  EXPECT_EQ(message.rfind("filling the band between the points at resolution 400 ", 0),
            0u)
    << message;
  EXPECT_NE(message.find(", and 300000 points)"), std::string::npos) << message;
}

TEST(EstimatorFill, AFillDecidedAfterThePointsBandIsCheckedToo)
{
  // The same points at 220 cells lie about 0.59 cells apart: dense enough that their
  // spacing is measured only once the band of their cells shows holes, and then filled.
  // That fill was not checked at all. Under a limit just above the grid's own
  // estimate (read from its refusal), the fill is now refused.
  const syn::CadModel model =
    syn::rotated(syn::cadModelByName("cube"), syn::randomRotation(4));
  const Cloud::Ptr cloud = sparseCloud(model, 300000, 4);
  Estimator est;
  est.setInputCloud(cloud);
  est.setResolution(220);
  est.setMemoryLimit(std::uint64_t{16} << 20);
  Output out;
  est.compute(out);
  const std::string grid = est.getErrorMessage();
  const std::size_t at = grid.find("needs about ");
  ASSERT_EQ(grid.rfind("a grid of ", 0), 0u) << grid;
  ASSERT_NE(at, std::string::npos) << grid;
  const double grid_mib = std::stod(grid.substr(at + 12));
  est.setMemoryLimit(static_cast<std::uint64_t>((grid_mib + 2.0) * 1024.0 * 1024.0));
  est.compute(out);
  EXPECT_TRUE(out.empty());
  const std::string& message = est.getErrorMessage();
  EXPECT_EQ(message.rfind("filling the band between the points at resolution 220 ", 0),
            0u)
    << message;
}

} // namespace
