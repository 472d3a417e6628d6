// PointLabeling (per-point assignment) and RegionPointGeometry on a small hand-made
// band: a flat layer of 10 x 10 cells with two faces, an edge between them and a vertex
// at one end of the edge.

#include <visfeat/core/common/error.h>
#include <visfeat/core/graph/topology_graph.h>
#include <visfeat/core/segmentation/point_labeling.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace {

using visfeat::CellCoord;
using visfeat::CellId;
using visfeat::FeatureClass;
using visfeat::PointLabel;
using visfeat::PointLabeling;
using visfeat::VoxelBand;

constexpr std::uint32_t kFaceA = 1;  // y <= 3
constexpr std::uint32_t kEdge = 2;   // y in {4, 5}, x >= 2
constexpr std::uint32_t kFaceB = 3;  // y >= 6
constexpr std::uint32_t kVertex = 4; // y in {4, 5}, x <= 1

/** Cells (x, y, 5), x, y in [0, 10), in a grid of unit cells at the origin. The
 * skeleton is the row y = 4; its middle line runs along y = 5, z = 5.5 (cell units);
 * edge cells have tangent x, vertex cells none. */
struct Layer
{
  VoxelBand band;
  std::vector<std::uint32_t> labels;
  std::vector<FeatureClass> classes{FeatureClass::kFace, FeatureClass::kEdge,
                                    FeatureClass::kFace, FeatureClass::kVertex};
  std::vector<char> skeleton;
  std::vector<Eigen::Vector3f> centres;
  std::vector<Eigen::Vector3f> tangents;

  Layer()
  {
    visfeat::GridSpec grid;
    grid.dims = Eigen::Vector3i(12, 12, 12);
    std::vector<CellCoord> cells;
    for (int y = 0; y < 10; ++y)
      for (int x = 0; x < 10; ++x)
        cells.emplace_back(x, y, 5);
    VoxelBand::Options no_repair;
    no_repair.repair = false;
    band = VoxelBand::fromCells(grid, cells, no_repair);
    const std::size_t n = band.size();
    labels.assign(n, 0);
    skeleton.assign(n, 0);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    centres.assign(n, Eigen::Vector3f::Constant(nan));
    tangents.assign(n, Eigen::Vector3f::Zero());
    for (std::size_t c = 0; c < n; ++c) {
      const CellCoord at = band.coord(static_cast<CellId>(c));
      labels[c] = at.y() <= 3   ? kFaceA
                  : at.y() >= 6 ? kFaceB
                  : at.x() <= 1 ? kVertex
                                : kEdge;
      if (at.y() == 4) {
        skeleton[c] = 1;
        centres[c] = Eigen::Vector3f(at.x() + 0.5f, 5.0f, 5.5f);
        if (labels[c] == kEdge)
          tangents[c] = Eigen::Vector3f::UnitX();
      }
    }
  }

  CellId cell(int x, int y) const { return band.find(CellCoord(x, y, 5)); }

  PointLabeling labeling(double distance) const
  {
    return PointLabeling(band, labels, classes, skeleton, centres, tangents, distance);
  }

  /** The label of a point given in cell units, in the cell it falls in. */
  PointLabel at(const PointLabeling& l, double x, double y) const
  {
    const Eigen::Vector3d q(x, y, 5.5);
    return l.labelOf(q, band.find(band.grid().cellOf(q)));
  }
};

void
expectLabel(const PointLabel& got, std::uint32_t label, FeatureClass cls)
{
  EXPECT_EQ(got.label, label);
  EXPECT_EQ(got.feature_class, cls);
}

TEST(PointLabeling, PointsNearTheMiddleLineAreFeaturePoints)
{
  const Layer layer;
  const PointLabeling l = layer.labeling(1.0);
  expectLabel(layer.at(l, 5.5, 5.6), kEdge, FeatureClass::kEdge);  // 0.6 away
  expectLabel(layer.at(l, 5.5, 5.95), kEdge, FeatureClass::kEdge); // 0.95
  expectLabel(layer.at(l, 5.5, 4.0), kEdge, FeatureClass::kEdge);  // 1.0: within
  // A face cell's point 1.5 from the line stays on its face.
  expectLabel(layer.at(l, 5.5, 6.5), kFaceB, FeatureClass::kFace);
  // A face cell's point 1.0 from the line joins the edge.
  expectLabel(layer.at(l, 5.5, 6.0), kEdge, FeatureClass::kEdge);
  expectLabel(layer.at(l, 5.5, 4.1), kEdge, FeatureClass::kEdge);
  expectLabel(layer.at(l, 5.5, 3.9), kFaceA, FeatureClass::kFace); // 1.1 away
}

