#include <visfeat/core/common/threads.h>

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <exception>
#include <mutex>
#include <stdexcept>

namespace visfeat {

int
resolveThreads(int requested)
{
  return requested > 0 ? requested : std::max(1, omp_get_max_threads());
}

void
parallelFor(std::size_t count,
            int threads,
            std::size_t chunk,
            const std::function<void(std::size_t begin, std::size_t end)>& body)
{
  if (chunk == 0)
    throw std::invalid_argument("parallelFor: chunk must be > 0");
  if (count == 0)
    return;
  const std::size_t chunks = (count + chunk - 1) / chunk;
  const int team = static_cast<int>(
    std::min<std::size_t>(chunks, static_cast<std::size_t>(resolveThreads(threads))));
  if (team <= 1) {
    for (std::size_t begin = 0; begin < count; begin += chunk)
      body(begin, std::min(count, begin + chunk));
    return;
  }
  std::atomic<bool> failed{false};
  std::exception_ptr first;
  std::mutex mutex;
#pragma omp parallel for num_threads(team) schedule(dynamic, 1)
  for (std::int64_t c = 0; c < static_cast<std::int64_t>(chunks); ++c) {
    if (failed.load(std::memory_order_relaxed))
      continue;
    const std::size_t begin = static_cast<std::size_t>(c) * chunk;
    try {
      body(begin, std::min(count, begin + chunk));
    } catch (...) {
      const std::lock_guard<std::mutex> lock(mutex);
      if (!first)
        first = std::current_exception();
      failed = true;
    }
  }
  if (first)
    std::rethrow_exception(first);
}

} // namespace visfeat
