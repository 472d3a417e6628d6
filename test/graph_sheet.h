#pragma once

// A flat sheet of band cells painted with region labels, and its topology graph, for
// the unit tests of the graph's merge rules (stray regions, open faces). Header-only,
// no PCL.

#include <visfeat/core/band/voxel_band.h>
#include <visfeat/core/common/feature_class.h>
#include <visfeat/core/graph/topology_graph.h>

#include <cstdint>
#include <functional>
#include <numeric>
#include <vector>

namespace visfeat_test {

using Labels = std::vector<std::uint32_t>;

/** \brief Cells z = 2, x and y in [0, side), labelled by `label` (x, y) (region
 * labels from 1, classes[label - 1] their classes), and their graph with the default
 * parameters but the dilation radius. */
struct LabelledSheet
{
  visfeat::VoxelBand band;
  Labels labels;
  visfeat::TopologyGraph graph;

  LabelledSheet(
    const std::vector<visfeat::FeatureClass>& classes,
    const std::function<std::uint32_t(int x, int y)>& label,
    int dilation_radius = visfeat::TopologyGraphParameters::kDefaultDilationRadius,
    int side = 40)
  {
    visfeat::GridSpec grid;
    grid.origin = Eigen::Vector3d(-1.0, 0.5, 2.0);
    grid.cell_size = 0.25;
    grid.dims = Eigen::Vector3i(side, side, 6);
    std::vector<visfeat::CellCoord> cells;
    for (int y = 0; y < side; ++y)
      for (int x = 0; x < side; ++x)
        cells.emplace_back(x, y, 2);
    visfeat::VoxelBand::Options options;
    options.repair = false;
    band = visfeat::VoxelBand::fromCells(grid, cells, options);
    labels.resize(band.size());
    for (std::size_t i = 0; i < band.size(); ++i) {
      const visfeat::CellCoord& c = band.coord(static_cast<visfeat::CellId>(i));
      labels[i] = label(c.x(), c.y());
    }
    visfeat::TopologyGraphParameters parameters;
    parameters.dilation_radius = dilation_radius;
    graph = visfeat::TopologyGraph::build(band, labels, classes, parameters);
  }
};

/** \brief The merge that keeps every one of `regions` labels: into[l] = l. */
inline Labels
identity(std::size_t regions)
{
  Labels into(regions + 1);
  std::iota(into.begin(), into.end(), 0u);
  return into;
}

/** \brief Whether lo <= v <= hi. */
inline bool
in(int v, int lo, int hi)
{
  return v >= lo && v <= hi;
}

} // namespace visfeat_test
