// Progress of the visibility map on the console, for the visfeat tool (not installed,
// not public API): the estimator's ProgressCallback turned into lines on stderr.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdio>
#include <memory>
#include <mutex>
#include <string>

namespace visfeat_tools {

/** \brief Progress of the visibility map: only after \a delay_seconds (2 s for the
 * tool), at most every 0.5 s while a map runs; one line rewritten with \r on a
 * terminal, plain lines otherwise. Called from several threads at once (the
 * estimator's ProgressCallback); a call that finds another printing is dropped.
 *
 * The automatic resolution's search and the noise check's coarser run compute the map
 * again: a map that starts after one reported done == total is named "visibility map
 * 2, another resolution", and so on (a fresh user saw the line fall back to 0% without
 * a word). */
class ProgressPrinter
{
public:
  /** \param out stream of the lines (stderr for the tool)
   * \param tty whether \a out is a terminal (lines rewritten with \r)
   * \param delay_seconds nothing is printed before this many seconds from construction
   */
  ProgressPrinter(std::FILE* out, bool tty, double delay_seconds);

  /** \brief ProgressPrinter on stderr after 2 s, \r lines when stderr is a terminal. */
  static std::shared_ptr<ProgressPrinter> forStderr();

  /** \brief One report of the estimator: \a done of \a total cells of the current map.
   */
  void operator()(std::size_t done, std::size_t total);

  /** \brief End the progress line, if one was started. */
  void finish();

private:
  using Clock = std::chrono::steady_clock;

  std::string mapName() const;

  std::mutex mutex_;
  std::FILE* out_;
  bool tty_;
  double delay_seconds_;
  Clock::time_point start_;
  Clock::time_point last_;
  bool printed_ = false;
  std::size_t last_total_ = 0;
  int map_ = 1;           ///< which map: the search and the noise check compute more
  bool map_done_ = false; ///< the current map reported done == total
};

} // namespace visfeat_tools
