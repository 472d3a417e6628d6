// Fuzz target: .stl input as the tool reads it. stlProblem (the guard in front of VTK's
// STL reader, which has no error path) and loadMeshAsCloud (the guard, then
// pcl::io::loadPolygonFileSTL, the mesh checks, the sampling).

#include "fuzz_input.h"

#include <cstddef>
#include <cstdint>

extern "C" int
LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  visfeat_fuzz::quietConsole();
  const std::string path = visfeat_fuzz::writeInput(data, size, ".stl");
  const std::string problem = visfeat_tools::stlProblem(path);
  if (problem.find('\n') != std::string::npos)
    visfeat_fuzz::fail("stlProblem is more than one line: " + problem);
  visfeat_fuzz::loadInputAsTool(path);
  return 0;
}
