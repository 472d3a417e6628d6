#include <visfeat/core/common/error.h>
#include <visfeat/core/visibility/band_tiles.h>
#include <visfeat/core/visibility/lattice_segment.h>
#include <visfeat/core/visibility/segment_table.h>

#include <algorithm>
#include <cmath>

namespace visfeat {
namespace {

/** Subcells [-2, 1]^3 around a cell centre are free whenever the cell is mixed. */
bool
inFreeBlock(const Eigen::Vector3i& s)
{
  return (s.array() >= -2).all() && (s.array() <= 1).all();
}

} // namespace

SegmentTable::SegmentTable(int max_distance)
    : max_distance_(max_distance)
{
  if (max_distance < 0)
    throw Error("segment table: negative distance");
  window_bricks_ = FreeSpaceWindow::bricksFor(max_distance);
  const std::int32_t side = window_bricks_ * FreeSpace::kBrickSide;
  const std::int32_t sy = side, sz = side * side;
  auto linear = [&](const Eigen::Vector3i& s) {
    return s.x() + sy * s.y() + sz * s.z();
  };
  const int w = 2 * max_distance + 1;
  row_start_.assign(static_cast<std::size_t>(w) * w, 0);
  std::int32_t stored = 0;
  for (int z = -max_distance; z <= max_distance; ++z)
    for (int y = -max_distance; y <= max_distance; ++y) {
      const int half = max_distance - std::abs(y) - std::abs(z);
      row_start_[static_cast<std::size_t>((y + max_distance) +
                                          w * (z + max_distance))] = stored;
      if (half >= 0)
        stored += 2 * half + 1;
    }
  spans_.assign(static_cast<std::size_t>(stored), Span{});

  for (int z = -max_distance; z <= max_distance; ++z)
    for (int y = -max_distance; y <= max_distance; ++y)
      for (int x = -max_distance; x <= max_distance; ++x) {
        const Eigen::Vector3i d(x, y, z);
        if (d.cwiseAbs().sum() > max_distance)
          continue;
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
        Span& span = spans_[spanIndex(d)];
        span.single_begin = static_cast<std::int32_t>(singles_.size());
        span.multi_begin = static_cast<std::int32_t>(multis_.size());
        for (const SegmentStretch& s : kept) {
          const float length = static_cast<float>(0.5 * s.length); // cell edges
          if (s.count == 1) {
            singles_.push_back(linear(s.subcells[0]));
            single_length_.push_back(length);
          } else {
            std::array<std::int32_t, 4> q;
            for (int i = 0; i < 4; ++i) // pad a pair by repeating it
              q[static_cast<std::size_t>(i)] =
                linear(s.subcells[static_cast<std::size_t>(i % s.count)]);
            multis_.push_back(q);
            multi_length_.push_back(length);
          }
        }
        span.single_end = static_cast<std::int32_t>(singles_.size());
        span.multi_end = static_cast<std::int32_t>(multis_.size());
      }
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
  return sees(window, window.linearIndex(FreeSpace::centre(a)), d, opacity);
}

std::size_t
SegmentTable::checksFor(const Eigen::Vector3i& d) const
{
  if (d.cwiseAbs().sum() > max_distance_)
    throw Error("segment table: offset beyond the table's distance");
  const Span& span = spans_[spanIndex(d)];
  return static_cast<std::size_t>(span.single_end - span.single_begin) +
         static_cast<std::size_t>(span.multi_end - span.multi_begin);
}

} // namespace visfeat
