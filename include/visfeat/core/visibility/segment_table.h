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
 * segment; the decomposition of the segment into stretches depends on d alone. The
 * table stores, for every offset d with |d|_1 <= max_distance (the offsets the
 * visibility rings can reach), the 32-bit offsets of the subcells of each stretch in a
 * FreeSpaceWindow of FreeSpaceWindow::bricksFor(max_distance) bricks a side, so a test
 * is a handful of bit loads from one small dense array, with no geometry.
 *
 * Stretches that touch the 4x4x4 block of subcells around either end are left out:
 * those subcells belong to a mixed cell or touch one, so they are always free. The
 * remaining stretches are ordered from the middle of the segment outwards, where a
 * blocked segment is most often blocked.
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
   * base = window.linearIndex(FreeSpace::centre(c)) and the window (of windowBricks()
   * bricks a side) was loaded around c's brick; same rule as FreeSpace::sees. */
  bool sees(const FreeSpaceWindow& window,
            std::int32_t base,
            const Eigen::Vector3i& d,
            double opacity) const
  {
    const Span& span = spans_[spanIndex(d)];
    const std::uint16_t* rows = window.rows();
    auto free_at = [rows](std::int32_t i) {
      return (rows[static_cast<std::uint32_t>(i) >> 4] >> (i & 15)) & 1u;
    };
    if (opacity <= 0.0) {
      for (std::int32_t s = span.single_begin; s < span.single_end; ++s)
        if (!free_at(base + singles_[static_cast<std::size_t>(s)]))
          return false;
      for (std::int32_t m = span.multi_begin; m < span.multi_end; ++m) {
        const auto& q = multis_[static_cast<std::size_t>(m)];
        if (!(free_at(base + q[0]) | free_at(base + q[1]) | free_at(base + q[2]) |
              free_at(base + q[3])))
          return false;
      }
      return true;
    }
    double blocked = 0.0;
    for (std::int32_t s = span.single_begin; s < span.single_end; ++s)
      if (!free_at(base + singles_[static_cast<std::size_t>(s)]) &&
          (blocked += single_length_[static_cast<std::size_t>(s)]) >= opacity)
        return false;
    for (std::int32_t m = span.multi_begin; m < span.multi_end; ++m) {
      const auto& q = multis_[static_cast<std::size_t>(m)];
      if (!(free_at(base + q[0]) | free_at(base + q[1]) | free_at(base + q[2]) |
            free_at(base + q[3])) &&
          (blocked += multi_length_[static_cast<std::size_t>(m)]) >= opacity)
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

  /** \brief Stretch checks stored for offset d (for tests and benchmarks). */
  std::size_t checksFor(const Eigen::Vector3i& d) const;

private:
  /** Stretches of one offset: singles [single_begin, multi_begin... see spans_. */
  struct Span
  {
    std::int32_t single_begin = 0, single_end = 0;
    std::int32_t multi_begin = 0, multi_end = 0;
  };

  /** Only the offsets with |d|_1 <= max_distance are stored (an octahedron, ~1/6 of
   * the cube of offsets, so the table stays in cache): row (dy, dz) starts at
   * row_start_ and holds dx = -(max_distance - |dy| - |dz|) .. +(...). */
  std::size_t spanIndex(const Eigen::Vector3i& d) const
  {
    const int w = 2 * max_distance_ + 1;
    const std::size_t row =
      static_cast<std::size_t>((d.y() + max_distance_) + w * (d.z() + max_distance_));
    const int half = max_distance_ - std::abs(d.y()) - std::abs(d.z());
    return static_cast<std::size_t>(row_start_[row] + (d.x() + half));
  }

  int max_distance_ = 0;
  int window_bricks_ = 1;
  std::vector<std::int32_t> row_start_; // per (dy, dz), (2 max_distance + 1)^2
  std::vector<Span> spans_;
  std::vector<std::int32_t> singles_;
  std::vector<float> single_length_; // cell edges
  std::vector<std::array<std::int32_t, 4>> multis_;
  std::vector<float> multi_length_; // cell edges
};

} // namespace visfeat
