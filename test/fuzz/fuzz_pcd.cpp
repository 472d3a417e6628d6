// Fuzz target: .pcd input as the tool reads it. checkPcdHeader (the guard in front of
// PCL 1.13's PCDReader, which crashes on some headers) must say what is wrong when it
// refuses; loadCloud (the guard, then pcl::io::loadPCDFile) and what the tool does with
// the cloud must not crash.

#include "fuzz_input.h"

#include <cstddef>
#include <cstdint>

extern "C" int
LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  visfeat_fuzz::quietConsole();
  const std::string path = visfeat_fuzz::writeInput(data, size, ".pcd");
  std::string problem;
  if (!visfeat_tools::checkPcdHeader(path, size, problem) && problem.empty())
    visfeat_fuzz::fail("checkPcdHeader refused without a problem");
  visfeat_fuzz::loadInputAsTool(path);
  return 0;
}
