// Fuzz target: the .ply and .obj entry points of the tool. An input starting with
// "ply" (the PLY magic) is written as a .ply file: isMeshFile sends it to the mesh
// reader (pcl::io::loadPLYFile into a PolygonMesh) when its header declares faces,
// else to loadCloud (pcl::io::loadPLYFile into a PCLPointCloud2). Any other input is
// an .obj file (pcl::io::loadOBJFile into a PolygonMesh).

#include "fuzz_input.h"

#include <cstddef>
#include <cstdint>
#include <cstring>

extern "C" int
LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  visfeat_fuzz::quietConsole();
  const bool ply = size >= 3 && std::memcmp(data, "ply", 3) == 0;
  const std::string path = visfeat_fuzz::writeInput(data, size, ply ? ".ply" : ".obj");
  visfeat_fuzz::loadInputAsTool(path);
  return 0;
}
