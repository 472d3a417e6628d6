#pragma once

// Small bands, labels and helpers shared by the TopologyGraph tests
// (test_topology_graph.cpp: arcs and geometry; test_topology_graph_export.cpp: DOT,
// JSON and files).

#include "band_fixtures.h"

#include <visfeat/core/band/voxel_band.h>
#include <visfeat/core/common/feature_class.h>
#include <visfeat/core/graph/topology_graph.h>

#include <nlohmann/json.hpp>

#include <functional>
#include <queue>
#include <sstream>
#include <string>
#include <vector>

namespace visfeat_test {
namespace graph {

using visfeat::CellCoord;
using visfeat::CellId;
using visfeat::FeatureClass;
using visfeat::GraphMetadata;
using visfeat::GraphNode;
using visfeat::GridSpec;
using visfeat::kNoCell;
using visfeat::TopologyGraph;
using visfeat::TopologyGraphParameters;
using visfeat::VoxelBand;
using Arcs = std::vector<std::pair<std::uint32_t, std::uint32_t>>;
using Ids = std::vector<std::uint32_t>;

inline constexpr FeatureClass kV = FeatureClass::kVertex;
inline constexpr FeatureClass kE = FeatureClass::kEdge;
inline constexpr FeatureClass kF = FeatureClass::kFace;

/** A grid with a non-trivial origin and cell size. */
inline GridSpec
testGrid(int nx = 40, int ny = 16, int nz = 16)
{
  GridSpec grid;
  grid.origin = Eigen::Vector3d(-1.5, 2.0, 0.25);
  grid.cell_size = 0.5;
  grid.dims = Eigen::Vector3i(nx, ny, nz);
  return grid;
}

inline VoxelBand
bandOf(const GridSpec& grid, const std::vector<CellCoord>& cells)
{
  VoxelBand::Options options;
  options.repair = false;
  return VoxelBand::fromCells(grid, cells, options);
}

/** Per cell of the band, the label the function gives its coordinates. */
inline std::vector<std::uint32_t>
labelBand(const VoxelBand& band,
          const std::function<std::uint32_t(const CellCoord&)>& f)
{
  std::vector<std::uint32_t> labels(band.size());
  for (std::size_t i = 0; i < band.size(); ++i)
    labels[i] = f(band.coord(static_cast<CellId>(i)));
  return labels;
}

inline TopologyGraph
buildGraph(const VoxelBand& band,
           const std::vector<std::uint32_t>& labels,
           const std::vector<FeatureClass>& classes,
           int radius)
{
  TopologyGraphParameters p;
  p.dilation_radius = radius;
  // The literal dilation rule; the contact filter and the vertex-face rule have their
  // own tests.
  p.min_face_contact = 0.0;
  p.max_edge_faces = 0;
  p.vertex_faces_from_edges = false;
  return TopologyGraph::build(band, labels, classes, p);
}

// --- Fixtures ------------------------------------------------------------------

/** An L-shaped one-cell strip: V4 | F1 | E2 | F3, F3 turning up in y at its end.
 *  x = 2..3 V4, 4..9 F1, 10..11 E2, 12..19 F3 (y = 2, z = 2); (19, 3..6, 2) F3. */
struct Strip
{
  GridSpec grid = testGrid();
  VoxelBand band;
  std::vector<std::uint32_t> labels;
  std::vector<FeatureClass> classes{kF, kE, kF, kV};

  Strip()
  {
    std::vector<CellCoord> cells;
    for (int x = 2; x <= 19; ++x)
      cells.emplace_back(x, 2, 2);
    for (int y = 3; y <= 6; ++y)
      cells.emplace_back(19, y, 2);
    band = bandOf(grid, cells);
    labels = labelBand(band, [](const CellCoord& c) -> std::uint32_t {
      if (c.x() <= 3)
        return 4;
      if (c.x() <= 9)
        return 1;
      if (c.x() <= 11)
        return 2;
      return 3;
    });
  }
};

/** A sheet z = 2, x 2..15, y 2..9, with complete regions:
 *  F1 below the row y = 5, F3 above it; E2 the row y = 5 for x <= 10; V4 the block
 *  x 11..12, y 4..6; V5 the column x = 13, y 4..6; for x >= 14 the faces touch
 *  directly (F1 takes y = 5). Label 6 is an edge with no cells. */
struct Sheet
{
  GridSpec grid = testGrid();
  VoxelBand band;
  std::vector<std::uint32_t> labels;
  std::vector<FeatureClass> classes{kF, kE, kF, kV, kV, kE};

  Sheet()
  {
    std::vector<CellCoord> cells;
    for (int y = 2; y <= 9; ++y)
      for (int x = 2; x <= 15; ++x)
        cells.emplace_back(x, y, 2);
    band = bandOf(grid, cells);
    labels = labelBand(band, [](const CellCoord& c) -> std::uint32_t {
      const int x = c.x(), y = c.y();
      if (x >= 11 && x <= 12 && y >= 4 && y <= 6)
        return 4;
      if (x == 13 && y >= 4 && y <= 6)
        return 5;
      if (y == 5 && x <= 10)
        return 2;
      if (y < 5 || (y == 5 && x >= 14))
        return 1;
      return 3;
    });
  }
};

/** A JSON text parsed strictly (RFC 8259) by nlohmann-json; throws on bad syntax. */
using Json = nlohmann::json;

inline Json
parseJson(const std::string& s)
{
  return Json::parse(s);
}

// --- Brute force ---------------------------------------------------------------

/** Arcs by definition: full BFS from every region, pair joined iff the geodesic
 * distance between the regions is at most radius and the classes form a wanted pair. */
inline Arcs
bruteForceArcs(const VoxelBand& band,
               const std::vector<std::uint32_t>& labels,
               const std::vector<FeatureClass>& classes,
               int radius)
{
  const auto rank = [](FeatureClass c) {
    return c == kV ? 0 : c == kE ? 1 : c == kF ? 2 : -1;
  };
  Arcs arcs;
  for (std::uint32_t a = 1; a <= classes.size(); ++a) {
    std::vector<int> dist(band.size(), -1);
    std::queue<CellId> queue;
    for (std::size_t i = 0; i < band.size(); ++i)
      if (labels[i] == a) {
        dist[i] = 0;
        queue.push(static_cast<CellId>(i));
      }
    while (!queue.empty()) {
      const CellId c = queue.front();
      queue.pop();
      for (const CellId nb : band.neighbours(c))
        if (nb != kNoCell && dist[static_cast<std::size_t>(nb)] < 0) {
          dist[static_cast<std::size_t>(nb)] = dist[static_cast<std::size_t>(c)] + 1;
          queue.push(nb);
        }
    }
    for (std::uint32_t b = a + 1; b <= classes.size(); ++b) {
      const int ra = rank(classes[a - 1]), rb = rank(classes[b - 1]);
      if (ra < 0 || rb < 0 || ra == rb)
        continue;
      bool near = false;
      for (std::size_t i = 0; i < band.size() && !near; ++i)
        near = labels[i] == b && dist[i] >= 0 && dist[i] <= radius;
      if (near)
        arcs.emplace_back(a, b);
    }
  }
  return arcs;
}

inline std::string
jsonOf(const TopologyGraph& g, const GraphMetadata& meta = {})
{
  std::ostringstream s;
  g.writeJson(s, meta);
  return s.str();
}

inline std::string
dotOf(const TopologyGraph& g)
{
  std::ostringstream s;
  g.writeDot(s);
  return s.str();
}

} // namespace graph
} // namespace visfeat_test
