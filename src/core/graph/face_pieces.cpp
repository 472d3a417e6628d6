#include <visfeat/core/graph/face_pieces.h>

#include <algorithm>
#include <map>

namespace visfeat {

namespace {

/** The class of region `label` (classes[label - 1]; kNone for 0 or past the end). */
FeatureClass
classOfLabel(const std::vector<FeatureClass>& classes, std::uint32_t label)
{
  return label == 0 || label > classes.size() ? FeatureClass::kNone
                                              : classes[label - 1];
}

/** The 6-connected pieces of face `face` (ascending ids each; in order of their first
 * cell). */
std::vector<std::vector<CellId>>
facePieces(const VoxelBand& band,
           const std::vector<std::uint32_t>& cell_labels,
           std::uint32_t face,
           std::vector<char>& seen)
{
  std::vector<std::vector<CellId>> pieces;
  for (std::size_t c = 0; c < cell_labels.size(); ++c) {
    if (cell_labels[c] != face || seen[c])
      continue;
    std::vector<CellId> piece{static_cast<CellId>(c)};
    seen[c] = 1;
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
  for (const auto& piece : pieces)
    for (const CellId c : piece)
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
        facePieces(band, cell_labels, face, seen);
      if (pieces.size() < 2)
        continue;
      std::size_t largest = 0;
      for (std::size_t p = 1; p < pieces.size(); ++p)
        if (pieces[p].size() > pieces[largest].size())
          largest = p;
      for (std::size_t p = 0; p < pieces.size(); ++p) {
        if (p == largest)
          continue;
        std::map<std::uint32_t, std::size_t> shared;
        for (const CellId c : pieces[p])
          for (const CellId m : band.neighbours(c)) {
            const std::uint32_t l =
              m == kNoCell ? 0 : cell_labels[static_cast<std::size_t>(m)];
            if (l != face && classOfLabel(classes, l) == FeatureClass::kFace)
              ++shared[l];
          }
        std::uint32_t most = 0;
        std::size_t count = 0;
        bool tie = false;
        for (const auto& [label, n] : shared) {
          tie = n == count ? true : n > count ? false : tie;
          if (n > count) {
            most = label;
            count = n;
          }
        }
        if (most == other && !tie)
          found.push_back({std::move(pieces[p]), other});
      }
    }
  return found;
}

} // namespace visfeat
