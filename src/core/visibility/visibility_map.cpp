#include <visfeat/core/common/error.h>
#include <visfeat/core/visibility/band_tiles.h>
#include <visfeat/core/visibility/free_space_window.h>
#include <visfeat/core/visibility/segment_table.h>
#include <visfeat/core/visibility/visibility_map.h>

#include <visfeat/core/common/threads.h>

#include <omp.h>

#include <atomic>
#include <cmath>

namespace visfeat {
namespace {

/** Per-thread scratch for the ring BFS: visit marks need no clearing between cells
 * because each cell uses its own id + 1 as the mark. */
struct RingScratch
{
  explicit RingScratch(std::size_t cells)
      : mark(cells, 0)
  {}
  std::vector<std::uint32_t> mark;
  std::vector<CellId> ring, next;
};

int
radiusOf(CellId c,
         const VoxelBand& band,
         const FreeSpaceWindow& window,
         const SegmentTable& table,
         const VisibilityMap::Parameters& parameters,
         RingScratch& scratch,
         std::uint64_t& tests)
{
  const std::uint32_t stamp = static_cast<std::uint32_t>(c) + 1;
  const CellCoord origin = band.coord(c);
  const std::int32_t base = window.linearIndex(FreeSpace::centre(origin));
  scratch.ring.assign(1, c);
  scratch.mark[static_cast<std::size_t>(c)] = stamp;
  for (int k = 1; k <= parameters.max_radius; ++k) {
    scratch.next.clear();
    for (const CellId r : scratch.ring)
      for (const CellId n : band.neighbours(r))
        if (n != kNoCell && scratch.mark[static_cast<std::size_t>(n)] != stamp) {
          scratch.mark[static_cast<std::size_t>(n)] = stamp;
          scratch.next.push_back(n);
        }
    if (scratch.next.empty()) // the BFS ran out: this and all later rings are empty
      return parameters.max_radius;
    for (const CellId n : scratch.next) {
      ++tests;
      if (!table.sees(window, base, band.coord(n) - origin, parameters.opacity))
        return k - 1;
    }
    scratch.ring.swap(scratch.next);
  }
  return parameters.max_radius;
}

} // namespace

void
VisibilityMap::validate(const Parameters& p)
{
  checkRange("max_radius", p.max_radius, Parameters::kMaxRadiusRange, "rings");
  checkRange("opacity", p.opacity, Parameters::kOpacityRange, "cell edges");
  checkRange("threads", p.threads, Parameters::kThreadsRange, "0 = all available");
}

VisibilityMap
VisibilityMap::compute(const VoxelBand& band,
                       const FreeSpace& free_space,
                       const Parameters& parameters,
                       const ProgressCallback& progress)
{
  validate(parameters);
  if (free_space.dims() != 2 * band.grid().dims)
    throw Error("the free space was not built for this band");

  VisibilityMap map;
  map.parameters_ = parameters;
  const std::size_t n = band.size();
  map.radii_.assign(n, 0);
  const SegmentTable table(parameters.max_radius);
  const BandTiles tiles(band);

  const int threads = resolveThreads(parameters.threads);
  std::atomic<std::size_t> done{0};
  std::uint64_t tests = 0;
#pragma omp parallel num_threads(threads) reduction(+ : tests)
  {
    RingScratch scratch(n);
    FreeSpaceWindow window(table.windowBricks());
#pragma omp for schedule(dynamic, 1)
    for (std::int64_t t = 0; t < static_cast<std::int64_t>(tiles.size()); ++t) {
      const auto tile = static_cast<std::size_t>(t);
      window.load(free_space, tiles.brick(tile));
      for (const CellId* c = tiles.cellsBegin(tile); c != tiles.cellsEnd(tile); ++c)
        map.radii_[static_cast<std::size_t>(*c)] = static_cast<std::uint8_t>(
          radiusOf(*c, band, window, table, parameters, scratch, tests));
      const std::size_t so_far =
        done.fetch_add(tiles.cellCount(tile)) + tiles.cellCount(tile);
      if (progress && omp_get_thread_num() == 0)
        progress(so_far, n);
    }
  }
  if (progress)
    progress(n, n);
  map.tests_ = tests;
  return map;
}

std::uint64_t
VisibilityMap::estimateBytes(const VoxelBand& band, int threads)
{
  const std::uint64_t n = band.size();
  const std::uint64_t window_side =
    std::uint64_t{FreeSpace::kBrickSide} *
    static_cast<std::uint64_t>(FreeSpaceWindow::bricksFor(kMaxRadius));
  const std::uint64_t per_thread = 4 * n + window_side * window_side * window_side / 8;
  return n /* radii */ + 12 * n /* tiles */ +
         static_cast<std::uint64_t>(std::max(threads, 1)) * per_thread;
}

VisibilityMap
VisibilityMap::fromRadii(const Parameters& parameters, std::vector<std::uint8_t> radii)
{
  validate(parameters);
  for (std::size_t c = 0; c < radii.size(); ++c)
    if (radii[c] > parameters.max_radius) {
      std::ostringstream msg;
      msg << "radius " << int(radii[c]) << " of cell " << c << " is above max_radius "
          << parameters.max_radius << " (rings)";
      throw Error(msg.str());
    }
  VisibilityMap map;
  map.parameters_ = parameters;
  map.radii_ = std::move(radii);
  return map;
}

} // namespace visfeat
