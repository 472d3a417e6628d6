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

void
CellIndex::neighbourhood(const CellCoord& c, std::array<CellId, 27>& out) const
{
  const auto inner = [](int v) {
    const int o = v & kBrickMask;
    return o >= 1 && o < kBrickMask;
  };
  if (inner(c.x()) && inner(c.y()) && inner(c.z())) {
    const std::int32_t brick = brick_slot_[brickOf(c)];
    if (brick < 0) {
      out.fill(kNoCell);
      return;
    }
    const CellId* centre =
      cells_.data() + static_cast<std::size_t>(brick) * kBrickCells + offsetInBrick(c);
    constexpr std::ptrdiff_t dy = 1 << kBrickShift, dz = 1 << (2 * kBrickShift);
    std::size_t k = 0;
    for (std::ptrdiff_t z = -dz; z <= dz; z += dz)
      for (std::ptrdiff_t y = -dy; y <= dy; y += dy)
        for (std::ptrdiff_t x = -1; x <= 1; ++x)
          out[k++] = centre[z + y + x];
    return;
  }
  std::size_t k = 0;
  for (int z = -1; z <= 1; ++z)
    for (int y = -1; y <= 1; ++y)
      for (int x = -1; x <= 1; ++x)
        out[k++] = find(c + CellCoord(x, y, z));
}

std::uint64_t
CellIndex::memoryBytes() const
{
  return brick_slot_.capacity() * sizeof(std::int32_t) +
         cells_.capacity() * sizeof(CellId);
}

} // namespace visfeat
