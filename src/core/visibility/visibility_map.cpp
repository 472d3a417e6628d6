#include <visfeat/core/common/error.h>
#include <visfeat/core/common/threads.h>
#include <visfeat/core/visibility/band_tiles.h>
#include <visfeat/core/visibility/free_space_window.h>
#include <visfeat/core/visibility/segment_table.h>
#include <visfeat/core/visibility/visibility_map.h>

#include "tile_worker.h"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <sstream>

namespace visfeat {

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
  map.radii_.assign(n, detail::TileWorker::kUnknownRadius);
  const SegmentTable table(parameters.max_radius);
  const BandTiles tiles(band);

  const int threads = resolveThreads(parameters.threads);
  std::atomic<std::size_t> done{0};
  std::uint64_t tests = 0;
#pragma omp parallel num_threads(threads) reduction(+ : tests)
  {
    detail::TileWorker worker(band, free_space, tiles, table, parameters,
                              map.radii_.data());
#pragma omp for schedule(dynamic, 1)
    for (std::int64_t t = 0; t < static_cast<std::int64_t>(tiles.size()); ++t) {
      const auto tile = static_cast<std::size_t>(t);
      worker.run(tile);
      const std::size_t so_far =
        done.fetch_add(tiles.cellCount(tile)) + tiles.cellCount(tile);
      if (progress && omp_get_thread_num() == 0)
        progress(so_far, n);
    }
    tests += worker.tests();
  }
  if (progress)
    progress(n, n);
  map.tests_ = tests;
  return map;
}

std::uint64_t
VisibilityMap::estimateBytes(const VoxelBand& band, const Parameters& parameters)
{
  validate(parameters);
  const int threads = resolveThreads(parameters.threads);
  const std::uint64_t n = band.size();
  const std::uint64_t per_thread = detail::TileWorker::estimateBytes(
    FreeSpaceWindow::bricksFor(parameters.max_radius), n);
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
