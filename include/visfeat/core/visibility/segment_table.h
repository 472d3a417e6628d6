#pragma once

#include <visfeat/core/visibility/free_space_window.h>

#include <array>
#include <cstdint>
#include <cstdlib>
#include <vector>

namespace visfeat {

/** \brief The segment test, precomputed once for every cell offset on the lattice.
 *
 * Whether cell c sees cell c + d depends on d and on the free-space bits along the
 * segment; the decomposition of the segment into stretches (decomposeLatticeSegment)
 * depends on d alone. For every offset d with |d|_1 <= max_distance (the offsets the
 * visibility rings can reach) the table stores the cells of a FreeSpaceWindow of
 * windowBricks() bricks a side that the segment's stretches lie in, as offsets from
 * the source cell's byte, with the subcell bits each cell must show free; a test is a
 * handful of byte loads from one small dense array, with no geometry.
 *
 * Exact test (opacity 0): one check a cell, all the stretches in it at once. Where d
 * has a zero coordinate the segment runs along subcell faces (one zero) or edges (two
 * zeros), and a stretch is free when any of the 2 or 4 subcells around it is; such
 * cells are read through a fold (a 256-entry table) that ORs those subcells onto the
 * lowest one, so a check is always `(fold[byte] & mask) == mask`. The checks are read
 * kCheckBlock at a time, their misses ORed and tested once a block (each offset's list
 * padded with checks that always pass: the source cell, mask 0): one branch a block
 * instead of one a check: 2-6% off the map on the generated icosahedron at 256
 * (2026-12-02, old and new library alternated: 1 thread 1.62-1.68 s -> 1.58-1.60 s,
 * 2 threads 1.04-1.23 s -> 0.97-1.17 s); 8 checks a block measured as fast as 8-lane
 * AVX2 gathers, so the test stays portable.
 * With an opacity: one check a stretch, `byte & subcells` zero when blocked, with its
 * length.
 *
 * Stretches that touch the 4x4x4 block of subcells around either end are left out:
 * those subcells belong to a mixed cell or touch one, so they are always free. The
 * rest are ordered from the middle of the segment outwards, where a blocked segment
 * is most often blocked.
 */
class SegmentTable
{
public:
  SegmentTable() = default;

  /** \brief Tables for all offsets with |d|_1 <= max_distance (cells), for windows of
   * windowBricks() bricks a side. \throws visfeat::Error on a negative distance. */
  explicit SegmentTable(int max_distance);

  int maxDistance() const { return max_distance_; }

  /** \brief FreeSpaceWindow::bricksFor(maxDistance()): the window this table reads. */
  int windowBricks() const { return window_bricks_; }

  /** \brief Whether cell c sees cell c + d (|d|_1 <= maxDistance()), where
   * source = window.cellIndex(c) and the window (of windowBricks() bricks a side) was
   * loaded around c's brick; same rule as FreeSpace::sees. */
  bool sees(const FreeSpaceWindow& window,
            std::int32_t source,
            const Eigen::Vector3i& d,
            double opacity) const
  {
    return seesAt(window, source, offsetIndex(d), opacity);
  }

  /** \brief The table's index of offset d (|d|_1 <= maxDistance()), for seesAt. */
  std::size_t offsetIndex(const Eigen::Vector3i& d) const { return spanIndex(d); }

  /** \brief offsetIndex(b - a) in two parts, for many pairs of cells a, b:
   * rowMiddles()[rowKey(b) - rowKey(a)] + b.x - a.x, where rowKey(p) = p.y +
   * rowStride() p.z; the map computes each cell's key once, not once a pair. */
  std::int32_t rowStride() const { return 2 * max_distance_ + 1; }
  const std::int32_t* rowMiddles() const { return row_middle_.data() + row_centre_; }

  /** \brief Asks the cache for the first checks of offset index `at` (a hint only):
   * the map looks up the offsets of all sources of a target, prefetches, then tests,
   * so the table's loads of several tests overlap. */
  void prefetch(std::size_t at, double opacity) const
  {
    // one prefetch of a selected address: GCC 12 -O3 dropped both prefetches when each
    // branch had its own (no prefetch instruction in the library until 2026-12-07)
    const void* first =
      opacity <= 0.0
        ? static_cast<const void*>(checks_.data() + at * kCheckBlock)
        : static_cast<const void*>(stretches_.data() + stretch_spans_[at].begin);
    __builtin_prefetch(first);
  }

