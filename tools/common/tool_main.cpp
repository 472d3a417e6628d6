// The main() and console of the visfeat tools; see tool_main.h.

#include "common/tool_main.h"

#include <chrono>
#include <cstdio>

namespace visfeat_tools {

void
printError(const std::string& program, const std::string& message)
{
  // stdout first: piped, it is fully buffered, and its lines (the banner, "Computing
  // ...") would come after the error they led to
  std::fflush(stdout);
  pcl::console::print_error("%s: error: %s\n", program.c_str(), message.c_str());
}

void
beQuiet()
{
  pcl::console::setVerbosityLevel(pcl::console::L_ERROR);
  std::fflush(stdout);
  if (!std::freopen("/dev/null", "w", stdout))
    std::fclose(stdout);
}

double
secondsNow()
{
  return std::chrono::duration<double>(
           std::chrono::steady_clock::now().time_since_epoch())
    .count();
}

} // namespace visfeat_tools
