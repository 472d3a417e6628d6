// Points grouped by cell (private to the core: the smoothing of noisy points, the
// flat-ground test of feature points).
#pragma once

#include <visfeat/core/grid/cell_index.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace visfeat {
namespace detail {

/** The points of each of `cells` cells, in increasing point order (a counting sort):
 * the points of cell c are members[start[c] .. start[c + 1]). */
struct CellMembers
{
  std::vector<std::size_t> start;
  std::vector<std::uint32_t> members;

  /** \param cells the number of cells (ids 0 .. cells - 1)
   * \param cell_of per point, its cell id, or kNoCell (left out) */
  CellMembers(std::size_t cells, const std::vector<CellId>& cell_of)
      : start(cells + 1, 0)
  {
    for (const CellId c : cell_of)
      if (c != kNoCell)
        ++start[static_cast<std::size_t>(c) + 1];
    for (std::size_t c = 0; c < cells; ++c)
      start[c + 1] += start[c];
    members.resize(start[cells]);
    std::vector<std::size_t> fill(start.begin(), start.end() - 1);
    for (std::size_t i = 0; i < cell_of.size(); ++i)
      if (cell_of[i] != kNoCell)
        members[fill[static_cast<std::size_t>(cell_of[i])]++] =
          static_cast<std::uint32_t>(i);
  }
};

} // namespace detail
} // namespace visfeat
