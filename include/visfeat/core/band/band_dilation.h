#pragma once

#include <visfeat/core/band/voxel_band.h>

#include <cstdint>
#include <vector>

namespace visfeat {

/** \brief Geodesic dilation through the band: a breadth-first search over the band's
 * 6-adjacency from a set of cells, bounded by a number of steps. The paper's
 * vertex-edge test, and what the topology graph and the vertex test build on.
 *
 * The scratch is kept between runs and reset only where the last run wrote, so many
 * small dilations on a large band cost what they visit, not the band's size.
 */
class BandDilation
{
public:
  explicit BandDilation(const VoxelBand& band)
      : band_(&band)
      , steps_(band.size(), kUnreached)
  {}

  /** \brief Calls visit(cell) once for every cell within `radius` 6-steps of
   * `sources`, the sources included. */
  template <typename Visit>
  void run(const std::vector<CellId>& sources, std::uint32_t radius, Visit&& visit)
  {
    for (const CellId c : queue_)
      steps_[static_cast<std::size_t>(c)] = kUnreached;
    queue_.clear();
    for (const CellId c : sources)
      if (steps_[static_cast<std::size_t>(c)] == kUnreached) {
        steps_[static_cast<std::size_t>(c)] = 0;
        queue_.push_back(c);
      }
    for (std::size_t head = 0; head < queue_.size(); ++head) {
      const CellId c = queue_[head];
      visit(c);
      const std::uint32_t steps = steps_[static_cast<std::size_t>(c)];
      if (steps >= radius)
        continue;
      for (const CellId nb : band_->neighbours(c))
        if (nb != kNoCell && steps_[static_cast<std::size_t>(nb)] == kUnreached) {
          steps_[static_cast<std::size_t>(nb)] = steps + 1;
          queue_.push_back(nb);
        }
    }
  }

private:
  static constexpr std::uint32_t kUnreached = std::uint32_t(-1);

  const VoxelBand* band_;
  std::vector<std::uint32_t> steps_;
  std::vector<CellId> queue_; // the cells of the last run, in BFS order
};

} // namespace visfeat
