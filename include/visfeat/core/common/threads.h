#pragma once

#include <cstddef>
#include <functional>

namespace visfeat {

/** \brief The number of threads a parallel stage uses for a requested count.
 *
 * \param[in] requested threads asked for; 0 (or less) = all available, which is
 *            OpenMP's default team size (`OMP_NUM_THREADS`, else the cores)
 * \return at least 1.
 *
 * OpenMP is a private dependency of visfeat: code outside the library asks here
 * instead of calling `omp_get_max_threads()`. */
int resolveThreads(int requested);

/** \brief Calls body(begin, end) on disjoint chunks covering [0, count), on up to
 * resolveThreads(threads) threads (OpenMP, kept private to the library, so that
 * header templates such as the estimator can run in parallel without OpenMP flags in
 * the user's build).
 *
 * Chunks are at most `chunk` indices (> 0). The body must write only to its own
 * indices for the result to be the same for any thread count. An exception thrown by
 * the body stops the remaining chunks and the first one is rethrown here. */
void parallelFor(std::size_t count,
                 int threads,
                 std::size_t chunk,
                 const std::function<void(std::size_t begin, std::size_t end)>& body);

} // namespace visfeat
