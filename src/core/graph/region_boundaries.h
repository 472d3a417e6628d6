// Which regions a set of cells borders, and how much (private to core/graph: the
// contact creases, the pieces they cut off, the open faces).
#pragma once

#include <visfeat/core/band/voxel_band.h>
#include <visfeat/core/common/feature_class.h>

#include <cstddef>
#include <cstdint>
#include <map>
#include <vector>

namespace visfeat {
namespace detail {

/** The class of region `label` (classes[label - 1]; kNone for 0 or past the end). */
inline FeatureClass
classOfLabel(const std::vector<FeatureClass>& classes, std::uint32_t label)
{
  return label == 0 || label > classes.size() ? FeatureClass::kNone
                                              : classes[label - 1];
}

/** Fills each list of `cells_of` (keyed by region label) with that region's cells, in
 * ascending ids: one pass over the band. */
inline void
gatherCells(const std::vector<std::uint32_t>& cell_labels,
            std::map<std::uint32_t, std::vector<CellId>>& cells_of)
{
  for (std::size_t c = 0; c < cell_labels.size(); ++c) {
    const auto it = cells_of.find(cell_labels[c]);
    if (it != cells_of.end())
      it->second.push_back(static_cast<CellId>(c));
  }
}

/** Per region label other than `own` and 0, the 6-neighbour pairs of band cells between
 * `cells` and that region's cells (the boundary they share). */
inline std::map<std::uint32_t, std::size_t>
sharedBoundary(const VoxelBand& band,
               const std::vector<std::uint32_t>& cell_labels,
               const std::vector<CellId>& cells,
               std::uint32_t own)
{
  std::map<std::uint32_t, std::size_t> shared;
  for (const CellId c : cells)
    for (const CellId m : band.neighbours(c)) {
      const std::uint32_t l =
        m == kNoCell ? 0 : cell_labels[static_cast<std::size_t>(m)];
      if (l != own && l != 0)
        ++shared[l];
    }
  return shared;
}

/** The label of the greatest count, when no other label has as many; 0 when counts is
 * empty or the greatest is tied. */
inline std::uint32_t
soleLargest(const std::map<std::uint32_t, std::size_t>& counts)
{
  std::uint32_t largest = 0;
  std::size_t most = 0;
  bool tied = false;
  for (const auto& [label, count] : counts)
    if (count > most) {
      largest = label;
      most = count;
      tied = false;
    } else if (count == most) {
      tied = true;
    }
  return tied ? 0 : largest;
}

} // namespace detail
} // namespace visfeat
