#include <visfeat/core/band/band_dilation.h>
#include <visfeat/core/common/error.h>
#include <visfeat/core/graph/edge_bridges.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>

namespace visfeat {
namespace {

/** Fewest cells of an edge region that qualifies (a line through fewer is noise). */
constexpr std::size_t kMinBridgedEdgeCells = 8;

/** Cells of an edge's free end: within this distance of the end along its line. */
constexpr double kEndCells = 2.0;

Eigen::Vector3d
centreOf(const VoxelBand& band, CellId c)
{
  return band.coord(c).cast<double>() + Eigen::Vector3d::Constant(0.5);
}

Eigen::Vector3d
meanOf(const VoxelBand& band, const std::vector<CellId>& cells)
{
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const CellId c : cells)
    sum += centreOf(band, c);
  return sum / static_cast<double>(cells.size());
}

bool
contains(const std::vector<std::uint32_t>& list, std::uint32_t x)
{
  return std::find(list.begin(), list.end(), x) != list.end();
}

/** Per band cell, whether it lies within `steps` 6-steps of a cell of `cells` (through
 * any band cells). */
std::vector<char>
withinSteps(const VoxelBand& band, const std::vector<CellId>& cells, int steps)
{
  std::vector<char> near(band.size(), 0);
  BandDilation(band).run(cells, static_cast<std::uint32_t>(steps),
                         [&](CellId c) { near[static_cast<std::size_t>(c)] = 1; });
  return near;
}

/** Shortest path of 6-steps from `from` to a cell labelled `target` through cells of
 * face regions, at most max_steps: its face cells in order, or empty. A face cell
 * marked in `ends_near` (within the graph's reach of the target) ends the path too,
 * as its last cell. */
std::vector<CellId>
shortestPath(const VoxelBand& band,
             const std::vector<std::uint32_t>& labels,
             const TopologyGraph& graph,
             const std::vector<CellId>& from,
             std::uint32_t target,
             const std::vector<char>& ends_near,
             int max_steps)
{
  std::vector<CellId> visited(from.begin(), from.end());
  std::vector<int> parent(from.size(), -1);
  std::vector<char> seen(band.size(), 0);
  for (const CellId c : from)
    seen[static_cast<std::size_t>(c)] = 1;
  // the face cells from visited[at] back to (not including) a cell of `from`
  const auto pathTo = [&](std::size_t at) {
    std::vector<CellId> path;
    for (; parent[at] >= 0; at = static_cast<std::size_t>(parent[at]))
      path.push_back(visited[at]);
    std::reverse(path.begin(), path.end());
    return path;
  };
  std::size_t begin = 0;
  for (int step = 0; step < max_steps && begin < visited.size(); ++step) {
    const std::size_t end = visited.size();
    for (std::size_t i = begin; i < end; ++i)
      for (const CellId n : band.neighbours(visited[i])) {
        if (n == kNoCell || seen[static_cast<std::size_t>(n)])
          continue;
        const std::uint32_t label = labels[static_cast<std::size_t>(n)];
        if (label == target)
          return pathTo(i);
        if (label == 0 || label > graph.size() ||
            graph.node(label).feature_class != FeatureClass::kFace)
          continue;
        seen[static_cast<std::size_t>(n)] = 1;
        visited.push_back(n);
        parent.push_back(static_cast<int>(i));
        if (ends_near[static_cast<std::size_t>(n)])
          return pathTo(visited.size() - 1);
      }
    begin = end;
  }
  return {};
}

} // namespace

std::vector<EdgeBridge>
bridgesToCorners(const VoxelBand& band,
                 const std::vector<std::uint32_t>& cell_labels,
                 const TopologyGraph& graph,
                 double max_reach,
                 int reach_steps)
{
  if (reach_steps < 0)
    throw Error("edge bridges: negative reach of the graph");
  if (cell_labels.size() != band.size())
    throw Error("edge bridges: one label per band cell is needed");
  const std::size_t n = graph.size();
  std::vector<std::vector<CellId>> cells_of(n + 1);
  for (std::size_t c = 0; c < cell_labels.size(); ++c)
    if (cell_labels[c] != 0 && cell_labels[c] <= n)
      cells_of[cell_labels[c]].push_back(static_cast<CellId>(c));

  std::vector<EdgeBridge> bridges;
  for (std::uint32_t e = 1; e <= n; ++e) {
    if (graph.node(e).feature_class != FeatureClass::kEdge ||
        cells_of[e].size() < kMinBridgedEdgeCells)
      continue;
    const std::vector<std::uint32_t> vertices = graph.verticesOfEdge(e);
    const std::vector<std::uint32_t> faces = graph.facesOfEdge(e);
    if (vertices.size() != 1 || faces.size() != 2 || cells_of[vertices[0]].empty())
      continue;
    // the edge's line, oriented away from its corner
    const Eigen::Vector3d mean = meanOf(band, cells_of[e]);
    Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
    for (const CellId c : cells_of[e]) {
      const Eigen::Vector3d d = centreOf(band, c) - mean;
      scatter += d * d.transpose();
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(
      scatter / static_cast<double>(cells_of[e].size()));
    const Eigen::Vector3d spread = solver.eigenvalues().cwiseMax(0.0).cwiseSqrt();
    if (spread[1] > kStraightEdgeSpread * spread[2] + kStraightEdgeWidth)
      continue;
    Eigen::Vector3d line = solver.eigenvectors().col(2);
    if (line.dot(mean - meanOf(band, cells_of[vertices[0]])) < 0.0)
      line = -line;
    double end = -std::numeric_limits<double>::infinity();
    for (const CellId c : cells_of[e])
      end = std::max(end, line.dot(centreOf(band, c) - mean));

    // the corner ahead: on the line, else the one vertex of both faces near the end
    std::uint32_t corner = 0, near_end = 0;
    int near_end_count = 0;
    double nearest = std::numeric_limits<double>::infinity();
    for (std::uint32_t v = 1; v <= n; ++v) {
      if (v == vertices[0] || graph.node(v).feature_class != FeatureClass::kVertex ||
          cells_of[v].empty())
        continue;
      const std::vector<std::uint32_t> v_faces =
        graph.neighbours(v, FeatureClass::kFace);
      if (!contains(v_faces, faces[0]) || !contains(v_faces, faces[1]))
        continue;
      const Eigen::Vector3d to = meanOf(band, cells_of[v]) - mean;
      const double along = line.dot(to) - end;
      const double lateral = (to - line.dot(to) * line).norm();
      if (along <= 0.0)
        continue;
      if (along <= max_reach && lateral <= kBridgeLateralCells + 0.25 * along &&
          along < nearest) {
        nearest = along;
        corner = v;
      }
      if (std::hypot(along, lateral) <= kBridgeOffLineShare * max_reach) {
        near_end = v;
        ++near_end_count;
      }
    }
    if (corner == 0 && near_end_count == 1)
      corner = near_end;
    if (corner == 0)
      continue;
    std::vector<CellId> end_cells;
    for (const CellId c : cells_of[e])
      if (line.dot(centreOf(band, c) - mean) >= end - kEndCells)
        end_cells.push_back(c);
    const int max_steps =
      static_cast<int>(std::ceil(std::sqrt(3.0) * (max_reach + 3.0))) + 3;
    std::vector<CellId> path =
      shortestPath(band, cell_labels, graph, end_cells, corner,
                   withinSteps(band, cells_of[corner], reach_steps), max_steps);
    if (!path.empty())
      bridges.push_back(EdgeBridge{e, corner, std::move(path)});
  }
  return bridges;
}

} // namespace visfeat
