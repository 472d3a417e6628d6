#include <visfeat/core/visibility/free_space.h>
#include <visfeat/core/visibility/lattice_segment.h>

#include <algorithm>

namespace visfeat {
namespace {

constexpr int kBrickShift = 3; // log2(FreeSpace::kBrickCells)
static_assert(1 << kBrickShift == FreeSpace::kBrickCells,
              "brick side is 2^kBrickShift");

/** Bytes of a mask with this many bricks: the cell bytes and the sorted keys. */
std::uint64_t
bytesOfBricks(std::size_t bricks)
{
  return bricks * (sizeof(std::uint64_t) + FreeSpace::kBrickBytes);
}

/** The cells a mixed cell c frees subcells of: c and its 26 neighbours, clipped to the
 * grid. */
void
freeBlock(const CellCoord& c,
          const Eigen::Vector3i& dims,
          Eigen::Vector3i& lo,
          Eigen::Vector3i& hi)
{
  lo = (c - Eigen::Vector3i::Ones()).cwiseMax(0);
  hi = (c + Eigen::Vector3i::Ones()).cwiseMin(dims - Eigen::Vector3i::Ones());
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

/** Subcells of the cell at offset o (each coordinate -1, 0 or 1) from a mixed cell
 * that touch the mixed cell's subcells: all of them for o = 0; on an axis where o is
 * +1 (-1) only the subcells on the near side, coordinate 0 (1). */
std::uint8_t
touchingSubcells(const Eigen::Vector3i& o)
{
  // per axis: the bits whose coordinate on that axis is 0 and 1
  constexpr std::uint8_t kLow[3] = {0x55, 0x33, 0x0F};
  constexpr std::uint8_t kHigh[3] = {0xAA, 0xCC, 0xF0};
  std::uint8_t bits = 0xFF;
  for (int a = 0; a < 3; ++a)
    if (o[a] > 0)
      bits &= kLow[a];
    else if (o[a] < 0)
      bits &= kHigh[a];
  return bits;
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
brickDimsOf(const Eigen::Vector3i& cell_dims)
{
  return (cell_dims.array() + (FreeSpace::kBrickCells - 1)) / FreeSpace::kBrickCells;
}

} // namespace

FreeSpace::FreeSpace(const VoxelBand& band, const BeforeAllocating& before_allocating)
{
  const Eigen::Vector3i cell_dims = band.grid().dims;
  dims_ = 2 * cell_dims;
  brick_dims_ = brickDimsOf(cell_dims);
  brick_keys_ = sortedBrickKeys(band, cell_dims, brick_dims_);
  if (before_allocating)
    before_allocating(bytesOfBricks(brick_keys_.size()));
  cells_.assign(brick_keys_.size() * kBrickBytes, 0);

  std::uint8_t touching[27];
  for (int i = 0; i < 27; ++i)
    touching[i] =
      touchingSubcells(Eigen::Vector3i(i % 3 - 1, i / 3 % 3 - 1, i / 9 - 1));
  // A mixed cell frees its 2x2x2 subcells and every subcell touching them: subcells of
  // its 26 neighbours, clipped to the grid; at most 2 bricks a side.
  for (const CellCoord& c : band.coords()) {
    Eigen::Vector3i lo, hi;
    freeBlock(c, cell_dims, lo, hi);
    forEachBrickOfBlock(c, cell_dims, [&](const Eigen::Vector3i& b) {
      const std::int64_t slot = findBrick(linearKey(b, brick_dims_));
      std::uint8_t* bytes = cells_.data() + slot * kBrickBytes;
      const Eigen::Vector3i origin = kBrickCells * b;
      const Eigen::Vector3i blo = lo.cwiseMax(origin);
      const Eigen::Vector3i bhi = hi.cwiseMin(origin + Eigen::Vector3i::Constant(7));
      for (int z = blo.z(); z <= bhi.z(); ++z)
        for (int y = blo.y(); y <= bhi.y(); ++y)
          for (int x = blo.x(); x <= bhi.x(); ++x) {
            const int o = (x - c.x() + 1) + 3 * (y - c.y() + 1) + 9 * (z - c.z() + 1);
            bytes[(x - origin.x()) +
                  kBrickCells * ((y - origin.y()) + kBrickCells * (z - origin.z()))] |=
              touching[o];
          }
    });
  }
}

std::uint64_t
FreeSpace::estimateBytes(const VoxelBand& band)
{
  const Eigen::Vector3i dims = band.grid().dims;
  return bytesOfBricks(sortedBrickKeys(band, dims, brickDimsOf(dims)).size());
}

std::uint64_t
FreeSpace::memoryBytes() const
{
  return brick_keys_.capacity() * sizeof(std::uint64_t) + cells_.capacity();
}

std::int64_t
FreeSpace::findBrick(std::uint64_t key) const
{
  const auto it = std::lower_bound(brick_keys_.begin(), brick_keys_.end(), key);
  if (it == brick_keys_.end() || *it != key)
    return -1;
  return it - brick_keys_.begin();
}

const std::uint8_t*
FreeSpace::brickCells(const Eigen::Vector3i& b) const
{
  if (!((b.array() >= 0).all() && (b.array() < brick_dims_.array()).all()))
    return nullptr;
  const std::int64_t slot = findBrick(linearKey(b, brick_dims_));
  return slot < 0 ? nullptr : cells_.data() + slot * kBrickBytes;
}

bool
FreeSpace::isFree(const Eigen::Vector3i& s) const
{
  if (!((s.array() >= 0).all() && (s.array() < dims_.array()).all()))
    return false;
  const Eigen::Vector3i cell = s.unaryExpr([](int v) { return v >> 1; });
  const std::uint8_t* bytes =
    brickCells(cell.unaryExpr([](int v) { return v >> kBrickShift; }));
  if (bytes == nullptr)
    return false;
  const int m = kBrickCells - 1;
  return (bytes[(cell.x() & m) +
                kBrickCells * ((cell.y() & m) + kBrickCells * (cell.z() & m))] >>
          subcellBit(s)) &
         1u;
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
