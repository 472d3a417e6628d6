#pragma once

#include <visfeat/core/band/voxel_band.h>

#include <cstdint>
#include <vector>

namespace visfeat {

/** \brief The mixed cells grouped by brick of 8^3 cells ("tiles"), the unit of work of
 * the visibility map: the sources of one tile share one FreeSpaceWindow.
 *
 * Tiles are sorted by brick key (z, then y, then x); cells inside a tile keep the
 * band's order. Memory: 4 bytes a cell plus 16 bytes a tile.
 */
class BandTiles
{
public:
  /** \brief Cells a brick side. */
  static constexpr int kTileSide = 8;

  BandTiles() = default;
  explicit BandTiles(const VoxelBand& band);

  std::size_t size() const { return bricks_.size(); }

  /** \brief Brick coordinates of tile t (cell c lies in brick c / 8). */
  const Eigen::Vector3i& brick(std::size_t t) const { return bricks_[t]; }

  /** \brief Cells of tile t: [cellsBegin(t), cellsEnd(t)). */
  const CellId* cellsBegin(std::size_t t) const { return cells_.data() + begin_[t]; }

  const CellId* cellsEnd(std::size_t t) const { return cells_.data() + begin_[t + 1]; }

  std::size_t cellCount(std::size_t t) const { return begin_[t + 1] - begin_[t]; }

  /** \brief The tile of brick b, or -1 when no mixed cell lies in it. O(log tiles). */
  std::int64_t find(const Eigen::Vector3i& b) const;

  static Eigen::Vector3i brickOf(const CellCoord& c)
  {
    return c.unaryExpr([](int v) { return v >> 3; });
  }

private:
  Eigen::Vector3i brick_dims_{0, 0, 0};
  std::vector<std::uint64_t> keys_; // sorted, one a tile
  std::vector<Eigen::Vector3i> bricks_;
  std::vector<std::size_t> begin_; // size() + 1
  std::vector<CellId> cells_;
};

} // namespace visfeat
