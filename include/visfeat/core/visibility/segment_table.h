#pragma once

#include <visfeat/core/visibility/free_space.h>

#include <array>
#include <cstdint>
#include <vector>

namespace visfeat {

/** \brief The segment test, precomputed once for every cell offset on the lattice.
 *
 * Whether cell c sees cell c + d depends on d and on the free-space bits along the
 * segment; the decomposition of the segment into stretches depends on d alone. The
 * table stores, for every offset d with |d|_1 <= max_distance (the offsets the
 * visibility rings can reach), the linear mask offsets of the subcells of each stretch,
 * so a test is a handful of bit loads with no geometry and no tree descent.
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

  /** \brief Tables for one free-space mask (its strides) and all offsets with
   * |d|_1 <= max_distance. */
  SegmentTable(const FreeSpace& free_space, int max_distance);

  int maxDistance() const { return max_distance_; }

  /** \brief Whether cell c sees cell c + d (|d|_1 <= maxDistance()), where
   * base = free_space.linearIndex(FreeSpace::centre(c)); same rule as FreeSpace::sees.
   * The FreeSpace given to the constructor must still be alive. */
  bool sees(std::int64_t base, const Eigen::Vector3i& d, double opacity) const
  {
    const Span& span = spans_[spanIndex(d)];
    const std::uint64_t* words = words_;
    auto free_at = [words](std::int64_t i) {
      return (words[static_cast<std::size_t>(i >> 6)] >> (i & 63)) & 1u;
    };
    if (opacity <= 0.0) {
      for (std::int32_t s = span.single_begin; s < span.single_end; ++s)
        if (!free_at(base + singles_[s]))
          return false;
      for (std::int32_t m = span.multi_begin; m < span.multi_end; ++m) {
        const auto& q = multis_[m];
        if (!(free_at(base + q[0]) | free_at(base + q[1]) | free_at(base + q[2]) |
              free_at(base + q[3])))
          return false;
      }
      return true;
    }
    double blocked = 0.0;
    for (std::int32_t s = span.single_begin; s < span.single_end; ++s)
      if (!free_at(base + singles_[s]) && (blocked += single_length_[s]) >= opacity)
        return false;
    for (std::int32_t m = span.multi_begin; m < span.multi_end; ++m) {
      const auto& q = multis_[m];
      if (!(free_at(base + q[0]) | free_at(base + q[1]) | free_at(base + q[2]) |
            free_at(base + q[3])) &&
          (blocked += multi_length_[m]) >= opacity)
        return false;
    }
    return true;
  }

  /** \brief Convenience: cells a and b (|b - a|_1 <= maxDistance()). */
  bool sees(const CellCoord& a, const CellCoord& b, double opacity) const;

  /** \brief Stretch checks stored for offset d (for tests and benchmarks). */
  std::size_t checksFor(const Eigen::Vector3i& d) const;

private:
  struct Span
  {
    std::int32_t single_begin = 0, single_end = 0;
    std::int32_t multi_begin = 0, multi_end = 0;
  };

  std::size_t spanIndex(const Eigen::Vector3i& d) const
  {
    const int w = 2 * max_distance_ + 1;
    return static_cast<std::size_t>(
      (d.x() + max_distance_) +
      w * ((d.y() + max_distance_) + w * (d.z() + max_distance_)));
  }

  const FreeSpace* free_space_ = nullptr;
  const std::uint64_t* words_ = nullptr;
  int max_distance_ = 0;
  std::vector<Span> spans_;
  std::vector<std::int64_t> singles_;
  std::vector<float> single_length_; // cell edges
  std::vector<std::array<std::int64_t, 4>> multis_;
  std::vector<float> multi_length_; // cell edges
};

} // namespace visfeat
