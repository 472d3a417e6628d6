// Fuzz target: .off input as the tool reads it: loadMeshAsCloud (visfeat::readOff,
// the mesh checks, the sampling) and what the tool does with the samples.

#include "fuzz_input.h"

#include <cstddef>
#include <cstdint>

extern "C" int
LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  visfeat_fuzz::quietConsole();
  const std::string path = visfeat_fuzz::writeInput(data, size, ".off");
  visfeat_fuzz::loadInputAsTool(path);
  return 0;
}
