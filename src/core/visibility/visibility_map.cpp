#include <visfeat/core/common/error.h>
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
         const FreeSpace& free_space,
         const SegmentTable& table,
         const VisibilityMap::Parameters& parameters,
         RingScratch& scratch,
         std::uint64_t& tests)
{
  const std::uint32_t stamp = static_cast<std::uint32_t>(c) + 1;
  const CellCoord origin = band.coord(c);
  const std::int64_t base = free_space.linearIndex(FreeSpace::centre(origin));
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
      if (!table.sees(base, band.coord(n) - origin, parameters.opacity))
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
  const SegmentTable table(free_space, parameters.max_radius);

  const int threads = resolveThreads(parameters.threads);
  constexpr std::int64_t kChunk = 512;
  std::atomic<std::size_t> done{0};
  std::uint64_t tests = 0;
#pragma omp parallel num_threads(threads) reduction(+ : tests)
  {
    RingScratch scratch(n);
#pragma omp for schedule(dynamic, 1)
    for (std::int64_t chunk = 0;
         chunk < (static_cast<std::int64_t>(n) + kChunk - 1) / kChunk; ++chunk) {
      const std::int64_t end =
        std::min<std::int64_t>(static_cast<std::int64_t>(n), (chunk + 1) * kChunk);
      for (std::int64_t c = chunk * kChunk; c < end; ++c)
        map.radii_[static_cast<std::size_t>(c)] = static_cast<std::uint8_t>(radiusOf(
          static_cast<CellId>(c), band, free_space, table, parameters, scratch, tests));
      const std::size_t so_far =
        done.fetch_add(static_cast<std::size_t>(end - chunk * kChunk)) +
        static_cast<std::size_t>(end - chunk * kChunk);
      if (progress && omp_get_thread_num() == 0)
        progress(so_far, n);
    }
  }
  if (progress)
    progress(n, n);
  map.tests_ = tests;
  return map;
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