TEST(PointLabeling, EdgeCellPointsFarFromTheLineGoToTheNearestFaceCell)
{
  const Layer layer;
  const PointLabeling l = layer.labeling(0.5);
  // Cell (5, 4) is an edge cell; 0.8 from the line; the nearest face cell centre in
  // its 3x3x3 block is (5.5, 3.5): face A.
  expectLabel(layer.at(l, 5.5, 4.2), kFaceA, FeatureClass::kFace);
  // Cell (5, 5), 0.9 from the line: face B's cells (y = 6) are nearer than face A's.
  expectLabel(layer.at(l, 5.5, 5.9), kFaceB, FeatureClass::kFace);
  // Within 0.5: the edge.
  expectLabel(layer.at(l, 5.5, 5.4), kEdge, FeatureClass::kEdge);
}

TEST(PointLabeling, CornerPointsGoToTheVertex)
{
  const Layer layer;
  const PointLabeling l = layer.labeling(1.0);
  // The edge's piece at (2, 4) reaches back to x = 1: 0.3 from the point; the vertex's
  // skeleton centre (1.5, 5.0) is 0.316 away, within 1: the vertex wins.
  expectLabel(layer.at(l, 1.6, 5.3), kVertex, FeatureClass::kVertex);
  // Farther than 1 from every vertex skeleton cell: the edge.
  expectLabel(layer.at(l, 3.5, 5.3), kEdge, FeatureClass::kEdge);
  // A vertex cell point beyond reach of every skeleton goes to a face.
  const PointLabeling tight = layer.labeling(0.2);
  expectLabel(layer.at(tight, 0.5, 5.9), kFaceB, FeatureClass::kFace);
}

TEST(PointLabeling, OnlyCellsWithin2CellsOfTheSkeletonAreExamined)
{
  const Layer layer;
  const PointLabeling l = layer.labeling(1.0);
  const std::vector<char>& near = l.nearSkeleton();
  ASSERT_EQ(near.size(), layer.band.size());
  for (int y = 0; y < 10; ++y)
    for (int x = 0; x < 10; ++x)
      EXPECT_EQ(near[static_cast<std::size_t>(layer.cell(x, y))], std::abs(y - 4) <= 2)
        << x << " " << y;
  // Far cells keep their label whatever the point.
  expectLabel(layer.at(l, 5.5, 9.5), kFaceB, FeatureClass::kFace);
  expectLabel(layer.at(l, 5.5, 0.1), kFaceA, FeatureClass::kFace);
}

/** The rule of PointLabeling's docstring as written there: a scan of the block of
 * (2 reach + 1)^3 cells around the point's cell, in z, y, x order, for every point. */
PointLabel
scanReference(const VoxelBand& band,
              const std::vector<std::uint32_t>& labels,
              const std::vector<FeatureClass>& classes,
              const std::vector<char>& skeleton,
              const std::vector<Eigen::Vector3f>& centres,
              const std::vector<Eigen::Vector3f>& tangents,
              double distance,
              int reach,
              const Eigen::Vector3d& q,
              CellId cell)
{
  const auto cls = [&](CellId n) {
    const std::uint32_t l = labels[static_cast<std::size_t>(n)];
    return l == 0 ? FeatureClass::kNone : classes[l - 1];
  };
  PointLabel result{labels[static_cast<std::size_t>(cell)], cls(cell)};
  const CellCoord c = band.coord(cell);
  double near_skeleton = std::numeric_limits<double>::infinity(),
         near_vertex = near_skeleton, near_face = near_skeleton;
  CellId nearest_skeleton = visfeat::kNoCell, nearest_vertex = visfeat::kNoCell;
  std::uint32_t face = 0;
  bool any_skeleton = false;
  for (int dz = -reach; dz <= reach; ++dz)
    for (int dy = -reach; dy <= reach; ++dy)
      for (int dx = -reach; dx <= reach; ++dx) {
        const CellId n = band.find(c + CellCoord(dx, dy, dz));
        if (n == visfeat::kNoCell)
          continue;
        const auto s = static_cast<std::size_t>(n);
        if (skeleton[s]) {
          any_skeleton = true;
          const Eigen::Vector3d d = q - centres[s].cast<double>();
          const Eigen::Vector3d u = tangents[s].cast<double>();
          const double along =
            std::clamp(d.dot(u), -PointLabeling::kHalfPiece, PointLabeling::kHalfPiece);
          const double dist = (d - along * u).norm();
          if (dist < near_skeleton) {
            near_skeleton = dist;
            nearest_skeleton = n;
          }
          if (dist < near_vertex && cls(n) == FeatureClass::kVertex) {
            near_vertex = dist;
            nearest_vertex = n;
          }
        }
        if (std::abs(dx) <= 1 && std::abs(dy) <= 1 && std::abs(dz) <= 1 &&
            cls(n) == FeatureClass::kFace) {
          const double d =
            (band.coord(n).cast<double>() + Eigen::Vector3d::Constant(0.5) - q).norm();
          if (d < near_face) {
            near_face = d;
            face = labels[s];
          }
        }
      }
  if (!any_skeleton)
    return result;
  if (near_vertex <= distance)
    nearest_skeleton = nearest_vertex;
  if (near_skeleton <= distance)
    return {labels[static_cast<std::size_t>(nearest_skeleton)], cls(nearest_skeleton)};
  if ((result.feature_class == FeatureClass::kEdge ||
       result.feature_class == FeatureClass::kVertex) &&
      face != 0)
    return {face, FeatureClass::kFace};
  return result;
}

