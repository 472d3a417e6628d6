#pragma once

#include <visfeat/core/visibility/free_space.h>

#include <cstdint>
#include <vector>

namespace visfeat {

/** \brief A dense copy of the free-space bricks around one brick of cells.
 *
 * The visibility map works brick by brick (8^3 cells, a "tile"): the sources of one
 * tile test targets at most max_radius cells away, so every cell they read lies in the
 * cube of bricksFor(max_radius) bricks a side centred on the tile's brick. The window
 * copies that cube from the sparse FreeSpace once per tile (missing bricks are
 * occluded), so the pair tests read one small dense array (40^3 bytes, 62.5 KiB, for
 * a cap of 9-16 rings) at offsets precomputed in SegmentTable.
 *
 * Layout: byte i = x + strideY() y + strideZ() z in window-local cells, bits as
 * FreeSpace::subcellBit.
 */
class FreeSpaceWindow
{
public:
  /** \brief Bricks a side so that sources in the middle brick reach every cell of a
   * segment to a cell up to max_distance cells away: 1 + 2 ceil(max_distance / 8). */
  static int bricksFor(int max_distance)
  {
    return 1 +
           2 * ((max_distance + FreeSpace::kBrickCells - 1) / FreeSpace::kBrickCells);
  }

  /** \brief An empty (all occluded) window of bricks_per_side^3 bricks (odd, 1 to 63).
   * \throws visfeat::Error otherwise. */
  explicit FreeSpaceWindow(int bricks_per_side = 1);

  /** \brief Copy the bricks centred on brick `centre` (brick coordinates). */
  void load(const FreeSpace& free_space, const Eigen::Vector3i& centre);

  int bricksPerSide() const { return bricks_; }

  /** \brief Cells a side. */
  int side() const { return side_; }

  std::int32_t strideY() const { return side_; }

  std::int32_t strideZ() const { return side_ * side_; }

  /** \brief The absolute cell of window byte 0. */
  const CellCoord& origin() const { return origin_; }

  /** \brief Whether absolute cell c lies inside the window. */
  bool contains(const CellCoord& c) const
  {
    const Eigen::Vector3i l = c - origin_;
    return (l.array() >= 0).all() && (l.array() < side_).all();
  }

  /** \brief Window byte of absolute cell c (c must lie inside the window). */
  std::int32_t cellIndex(const CellCoord& c) const
  {
    const Eigen::Vector3i l = c - origin_;
    return l.x() + strideY() * l.y() + strideZ() * l.z();
  }

  /** \brief The free subcells of window byte i (bits as FreeSpace::subcellBit). */
  std::uint8_t freeBits(std::int32_t i) const
  {
    return cells_[static_cast<std::size_t>(i)];
  }

  /** \brief Whether absolute subcell s is free (false outside the window). */
  bool isFree(const Eigen::Vector3i& s) const
  {
    const CellCoord c = s.unaryExpr([](int v) { return v >> 1; });
    return contains(c) && ((freeBits(cellIndex(c)) >> FreeSpace::subcellBit(s)) & 1u);
  }

  const std::uint8_t* cells() const { return cells_.data(); }

private:
  int bricks_ = 1;
  int side_ = FreeSpace::kBrickCells; // cells a side
  CellCoord origin_{0, 0, 0};
  std::vector<std::uint8_t> cells_;
};

} // namespace visfeat
