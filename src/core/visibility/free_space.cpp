#include <visfeat/core/visibility/free_space.h>
#include <visfeat/core/visibility/lattice_segment.h>

namespace visfeat {

FreeSpace::FreeSpace(const VoxelBand& band)
{
  dims_ = 2 * band.grid().dims;
  stride_y_ = dims_.x();
  stride_z_ = static_cast<std::int64_t>(dims_.x()) * dims_.y();
  const std::int64_t total = stride_z_ * dims_.z();
  words_.assign(static_cast<std::size_t>((total + 63) / 64), 0);

  // A mixed cell frees its 2x2x2 subcells and every subcell touching them: the 4x4x4
  // block [2c - 1, 2c + 2], clipped to the mask.
  for (const CellCoord& c : band.coords()) {
    const Eigen::Vector3i lo = (2 * c - Eigen::Vector3i::Ones()).cwiseMax(0);
    const Eigen::Vector3i hi =
      (2 * c + Eigen::Vector3i::Constant(2)).cwiseMin(dims_ - Eigen::Vector3i::Ones());
    const int run = hi.x() - lo.x() + 1;
    for (int z = lo.z(); z <= hi.z(); ++z)
      for (int y = lo.y(); y <= hi.y(); ++y) {
        const std::int64_t first = lo.x() + stride_y_ * y + stride_z_ * z;
        // a run of at most 4 bits, possibly across a word boundary
        const std::uint64_t bits = (std::uint64_t{1} << run) - 1;
        const std::size_t word = static_cast<std::size_t>(first >> 6);
        const int shift = static_cast<int>(first & 63);
        words_[word] |= bits << shift;
        if (shift + run > 64)
          words_[word + 1] |= bits >> (64 - shift);
      }
  }
}

std::uint64_t
FreeSpace::estimateBytes(const GridSpec& grid)
{
  const std::uint64_t bits = std::uint64_t{8} *
                             static_cast<std::uint64_t>(grid.dims.x()) *
                             static_cast<std::uint64_t>(grid.dims.y()) *
                             static_cast<std::uint64_t>(grid.dims.z());
  return (bits + 63) / 64 * sizeof(std::uint64_t);
}

double
FreeSpace::blockedLength(const CellCoord& a, const CellCoord& b) const
{
  const Eigen::Vector3i start = centre(a);
  double blocked = 0.0;
  for (const SegmentStretch& s : decomposeLatticeSegment(2 * (b - a))) {
    bool occluded = true;
    for (int i = 0; i < s.count && occluded; ++i)
      occluded = !isFree(start + s.subcells[static_cast<std::size_t>(i)]);
    if (occluded)
      blocked += s.length;
  }
  return 0.5 * blocked; // subcell edges -> cell edges
}

} // namespace visfeat
