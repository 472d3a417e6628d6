#pragma once

#include <visfeat/core/grid/grid_spec.h>

#include <array>
#include <cstdint>
#include <vector>

namespace visfeat {

/** \brief Index of a mixed cell in a VoxelBand: 0 .. size()-1, or kNoCell. */
using CellId = std::int32_t;
constexpr CellId kNoCell = -1;

/** \brief O(1) map from cell coordinates to cell ids, sparse in bricks of 8^3 cells.
 *
 * A dense table over the bricks of the grid points at 512-entry blocks that are
 * allocated only where a cell is inserted, so memory follows the band (a surface),
 * not the volume: a 1024^3 grid costs 8 MiB of table plus 2 KiB per touched brick.
 * No tree descent, no hashing: two loads per lookup.
 */
class CellIndex
{
public:
  CellIndex() = default;
  explicit CellIndex(const Eigen::Vector3i& dims);

  /** \brief Bytes the index would need for a grid of these dimensions before any
   * brick is allocated. */
  static std::uint64_t tableBytes(const Eigen::Vector3i& dims);

  /** \brief Map c to id (c must lie inside the grid). */
  void insert(const CellCoord& c, CellId id);

  /** \brief Allocates the bricks of these cells (all inside the grid) at once, before
   * they are inserted: one allocation instead of a growing block list (the generated
   * icosahedron at 256 holds about 9,000 bricks, 18 MiB). Ids stay kNoCell until
   * inserted; finds are unchanged. Inserts into allocated bricks allocate nothing,
   * so inserts of distinct cells may then run on several threads. */
  void allocateBricks(const std::vector<CellCoord>& cells);

  /** \brief The id of c, or kNoCell when c is outside the grid or not inserted. */
  CellId find(const CellCoord& c) const
  {
    if (!((c.array() >= 0).all() && (c.array() < dims_.array()).all()))
      return kNoCell;
    const std::int32_t brick = brick_slot_[brickOf(c)];
    if (brick < 0)
      return kNoCell;
    return cells_[static_cast<std::size_t>(brick) * kBrickCells + offsetInBrick(c)];
  }

  /** \brief The ids of the 3x3x3 block around c (c inside the grid): out[(z + 1) * 9
   * + (y + 1) * 3 + (x + 1)] = find(c + (x, y, z)). One brick lookup where the block
   * lies in c's brick (a cell 1..6 from its brick's corner on every axis, 42% of
   * them), 27 finds otherwise. */
  void neighbourhood(const CellCoord& c, std::array<CellId, 27>& out) const;

  std::uint64_t memoryBytes() const;

private:
  static constexpr int kBrickShift = 3; // 8 cells a side
  static constexpr int kBrickMask = (1 << kBrickShift) - 1;
  static constexpr std::size_t kBrickCells = 1u << (3 * kBrickShift);

  std::size_t brickOf(const CellCoord& c) const
  {
    return static_cast<std::size_t>(
      linearKey(c.unaryExpr([](int v) { return v >> kBrickShift; }), brick_dims_));
  }

  static std::size_t offsetInBrick(const CellCoord& c)
  {
    return static_cast<std::size_t>(c.x() & kBrickMask) |
           (static_cast<std::size_t>(c.y() & kBrickMask) << kBrickShift) |
           (static_cast<std::size_t>(c.z() & kBrickMask) << (2 * kBrickShift));
  }

  Eigen::Vector3i dims_{0, 0, 0};
  Eigen::Vector3i brick_dims_{0, 0, 0};
  std::vector<std::int32_t> brick_slot_; // per brick: block number in cells_, or -1
  std::vector<CellId> cells_;            // kBrickCells ids per allocated brick
};

} // namespace visfeat
