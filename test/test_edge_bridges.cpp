// bridgesToCorners: an edge region that stops short of its corner (the faces filled
// the gap) is bridged to the corner ahead on its line through the faces' cells (or to
// the one corner of both faces near its end, off its line); an
// edge with both corners, an edge whose corner lies beyond the reach and a dangling
// edge with no corner ahead (an open scan's border) get none.

#include <visfeat/core/band/voxel_band.h>
#include <visfeat/core/common/error.h>
#include <visfeat/core/common/feature_class.h>
#include <visfeat/core/graph/edge_bridges.h>
#include <visfeat/core/graph/topology_graph.h>

#include <gtest/gtest.h>

#include <functional>

namespace {

using visfeat::CellCoord;
using visfeat::CellId;
using visfeat::FeatureClass;
using visfeat::GridSpec;
using visfeat::TopologyGraph;
using visfeat::VoxelBand;

constexpr FeatureClass kV = FeatureClass::kVertex;
constexpr FeatureClass kE = FeatureClass::kEdge;
constexpr FeatureClass kF = FeatureClass::kFace;

/** A 40 x 40 sheet of cells (z = 2) labelled by `label` (x, y), and its graph. */
struct Sheet
{
  VoxelBand band;
  std::vector<std::uint32_t> labels;
  TopologyGraph graph;

