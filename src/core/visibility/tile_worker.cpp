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
  // window bytes and local_of_; per local cell: index, coord, place, adjacency, known,
  // three bit words, two ring entries, batch slot
  return window_cells * (1 + sizeof(std::int32_t)) +
         local * (4 + sizeof(Coord) + sizeof(Place) + 24 + 1 + 24 + 8 + 1);
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
  const std::int32_t row_stride = table_.rowStride();
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
          place_.push_back(Place{l.y() + row_stride * l.z(), l.x()});
          known_.push_back(__atomic_load_n(radii_ + *c, __ATOMIC_RELAXED));
        }
      }
  const std::size_t n = window_index_.size();
  const auto sentinel = static_cast<std::int32_t>(n);
  const int side = window_.side();
  adjacent_.resize(n);
  for (std::size_t l = 0; l < n; ++l) {
    const Coord& c = coord_[l];
    const int at[6] = {c.x, c.x, c.y, c.y, c.z, c.z};
    for (int d = 0; d < 6; ++d) {
      const int moved = at[d] + ((d & 1) ? -1 : 1);
      const std::int32_t y =
        moved < 0 || moved >= side
          ? -1
          : local_of_[static_cast<std::size_t>(window_index_[l] +
                                               steps_[static_cast<std::size_t>(d)])];
      adjacent_[l][static_cast<std::size_t>(d)] = y < 0 ? sentinel : y;
    }
  }
  visited_.assign(n + 1, 0);
  ring_bits_.assign(n + 1, 0);
  next_bits_.assign(n + 1, 0);
  slot_.assign(n, -1);
  ring_.resize(n + 1);
  next_.resize(n + 1);
}

void
TileWorker::unload()
{
  for (const std::int32_t i : window_index_)
    local_of_[static_cast<std::size_t>(i)] = -1;
  window_index_.clear();
  coord_.clear();
  place_.clear();
  known_.clear();
}

std::size_t
TileWorker::growRing(std::uint64_t active)
{
  // ring k of every active source at once: the unvisited neighbours of ring k - 1.
  // No branch a neighbour: a missing one is the sentinel (always visited, so no fresh
  // bit), and a cell is written at next_[count] every time but kept (count moves on)
  // only when it gets its first bit of the ring.
  std::size_t count = 0;
  std::int32_t* next = next_.data();
  std::uint64_t* visited = visited_.data();
  std::uint64_t* ring_bits = ring_bits_.data();
  std::uint64_t* next_bits = next_bits_.data();
  for (std::size_t i = 0; i < ring_count_; ++i) {
    const auto x = static_cast<std::size_t>(ring_[i]);
    const std::uint64_t m = ring_bits[x] & active;
    ring_bits[x] = 0;
    if (m == 0)
      continue;
    for (const std::int32_t y : adjacent_[x]) {
      const auto yi = static_cast<std::size_t>(y);
      const std::uint64_t seen = visited[yi];
      const std::uint64_t fresh = m & ~seen;
      const std::uint64_t bits = next_bits[yi];
      next[count] = y;
      count += static_cast<std::size_t>((bits == 0) & (fresh != 0));
      next_bits[yi] = bits | fresh;
      visited[yi] = seen | fresh;
    }
  }
  return count;
}

void
TileWorker::runBatch(const CellId* first, int count)
{
  const int max_radius = parameters_.max_radius;
  std::array<std::int32_t, 64> source{}, source_index{}, source_row{}, source_x{};
  std::array<int, 64> radius{};
  std::uint64_t active =
    count == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << count) - 1;
  std::fill(visited_.begin(), visited_.end() - 1, 0);
  visited_.back() = ~std::uint64_t{0};
  ring_count_ = 0;
  for (int j = 0; j < count; ++j) {
    const auto ji = static_cast<std::size_t>(j);
    const std::int32_t l =
      local_of_[static_cast<std::size_t>(window_.cellIndex(band_.coord(first[j])))];
    const auto li = static_cast<std::size_t>(l);
    source[ji] = l;
    source_index[ji] = window_index_[li];
    source_row[ji] = place_[li].row;
    source_x[ji] = place_[li].x;
    slot_[li] = static_cast<std::int8_t>(j);
    sees_[ji] = hidden_[ji] = 0;
    radius[ji] = max_radius;
    const std::uint64_t bit = std::uint64_t{1} << j;
    visited_[li] |= bit;
    ring_bits_[li] |= bit;
    ring_[ring_count_++] = l;
  }

  const std::int32_t* row_middles = table_.rowMiddles();
  std::uint64_t tests = 0;
  for (int k = 1; k <= max_radius && active != 0 && ring_count_ != 0; ++k) {
    const std::size_t next_count = growRing(active);
    // each source tests its ring-k cells until one is hidden
    for (std::size_t i = 0; i < next_count; ++i) {
      const auto yi = static_cast<std::size_t>(next_[i]);
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
      const Place to = place_[yi];
      const std::int32_t* rows = row_middles + to.row;
      int n = 0;
      for (; m != 0; m &= m - 1) {
        const int j = __builtin_ctzll(m);
        const auto ji = static_cast<std::size_t>(j);
        const auto at =
          static_cast<std::size_t>(rows[-source_row[ji]] + to.x - source_x[ji]);
        table_.prefetch(at, parameters_.opacity);
        pending_[static_cast<std::size_t>(n)] = {j, at};
        ++n;
      }
      for (int p = 0; p < n; ++p) {
        const auto [j, at] = pending_[static_cast<std::size_t>(p)];
        ++tests;
        const bool seen = table_.seesAt(
          window_, source_index[static_cast<std::size_t>(j)], at, parameters_.opacity);
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
    ring_count_ = next_count;
    ring_bits_.swap(
      next_bits_); // next_bits_ now all 0: ring k - 1's were cleared above
  }
  for (std::size_t i = 0; i < ring_count_; ++i)
    ring_bits_[static_cast<std::size_t>(ring_[i])] = 0;

  tests_ += tests;
  for (int j = 0; j < count; ++j) {
    slot_[static_cast<std::size_t>(source[static_cast<std::size_t>(j)])] = -1;
    const auto r = static_cast<std::uint8_t>(radius[static_cast<std::size_t>(j)]);
    known_[static_cast<std::size_t>(source[static_cast<std::size_t>(j)])] = r;
    __atomic_store_n(radii_ + first[j], r, __ATOMIC_RELAXED);
  }
}

} // namespace detail
} // namespace visfeat
