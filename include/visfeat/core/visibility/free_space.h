#pragma once

#include <visfeat/core/band/voxel_band.h>

#include <cstdint>
#include <vector>

namespace visfeat {

/** \brief Visible when nothing is blocked, or the blocked length stays below opacity.
 */
inline bool
isVisible(double blocked_length, double opacity)
{
  return blocked_length <= 0.0 || blocked_length < opacity;
}

/** \brief The eroded occluder as a bit-packed mask of 2x2x2 subcells.
 *
 * Every cell is split into 2x2x2 subcells. A subcell is free when it belongs to a mixed
 * cell or touches such a subcell by a face, edge or corner; the rest of space (outside
 * the grid too) is the occluder eroded by half a cell (the paper's O (-) C). Two mixed
 * cells see each other when the segment between their centres does not pass through
 * the interior of the occluder (see SegmentStretch for the open-occluder rule), or,
 * with an opacity, when the blocked stretches add up to less than the opacity.
 *
 * Cell centres are subcell-grid vertices: the centre of cell c is the lattice point
 * 2c + 1 in subcell units, so the test is exact. One bit per subcell: (2 dims)^3 bits.
 */
class FreeSpace
{
public:
  FreeSpace() = default;
  explicit FreeSpace(const VoxelBand& band);

  /** \brief Bytes of the mask for a grid, for memory checks before building. */
  static std::uint64_t estimateBytes(const GridSpec& grid);

  /** \brief Subcells per axis (twice the grid's dims). */
  const Eigen::Vector3i& dims() const { return dims_; }

  /** \brief Linear index of subcell s (s must lie inside the mask). */
  std::int64_t linearIndex(const Eigen::Vector3i& s) const
  {
    return s.x() + stride_y_ * s.y() + stride_z_ * s.z();
  }

  std::int64_t strideY() const { return stride_y_; }

  std::int64_t strideZ() const { return stride_z_; }

  bool isFreeAt(std::int64_t linear) const
  {
    return (words_[static_cast<std::size_t>(linear >> 6)] >> (linear & 63)) & 1u;
  }

  /** \brief Whether subcell s is free; everything outside the mask is occluded. */
  bool isFree(const Eigen::Vector3i& s) const
  {
    if (!((s.array() >= 0).all() && (s.array() < dims_.array()).all()))
      return false;
    return isFreeAt(linearIndex(s));
  }

  /** \brief The lattice point (subcell units) at the centre of cell c. */
  static Eigen::Vector3i centre(const CellCoord& c)
  {
    return 2 * c + Eigen::Vector3i::Ones();
  }

  /** \brief Total length, in cell edges, of the stretches of the segment between the
   * centres of a and b that run through the interior of the occluder. */
  double blockedLength(const CellCoord& a, const CellCoord& b) const;

  /** \brief Whether cells a and b see each other with the given opacity (cell edges).
   */
  bool sees(const CellCoord& a, const CellCoord& b, double opacity = 0.0) const
  {
    return isVisible(blockedLength(a, b), opacity);
  }

  std::uint64_t memoryBytes() const { return words_.size() * sizeof(std::uint64_t); }

  /** \brief The packed bits, 64 subcells a word, linearIndex() order. */
  const std::uint64_t* wordData() const { return words_.data(); }

private:
  Eigen::Vector3i dims_{0, 0, 0};
  std::int64_t stride_y_ = 0;
  std::int64_t stride_z_ = 0;
  std::vector<std::uint64_t> words_;
};

} // namespace visfeat