  /** \brief sees() for the offset of index `at` = offsetIndex(d). */
  bool seesAt(const FreeSpaceWindow& window,
              std::int32_t source,
              std::size_t at,
              double opacity) const
  {
    const std::uint8_t* cells = window.cells() + source;
    if (opacity <= 0.0) {
      // the first block at a place known from `at` alone: its loads need not wait
      // for the span's
      const CheckSpan& span = check_spans_[at];
      const std::uint8_t* fold = folds_[span.fold].data(); // folds_[0]: identity
      const auto read = [fold](unsigned byte) { return unsigned{fold[byte]}; };
      const std::int32_t* first = checks_.data() + at * kCheckBlock;
      if (!passBlocks(cells, first, first + kCheckBlock, read))
        return false;
      if (span.count <= kCheckBlock)
        return true;
      const std::int32_t* v = checks_.data() + span.begin;
      return passBlocks(cells, v, v + paddedCount(span.count) - kCheckBlock, read);
    }
    const StretchSpan& span = stretch_spans_[at];
    double blocked = 0.0;
    for (std::int32_t i = span.begin; i < span.end; ++i) {
      const std::int32_t v = stretches_[static_cast<std::size_t>(i)];
      if ((cells[v >> 8] & static_cast<unsigned>(v) & 0xFFu) == 0 &&
          (blocked += stretch_length_[static_cast<std::size_t>(i)]) >= opacity)
        return false;
    }
    return true;
  }

  /** \brief Convenience for tests: cells a and b (|b - a|_1 <= maxDistance()) through
   * a window loaded around a. Slow (loads a window per call). */
  bool sees(const FreeSpace& free_space,
            const CellCoord& a,
            const CellCoord& b,
            double opacity) const;

  /** \brief Checks the exact test reads at once (one branch a block). */
  static constexpr int kCheckBlock = 8;

  /** \brief Cell checks of the exact test for offset d (for tests and benchmarks). */
  std::size_t checksFor(const Eigen::Vector3i& d) const;

  /** \brief Stretches checked for offset d with an opacity. */
  std::size_t stretchesFor(const Eigen::Vector3i& d) const;

private:
  /** The exact test's checks of one offset: count checks, the first block at
   * checks_[kCheckBlock spanIndex(d)], the rest from checks_[begin]. */
  struct CheckSpan
  {
    std::int32_t begin = 0;
    std::uint16_t count = 0;
    std::uint8_t fold = 0; // folds_: bit a set when d's coordinate a is 0
  };

  /** The stretches of one offset: stretches_[begin, end). */
  struct StretchSpan
  {
    std::int32_t begin = 0, end = 0;
  };

  /** Only the offsets with |d|_1 <= max_distance are stored (an octahedron, ~1/6 of
   * the cube of offsets, so the table stays in cache): row (dy, dz) holds
   * dx = -(max_distance - |dy| - |dz|) .. +(...), and row_middle_ gives the index of
   * its dx = 0 (row (dy, dz) is dy + w dz + row_centre_, w = 2 max_distance + 1). */
  std::size_t spanIndex(const Eigen::Vector3i& d) const
  {
    const int row = d.y() + (2 * max_distance_ + 1) * d.z() + row_centre_;
    return static_cast<std::size_t>(row_middle_[static_cast<std::size_t>(row)] + d.x());
  }

  void addOffset(const Eigen::Vector3i& d, std::int32_t side);

  /** Checks [v, end) (a whole number of blocks) of a source's byte `cells`: false at
   * the first block with a subcell of some mask not free after `read`. */
  template <typename Read>
  static bool passBlocks(const std::uint8_t* cells,
                         const std::int32_t* v,
                         const std::int32_t* end,
                         Read read)
  {
    for (; v != end; v += kCheckBlock) {
      unsigned missing = 0;
      for (int i = 0; i < kCheckBlock; ++i)
        missing |= static_cast<unsigned>(v[i]) & ~read(unsigned{cells[v[i] >> 8]});
      if ((missing & 0xFFu) != 0)
        return false;
    }
    return true;
  }

  static std::size_t paddedCount(std::size_t count)
  {
    return (count + kCheckBlock - 1) / kCheckBlock * kCheckBlock;
  }

  int max_distance_ = 0;
  int window_bricks_ = 1;
  int row_centre_ = 0;                     // the row of (dy, dz) = (0, 0)
  std::vector<std::int32_t> row_middle_;   // per (dy, dz), (2 max_distance + 1)^2
  std::vector<CheckSpan> check_spans_;     // per offset, spanIndex order
  std::vector<StretchSpan> stretch_spans_; // per offset, spanIndex order
  /** (window offset << 8) | mask: the exact test's checks, first a block per offset
   * (spanIndex order) then the rest of each; each offset's list is padded to whole
   * blocks (kCheckBlock) with pack(0, 0), which always passes. */
  std::vector<std::int32_t> checks_;
  /** (window offset << 8) | subcells: the stretches, for an opacity. */
  std::vector<std::int32_t> stretches_;
  std::vector<float> stretch_length_; // cell edges
  /** fold[f][byte]: bit i set when any subcell that differs from i only on the axes in
   * f is free. */
  std::array<std::array<std::uint8_t, 256>, 8> folds_{};
};

} // namespace visfeat
