// The main() and console of the visfeat tools (not installed, not public API): help and
// exceptions handled alike in every tool, one-line errors, -q, PCL readers silenced.
#pragma once

#include <pcl/console/parse.h>
#include <pcl/console/print.h>

#include <exception>
#include <new>
#include <string>

namespace visfeat_tools {

/** \brief Print one error line "program: error: message" (PCL style, red on a
 * terminal) to stderr, after flushing stdout (so that a piped run keeps its order). */
void printError(const std::string& program, const std::string& message);

/** \brief -q: errors only. print_highlight() and print_value() ignore the verbosity
 * level, so stdout itself is sent to /dev/null; errors go to stderr. */
void beQuiet();

/** \brief Monotonic seconds, for timing phases of a tool run. */
double secondsNow();

/** \brief Run a PCL reader or writer with its console messages silenced (the tools
 * print one line of their own instead), restoring the verbosity afterwards. */
template <typename Function>
int
quietly(Function&& function)
{
  const pcl::console::VERBOSITY_LEVEL level = pcl::console::getVerbosityLevel();
  pcl::console::setVerbosityLevel(pcl::console::L_ALWAYS);
  const int result = function();
  pcl::console::setVerbosityLevel(level);
  return result;
}

/** \brief The shared main() of the tools: -h / --help print the help (exit 0), no
 * argument at all prints it too (exit 1) when `arguments_required`, and any exception
 * escaping `run` becomes one error line and exit code 1, never a crash. */
template <typename Help, typename Run>
int
toolMain(int argc,
         char** argv,
         const std::string& program,
         bool arguments_required,
         Help&& print_help,
         Run&& run)
{
  if (arguments_required && argc < 2) {
    print_help(argv[0]);
    return 1;
  }
  if (pcl::console::find_switch(argc, argv, "-h") ||
      pcl::console::find_switch(argc, argv, "--help")) {
    print_help(argv[0]);
    return 0;
  }
  try {
    return run(argc, argv);
  } catch (const std::bad_alloc&) {
    printError(program, "out of memory");
  } catch (const std::exception& e) {
    printError(program, e.what());
  }
  return 1;
}

} // namespace visfeat_tools