  Sheet(const std::vector<FeatureClass>& classes,
        const std::function<std::uint32_t(int x, int y)>& label)
  {
    GridSpec grid;
    grid.origin = Eigen::Vector3d(0.0, 0.0, 0.0);
    grid.cell_size = 1.0;
    grid.dims = Eigen::Vector3i(40, 40, 6);
    std::vector<CellCoord> cells;
    for (int y = 0; y < 40; ++y)
      for (int x = 0; x < 40; ++x)
        cells.emplace_back(x, y, 2);
    VoxelBand::Options options;
    options.repair = false;
    band = VoxelBand::fromCells(grid, cells, options);
    for (std::size_t i = 0; i < band.size(); ++i) {
      const CellCoord& c = band.coord(static_cast<CellId>(i));
      labels.push_back(label(c.x(), c.y()));
    }
    graph = TopologyGraph::build(band, labels, classes, {});
  }
};

const std::vector<FeatureClass> kClasses{kF, kF, kE, kV, kV};

/** Crease y 19..20 between F1 (below) and F2 (above) from corner V4 (x <= 3); its edge
 * region E3 runs to x = edge_end; corner V5 (x >= 34, y 17..22) touches both faces;
 * the cells between are the faces'. */
std::function<std::uint32_t(int, int)>
shortEdge(int edge_end, bool corner = true)
{
  return [=](int x, int y) -> std::uint32_t {
    if (corner && x >= 34 && y >= 17 && y <= 22)
      return 5;
    if (y == 19 || y == 20) {
      if (x <= 3)
        return 4;
      if (x <= edge_end)
        return 3;
    }
    return y < 20 ? 1 : 2;
  };
}

TEST(EdgeBridges, AnEdgeShortOfItsCornerIsBridgedAlongItsLine)
{
  const Sheet sheet(kClasses, shortEdge(20));
  ASSERT_EQ(sheet.graph.verticesOfEdge(3), std::vector<std::uint32_t>{4});
  ASSERT_EQ(sheet.graph.facesOfEdge(3), (std::vector<std::uint32_t>{1, 2}));
  const std::vector<visfeat::EdgeBridge> bridges =
    visfeat::bridgesToCorners(sheet.band, sheet.labels, sheet.graph, 48.0);
  ASSERT_EQ(bridges.size(), 1u);
  EXPECT_EQ(bridges[0].edge, 3u);
  EXPECT_EQ(bridges[0].vertex, 5u);
  ASSERT_EQ(bridges[0].cells.size(), 13u); // x = 21..33, a shortest path
  int x = 21;
  for (const CellId c : bridges[0].cells) {
    const CellCoord& at = sheet.band.coord(c);
    EXPECT_EQ(at.x(), x++);
    EXPECT_TRUE(at.y() == 19 || at.y() == 20) << at.transpose();
    const std::uint32_t label = sheet.labels[static_cast<std::size_t>(c)];
    EXPECT_TRUE(label == 1 || label == 2);
  }
}

TEST(EdgeBridges, NoBridgeBeyondTheReachOrWithoutACornerAhead)
{
  // the corner 23 cells ahead, the reach 16
  const Sheet far(kClasses, shortEdge(10));
  EXPECT_TRUE(visfeat::bridgesToCorners(far.band, far.labels, far.graph, 16.0).empty());
  EXPECT_EQ(visfeat::bridgesToCorners(far.band, far.labels, far.graph, 48.0).size(),
            1u);
  // a dangling edge: nothing ahead (V5 is a face cell here, an empty region)
  const Sheet open(kClasses, shortEdge(20, false));
  EXPECT_TRUE(
    visfeat::bridgesToCorners(open.band, open.labels, open.graph, 48.0).empty());
}

TEST(EdgeBridges, AnEdgeWithBothCornersGetsNone)
{
  const Sheet sheet(kClasses, shortEdge(33));
  ASSERT_EQ(sheet.graph.verticesOfEdge(3), (std::vector<std::uint32_t>{4, 5}));
  EXPECT_TRUE(
    visfeat::bridgesToCorners(sheet.band, sheet.labels, sheet.graph, 48.0).empty());
}

/** The crease of shortEdge(20) and corners off its line: V5 (x 28..31, y 18..36,
 * centroid 9.5 cells ahead of the edge's end and 7.5 beside its line, touching both
 * faces) and, with `second`, V6 (x 33..36, y 4..21: 14.5 ahead, 7 beside). */
std::function<std::uint32_t(int, int)>
cornersOffTheLine(bool second)
{
  return [=](int x, int y) -> std::uint32_t {
    if (x >= 28 && x <= 31 && y >= 18 && y <= 36)
      return 5;
    if (second && x >= 33 && x <= 36 && y >= 4 && y <= 21)
      return 6;
    if ((y == 19 || y == 20) && x <= 20)
      return x <= 3 ? 4 : 3;
    return y < 20 ? 1 : 2;
  };
}

TEST(EdgeBridges, TheOneCornerOfBothFacesNearTheEndIsBridgedOffTheLine)
{
  // a sparse cloud's corner region may form beside the true corner: off the cone of
  // the line (7.5 > 3 + 9.5 / 4 cells), but the only vertex of both faces within
  // half the reach of the edge's end
  const std::vector<FeatureClass> classes{kF, kF, kE, kV, kV, kV};
  const Sheet sheet(classes, cornersOffTheLine(false));
  ASSERT_EQ(sheet.graph.verticesOfEdge(3), std::vector<std::uint32_t>{4});
  ASSERT_EQ(sheet.graph.neighbours(5, kF), (std::vector<std::uint32_t>{1, 2}));
  const std::vector<visfeat::EdgeBridge> bridges =
    visfeat::bridgesToCorners(sheet.band, sheet.labels, sheet.graph, 48.0);
  ASSERT_EQ(bridges.size(), 1u);
  EXPECT_EQ(bridges[0].vertex, 5u);
  EXPECT_EQ(bridges[0].cells.size(), 7u); // x = 21..27 on the crease's rows
  // beyond half the reach (12.1 cells from the end): none
  EXPECT_TRUE(
    visfeat::bridgesToCorners(sheet.band, sheet.labels, sheet.graph, 24.0).empty());
  // two such corners: which one is the edge's is not known, so none
  const Sheet two(classes, cornersOffTheLine(true));
  EXPECT_TRUE(visfeat::bridgesToCorners(two.band, two.labels, two.graph, 48.0).empty());
}

TEST(EdgeBridges, ACornerThatTouchesOnlyItsOtherEdgesIsReachedWithinTheGraphsReach)
{
  // V5 (x 30..31, y 19..20) ringed by the cells of another edge E6 (x 29..32, y
  // 18..21): no face cell touches it, but the face cells 2 steps away join it in the
  // graph (dilation radius 2)
  const std::vector<FeatureClass> classes{kF, kF, kE, kV, kV, kE};
  const Sheet sheet(classes, [](int x, int y) -> std::uint32_t {
    if (x >= 29 && x <= 32 && y >= 18 && y <= 21)
      return x >= 30 && x <= 31 && y >= 19 && y <= 20 ? 5 : 6;
    if ((y == 19 || y == 20) && x <= 20)
      return x <= 3 ? 4 : 3;
    return y < 20 ? 1 : 2;
  });
  ASSERT_EQ(sheet.graph.verticesOfEdge(3), std::vector<std::uint32_t>{4});
  EXPECT_TRUE(
    visfeat::bridgesToCorners(sheet.band, sheet.labels, sheet.graph, 48.0, 0).empty());
  const std::vector<visfeat::EdgeBridge> bridges =
    visfeat::bridgesToCorners(sheet.band, sheet.labels, sheet.graph, 48.0, 2);
  ASSERT_EQ(bridges.size(), 1u);
  EXPECT_EQ(bridges[0].vertex, 5u);
  ASSERT_EQ(bridges[0].cells.size(), 8u); // x = 21..28: x = 28 is 2 steps from V5
  EXPECT_EQ(sheet.band.coord(bridges[0].cells.back()).x(), 28);
  EXPECT_THROW(
    visfeat::bridgesToCorners(sheet.band, sheet.labels, sheet.graph, 48.0, -1),
    visfeat::Error);
}

TEST(EdgeBridges, LabelsOfAnotherBandAreRefused)
{
  const Sheet sheet(kClasses, shortEdge(20));
  std::vector<std::uint32_t> fewer(sheet.labels.begin(), sheet.labels.end() - 1);
  EXPECT_THROW(visfeat::bridgesToCorners(sheet.band, fewer, sheet.graph, 48.0),
               visfeat::Error);
}

} // namespace