TEST(PointLabeling, TheListedSkeletonGivesTheLabelsOfAScanOfTheBlock)
{
  // A random band (a thick shell of a sphere, cells kept at random), random labels,
  // skeleton, centres on a coarse lattice (so that exact ties between skeleton cells
  // happen) and tangents: the lists built once must give every point the label the
  // docstring's scan gives it, ties included.
  std::mt19937 random(20261202);
  visfeat::GridSpec grid;
  grid.dims = Eigen::Vector3i(24, 24, 24);
  std::vector<CellCoord> cells;
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int z = 0; z < 24; ++z)
    for (int y = 0; y < 24; ++y)
      for (int x = 0; x < 24; ++x) {
        const double r = Eigen::Vector3d(x - 11.5, y - 11.5, z - 11.5).norm();
        if (r > 7.0 && r < 10.0 && unit(random) < 0.7)
          cells.emplace_back(x, y, z);
      }
  VoxelBand::Options no_repair;
  no_repair.repair = false;
  const VoxelBand band = VoxelBand::fromCells(grid, cells, no_repair);
  const std::size_t n = band.size();
  const std::vector<FeatureClass> classes{FeatureClass::kFace, FeatureClass::kEdge,
                                          FeatureClass::kVertex, FeatureClass::kFace};
  std::vector<std::uint32_t> labels(n);
  std::vector<char> skeleton(n, 0);
  std::vector<Eigen::Vector3f> centres(n, Eigen::Vector3f::Zero());
  std::vector<Eigen::Vector3f> tangents(n, Eigen::Vector3f::Zero());
  std::uniform_int_distribution<std::uint32_t> label(0, 4);
  for (std::size_t c = 0; c < n; ++c) {
    labels[c] = label(random);
    if (unit(random) < 0.15) {
      skeleton[c] = 1;
      const CellCoord at = band.coord(static_cast<CellId>(c));
      centres[c] = at.cast<float>() + Eigen::Vector3f::Constant(0.5f);
      if (unit(random) < 0.5)
        tangents[c] = Eigen::Vector3f::Unit(static_cast<Eigen::Index>(c % 3));
    }
  }
  std::size_t changed = 0, checked = 0;
  for (const double distance : {0.8, 1.5, 3.2}) {
    const PointLabeling l(band, labels, classes, skeleton, centres, tangents, distance);
    for (std::size_t c = 0; c < n; ++c)
      for (int k = 0; k < 3; ++k) {
        const CellCoord at = band.coord(static_cast<CellId>(c));
        // points on a half-cell lattice (ties) and at random
        const Eigen::Vector3d offset =
          k == 0 ? Eigen::Vector3d::Constant(0.5)
                 : Eigen::Vector3d(unit(random), unit(random), unit(random));
        const Eigen::Vector3d q = at.cast<double>() + offset;
        const PointLabel got = l.labelOf(q, static_cast<CellId>(c));
        const PointLabel want =
          scanReference(band, labels, classes, skeleton, centres, tangents, distance,
                        l.reach(), q, static_cast<CellId>(c));
        ASSERT_EQ(got.label, want.label) << "cell " << c << " d " << distance;
        ASSERT_EQ(got.feature_class, want.feature_class);
        ++checked;
        changed += got.label != labels[c];
      }
  }
  EXPECT_GT(checked, 10000u);
  EXPECT_GT(changed, checked / 10); // the rule moved many points: the test has teeth
}

TEST(PointLabeling, OffOrWithoutSkeletonPointsTakeTheirCellsLabel)
{
  Layer layer;
  const PointLabeling off = layer.labeling(0.0);
  EXPECT_TRUE(off.nearSkeleton().empty());
  expectLabel(layer.at(off, 5.5, 4.2), kEdge, FeatureClass::kEdge);
  expectLabel(layer.at(off, 5.5, 6.1), kFaceB, FeatureClass::kFace);
  expectLabel(layer.at(off, 1.6, 5.3), kVertex, FeatureClass::kVertex);
  expectLabel(off.labelOf(Eigen::Vector3d(5.5, 5.5, 5.5), visfeat::kNoCell), 0,
              FeatureClass::kNone);

  layer.skeleton.clear();
  const PointLabeling none = layer.labeling(1.0);
  EXPECT_TRUE(none.nearSkeleton().empty());
  expectLabel(layer.at(none, 5.5, 4.2), kEdge, FeatureClass::kEdge);

  // Unlabelled cells: label 0, class none.
  Layer blank;
  blank.labels[static_cast<std::size_t>(blank.cell(7, 8))] = 0;
  const PointLabeling b = blank.labeling(1.0);
  expectLabel(blank.at(b, 7.5, 8.5), 0, FeatureClass::kNone);
}

