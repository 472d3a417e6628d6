#include <visfeat/core/grid/cell_index.h>

namespace visfeat {

CellIndex::CellIndex(const Eigen::Vector3i& dims)
    : dims_(dims)
{
  brick_dims_ = (dims.array() + kBrickMask) / (kBrickMask + 1);
  brick_slot_.assign(
    static_cast<std::size_t>(brick_dims_.x()) * brick_dims_.y() * brick_dims_.z(), -1);
}

std::uint64_t
CellIndex::tableBytes(const Eigen::Vector3i& dims)
{
  const Eigen::Vector3i bricks = (dims.array() + kBrickMask) / (kBrickMask + 1);
  return static_cast<std::uint64_t>(bricks.x()) * bricks.y() * bricks.z() *
         sizeof(std::int32_t);
}

void
CellIndex::insert(const CellCoord& c, CellId id)
{
  std::int32_t& slot = brick_slot_[brickOf(c)];
  if (slot < 0) {
    slot = static_cast<std::int32_t>(cells_.size() / kBrickCells);
    cells_.resize(cells_.size() + kBrickCells, kNoCell);
  }
  cells_[static_cast<std::size_t>(slot) * kBrickCells + offsetInBrick(c)] = id;
}

void
CellIndex::allocateBricks(const std::vector<CellCoord>& cells)
{
  std::size_t blocks = cells_.size() / kBrickCells;
  for (const CellCoord& c : cells) {
    std::int32_t& slot = brick_slot_[brickOf(c)];
    if (slot < 0)
      slot = static_cast<std::int32_t>(blocks++);
  }
  cells_.resize(blocks * kBrickCells, kNoCell);
}

std::uint64_t
CellIndex::memoryBytes() const
{
  return brick_slot_.capacity() * sizeof(std::int32_t) +
         cells_.capacity() * sizeof(CellId);
}

} // namespace visfeat
