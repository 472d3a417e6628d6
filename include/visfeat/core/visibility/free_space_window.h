#pragma once

#include <visfeat/core/visibility/free_space.h>

#include <cstdint>
#include <vector>

namespace visfeat {

/** \brief A dense copy of the free-space bricks around one brick of cells.
 *
 * The visibility map works brick by brick (8^3 cells, a "tile"): the sources of one
 * tile test targets at most max_radius cells away, so every subcell they read lies in
 * the cube of bricksFor(max_radius) bricks a side centred on the tile's brick. The
 * window copies that cube from the sparse FreeSpace once per tile (missing bricks are
 * occluded), so the pair tests read one small dense array (64 KiB for a cap of 9-16
 * rings) at fixed strides, with 32-bit offsets precomputed in SegmentTable.
 *
 * Layout: bit i = x + strideY() y + strideZ() z in window-local subcells, stored as
 * 16-bit rows (one per brick column and (y, z)).
 */
class FreeSpaceWindow
{
public:
  /** \brief Bricks a side so that sources in the middle brick reach every subcell of
   * a segment to a cell up to max_distance cells away: 1 + 2 ceil(2 max_distance / 16).
   */
  static int bricksFor(int max_distance)
  {
    return 1 +
           2 * ((2 * max_distance + FreeSpace::kBrickSide - 1) / FreeSpace::kBrickSide);
  }

  /** \brief An empty (all occluded) window of bricks_per_side^3 bricks (odd, >= 1). */
  explicit FreeSpaceWindow(int bricks_per_side = 1);

  /** \brief Copy the bricks centred on brick `centre` (brick coordinates). */
  void load(const FreeSpace& free_space, const Eigen::Vector3i& centre);

  int bricksPerSide() const { return bricks_; }

  std::int32_t strideY() const { return stride_y_; }

  std::int32_t strideZ() const { return stride_z_; }

  /** \brief The absolute subcell of window bit 0. */
  const Eigen::Vector3i& origin() const { return origin_; }

  /** \brief Whether absolute subcell s lies inside the window. */
  bool contains(const Eigen::Vector3i& s) const
  {
    const Eigen::Vector3i l = s - origin_;
    return (l.array() >= 0).all() && (l.array() < side_).all();
  }

  /** \brief Window bit of absolute subcell s (s must lie inside the window). */
  std::int32_t linearIndex(const Eigen::Vector3i& s) const
  {
    const Eigen::Vector3i l = s - origin_;
    return l.x() + stride_y_ * l.y() + stride_z_ * l.z();
  }

  bool isFreeAt(std::int32_t i) const
  {
    return (rows_[static_cast<std::size_t>(i >> 4)] >> (i & 15)) & 1u;
  }

  /** \brief Whether absolute subcell s is free (false outside the window). */
  bool isFree(const Eigen::Vector3i& s) const
  {
    return contains(s) && isFreeAt(linearIndex(s));
  }

  const std::uint16_t* rows() const { return rows_.data(); }

private:
  int bricks_ = 1;
  int side_ = FreeSpace::kBrickSide; // subcells a side
  std::int32_t stride_y_ = 0;
  std::int32_t stride_z_ = 0;
  Eigen::Vector3i origin_{0, 0, 0};
  std::vector<std::uint16_t> rows_;
};

} // namespace visfeat
