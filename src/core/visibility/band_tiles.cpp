#include <visfeat/core/visibility/band_tiles.h>

#include <algorithm>
#include <numeric>

namespace visfeat {

BandTiles::BandTiles(const VoxelBand& band)
{
  brick_dims_ = (band.grid().dims.array() + (kTileSide - 1)) / kTileSide;
  const std::size_t n = band.size();
  std::vector<std::uint64_t> cell_keys(n);
  for (std::size_t c = 0; c < n; ++c)
    cell_keys[c] = linearKey(brickOf(band.coord(static_cast<CellId>(c))), brick_dims_);
  cells_.resize(n);
  std::iota(cells_.begin(), cells_.end(), CellId{0});
  std::stable_sort(cells_.begin(), cells_.end(), [&](CellId a, CellId b) {
    return cell_keys[static_cast<std::size_t>(a)] <
           cell_keys[static_cast<std::size_t>(b)];
  });
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint64_t k = cell_keys[static_cast<std::size_t>(cells_[i])];
    if (keys_.empty() || keys_.back() != k) {
      keys_.push_back(k);
      bricks_.push_back(brickOf(band.coord(cells_[i])));
      begin_.push_back(i);
    }
  }
  begin_.push_back(n);
}

std::int64_t
BandTiles::find(const Eigen::Vector3i& b) const
{
  if (!((b.array() >= 0).all() && (b.array() < brick_dims_.array()).all()))
    return -1;
  const std::uint64_t k = linearKey(b, brick_dims_);
  const auto it = std::lower_bound(keys_.begin(), keys_.end(), k);
  if (it == keys_.end() || *it != k)
    return -1;
  return it - keys_.begin();
}

} // namespace visfeat
