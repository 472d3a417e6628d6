#include <visfeat/core/visibility/free_space.h>
#include <visfeat/core/visibility/lattice_segment.h>

#include <algorithm>

namespace visfeat {
namespace {

constexpr int kBrickShift = 4; // log2(FreeSpace::kBrickSide)
static_assert(1 << kBrickShift == FreeSpace::kBrickSide, "brick side is 2^kBrickShift");

/** Bytes of a mask with this many bricks: the rows and the sorted keys. */
std::uint64_t
bytesOfBricks(std::size_t bricks)
{
  return bricks *
         (sizeof(std::uint64_t) + FreeSpace::kBrickRows * sizeof(std::uint16_t));
}

/** The free block of mixed cell c: subcells [2c - 1, 2c + 2], clipped to the mask. */
void
freeBlock(const CellCoord& c,
          const Eigen::Vector3i& dims,
          Eigen::Vector3i& lo,
          Eigen::Vector3i& hi)
{
  lo = (2 * c - Eigen::Vector3i::Ones()).cwiseMax(0);
  hi = (2 * c + Eigen::Vector3i::Constant(2)).cwiseMin(dims - Eigen::Vector3i::Ones());
}

/** Calls f(brick) for every brick that the free block of c touches. */
template <typename F>
void
forEachBrickOfBlock(const CellCoord& c, const Eigen::Vector3i& dims, F&& f)
{
  Eigen::Vector3i lo, hi;
  freeBlock(c, dims, lo, hi);
  const Eigen::Vector3i blo = lo.unaryExpr([](int v) { return v >> kBrickShift; });
  const Eigen::Vector3i bhi = hi.unaryExpr([](int v) { return v >> kBrickShift; });
  for (int z = blo.z(); z <= bhi.z(); ++z)
    for (int y = blo.y(); y <= bhi.y(); ++y)
      for (int x = blo.x(); x <= bhi.x(); ++x)
        f(Eigen::Vector3i(x, y, z));
}

std::vector<std::uint64_t>
sortedBrickKeys(const VoxelBand& band,
                const Eigen::Vector3i& dims,
                const Eigen::Vector3i& brick_dims)
{
  std::vector<std::uint64_t> keys;
  keys.reserve(band.size() / 8 + 16);
  // Compact whenever the scratch doubles, so it stays within a few times the bricks.
  std::size_t compact_at = band.size() / 4 + 1024;
  for (const CellCoord& c : band.coords()) {
    forEachBrickOfBlock(c, dims, [&](const Eigen::Vector3i& b) {
      keys.push_back(linearKey(b, brick_dims));
    });
    if (keys.size() >= compact_at) {
      std::sort(keys.begin(), keys.end());
      keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
      compact_at = std::max(compact_at, 2 * keys.size());
    }
  }
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  keys.shrink_to_fit();
  return keys;
}

Eigen::Vector3i
brickDimsOf(const Eigen::Vector3i& subcell_dims)
{
  return (subcell_dims.array() + (FreeSpace::kBrickSide - 1)) / FreeSpace::kBrickSide;
}

} // namespace

FreeSpace::FreeSpace(const VoxelBand& band, const BeforeAllocating& before_allocating)
{
  dims_ = 2 * band.grid().dims;
  brick_dims_ = brickDimsOf(dims_);
  brick_keys_ = sortedBrickKeys(band, dims_, brick_dims_);
  if (before_allocating)
    before_allocating(bytesOfBricks(brick_keys_.size()));
  rows_.assign(brick_keys_.size() * kBrickRows, 0);

  // A mixed cell frees its 2x2x2 subcells and every subcell touching them: the 4x4x4
  // block [2c - 1, 2c + 2], clipped to the mask; at most 2 bricks a side.
  for (const CellCoord& c : band.coords()) {
    Eigen::Vector3i lo, hi;
    freeBlock(c, dims_, lo, hi);
    forEachBrickOfBlock(c, dims_, [&](const Eigen::Vector3i& b) {
      const std::int64_t slot = findBrick(linearKey(b, brick_dims_));
      std::uint16_t* rows = rows_.data() + slot * kBrickRows;
      const Eigen::Vector3i origin = kBrickSide * b;
      const Eigen::Vector3i blo = (lo - origin).cwiseMax(0);
      const Eigen::Vector3i bhi = (hi - origin).cwiseMin(kBrickSide - 1);
      const auto bits = static_cast<std::uint16_t>(((1u << (bhi.x() + 1)) - 1u) &
                                                   ~((1u << blo.x()) - 1u));
      for (int z = blo.z(); z <= bhi.z(); ++z)
        for (int y = blo.y(); y <= bhi.y(); ++y)
          rows[y + kBrickSide * z] |= bits;
    });
  }
}

std::uint64_t
FreeSpace::estimateBytes(const VoxelBand& band)
{
  const Eigen::Vector3i dims = 2 * band.grid().dims;
  return bytesOfBricks(sortedBrickKeys(band, dims, brickDimsOf(dims)).size());
}

std::uint64_t
FreeSpace::memoryBytes() const
{
  return brick_keys_.capacity() * sizeof(std::uint64_t) +
         rows_.capacity() * sizeof(std::uint16_t);
}

std::int64_t
FreeSpace::findBrick(std::uint64_t key) const
{
  const auto it = std::lower_bound(brick_keys_.begin(), brick_keys_.end(), key);
  if (it == brick_keys_.end() || *it != key)
    return -1;
  return it - brick_keys_.begin();
}

const std::uint16_t*
FreeSpace::brickRows(const Eigen::Vector3i& b) const
{
  if (!((b.array() >= 0).all() && (b.array() < brick_dims_.array()).all()))
    return nullptr;
  const std::int64_t slot = findBrick(linearKey(b, brick_dims_));
  return slot < 0 ? nullptr : rows_.data() + slot * kBrickRows;
}

bool
FreeSpace::isFree(const Eigen::Vector3i& s) const
{
  if (!((s.array() >= 0).all() && (s.array() < dims_.array()).all()))
    return false;
  const std::uint16_t* rows =
    brickRows(s.unaryExpr([](int v) { return v >> kBrickShift; }));
  if (rows == nullptr)
    return false;
  const int m = kBrickSide - 1;
  return (rows[(s.y() & m) + kBrickSide * (s.z() & m)] >> (s.x() & m)) & 1u;
}

double
FreeSpace::blockedLength(const CellCoord& a, const CellCoord& b) const
{
  const Eigen::Vector3i start = centre(a);
  double blocked = 0.0;
  for (const SegmentStretch& s : decomposeLatticeSegment(2 * (b - a))) {
    bool occluded = true;
    for (int i = 0; i < s.count && occluded; ++i)
      occluded = !isFree(start + s.subcells[static_cast<std::size_t>(i)]);
    if (occluded)
      blocked += s.length;
  }
  return 0.5 * blocked; // subcell edges -> cell edges
}

} // namespace visfeat
