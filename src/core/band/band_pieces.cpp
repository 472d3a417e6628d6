#include <visfeat/core/band/band_pieces.h>

namespace visfeat {

std::vector<std::uint32_t>
bandPieceSizes(const VoxelBand& band)
{
  const std::size_t n = band.size();
  std::vector<std::uint32_t> size(n, 0);
  std::vector<bool> seen(n, false);
  std::vector<CellId> piece;
  for (std::size_t seed = 0; seed < n; ++seed) {
    if (seen[seed])
      continue;
    piece.assign(1, static_cast<CellId>(seed));
    seen[seed] = true;
    for (std::size_t head = 0; head < piece.size(); ++head)
      for (const CellId nb : band.neighbours(piece[head]))
        if (nb != kNoCell && !seen[static_cast<std::size_t>(nb)]) {
          seen[static_cast<std::size_t>(nb)] = true;
          piece.push_back(nb);
        }
    for (const CellId c : piece)
      size[static_cast<std::size_t>(c)] = static_cast<std::uint32_t>(piece.size());
  }
  return size;
}

} // namespace visfeat
