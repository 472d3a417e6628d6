#pragma once

#include <visfeat/core/band/voxel_band.h>

#include <cstdint>
#include <functional>
#include <vector>

namespace visfeat {

/** \brief Visible when nothing is blocked, or the blocked length stays below opacity.
 */
inline bool
isVisible(double blocked_length, double opacity)
{
  return blocked_length <= 0.0 || blocked_length < opacity;
}

/** \brief The eroded occluder as a bit-packed mask of 2x2x2 subcells, stored sparse.
 *
 * Every cell is split into 2x2x2 subcells. A subcell is free when it belongs to a mixed
 * cell or touches such a subcell by a face, edge or corner; the rest of space (outside
 * the grid too) is the occluder eroded by half a cell (the paper's O (-) C). Two mixed
 * cells see each other when the segment between their centres does not pass through
 * the interior of the occluder (see SegmentStretch for the open-occluder rule), or,
 * with an opacity, when the blocked stretches add up to less than the opacity.
 *
 * Cell centres are subcell-grid vertices: the centre of cell c is the lattice point
 * 2c + 1 in subcell units, so the test is exact.
 *
 * Storage: bricks of kBrickCells^3 cells (kBrickSide^3 subcells), one byte a cell
 * (bit sx + 2 sy + 4 sz for its subcell (sx, sy, sz), each 0 or 1), 512 bytes a
 * brick, allocated only where a mixed cell frees a subcell, kept sorted by brick key.
 * A byte a cell lets the segment test read all the subcells it needs in one cell with
 * one load (SegmentTable).
 * Memory follows the band (a surface), not the grid: about 12 bytes per mixed cell
 * on the generated models (see visfeat_benchmark), and no per-grid table. A missing
 * brick is all occluded. The visibility map reads it through FreeSpaceWindow, a
 * dense copy of the bricks around one brick of sources.
 */
class FreeSpace
{
public:
  /** \brief Cells a brick side. */
  static constexpr int kBrickCells = 8;
  /** \brief Subcells a brick side. */
  static constexpr int kBrickSide = 2 * kBrickCells;
  /** \brief Bytes a brick: one per cell, index x + 8 y + 64 z (brick-local cells). */
  static constexpr int kBrickBytes = kBrickCells * kBrickCells * kBrickCells;

  /** \brief Bit of subcell s within its cell's byte: (s.x & 1) + 2 (s.y & 1) + 4 (s.z
   * & 1). */
  static int subcellBit(const Eigen::Vector3i& s)
  {
    return (s.x() & 1) | ((s.y() & 1) << 1) | ((s.z() & 1) << 2);
  }

  /** \brief Called with the exact bytes the mask will hold, before they are
   * allocated; it may throw to refuse them (a memory check). */
  using BeforeAllocating = std::function<void(std::uint64_t bytes)>;

  FreeSpace() = default;
  /** \brief The mask of a band; before_allocating, if given, is called once the
   * bricks are counted and before they are allocated. */
  explicit FreeSpace(const VoxelBand& band,
                     const BeforeAllocating& before_allocating = {});

  /** \brief Exact bytes FreeSpace(band) will hold, counted from the band (the same
   * count FreeSpace(band) makes: to check memory while building, pass
   * before_allocating instead of counting twice). */
  static std::uint64_t estimateBytes(const VoxelBand& band);

  /** \brief Subcells per axis (twice the grid's dims). */
  const Eigen::Vector3i& dims() const { return dims_; }

  /** \brief Bricks per axis (the grid's dims / 8, rounded up). */
  const Eigen::Vector3i& brickDims() const { return brick_dims_; }

  /** \brief Whether subcell s is free; everything outside the mask is occluded.
   * O(log bricks): for tests and single queries; the map uses FreeSpaceWindow. */
  bool isFree(const Eigen::Vector3i& s) const;

  /** \brief The kBrickBytes cell bytes (index x + 8 y + 64 z in brick-local cells,
   * bits as subcellBit) of the brick at brick coordinates b (cell c lies in brick
   * c / 8), or nullptr when none is allocated (all occluded, also outside the grid). */
  const std::uint8_t* brickCells(const Eigen::Vector3i& b) const;

  /** \brief The lattice point (subcell units) at the centre of cell c. */
  static Eigen::Vector3i centre(const CellCoord& c)
  {
    return 2 * c + Eigen::Vector3i::Ones();
  }

  /** \brief Total length, in cell edges, of the stretches of the segment between the
   * centres of a and b that run through the interior of the occluder. */
  double blockedLength(const CellCoord& a, const CellCoord& b) const;

  /** \brief Whether cells a and b see each other with the given opacity (cell edges).
   */
  bool sees(const CellCoord& a, const CellCoord& b, double opacity = 0.0) const
  {
    return isVisible(blockedLength(a, b), opacity);
  }

  /** \brief Allocated bricks. */
  std::size_t brickCount() const { return brick_keys_.size(); }

  /** \brief Bytes held (bricks and their keys). */
  std::uint64_t memoryBytes() const;

private:
  /** Slot of the brick with this key (linearKey over brickDims()), or -1. */
  std::int64_t findBrick(std::uint64_t key) const;

  Eigen::Vector3i dims_{0, 0, 0};
  Eigen::Vector3i brick_dims_{0, 0, 0};
  std::vector<std::uint64_t> brick_keys_; // sorted
  std::vector<std::uint8_t> cells_;       // kBrickBytes per brick, brick_keys_ order
};

} // namespace visfeat
