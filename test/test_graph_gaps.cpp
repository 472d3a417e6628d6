// findGraphGaps(): where a topology graph departs from that of a closed part. A box's
// surface labelled by its faces, edges and corners has none; the same box with one
// corner relabelled as face, or a face cut off from the rest, has them; an edge with
// the same face on both sides and a free end (a crease fading into its face) is
// counted apart; two corners merged across a short edge leave a corner whose edges
// leave it side by side.

#include "band_fixtures.h"

#include <visfeat/core/graph/graph_gaps.h>
#include <visfeat/core/graph/topology_graph.h>

#include <gtest/gtest.h>

#include <array>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace {

using visfeat::CellCoord;
using visfeat::CellId;
using visfeat::FeatureClass;
using visfeat::GraphGaps;
using visfeat::TopologyGraph;
using visfeat::VoxelBand;

/** A hollowBox() band with its faces, edges and corners (8 / 12 / 6 regions). */
struct LabelledBox
{
  VoxelBand band;
  std::vector<std::uint32_t> labels;
  std::vector<FeatureClass> classes;
  std::map<std::array<int, 3>, std::uint32_t> ids; // extremes signature -> label

  explicit LabelledBox(int sx = 10, int sy = 8, int sz = 5)
  {
    const visfeat_test::CellBand box = visfeat_test::hollowBox(sx, sy, sz);
    VoxelBand::Options options;
    options.repair = false;
    band = VoxelBand::fromCells(box.grid, box.cells, options);
    visfeat_test::BoxRegions regions = visfeat_test::hollowBoxRegions(band, sx, sy, sz);
    labels = std::move(regions.labels);
    classes = std::move(regions.classes);
    ids = std::move(regions.ids);
  }

  /** Region `gone` joins region `into`; the last label takes its number (so that no
   * label is left without cells, which would be a lone region). */
  void joinRegion(std::uint32_t gone, std::uint32_t into)
  {
    const auto last = static_cast<std::uint32_t>(classes.size());
    for (std::uint32_t& l : labels)
      l = l == gone ? into : l;
    for (std::uint32_t& l : labels)
      l = l == last ? gone : l;
    classes[gone - 1] = classes[last - 1];
    classes.pop_back();
    for (auto it = ids.begin(); it != ids.end();)
      if (it->second == gone)
        it = ids.erase(it);
      else {
        it->second = it->second == last ? gone : it->second;
        ++it;
      }
  }

  TopologyGraph graph() const
  {
    return TopologyGraph::build(band, labels, classes,
                                visfeat::TopologyGraphParameters());
  }
};

TEST(GraphGaps, AClosedBoxHasNone)
{
  const LabelledBox box;
  const GraphGaps gaps = visfeat::findGraphGaps(box.graph());
  EXPECT_EQ(gaps.edges, 12u);
  EXPECT_EQ(gaps.one_corner, 0u);
  EXPECT_EQ(gaps.no_corner, 0u);
  EXPECT_EQ(gaps.not_two_faces, 0u);
  EXPECT_EQ(gaps.lone_regions, 0u);
  EXPECT_FALSE(gaps.any());
  EXPECT_EQ(gaps.describe(), "");
}

TEST(GraphGaps, AMissingCornerLeavesThreeEdgesWithOneCorner)
{
  LabelledBox box;
  // the corner at the low extremes becomes part of the face x = lo
  const std::uint32_t corner = box.ids.at({-1, -1, -1});
  const std::uint32_t face = box.ids.at({-1, 0, 0});
  for (std::uint32_t& l : box.labels)
    if (l == corner)
      l = face;
  box.classes[corner - 1] = FeatureClass::kFace; // no cells left: a lone region
  const GraphGaps gaps = visfeat::findGraphGaps(box.graph());
  EXPECT_EQ(gaps.one_corner, 3u);
  EXPECT_EQ(gaps.no_corner, 0u);
  EXPECT_EQ(gaps.not_two_faces, 0u);
  EXPECT_EQ(gaps.lone_regions, 1u);
  EXPECT_TRUE(gaps.any());
  EXPECT_EQ(gaps.describe(), "3 of 12 edges end at a corner on one side only, 1 region "
                             "touches no other");
}

