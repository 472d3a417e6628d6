// The check of an .obj file (and the material libraries it names) before PCL's OBJ
// reader sees it (not installed, not public API).
#pragma once

#include <string>

namespace visfeat_tools {

/** \brief What is wrong with an .obj file for pcl::io::loadOBJFile (PCL 1.13), empty
 * when it can be read safely. PCL's reader indexes its tokens and its buffers without
 * checking them: a vertex line with fewer than 3 coordinates, a 'v' followed by a tab
 * (not counted by its first pass, written by its second), more normals than vertices,
 * a face index that is not an integer (left uninitialised), an 'mtllib' line without
 * a name, or a material library it would read forever (a directory) or crash on (a
 * material attribute before any 'newmtl') read memory that is not there or never
 * return. Those are refused here, with the line. */
std::string objProblem(const std::string& path);

} // namespace visfeat_tools
