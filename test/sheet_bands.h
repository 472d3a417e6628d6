#pragma once

// Small hand-made bands with hand-painted visibility radii, for the unit tests of the
// segmentation stages: a flat sheet one cell thick, whose radii come from a picture or
// a function of the cell's position. Header-only, no PCL.

#include <visfeat/core/band/voxel_band.h>
#include <visfeat/core/grid/grid_spec.h>
#include <visfeat/core/segmentation/feature_segmentation.h>
#include <visfeat/core/visibility/visibility_map.h>

#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace visfeat_test {

/** \brief A one-cell-thick sheet: picture cell (x, y) is grid cell (x + 1, y + 1, 1)
 * (a padding of one cell around it). Cell ids follow the grid's order: row by row (y),
 * x fastest, so in a full rectangle of width w, id = x + w * y. */
struct Sheet
{
  visfeat::VoxelBand band;
  visfeat::VisibilityMap map;

  /** \brief The band cell at picture position (x, y); kNoCell where there is none. */
  visfeat::CellId at(int x, int y) const
  {
    return band.find(visfeat::CellCoord(x + 1, y + 1, 1));
  }

  /** \brief Picture position of a band cell. */
  Eigen::Vector2i position(visfeat::CellId c) const
  {
    const visfeat::CellCoord& q = band.coord(c);
    return {q.x() - 1, q.y() - 1};
  }
};

/** \brief A width x height sheet where cell (x, y) has radius radius(x, y) (a
 * negative radius: no cell there). No repair. max_radius: the map's cap. */
inline Sheet
sheetFromRadius(int width,
                int height,
                int max_radius,
                const std::function<int(int x, int y)>& radius)
{
  visfeat::GridSpec grid;
  grid.dims = visfeat::CellCoord(width + 2, height + 2, 3);
  std::vector<visfeat::CellCoord> cells;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      if (radius(x, y) >= 0)
        cells.emplace_back(x + 1, y + 1, 1);
  visfeat::VoxelBand::Options options;
  options.repair = false;
  Sheet sheet{visfeat::VoxelBand::fromCells(grid, cells, options), {}};
  std::vector<std::uint8_t> radii(sheet.band.size());
  for (std::size_t c = 0; c < radii.size(); ++c) {
    const Eigen::Vector2i p = sheet.position(static_cast<visfeat::CellId>(c));
    radii[c] = static_cast<std::uint8_t>(radius(p.x(), p.y()));
  }
  visfeat::VisibilityMap::Parameters parameters;
  parameters.max_radius = max_radius;
  sheet.map = visfeat::VisibilityMap::fromRadii(parameters, std::move(radii));
  return sheet;
}

/** \brief A sheet painted as rows of characters: '0'-'9' a cell with that radius,
 * ' ' no cell. Rows may differ in length. */
inline Sheet
paintSheet(const std::vector<std::string>& rows, int max_radius)
{
  int width = 0;
  for (const std::string& row : rows)
    width = std::max(width, static_cast<int>(row.size()));
  return sheetFromRadius(width, static_cast<int>(rows.size()), max_radius,
                         [&](int x, int y) {
                           const std::string& row = rows[static_cast<std::size_t>(y)];
                           if (x >= static_cast<int>(row.size()) || row[x] == ' ')
                             return -1;
                           if (row[x] < '0' || row[x] > '9')
                             throw std::invalid_argument("bad picture character");
                           return row[x] - '0';
                         });
}

/** \brief Raw-mode segmentation (cores only) of a painted sheet whose cores of radius 3
 * are faces: min_radius 3, no flat-core faces; e.g. two 4 x 4 face cores either side
 * of a valley column, for the tests of the operations that move face cells. */
inline visfeat::FeatureSegmentation
rawFaceCores(const Sheet& sheet)
{
  visfeat::SegmentationParameters p;
  p.raw = true;
  p.components.min_radius = 3;
  p.components.vertex_max_cells = 4;
  p.components.dimensionality = 2.0;
  p.components.face_min_depth = 2;
  p.components.flat_core_faces = false;
  return visfeat::FeatureSegmentation::compute(sheet.band, sheet.map, p);
}

} // namespace visfeat_test
