#include <visfeat/core/common/error.h>
#include <visfeat/core/visibility/band_tiles.h>
#include <visfeat/core/visibility/lattice_segment.h>
#include <visfeat/core/visibility/segment_table.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace visfeat {
namespace {

/** Subcells [-2, 1]^3 around a cell centre are free whenever the cell is mixed. */
bool
inFreeBlock(const Eigen::Vector3i& s)
{
  return (s.array() >= -2).all() && (s.array() <= 1).all();
}

/** Bit a of a subcell index: 1, 2, 4 for x, y, z. */
constexpr unsigned
axisBit(int a)
{
  return 1u << a;
}

/** fold f of byte b: bit i = OR of the bits j with j & ~f == i & ~f. */
std::uint8_t
foldOf(unsigned f, unsigned b)
{
  for (int a = 0; a < 3; ++a)
    if (f & axisBit(a))
      b |= b >> axisBit(a);
  return static_cast<std::uint8_t>(b);
}

/** Cell (relative to the source cell) and bit of a subcell given relative to the
 * source's centre, the lattice point 2c + 1: subcell 2c + 1 + s. */
void
cellOfSubcell(const Eigen::Vector3i& s, Eigen::Vector3i& cell, unsigned& bit)
{
  const Eigen::Vector3i absolute = s + Eigen::Vector3i::Ones(); // relative to 2c
  cell = absolute.unaryExpr([](int v) { return v >> 1; });
  bit = static_cast<unsigned>(FreeSpace::subcellBit(absolute));
}

std::int32_t
pack(std::int32_t offset, unsigned mask)
{
  return static_cast<std::int32_t>(static_cast<std::uint32_t>(offset) << 8 | mask);
}

} // namespace

SegmentTable::SegmentTable(int max_distance)
    : max_distance_(max_distance)
{
  if (max_distance < 0)
    throw Error("segment table: negative distance");
  window_bricks_ = FreeSpaceWindow::bricksFor(max_distance);
  for (unsigned f = 0; f < 8; ++f)
    for (unsigned b = 0; b < 256; ++b)
      folds_[f][b] = foldOf(f, b);

  const int w = 2 * max_distance + 1;
  row_centre_ = max_distance + w * max_distance;
  row_middle_.assign(static_cast<std::size_t>(w) * w, 0);
  std::int32_t stored = 0;
  for (int z = -max_distance; z <= max_distance; ++z)
    for (int y = -max_distance; y <= max_distance; ++y) {
      const int half = max_distance - std::abs(y) - std::abs(z);
      row_middle_[static_cast<std::size_t>(y + w * z + row_centre_)] = stored + half;
      if (half >= 0)
        stored += 2 * half + 1;
    }
  check_spans_.assign(static_cast<std::size_t>(stored), CheckSpan{});
  checks_.assign(static_cast<std::size_t>(stored) * kCheckBlock, pack(0, 0));
  stretch_spans_.assign(static_cast<std::size_t>(stored), StretchSpan{});

  const std::int32_t side = window_bricks_ * FreeSpace::kBrickCells;
  for (int z = -max_distance; z <= max_distance; ++z)
    for (int y = -max_distance; y <= max_distance; ++y)
      for (int x = -max_distance; x <= max_distance; ++x) {
        const Eigen::Vector3i d(x, y, z);
        if (d.cwiseAbs().sum() <= max_distance)
          addOffset(d, side);
      }
}

