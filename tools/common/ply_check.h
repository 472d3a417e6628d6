#pragma once

// The PLY header check of the visfeat tools: what PCL's PLY reader must not be given.

#include <string>

namespace visfeat_tools {

/** \brief What PCL 1.13's PLY reader cannot read in the header of the .ply file at
 * `path` (cloud or mesh), empty when nothing:
 * - a list property of the vertex element (PCL aborts on an assertion when its length
 *   varies from vertex to vertex);
 * - a 'green' or 'blue' property without a 'red' before it (an assertion too);
 * - element counts whose data cannot fit in the file: at least the fixed-size
 *   properties' bytes per element (a list's count, at least) in a binary file, two
 *   characters per property in an ASCII one. PCL allocates the declared vertices
 *   first: a 36-byte file declaring 10^9 vertices took 58 s and 11.7 GB before it
 *   failed;
 * - in an ASCII file, fewer non-blank data lines than the declared elements (PCL then
 *   said only that the file could not be parsed). */
std::string plyProblem(const std::string& path);

} // namespace visfeat_tools
