// Fuzz target: .xyz / .txt text clouds as the tool reads them: loadCloud (its file
// checks, then readTextCloud in double precision) and what the tool does with the cloud
// (hasXYZ, the recentring offset, toXYZ, withoutFields) must not crash, and a refusal
// must say what is wrong.

#include "fuzz_input.h"

#include <cstddef>
#include <cstdint>

extern "C" int
LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  visfeat_fuzz::quietConsole();
  const std::string path = visfeat_fuzz::writeInput(data, size, ".xyz");
  visfeat_fuzz::loadInputAsTool(path);
  return 0;
}
