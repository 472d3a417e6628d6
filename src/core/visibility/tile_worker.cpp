#include "tile_worker.h"

#include <algorithm>

namespace visfeat {
namespace detail {

TileWorker::TileWorker(const VoxelBand& band,
                       const FreeSpace& free_space,
                       const BandTiles& tiles,
                       const SegmentTable& table,
                       const VisibilityMap::Parameters& parameters,
                       std::uint8_t* radii)
    : band_(band)
    , free_space_(free_space)
    , tiles_(tiles)
    , table_(table)
    , parameters_(parameters)
    , radii_(radii)
    , window_(table.windowBricks())
{
  const auto side = static_cast<std::size_t>(window_.side());
  local_of_.assign(side * side * side, -1);
  const std::int32_t sy = window_.strideY(), sz = window_.strideZ();
  steps_ = {1, -1, sy, -sy, sz, -sz};
}

std::uint64_t
TileWorker::estimateBytes(int window_bricks, std::uint64_t cells)
{
  const std::uint64_t side =
    static_cast<std::uint64_t>(window_bricks) * FreeSpace::kBrickCells;
  const std::uint64_t window_cells = side * side * side;
  const std::uint64_t local = std::min(cells, window_cells);
  // window bytes and local_of_; per local cell: index, coord, adjacency, known, three
  // bit words, two ring entries, batch slot
  return window_cells * (1 + sizeof(std::int32_t)) +
         local * (4 + sizeof(Coord) + 24 + 1 + 24 + 8 + 1);
}

void
TileWorker::run(std::size_t t)
{
  load(t);
  const CellId* first = tiles_.cellsBegin(t);
  const CellId* last = tiles_.cellsEnd(t);
  while (first != last) {
    const int count = static_cast<int>(std::min<std::ptrdiff_t>(64, last - first));
    runBatch(first, count);
    first += count;
  }
  unload();
}

void
TileWorker::load(std::size_t t)
{
  const Eigen::Vector3i& centre = tiles_.brick(t);
  window_.load(free_space_, centre);
  const CellCoord& origin = window_.origin();
  const int half = window_.bricksPerSide() / 2;
  for (int z = -half; z <= half; ++z)
    for (int y = -half; y <= half; ++y)
      for (int x = -half; x <= half; ++x) {
        const std::int64_t other = tiles_.find(centre + Eigen::Vector3i(x, y, z));
        if (other < 0)
          continue;
        const auto o = static_cast<std::size_t>(other);
        for (const CellId* c = tiles_.cellsBegin(o); c != tiles_.cellsEnd(o); ++c) {
          const CellCoord l = band_.coord(*c) - origin;
          const std::int32_t i = window_.cellIndex(band_.coord(*c));
          local_of_[static_cast<std::size_t>(i)] =
            static_cast<std::int32_t>(window_index_.size());
          window_index_.push_back(i);
          coord_.push_back(Coord{static_cast<std::int16_t>(l.x()),
                                 static_cast<std::int16_t>(l.y()),
                                 static_cast<std::int16_t>(l.z())});
          known_.push_back(__atomic_load_n(radii_ + *c, __ATOMIC_RELAXED));
        }
      }
  const std::size_t n = window_index_.size();
  const int side = window_.side();
  adjacent_.resize(n);
  for (std::size_t l = 0; l < n; ++l) {
    const Coord& c = coord_[l];
    const int at[6] = {c.x, c.x, c.y, c.y, c.z, c.z};
    for (int d = 0; d < 6; ++d) {
      const int moved = at[d] + ((d & 1) ? -1 : 1);
      adjacent_[l][static_cast<std::size_t>(d)] =
        moved < 0 || moved >= side
          ? -1
          : local_of_[static_cast<std::size_t>(window_index_[l] +
                                               steps_[static_cast<std::size_t>(d)])];
    }
  }
  visited_.assign(n, 0);
  slot_.assign(n, -1);
  ring_bits_.assign(n, 0);
  next_bits_.assign(n, 0);
}

void
TileWorker::unload()
{
  for (const std::int32_t i : window_index_)
    local_of_[static_cast<std::size_t>(i)] = -1;
  window_index_.clear();
  coord_.clear();
  known_.clear();
}

void
TileWorker::runBatch(const CellId* first, int count)
{
  const int max_radius = parameters_.max_radius;
  std::array<std::int32_t, 64> source{};
  std::array<int, 64> radius{};
  std::uint64_t active =
    count == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << count) - 1;
  std::fill(visited_.begin(), visited_.end(), 0);
  ring_.clear();
  for (int j = 0; j < count; ++j) {
    const std::int32_t l =
      local_of_[static_cast<std::size_t>(window_.cellIndex(band_.coord(first[j])))];
    source[static_cast<std::size_t>(j)] = l;
    slot_[static_cast<std::size_t>(l)] = static_cast<std::int8_t>(j);
    sees_[static_cast<std::size_t>(j)] = hidden_[static_cast<std::size_t>(j)] = 0;
    radius[static_cast<std::size_t>(j)] = max_radius;
    const std::uint64_t bit = std::uint64_t{1} << j;
    visited_[static_cast<std::size_t>(l)] |= bit;
    ring_bits_[static_cast<std::size_t>(l)] |= bit;
    ring_.push_back(l);
  }

