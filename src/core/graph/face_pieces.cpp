#include <visfeat/core/graph/face_pieces.h>

#include "region_boundaries.h"

#include <algorithm>
#include <iterator>
#include <map>

namespace visfeat {

using detail::classOfLabel;

namespace {

/** The 6-connected pieces of face `face`, whose cells are `cells` (ascending ids each;
 * in order of their first cell). */
std::vector<std::vector<CellId>>
facePieces(const VoxelBand& band,
           const std::vector<std::uint32_t>& cell_labels,
           std::uint32_t face,
           const std::vector<CellId>& cells,
           std::vector<char>& seen)
{
  std::vector<std::vector<CellId>> pieces;
  for (const CellId seed : cells) {
    if (seen[static_cast<std::size_t>(seed)])
      continue;
    std::vector<CellId> piece{seed};
    seen[static_cast<std::size_t>(seed)] = 1;
    for (std::size_t i = 0; i < piece.size(); ++i)
      for (const CellId m : band.neighbours(piece[i])) {
        if (m == kNoCell)
          continue;
        const auto mi = static_cast<std::size_t>(m);
        if (cell_labels[mi] == face && !seen[mi]) {
          seen[mi] = 1;
          piece.push_back(m);
        }
      }
    std::sort(piece.begin(), piece.end());
    pieces.push_back(std::move(piece));
  }
  for (const CellId c : cells)
    seen[static_cast<std::size_t>(c)] = 0;
  return pieces;
}

} // namespace

std::vector<FacePiece>
cutOffFacePieces(const VoxelBand& band,
                 const std::vector<std::uint32_t>& cell_labels,
                 const std::vector<FeatureClass>& classes,
                 const std::vector<std::array<std::uint32_t, 2>>& pairs)
{
  // the cells of the pairs' faces, gathered in one pass (ascending ids)
  std::map<std::uint32_t, std::vector<CellId>> cells_of;
  for (const auto& pair : pairs)
    if (classOfLabel(classes, pair[0]) == FeatureClass::kFace &&
        classOfLabel(classes, pair[1]) == FeatureClass::kFace)
      for (const std::uint32_t face : pair)
        cells_of[face];
  if (cells_of.empty())
    return {};
  detail::gatherCells(cell_labels, cells_of);
  std::vector<FacePiece> found;
  std::vector<char> seen(cell_labels.size(), 0);
  for (const auto& pair : pairs)
    for (int side = 0; side < 2; ++side) {
      const std::uint32_t face = pair[static_cast<std::size_t>(side)];
      const std::uint32_t other = pair[static_cast<std::size_t>(1 - side)];
      if (classOfLabel(classes, face) != FeatureClass::kFace ||
          classOfLabel(classes, other) != FeatureClass::kFace)
        continue;
      std::vector<std::vector<CellId>> pieces =
        facePieces(band, cell_labels, face, cells_of.at(face), seen);
      if (pieces.size() < 2)
        continue;
      std::size_t largest = 0;
      for (std::size_t p = 1; p < pieces.size(); ++p)
        if (pieces[p].size() > pieces[largest].size())
          largest = p;
      for (std::size_t p = 0; p < pieces.size(); ++p) {
        if (p == largest)
          continue;
        // the faces it borders (not the edges and vertices)
        std::map<std::uint32_t, std::size_t> shared =
          detail::sharedBoundary(band, cell_labels, pieces[p], face);
        for (auto it = shared.begin(); it != shared.end();)
          it = classOfLabel(classes, it->first) == FeatureClass::kFace
                 ? std::next(it)
                 : shared.erase(it);
        if (detail::soleLargest(shared) == other)
          found.push_back({std::move(pieces[p]), other});
      }
    }
  return found;
}

} // namespace visfeat
