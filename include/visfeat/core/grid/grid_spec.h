#pragma once

#include <visfeat/core/common/parameters.h>

#include <Eigen/Core>

#include <array>
#include <cstdint>

namespace visfeat {

/** \brief Integer coordinates (i, j, k) of a cell of the grid. */
using CellCoord = Eigen::Vector3i;

/** \brief Linear key of integer coordinates c (each in [0, dims)) in a box of dims, x
 * fastest: sorting by it sorts z-major. For cells, and for bricks of cells. */
inline std::uint64_t
linearKey(const Eigen::Vector3i& c, const Eigen::Vector3i& dims)
{
  return static_cast<std::uint64_t>(c.x()) +
         static_cast<std::uint64_t>(dims.x()) *
           (static_cast<std::uint64_t>(c.y()) +
            static_cast<std::uint64_t>(dims.y()) * static_cast<std::uint64_t>(c.z()));
}

/** \brief The regular grid the band lives in: origin, cell size and dimensions.
 *
 * Cell (i, j, k) spans origin + cell_size * [i, i+1) x [j, j+1) x [k, k+1).
 * A grid made by fromBounds() follows DESIGN.md: cell_size = extent / resolution,
 * where extent is the largest side of the bounding box, and a padding of
 * kPadding cells on every side so that every dilation stays inside the grid.
 */
struct GridSpec
{
  /** \brief Cells of padding around the bounding box on each side. */
  static constexpr int kPadding = 2;
  /** \brief Smallest accepted resolution (cells along the longest side). */
  static constexpr int kMinResolution = 4;
  /** \brief Largest accepted resolution; memory is checked separately. */
  static constexpr int kMaxResolution = 8192;
  /** \brief [kMinResolution, kMaxResolution] cells along the longest side. */
  static constexpr ParameterRange<int> kResolutionRange{kMinResolution, kMaxResolution};
  /** \brief The resolution of DESIGN.md when the caller gives none (the estimator's
   * default; the tool chooses it from the point spacing). */
  static constexpr int kDefaultResolution = 256;

  Eigen::Vector3d origin{0.0, 0.0, 0.0};
  double cell_size = 1.0;
  Eigen::Vector3i dims{0, 0, 0};

  /** \brief The grid of DESIGN.md for the box [min, max] and a resolution.
   * \throws visfeat::Error when the resolution is outside
   * [kMinResolution, kMaxResolution], or the box is empty, a single point or not
   * finite.
   */
  static GridSpec
  fromBounds(const Eigen::Vector3d& min, const Eigen::Vector3d& max, int resolution);

  /** \brief The same grid moved half a cell towards -axis, one cell longer, on each
   * flagged axis: the bounding box's sides on that axis then lie at cell centres. For
   * clouds with a face on a side of their box (axis-aligned parts): on a cell boundary
   * its points, and by rounding a fill's triangles, split between two layers of cells
   * (an unrotated cube of 20,000 points gave 21/30/16; see gridForCloud()). */
  GridSpec withSidesAtCellCentres(const std::array<bool, 3>& axes) const
  {
    GridSpec grid = *this;
    for (int a = 0; a < 3; ++a)
      if (axes[static_cast<std::size_t>(a)]) {
        grid.origin[a] -= 0.5 * cell_size;
        grid.dims[a] += 1;
      }
    return grid;
  }

  /** \brief Number of cells of the grid. */
  std::uint64_t cellCount() const
  {
    return static_cast<std::uint64_t>(dims.x()) * dims.y() * dims.z();
  }

  bool contains(const CellCoord& c) const
  {
    return (c.array() >= 0).all() && (c.array() < dims.array()).all();
  }

  /** \brief Linear key of a cell, x fastest; sorting by it sorts cells z-major. */
  std::uint64_t linearKey(const CellCoord& c) const
  {
    return visfeat::linearKey(c, dims);
  }

  /** \brief The cell of a linear key (the inverse of linearKey()). */
  CellCoord cellOfKey(std::uint64_t key) const
  {
    const auto nx = static_cast<std::uint64_t>(dims.x());
    const auto ny = static_cast<std::uint64_t>(dims.y());
    return CellCoord(static_cast<int>(key % nx), static_cast<int>((key / nx) % ny),
                     static_cast<int>(key / (nx * ny)));
  }

  /** \brief A world point in cell units: (p - origin) / cell_size, so that cell
   * (i, j, k) spans [i, i+1) x [j, j+1) x [k, k+1). */
  Eigen::Vector3d toCellUnits(const Eigen::Vector3d& p) const
  {
    return (p - origin) / cell_size;
  }

  /** \brief The cell holding world point p: on each axis floor((p - origin) /
   * cell_size), i.e. the cell (i, j, k) whose box origin + cell_size * [i, i+1) x
   * [j, j+1) x [k, k+1) contains p. It is the arithmetic of pcl::octree's keys (the
   * octree of buildVoxelBand() uses the grid's origin and cell size, and truncates,
   * which is floor inside the grid), so a point finds the cell the band put it in.
   *
   * Outside the grid: an axis below the grid (or a NaN coordinate) gives -1, an axis
   * at or above dims gives dims on that axis, so contains(cellOf(p)) is false exactly
   * when p lies outside the grid or is not finite. No overflow for far points. */
  CellCoord cellOf(const Eigen::Vector3d& p) const
  {
    CellCoord c;
    for (int a = 0; a < 3; ++a) {
      const double u = (p[a] - origin[a]) / cell_size;
      if (!(u >= 0.0))
        c[a] = -1; // below the grid, or NaN
      else if (u >= dims[a])
        c[a] = dims[a];
      else
        c[a] = static_cast<int>(u); // truncation = floor for u >= 0
    }
    return c;
  }

  /** \brief World position of the centre of a cell. */
  Eigen::Vector3d cellCenter(const CellCoord& c) const
  {
    return origin + cell_size * (c.cast<double>().array() + 0.5).matrix();
  }
};

} // namespace visfeat
