#pragma once

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

} // namespace visfeat
