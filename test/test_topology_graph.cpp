// TopologyGraph: arcs from the dilation test (against hand-worked layouts and a
// brute-force geodesic distance), node geometry in world units, queries, errors; the
// faces an edge keeps. DOT / JSON export and writeFile: test_topology_graph_export.cpp.

#include "band_fixtures.h"
#include "graph_fixtures.h"
#include <support/portable_random.h>

#include <visfeat/core/band/voxel_band.h>
#include <visfeat/core/common/error.h>
#include <visfeat/core/common/feature_class.h>
#include <visfeat/core/graph/topology_graph.h>

#include <boost/graph/connected_components.hpp>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <queue>
#include <random>
#include <set>
#include <sstream>

namespace {

using namespace visfeat_test::graph;

// --- Tests ---------------------------------------------------------------------

TEST(TopologyGraph, StripArcsAndQueries)
{
  const Strip s;
  const TopologyGraph g = buildGraph(s.band, s.labels, s.classes, 2);
  ASSERT_EQ(g.size(), 4u);
  EXPECT_EQ(g.arcs(), (Arcs{{1, 2}, {1, 4}, {2, 3}}));
  EXPECT_EQ(g.arcCount(), 3u);
  EXPECT_EQ(g.classCount(kV), 1u);
  EXPECT_EQ(g.classCount(kE), 1u);
  EXPECT_EQ(g.classCount(kF), 2u);
  EXPECT_EQ(g.classCount(FeatureClass::kNone), 0u);
  for (std::uint32_t id = 1; id <= 4; ++id) {
    EXPECT_EQ(g.node(id).id, id);
    EXPECT_EQ(g.node(id).feature_class, s.classes[id - 1]);
  }
  EXPECT_EQ(g.node(1).cells, 6u);
  EXPECT_EQ(g.node(2).cells, 2u);
  EXPECT_EQ(g.node(3).cells, 12u);
  EXPECT_EQ(g.node(4).cells, 2u);
  EXPECT_EQ(g.node(3).points, 12u);
  EXPECT_EQ(g.neighbours(1), (Ids{2, 4}));
  EXPECT_EQ(g.neighbours(2), (Ids{1, 3}));
  EXPECT_EQ(g.neighbours(4), (Ids{1}));
  EXPECT_EQ(g.neighbours(1, kE), (Ids{2}));
  EXPECT_EQ(g.neighbours(1, kV), (Ids{4}));
  EXPECT_EQ(g.neighbours(1, kF), Ids{});
  EXPECT_EQ(g.edgesOfFace(1), (Ids{2}));
  EXPECT_EQ(g.edgesOfFace(3), (Ids{2}));
  EXPECT_EQ(g.facesOfEdge(2), (Ids{1, 3}));
  EXPECT_EQ(g.verticesOfEdge(2), Ids{});
  EXPECT_TRUE(g.adjacent(2, 1));
  EXPECT_FALSE(g.adjacent(1, 3));

  // V4 (x <= 3) reaches E2 (x = 10) at 7 steps, F3 (x = 12) at 9.
  EXPECT_EQ(buildGraph(s.band, s.labels, s.classes, 6).arcs(),
            (Arcs{{1, 2}, {1, 4}, {2, 3}}));
  const TopologyGraph g7 = buildGraph(s.band, s.labels, s.classes, 7);
  EXPECT_EQ(g7.arcs(), (Arcs{{1, 2}, {1, 4}, {2, 3}, {2, 4}}));
  EXPECT_EQ(g7.verticesOfEdge(2), (Ids{4}));
  EXPECT_EQ(buildGraph(s.band, s.labels, s.classes, 9).arcs(),
            (Arcs{{1, 2}, {1, 4}, {2, 3}, {2, 4}, {3, 4}}));
  // Radius 0 joins nothing; a huge radius joins every pair of different classes but
  // never the two faces.
  EXPECT_EQ(buildGraph(s.band, s.labels, s.classes, 0).arcCount(), 0u);
  EXPECT_EQ(buildGraph(s.band, s.labels, s.classes, 1000).arcs(),
            (Arcs{{1, 2}, {1, 4}, {2, 3}, {2, 4}, {3, 4}}));
}

TEST(TopologyGraph, SheetAllPairTypesNoSameClassArcs)
{
  const Sheet s;
  const TopologyGraph g = buildGraph(s.band, s.labels, s.classes, 1);
  ASSERT_EQ(g.size(), 6u);
  EXPECT_EQ(g.arcs(), (Arcs{{1, 2}, {1, 4}, {1, 5}, {2, 3}, {2, 4}, {3, 4}, {3, 5}}));
  EXPECT_EQ(g.verticesOfEdge(2), (Ids{4}));
  EXPECT_EQ(g.facesOfEdge(2), (Ids{1, 3}));
  EXPECT_EQ(g.neighbours(4), (Ids{1, 2, 3}));
  EXPECT_EQ(g.neighbours(5), (Ids{1, 3}));
  EXPECT_EQ(g.classCount(kV), 2u);
  EXPECT_EQ(g.classCount(kE), 2u);
  // The empty edge 6: a node without cells, points, geometry or arcs.
  EXPECT_EQ(g.node(6).cells, 0u);
  EXPECT_EQ(g.node(6).points, 0u);
  EXPECT_TRUE(g.node(6).centroid.array().isNaN().all());
  EXPECT_TRUE(g.neighbours(6).empty());
  EXPECT_EQ(g.facesOfEdge(6), Ids{});

  // V5 (x = 13) is 3 steps from E2 (ends at x = 10), through V4's cells.
  EXPECT_FALSE(buildGraph(s.band, s.labels, s.classes, 2).adjacent(2, 5));
  EXPECT_TRUE(buildGraph(s.band, s.labels, s.classes, 3).adjacent(2, 5));

  for (int r : {1, 2, 3, 5, 20}) {
    const TopologyGraph gr = buildGraph(s.band, s.labels, s.classes, r);
    EXPECT_EQ(gr.arcs(), bruteForceArcs(s.band, s.labels, s.classes, r)) << r;
    for (const auto& arc : gr.arcs())
      EXPECT_NE(gr.node(arc.first).feature_class, gr.node(arc.second).feature_class);
    EXPECT_FALSE(gr.adjacent(1, 3)) << "face-face arc at radius " << r;
    EXPECT_FALSE(gr.adjacent(4, 5)) << "vertex-vertex arc at radius " << r;
  }
}

TEST(TopologyGraph, GapNeedsRadiusAboveGap)
{
  // Raw-style strip: region A on x = 2..5, k unlabelled cells, region B after them.
  // The last cell of A is at distance 0, the gap cells at 1..k, B's first cell at
  // k + 1: joined iff dilation_radius >= k + 1.
  const GridSpec grid = testGrid(64, 8, 8);
  for (const int k : {0, 1, 2, 5, 16}) {
    std::vector<CellCoord> cells;
    for (int x = 2; x <= 5 + k + 4; ++x)
      cells.emplace_back(x, 3, 3);
    const VoxelBand band = bandOf(grid, cells);
    const auto labels = labelBand(band, [&](const CellCoord& c) -> std::uint32_t {
      if (c.x() <= 5)
        return 1;
      return c.x() <= 5 + k ? 0 : 2;
    });
    for (const auto& pair : std::vector<std::vector<FeatureClass>>{
           {kV, kE}, {kE, kV}, {kE, kF}, {kF, kE}, {kV, kF}, {kF, kV}}) {
      for (int r = 0; r <= k + 3; ++r) {
        const TopologyGraph g = buildGraph(band, labels, pair, r);
        EXPECT_EQ(g.arcCount(), r >= k + 1 ? 1u : 0u)
          << "gap " << k << " radius " << r << " classes "
          << TopologyGraph::className(pair[0]) << "-"
          << TopologyGraph::className(pair[1]);
      }
    }
    for (const auto& same : std::vector<std::vector<FeatureClass>>{
           {kV, kV}, {kE, kE}, {kF, kF}, {kE, FeatureClass::kNone}})
      EXPECT_EQ(buildGraph(band, labels, same, 1000).arcCount(), 0u);
  }
}

TEST(TopologyGraph, DilationIsGeodesic)
{
  // Two rows y = 2 and y = 4 (no cells at y = 3) joined by a column at x = 10:
  // E1 at (2..4, 2) and F2 at (2..4, 4) are 2 cells apart in space but 14 steps apart
  // through the band: 4 -> 10 (6), up 2, 10 -> 4 (6).
  std::vector<CellCoord> cells;
  for (int x = 2; x <= 10; ++x) {
    cells.emplace_back(x, 2, 2);
    cells.emplace_back(x, 4, 2);
  }
  cells.emplace_back(10, 3, 2);
  const VoxelBand band = bandOf(testGrid(), cells);
  const auto labels = labelBand(band, [](const CellCoord& c) -> std::uint32_t {
    if (c.x() > 4)
      return 0;
    return c.y() == 2 ? 1 : 2;
  });
  const std::vector<FeatureClass> classes{kE, kF};
  EXPECT_EQ(buildGraph(band, labels, classes, 13).arcCount(), 0u);
  EXPECT_EQ(buildGraph(band, labels, classes, 14).arcCount(), 1u);
}

TEST(TopologyGraph, HollowBoxTopology)
{
  // The surface of a box of cells, labelled by how many of its coordinates are on
  // the box's extremes: 1 face, 2 edge, 3 vertex.
  const visfeat_test::CellBand box = visfeat_test::hollowBox(10, 8, 5);
  VoxelBand::Options options;
  options.repair = false;
  const VoxelBand band = VoxelBand::fromCells(box.grid, box.cells, options);
  const visfeat_test::BoxRegions regions = visfeat_test::hollowBoxRegions(band);
  const std::vector<std::uint32_t>& labels = regions.labels;
  const std::vector<FeatureClass>& classes = regions.classes;
  ASSERT_EQ(classes.size(), 26u);

  const TopologyGraph g1 = buildGraph(band, labels, classes, 1);
  EXPECT_EQ(g1.classCount(kV), 8u);
  EXPECT_EQ(g1.classCount(kE), 12u);
  EXPECT_EQ(g1.classCount(kF), 6u);
  EXPECT_EQ(g1.arcCount(), 48u); // 8 x 3 vertex-edge + 12 x 2 edge-face
  for (std::uint32_t id = 1; id <= g1.size(); ++id) {
    const FeatureClass cls = g1.node(id).feature_class;
    if (cls == kE) {
      EXPECT_EQ(g1.verticesOfEdge(id).size(), 2u) << id;
      EXPECT_EQ(g1.facesOfEdge(id).size(), 2u) << id;
    } else if (cls == kF) {
      EXPECT_EQ(g1.edgesOfFace(id).size(), 4u) << id;
      EXPECT_TRUE(g1.neighbours(id, kV).empty()) << id; // corners touch edges only
    } else {
      EXPECT_EQ(g1.neighbours(id, kE).size(), 3u) << id;
    }
  }
  // Radius 2 adds the 8 x 3 vertex-face incidences (corner -> edge cell -> face).
  const TopologyGraph g2 = buildGraph(band, labels, classes, 2);
  EXPECT_EQ(g2.arcCount(), 72u);
  for (std::uint32_t id = 1; id <= g2.size(); ++id) {
    if (g2.node(id).feature_class == kV) {
      EXPECT_EQ(g2.neighbours(id, kF).size(), 3u) << id;
    }
  }
  // Radius 3 reaches through the corner into the third face: the documented limit.
  EXPECT_GT(buildGraph(band, labels, classes, 3).arcCount(), 72u);
  for (int r : {1, 2, 3, 4})
    EXPECT_EQ(buildGraph(band, labels, classes, r).arcs(),
              bruteForceArcs(band, labels, classes, r));

  // A corner lies on the faces of its edges: with vertex_faces_from_edges, radius 1
  // gives the 8 x 3 vertex-face arcs that its dilation does not reach.
  TopologyGraphParameters corner;
  corner.dilation_radius = 1;
  corner.min_face_contact = 0.0;
  corner.vertex_faces_from_edges = true;
  const TopologyGraph g1_corner = TopologyGraph::build(band, labels, classes, corner);
  EXPECT_EQ(g1_corner.arcs(), g2.arcs());
  for (std::uint32_t id = 1; id <= g1_corner.size(); ++id)
    if (g1_corner.node(id).feature_class == kV) {
      std::set<std::uint32_t> faces_of_edges;
      for (const std::uint32_t e : g1_corner.neighbours(id, kE))
        for (const std::uint32_t f : g1_corner.facesOfEdge(e))
          faces_of_edges.insert(f);
      const Ids faces = g1_corner.neighbours(id, kF);
      EXPECT_EQ(std::set<std::uint32_t>(faces.begin(), faces.end()), faces_of_edges)
        << id;
    }

  // Boost Graph algorithms run on graph(): the box is one connected piece.
  std::vector<int> component(boost::num_vertices(g1.graph()));
  EXPECT_EQ(boost::connected_components(g1.graph(), component.data()), 1);
  EXPECT_EQ(g1.graph()[0].id, 1u);
}

TEST(TopologyGraph, RandomLabelsMatchBruteForce)
{
  // A sheet with holes, labelled by nearest seed (Chebyshev), with unlabelled seams of
  // random width between regions; classes random.
  std::mt19937_64 rng(20240611);
  const GridSpec grid = testGrid(48, 48, 8);
  std::vector<CellCoord> cells;
  visfeat::synthetic::UniformInt pct(0, 99);
  for (int y = 1; y < 47; ++y)
    for (int x = 1; x < 47; ++x)
      if (pct(rng) >= 8)
        cells.emplace_back(x, y, 3);
  const VoxelBand band = bandOf(grid, cells);
  visfeat::synthetic::UniformInt coord(1, 46), cls(1, 3);
  std::vector<Eigen::Vector2i> seeds;
  std::vector<FeatureClass> classes;
  for (int s = 0; s < 24; ++s) {
    seeds.emplace_back(coord(rng), coord(rng));
    classes.push_back(static_cast<FeatureClass>(cls(rng)));
  }
  classes.push_back(kE); // a label with no cells
  const auto labels = labelBand(band, [&](const CellCoord& c) -> std::uint32_t {
    std::vector<std::pair<int, std::uint32_t>> d;
    for (std::size_t s = 0; s < seeds.size(); ++s)
      d.emplace_back(
        std::max(std::abs(c.x() - seeds[s].x()), std::abs(c.y() - seeds[s].y())),
        static_cast<std::uint32_t>(s + 1));
    std::sort(d.begin(), d.end());
    // Seam: unlabelled where the two nearest seeds are nearly tied.
    const int seam = static_cast<int>(d[0].second % 4);
    return d[1].first - d[0].first < seam ? 0 : d[0].second;
  });
  std::size_t previous = 0;
  for (int r : {0, 1, 2, 3, 6, 12}) {
    const TopologyGraph g = buildGraph(band, labels, classes, r);
    EXPECT_GE(g.arcCount(), previous); // monotone in the radius
    previous = g.arcCount();
    EXPECT_EQ(g.arcs(), bruteForceArcs(band, labels, classes, r)) << "radius " << r;
    // Determinism: same input, same graph, same export.
    const TopologyGraph again = buildGraph(band, labels, classes, r);
    EXPECT_EQ(again.arcs(), g.arcs());
    EXPECT_EQ(jsonOf(again), jsonOf(g));
    EXPECT_EQ(dotOf(again), dotOf(g));
  }
  EXPECT_GE(buildGraph(band, labels, classes, 1).arcCount(), 5u);
  EXPECT_GT(previous, buildGraph(band, labels, classes, 1).arcCount());
}

TEST(TopologyGraph, GeometryInWorldUnits)
{
  // Cells with various point counts: region 1 = (4,5,6) x3 points, (6,5,6) x1 point,
  // (5,7,6) x0 points; region 2 = (10,2,3), (10,2,4), both without points.
  const GridSpec grid = testGrid();
  std::vector<visfeat::OccupiedCell> occupied(5);
  const CellCoord coords[5] = {{4, 5, 6}, {6, 5, 6}, {5, 7, 6}, {10, 2, 3}, {10, 2, 4}};
  const std::uint32_t counts[5] = {3, 1, 0, 0, 0};
  for (int i = 0; i < 5; ++i) {
    occupied[static_cast<std::size_t>(i)].coord = coords[i];
    occupied[static_cast<std::size_t>(i)].point_count = counts[i];
  }
  VoxelBand::Options options;
  options.repair = false;
  const VoxelBand band = VoxelBand::build(grid, occupied, {}, options);
  const auto labels = labelBand(
    band, [](const CellCoord& c) -> std::uint32_t { return c.x() == 10 ? 2 : 1; });
  const TopologyGraph g = buildGraph(band, labels, {kF, kE}, 2);

  const GraphNode& n1 = g.node(1);
  EXPECT_EQ(n1.cells, 3u);
  EXPECT_EQ(n1.points, 4u);
  // Weighted centre in cells: (3 * 4.5 + 1 * 6.5) / 4 = 5.0 in x, 5.5 in y, 6.5 in z.
  const Eigen::Vector3d c1 = grid.origin + 0.5 * Eigen::Vector3d(5.0, 5.5, 6.5);
  EXPECT_NEAR((n1.centroid - c1).norm(), 0.0, 1e-12) << n1.centroid.transpose();
  EXPECT_NEAR((n1.min - (grid.origin + 0.5 * Eigen::Vector3d(4, 5, 6))).norm(), 0.0,
              1e-12);
  EXPECT_NEAR((n1.max - (grid.origin + 0.5 * Eigen::Vector3d(7, 8, 7))).norm(), 0.0,
              1e-12);
  EXPECT_NEAR(n1.min.x(), -1.5 + 2.0, 1e-12);
  EXPECT_NEAR(n1.max.z(), 0.25 + 3.5, 1e-12);

  // No points: the plain mean of the cell centres.
  const GraphNode& n2 = g.node(2);
  EXPECT_EQ(n2.points, 0u);
  const Eigen::Vector3d c2 = grid.origin + 0.5 * Eigen::Vector3d(10.5, 2.5, 4.0);
  EXPECT_NEAR((n2.centroid - c2).norm(), 0.0, 1e-12) << n2.centroid.transpose();
  EXPECT_NEAR((n2.max - (grid.origin + 0.5 * Eigen::Vector3d(11, 3, 5))).norm(), 0.0,
              1e-12);
  EXPECT_EQ(g.arcCount(), 0u); // not connected through the band

  TopologyGraph h = g;
  h.setPointGeometry(2, 17, Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(0, 1, 2),
                     Eigen::Vector3d(2, 3, 4));
  EXPECT_EQ(h.node(2).points, 17u);
  EXPECT_EQ(h.node(2).centroid, Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(h.node(2).min, Eigen::Vector3d(0, 1, 2));
  EXPECT_EQ(h.node(2).max, Eigen::Vector3d(2, 3, 4));
  EXPECT_EQ(h.node(2).cells, 2u); // unchanged
  EXPECT_EQ(g.node(2).points, 0u);
  EXPECT_THROW(h.setPointGeometry(3, 1, c1, c1, c1), visfeat::Error);
  EXPECT_THROW(h.setPointGeometry(0, 1, c1, c1, c1), visfeat::Error);
}

TEST(TopologyGraph, ErrorsAndValidation)
{
  const Strip s;
  TopologyGraphParameters p;
  p.dilation_radius = -1;
  EXPECT_THROW(TopologyGraph::build(s.band, s.labels, s.classes, p), visfeat::Error);
  p.dilation_radius = 1001;
  EXPECT_THROW(TopologyGraph::build(s.band, s.labels, s.classes, p), visfeat::Error);
  p.dilation_radius = 1000;
  EXPECT_NO_THROW(TopologyGraph::build(s.band, s.labels, s.classes, p));
  p.dilation_radius = 2;
  std::vector<std::uint32_t> short_labels(s.labels.begin(), s.labels.end() - 1);
  EXPECT_THROW(TopologyGraph::build(s.band, short_labels, s.classes, p),
               visfeat::Error);
  std::vector<std::uint32_t> bad_labels = s.labels;
  bad_labels[3] = 5;
  EXPECT_THROW(TopologyGraph::build(s.band, bad_labels, s.classes, p), visfeat::Error);
  std::vector<FeatureClass> bad_classes = s.classes;
  bad_classes[1] = static_cast<FeatureClass>(7);
  EXPECT_THROW(TopologyGraph::build(s.band, s.labels, bad_classes, p), visfeat::Error);

  const TopologyGraph g = TopologyGraph::build(s.band, s.labels, s.classes, p);
  EXPECT_THROW(g.node(0), visfeat::Error);
  EXPECT_THROW(g.node(5), visfeat::Error);
  EXPECT_THROW(g.neighbours(99), visfeat::Error);
  EXPECT_THROW(g.neighbours(0, kE), visfeat::Error);
  EXPECT_THROW(g.adjacent(1, 9), visfeat::Error);
  EXPECT_THROW(g.edgesOfFace(2), visfeat::Error);    // an edge, not a face
  EXPECT_THROW(g.verticesOfEdge(1), visfeat::Error); // a face
  EXPECT_THROW(g.facesOfEdge(4), visfeat::Error);    // a vertex
  EXPECT_THROW(g.edgesOfFace(42), visfeat::Error);
  try {
    g.node(5);
  } catch (const visfeat::Error& e) {
    EXPECT_NE(std::string(e.what()).find("5"), std::string::npos) << e.what();
  }

  // No regions at all: an empty graph.
  const TopologyGraph empty =
    TopologyGraph::build(s.band, std::vector<std::uint32_t>(s.band.size(), 0), {}, p);
  EXPECT_TRUE(empty.empty());
  EXPECT_EQ(empty.arcCount(), 0u);
  const Json j = parseJson(jsonOf(empty));
  EXPECT_TRUE(j.at("nodes").is_array() && j.at("nodes").empty());
  EXPECT_TRUE(j.at("arcs").is_array() && j.at("arcs").empty());
  EXPECT_NE(dotOf(empty).find("graph"), std::string::npos);
}

TEST(TopologyGraph, EdgeKeepsOnlyFacesAlongItsLength)
{
  GridSpec grid;
  grid.dims = Eigen::Vector3i(40, 20, 3);
  std::vector<visfeat::CellCoord> cells;
  for (int y = 0; y <= 10; ++y)
    for (int x = 0; x <= 20; ++x)
      cells.emplace_back(x, y, 1);
  for (int y = 4; y <= 6; ++y) // C: a patch right of the edge's end
    for (int x = 21; x <= 25; ++x)
      cells.emplace_back(x, y, 1);
  const VoxelBand band = VoxelBand::fromCells(grid, cells, VoxelBand::Options{false});
  // labels: 1 = A (y < 5), 2 = edge (y == 5, x <= 20), 3 = B (y > 5), 4 = C (x > 20)
  std::vector<std::uint32_t> labels(band.size(), 0);
  for (std::size_t i = 0; i < band.size(); ++i) {
    const visfeat::CellCoord& c = band.coord(static_cast<visfeat::CellId>(i));
    labels[i] = c.x() > 20 ? 4u : (c.y() < 5 ? 1u : (c.y() == 5 ? 2u : 3u));
  }
  const std::vector<FeatureClass> classes{FeatureClass::kFace, FeatureClass::kEdge,
                                          FeatureClass::kFace, FeatureClass::kFace};
  TopologyGraphParameters p;
  p.dilation_radius = 2;
  const TopologyGraph filtered = TopologyGraph::build(band, labels, classes, p);
  EXPECT_EQ(filtered.facesOfEdge(2), (std::vector<std::uint32_t>{1, 3}));
  p.min_face_contact = 0.0;
  p.max_edge_faces = 0;
  const TopologyGraph literal = TopologyGraph::build(band, labels, classes, p);
  EXPECT_EQ(literal.facesOfEdge(2), (std::vector<std::uint32_t>{1, 3, 4}));
  p.min_face_contact = 1.5;
  EXPECT_THROW(TopologyGraph::validate(p), visfeat::Error);
}

TEST(TopologyGraph, AnEdgeKeepsTheTwoFacesItTouchesMost)
{
  // A strip x = 0..19, y = 0..10: the edge (y == 5) between faces A (y < 5) and B
  // (y > 5); a third face C holds the two rows next to the edge on A's side for
  // x >= 12 (as a face that leaked around a corner does), reaching past the fair share
  // of contact: B 2 rows x 20, A 2 x 12, C 2 x 8.
  GridSpec grid;
  grid.dims = Eigen::Vector3i(40, 20, 3);
  std::vector<visfeat::CellCoord> cells;
  for (int y = 0; y <= 10; ++y)
    for (int x = 0; x <= 19; ++x)
      cells.emplace_back(x, y, 1);
  const VoxelBand band = VoxelBand::fromCells(grid, cells, VoxelBand::Options{false});
  std::vector<std::uint32_t> labels(band.size(), 0);
  for (std::size_t i = 0; i < band.size(); ++i) {
    const visfeat::CellCoord& c = band.coord(static_cast<visfeat::CellId>(i));
    labels[i] = c.y() == 5                                    ? 2u
                : (c.x() >= 12 && (c.y() == 3 || c.y() == 4)) ? 4u
                : c.y() < 5                                   ? 1u
                                                              : 3u;
  }
  const std::vector<FeatureClass> classes{FeatureClass::kFace, FeatureClass::kEdge,
                                          FeatureClass::kFace, FeatureClass::kFace};
  TopologyGraphParameters p;
  p.dilation_radius = 2;
  EXPECT_EQ(p.max_edge_faces, 2);
  const TopologyGraph two = TopologyGraph::build(band, labels, classes, p);
  EXPECT_EQ(two.facesOfEdge(2), (std::vector<std::uint32_t>{1, 3}));
  p.max_edge_faces = 0; // no limit: C too, it passes the fair share
  const TopologyGraph any = TopologyGraph::build(band, labels, classes, p);
  EXPECT_EQ(any.facesOfEdge(2), (std::vector<std::uint32_t>{1, 3, 4}));
  p.max_edge_faces = 1; // the one it touches most
  const TopologyGraph one = TopologyGraph::build(band, labels, classes, p);
  EXPECT_EQ(one.facesOfEdge(2), (std::vector<std::uint32_t>{3}));
  p.max_edge_faces = -1;
  EXPECT_THROW(TopologyGraph::validate(p), visfeat::Error);
}

} // namespace