void
SegmentTable::addOffset(const Eigen::Vector3i& d, std::int32_t side)
{
  unsigned fold = 0;
  for (int a = 0; a < 3; ++a)
    if (d[a] == 0)
      fold |= axisBit(a);
  const Eigen::Vector3i end = 2 * d;
  std::vector<SegmentStretch> kept;
  for (const SegmentStretch& s : decomposeLatticeSegment(end)) {
    bool always_free = false;
    for (int i = 0; i < s.count && !always_free; ++i) {
      const Eigen::Vector3i& sub = s.subcells[static_cast<std::size_t>(i)];
      always_free = inFreeBlock(sub) || inFreeBlock(sub - end);
    }
    if (!always_free)
      kept.push_back(s);
  }
  std::stable_sort(kept.begin(), kept.end(),
                   [](const SegmentStretch& a, const SegmentStretch& b) {
                     return std::abs(a.t_mid - 0.5) < std::abs(b.t_mid - 0.5);
                   });

  StretchSpan& stretch_span = stretch_spans_[spanIndex(d)];
  stretch_span.begin = static_cast<std::int32_t>(stretches_.size());
  std::vector<std::pair<std::int32_t, unsigned>> cells; // middle first
  for (const SegmentStretch& s : kept) {
    // The subcells around a stretch differ only on the axes where d is 0 (the segment
    // lies on the faces between them), so they share one cell: the centres sit on odd
    // lattice points, the middles of cells.
    Eigen::Vector3i cell;
    unsigned bit = 0, subcells = 0;
    cellOfSubcell(s.subcells[0], cell, bit);
    for (int i = 0; i < s.count; ++i) {
      Eigen::Vector3i other;
      unsigned other_bit = 0;
      cellOfSubcell(s.subcells[static_cast<std::size_t>(i)], other, other_bit);
      if (other != cell || ((other_bit ^ bit) & ~fold) != 0)
        throw std::logic_error("segment table: a stretch spans two cells");
      subcells |= 1u << other_bit;
    }
    if (s.count != 1 << __builtin_popcount(fold))
      throw std::logic_error("segment table: stretch count does not match the offset");
    const std::int32_t offset = cell.x() + side * (cell.y() + side * cell.z());
    stretches_.push_back(pack(offset, subcells));
    stretch_length_.push_back(static_cast<float>(0.5 * s.length)); // cell edges
    const unsigned lowest = bit & ~fold;
    auto it = std::find_if(cells.begin(), cells.end(),
                           [&](const auto& c) { return c.first == offset; });
    if (it == cells.end())
      cells.emplace_back(offset, 1u << lowest);
    else
      it->second |= 1u << lowest;
  }
  stretch_span.end = static_cast<std::int32_t>(stretches_.size());
  const std::size_t at = spanIndex(d);
  CheckSpan& check_span = check_spans_[at];
  check_span.fold = static_cast<std::uint8_t>(fold);
  check_span.begin = static_cast<std::int32_t>(checks_.size());
  check_span.count = static_cast<std::uint16_t>(cells.size());
  for (std::size_t i = 0; i < cells.size(); ++i)
    if (i < kCheckBlock)
      checks_[at * kCheckBlock + i] = pack(cells[i].first, cells[i].second);
    else
      checks_.push_back(pack(cells[i].first, cells[i].second));
  // the source cell, no subcell: always passes
  checks_.resize(
    static_cast<std::size_t>(check_span.begin) +
      (cells.size() > kCheckBlock ? paddedCount(cells.size()) - kCheckBlock : 0),
    pack(0, 0));
}

bool
SegmentTable::sees(const FreeSpace& free_space,
                   const CellCoord& a,
                   const CellCoord& b,
                   double opacity) const
{
  const Eigen::Vector3i d = b - a;
  if (d.cwiseAbs().sum() > max_distance_)
    throw Error("segment table: offset beyond the table's distance");
  FreeSpaceWindow window(window_bricks_);
  window.load(free_space, BandTiles::brickOf(a));
  return sees(window, window.cellIndex(a), d, opacity);
}

std::size_t
SegmentTable::checksFor(const Eigen::Vector3i& d) const
{
  if (d.cwiseAbs().sum() > max_distance_)
    throw Error("segment table: offset beyond the table's distance");
  return check_spans_[spanIndex(d)].count;
}

std::size_t
SegmentTable::stretchesFor(const Eigen::Vector3i& d) const
{
  if (d.cwiseAbs().sum() > max_distance_)
    throw Error("segment table: offset beyond the table's distance");
  const StretchSpan& span = stretch_spans_[spanIndex(d)];
  return static_cast<std::size_t>(span.end - span.begin);
}

} // namespace visfeat