  for (int k = 1; k <= max_radius && active != 0 && !ring_.empty(); ++k) {
    // ring k of every active source at once: the unvisited neighbours of ring k - 1
    next_.clear();
    for (const std::int32_t x : ring_) {
      const std::uint64_t m = ring_bits_[static_cast<std::size_t>(x)] & active;
      ring_bits_[static_cast<std::size_t>(x)] = 0;
      if (m == 0)
        continue;
      for (const std::int32_t y : adjacent_[static_cast<std::size_t>(x)]) {
        if (y < 0)
          continue;
        const auto yi = static_cast<std::size_t>(y);
        const std::uint64_t fresh = m & ~visited_[yi];
        if (fresh == 0)
          continue;
        if (next_bits_[yi] == 0)
          next_.push_back(y);
        next_bits_[yi] |= fresh;
        visited_[yi] |= fresh;
      }
    }
    // each source tests its ring-k cells until one is hidden
    for (const std::int32_t y : next_) {
      const auto yi = static_cast<std::size_t>(y);
      std::uint64_t m = next_bits_[yi] & active;
      const std::uint8_t known = known_[yi];
      if (m == 0 || (known != kUnknownRadius && known >= k))
        continue; // y sees its ring k, every source of m among it
      const int t = slot_[yi];
      if (t >= 0) {
        // y is source t of this batch: the pairs t already tested need no test
        const auto ti = static_cast<std::size_t>(t);
        const std::uint64_t hidden = m & hidden_[ti];
        for (std::uint64_t h = hidden; h != 0; h &= h - 1)
          radius[static_cast<std::size_t>(__builtin_ctzll(h))] = k - 1;
        active &= ~hidden;
        m &= ~(hidden | sees_[ti]);
      }
      // look up every source's offset and prefetch its checks first, then test: the
      // table loads of the tests overlap instead of waiting one after another
      const Coord& to = coord_[yi];
      int n = 0;
      for (; m != 0; m &= m - 1) {
        const int j = __builtin_ctzll(m);
        const Coord& from =
          coord_[static_cast<std::size_t>(source[static_cast<std::size_t>(j)])];
        const std::size_t at = table_.offsetIndex(
          Eigen::Vector3i(to.x - from.x, to.y - from.y, to.z - from.z));
        table_.prefetch(at, parameters_.opacity);
        pending_[static_cast<std::size_t>(n)] = {j, at};
        ++n;
      }
      for (int i = 0; i < n; ++i) {
        const auto [j, at] = pending_[static_cast<std::size_t>(i)];
        ++tests_;
        const bool seen = table_.seesAt(
          window_,
          window_index_[static_cast<std::size_t>(source[static_cast<std::size_t>(j)])],
          at, parameters_.opacity);
        if (!seen) {
          radius[static_cast<std::size_t>(j)] = k - 1;
          active &= ~(std::uint64_t{1} << j);
        }
        if (t >= 0) // source t gets the result when its ring k reaches source j
          (seen ? sees_ : hidden_)[static_cast<std::size_t>(j)] |= std::uint64_t{1}
                                                                   << t;
      }
    }
    ring_.swap(next_);
    ring_bits_.swap(
      next_bits_); // next_bits_ now all 0: ring k - 1's were cleared above
  }
  for (const std::int32_t x : ring_)
    ring_bits_[static_cast<std::size_t>(x)] = 0;

  for (int j = 0; j < count; ++j) {
    slot_[static_cast<std::size_t>(source[static_cast<std::size_t>(j)])] = -1;
    const auto r = static_cast<std::uint8_t>(radius[static_cast<std::size_t>(j)]);
    known_[static_cast<std::size_t>(source[static_cast<std::size_t>(j)])] = r;
    __atomic_store_n(radii_ + first[j], r, __ATOMIC_RELAXED);
  }
}

} // namespace detail
} // namespace visfeat
