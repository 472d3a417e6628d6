#include "common/progress_printer.h"

#include <unistd.h>

namespace visfeat_tools {

namespace {

double
seconds(std::chrono::steady_clock::duration d)
{
  return std::chrono::duration<double>(d).count();
}

} // namespace

ProgressPrinter::ProgressPrinter(std::FILE* out, bool tty, double delay_seconds)
    : out_(out)
    , tty_(tty)
    , delay_seconds_(delay_seconds)
    , start_(Clock::now())
    , last_(start_)
{}

std::shared_ptr<ProgressPrinter>
ProgressPrinter::forStderr()
{
  return std::make_shared<ProgressPrinter>(stderr, isatty(fileno(stderr)) != 0, 2.0);
}

void
ProgressPrinter::operator()(std::size_t done, std::size_t total)
{
  std::unique_lock<std::mutex> lock(mutex_, std::try_to_lock);
  if (!lock.owns_lock() || total == 0)
    return;
  if (map_done_ && done >= total)
    return; // the estimator's closing call repeats the end of the map
  if (map_done_ && done < total) { // the map of the next run has begun
    map_done_ = false;
    ++map_;
    if (printed_ && tty_)
      std::fputc('\n', out_); // keep the finished map's line
  }
  if (done >= total)
    map_done_ = true;
  const Clock::time_point now = Clock::now();
  const double elapsed = seconds(now - start_);
  if (elapsed < delay_seconds_ ||
      (printed_ && seconds(now - last_) < 0.5 && done < total))
    return;
  if (!printed_) {
    // Leave the "Computing ..." line of stdout intact when both streams share a
    // terminal or a log file.
    std::fflush(stdout);
    std::fputc('\n', out_);
  }
  last_ = now;
  printed_ = true;
  last_total_ = total;
  std::fprintf(out_, "%s  %s: %3d%% (%zu / %zu cells, %.1f s since start)%s",
               tty_ ? "\r" : "", mapName().c_str(),
               static_cast<int>(100.0 * done / total), done, total, elapsed,
               tty_ ? "" : "\n");
  std::fflush(out_);
}

void
ProgressPrinter::finish()
{
  std::lock_guard<std::mutex> lock(mutex_);
  if (printed_ && tty_) {
    std::fprintf(out_, "\r  %s: 100%% (%zu / %zu cells, %.1f s since start)\n",
                 mapName().c_str(), last_total_, last_total_,
                 seconds(Clock::now() - start_));
    std::fflush(out_);
  }
  printed_ = false;
}

std::string
ProgressPrinter::mapName() const
{
  return map_ == 1 ? std::string("visibility map")
                   : "visibility map " + std::to_string(map_) + ", another resolution";
}

} // namespace visfeat_tools
