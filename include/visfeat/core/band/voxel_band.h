#pragma once

#include <visfeat/core/grid/cell_index.h>
#include <visfeat/core/grid/grid_spec.h>

#include <array>
#include <cstdint>
#include <vector>

namespace visfeat {

/** \brief A cell that holds input points, as the PCL edge (or a test) reports it.
 *
 * offset_sum is the sum over the cell's points of their position inside the cell in
 * units of cell_size / kOffsetScale (each point rounded to an integer first), so the
 * centroid is exact and independent of the order in which points were added.
 */
struct OccupiedCell
{
  static constexpr double kOffsetScale = 1 << 16;

  CellCoord coord{0, 0, 0};
  std::uint32_t point_count = 0;
  Eigen::Matrix<std::int64_t, 3, 1> offset_sum{0, 0, 0};
};

/** \brief The discrete band: the mixed cells of a grid, compactly indexed.
 *
 * Cells are numbered 0 .. size()-1 in increasing GridSpec::linearKey order, so ids do
 * not depend on the order of the input points. Each cell knows its six face
 * neighbours in the band (kNoCell where the neighbour is not mixed), ordered
 * -x, +x, -y, +y, -z, +z.
 *
 * The repair step (Options::repair, on by default) makes the band 6-connected where
 * the points only made it 26-connected. For every pair of mixed cells that touch by an
 * edge (box 2x2x1) or a corner (box 2x2x2) but are not joined by a face path inside
 * their box, it adds the fewest cells of that box that join them, choosing the cells
 * closest to the centroid of the pair's points. Cells it adds are repaired in turn, so
 * afterwards every 26-adjacent pair of the band is 6-connected within its box. Added
 * cells hold no points.
 */
class VoxelBand
{
public:
  struct Options
  {
    /** \brief Add cells so that 26-adjacent mixed cells are 6-connected. */
    bool repair = true;
    /** \brief Threads for the parallel steps (building from a cloud, adjacency,
     * point cells); 0 (default) = all available. The band does not depend on it. */
    int threads = 0;
  };

  using Neighbours = std::array<CellId, 6>;

  VoxelBand() = default;

  /** \brief Build the band from the cells that hold points.
   * \param[in] grid the grid (see GridSpec::fromBounds)
   * \param[in] occupied one entry per cell holding points, any order, no duplicates;
   *            every coordinate must lie inside the grid
   * \param[in] point_occupied per input point, its entry in occupied (-1 = skipped,
   *            e.g. NaN); stored as pointCell() after renumbering
   * \param[in] options see Options
   * \param[in] fill cells of the surface between the points (a rasterised mesh or
   *            local triangles, see triangle_cells.h): those not in occupied join the
   *            band without points (fillCellCount()), before the repair; any order,
   *            duplicates allowed, every coordinate inside the grid
   * \throws visfeat::Error when occupied and fill are both empty, occupied holds
   *         duplicates, or a coordinate lies outside the grid.
   */
  static VoxelBand build(const GridSpec& grid,
                         std::vector<OccupiedCell> occupied,
                         const std::vector<std::int32_t>& point_occupied,
                         const Options& options,
                         const std::vector<CellCoord>& fill = {});

  /** \brief Same, from bare cell coordinates (one point each, at the centre). */
  static VoxelBand fromCells(const GridSpec& grid,
                             const std::vector<CellCoord>& cells,
                             const Options& options);

  const GridSpec& grid() const { return grid_; }

  /** \brief Number of mixed cells (repair cells included). */
  std::size_t size() const { return coords_.size(); }

  bool empty() const { return coords_.empty(); }

  const CellCoord& coord(CellId id) const
  {
    return coords_[static_cast<std::size_t>(id)];
  }

  const std::vector<CellCoord>& coords() const { return coords_; }

  const Neighbours& neighbours(CellId id) const
  {
    return neighbours_[static_cast<std::size_t>(id)];
  }

  /** \brief O(1): the id of the mixed cell at c, or kNoCell. */
  CellId find(const CellCoord& c) const { return index_.find(c); }

  /** \brief Points that fell into the cell (0 for cells added by the repair). */
  std::uint32_t pointCount(CellId id) const
  {
    return point_counts_[static_cast<std::size_t>(id)];
  }

  /** \brief Per input point, the id of its cell, or kNoCell for skipped points. */
  const std::vector<CellId>& pointCell() const { return point_cell_; }

  /** \brief Cells added by the repair step. */
  std::size_t repairCellCount() const { return repair_cells_; }
  /** \brief Cells that came from the fill (build()'s `fill`) and hold no point. */
  std::size_t fillCellCount() const { return fill_cells_; }

  /** \brief How far the points scatter about the surface, cells (bandRoughness() of
   * the occupied cells, measured by build()); -1 when not measured (too few points a
   * cell, or a band made by fromCells()). */
  double roughness() const { return roughness_; }

  /** \brief Bytes held by the band (cells, neighbours, index, point map). */
  std::uint64_t memoryBytes() const;

  /** \brief Estimate of memoryBytes() before building, for memory checks. */
  static std::uint64_t
  estimateBytes(const GridSpec& grid, std::size_t cells, std::size_t points);

private:
  void finalize(std::vector<CellCoord> coords,
                std::vector<std::uint32_t> counts,
                int threads);

  GridSpec grid_;
  std::vector<CellCoord> coords_;
  std::vector<std::uint32_t> point_counts_;
  std::vector<Neighbours> neighbours_;
  std::vector<CellId> point_cell_;
  CellIndex index_;
  std::size_t repair_cells_ = 0;
  std::size_t fill_cells_ = 0;
  double roughness_ = -1.0;
};

} // namespace visfeat