TEST(GraphGaps, AnEdgeWithOneFaceOnBothSidesIsAFadingCreaseNotAGap)
{
  LabelledBox box;
  // the face y = lo joins the face x = lo: the edge between them has that face on
  // both sides and a corner at both ends, so no end fades: the face on its other side
  // merged (2026-12-07; it counted as a fading crease before, and the generated thin
  // plate at 510 cells hid four such edges behind a closed-looking graph)
  box.joinRegion(box.ids.at({0, -1, 0}), box.ids.at({-1, 0, 0}));
  const TopologyGraph graph = box.graph();
  ASSERT_EQ(graph.facesOfEdge(box.ids.at({-1, -1, 0})),
            std::vector<std::uint32_t>{box.ids.at({-1, 0, 0})});
  const GraphGaps merged = visfeat::findGraphGaps(graph);
  EXPECT_EQ(merged.edges, 12u);
  EXPECT_EQ(merged.one_face, 0u);
  EXPECT_EQ(merged.one_corner, 0u);
  EXPECT_EQ(merged.not_two_faces, 1u);
  EXPECT_TRUE(merged.any());
  EXPECT_EQ(merged.describe(), "1 edge does not lie between two faces");

  // with its corner at z = lo gone as well, it ends in its face there, as a crease
  // fading into its face does: counted apart; the two other edges at that corner lose
  // it
  box.joinRegion(box.ids.at({-1, -1, -1}), box.ids.at({-1, 0, 0}));
  const GraphGaps fading = visfeat::findGraphGaps(box.graph());
  EXPECT_EQ(fading.one_face, 1u);
  EXPECT_EQ(fading.one_corner, 2u);
  EXPECT_EQ(fading.not_two_faces, 0u);
  EXPECT_TRUE(fading.any());
  EXPECT_EQ(fading.describe(),
            "2 of 12 edges end at a corner on one side only (1 more edge has one face "
            "on both sides: a crease fading into it)");
}

/** The box with its edge x = lo, y = lo (along z) and the corner at its z = hi end
 * joined into the corner at its z = lo end: two corners merged into one, which ends the
 * four other edges of both. */
GraphGaps
mergedCornerGaps(int sx, int sy, int sz)
{
  LabelledBox box(sx, sy, sz);
  box.joinRegion(box.ids.at({-1, -1, 0}), box.ids.at({-1, -1, -1}));
  box.joinRegion(box.ids.at({-1, -1, 1}), box.ids.at({-1, -1, -1}));
  const TopologyGraph graph = box.graph();
  EXPECT_EQ(graph.neighbours(box.ids.at({-1, -1, -1}), FeatureClass::kEdge).size(), 4u);
  return visfeat::findGraphGaps(graph);
}

TEST(GraphGaps, CornersMergedAcrossAShortEdge)
{
  // the short edge (4 cells) between two corners vanishes into them: the graph is
  // closed (11 edges, each between two faces and two corners), but two edges leave the
  // merged corner side by side (19 and 23 degrees apart)
  const GraphGaps merged = mergedCornerGaps(24, 20, 4);
  EXPECT_EQ(merged.edges, 11u);
  EXPECT_EQ(merged.one_corner, 0u);
  EXPECT_EQ(merged.not_two_faces, 0u);
  EXPECT_EQ(merged.lone_regions, 0u);
  EXPECT_EQ(merged.merged_corners, 1u);
  EXPECT_TRUE(merged.any());
  EXPECT_EQ(merged.describe(), "1 corner ends 4 or more edges, two leaving within 25 "
                               "degrees of each other (corners merged into one)");
  // across an edge as long as the others, the four edges spread (53 degrees and more):
  // a corner of 4 edges, as a pyramid's apex has, is not counted
  const GraphGaps wide = mergedCornerGaps(10, 8, 5);
  EXPECT_EQ(wide.merged_corners, 0u);
  EXPECT_FALSE(wide.any());
}

TEST(GraphGaps, EdgesWithoutCornersAloneAreNoGap)
{
  // a cylinder's rims are closed loops without corners
  GraphGaps loops;
  loops.edges = 2;
  loops.no_corner = 2;
  EXPECT_FALSE(loops.any());
  EXPECT_EQ(loops.describe(), "");
  GraphGaps one = loops;
  one.edges = 8;
  one.one_corner = 1;
  one.no_corner = 0;
  EXPECT_EQ(one.describe(), "1 of 8 edges ends at a corner on one side only");
  GraphGaps all = loops;
  all.edges = 28;
  all.one_corner = 11;
  all.no_corner = 8;
  all.not_two_faces = 1;
  all.lone_regions = 2;
  all.merged_corners = 2;
  all.one_face = 2;
  EXPECT_TRUE(all.any());
  EXPECT_EQ(all.describe(),
            "11 of 28 edges end at a corner on one side only and 8 more at "
            "neither, 1 edge does not lie between two faces, 2 regions "
            "touch no other, 2 corners end 4 or more edges, two leaving within 25 "
            "degrees of each other (corners merged into one) (2 more edges have one "
            "face on both sides: creases fading into it)");
  GraphGaps fading = loops;
  fading.one_face = 3;
  EXPECT_FALSE(fading.any());
}

} // namespace