TEST(PointLabeling, InconsistentInputIsRefused)
{
  Layer layer;
  EXPECT_THROW(layer.labeling(-1.0), visfeat::Error);
  EXPECT_THROW(layer.labeling(std::nan("")), visfeat::Error);
  layer.labels[0] = 5; // 4 regions
  EXPECT_THROW(layer.labeling(1.0), visfeat::Error);
  layer.labels[0] = kFaceA;
  layer.centres.pop_back();
  EXPECT_THROW(layer.labeling(1.0), visfeat::Error);
  layer.centres.push_back(Eigen::Vector3f::Zero());
  layer.labels.pop_back();
  EXPECT_THROW(layer.labeling(1.0), visfeat::Error);
}

TEST(PointlessVertices, OnlyVertexRegionsWithCellsAndNoPoint)
{
  // regions 1 face, 2 vertex, 3 edge, 4 vertex, 5 vertex (no cell)
  const std::vector<FeatureClass> classes = {FeatureClass::kFace, FeatureClass::kVertex,
                                             FeatureClass::kEdge, FeatureClass::kVertex,
                                             FeatureClass::kVertex};
  const std::vector<std::uint32_t> cells = {1, 2, 0, 4, 3, 4, 1, 2};
  // vertex 2 has a point, vertex 4 none: only 4 is listed, with its cells in order
  auto pointless = visfeat::pointlessVertices(cells, classes, {0, 5, 1, 2, 0, 0});
  ASSERT_EQ(pointless.size(), 1u);
  EXPECT_EQ(pointless[0].first, 4u);
  EXPECT_EQ(pointless[0].second, (std::vector<CellId>{3, 5}));
  // labels beyond the counts count as without points: 2 and 4 both listed
  pointless = visfeat::pointlessVertices(cells, classes, {0, 5});
  ASSERT_EQ(pointless.size(), 2u);
  EXPECT_EQ(pointless[0].first, 2u);
  EXPECT_EQ(pointless[0].second, (std::vector<CellId>{1, 7}));
  EXPECT_EQ(pointless[1].first, 4u);
  // every vertex with a point: none
  EXPECT_TRUE(visfeat::pointlessVertices(cells, classes, {0, 1, 1, 1, 1, 1}).empty());
  // a cell label beyond the regions is refused
  EXPECT_THROW(visfeat::pointlessVertices({6}, classes, {}), visfeat::Error);
}

TEST(RegionPointGeometry, CentroidsAndBoundsOfThePoints)
{
  const Layer layer;
  visfeat::TopologyGraph graph = visfeat::TopologyGraph::build(
    layer.band, layer.labels, layer.classes, visfeat::TopologyGraphParameters{});
  visfeat::RegionPointGeometry geometry(layer.classes.size());
  geometry.add(kEdge, Eigen::Vector3d(1.0, 2.0, 3.0));
  geometry.add(kEdge, Eigen::Vector3d(3.0, 0.0, 5.0));
  geometry.add(kEdge, Eigen::Vector3d(std::nan(""), 0.0, 0.0)); // ignored
  geometry.add(0, Eigen::Vector3d(9.0, 9.0, 9.0));              // ignored
  geometry.add(7, Eigen::Vector3d(9.0, 9.0, 9.0));              // ignored
  geometry.add(kVertex, Eigen::Vector3d(-1.0, -1.0, -1.0));
  const visfeat::GraphNode face_before = graph.node(kFaceA);
  geometry.applyTo(graph);
  const visfeat::GraphNode& edge = graph.node(kEdge);
  EXPECT_EQ(edge.points, 2u);
  EXPECT_EQ(edge.centroid, Eigen::Vector3d(2.0, 1.0, 4.0));
  EXPECT_EQ(edge.min, Eigen::Vector3d(1.0, 0.0, 3.0));
  EXPECT_EQ(edge.max, Eigen::Vector3d(3.0, 2.0, 5.0));
  EXPECT_EQ(graph.node(kVertex).points, 1u);
  EXPECT_EQ(graph.node(kVertex).centroid, Eigen::Vector3d(-1.0, -1.0, -1.0));
  // A region without points keeps the geometry of its cells.
  EXPECT_EQ(graph.node(kFaceA).points, face_before.points);
  EXPECT_EQ(graph.node(kFaceA).centroid, face_before.centroid);
}

} // namespace
