// The PCD header check of the visfeat tools (not installed, not public API): the guard
// in front of PCL 1.13's PCDReader, which crashes or reads past its buffers on some
// headers (see the fuzz corpus, test/fuzz/corpus/pcd).
#pragma once

#include <cstdint>
#include <string>

namespace visfeat_tools {

/** \brief Validate a PCD header before PCL reads the file.
 *
 * PCL 1.13's PCDReader dereferences garbage when the header has no FIELDS line or is
 * not a PCD header at all (a text file or an empty file renamed .pcd crashes it), so
 * the header is checked first: the keywords FIELDS, SIZE, TYPE, WIDTH, POINTS and
 * DATA, consistent counts, and for DATA binary a file long enough for the points.
 * `file_size` is the size of the file in bytes. On failure `problem` says what is
 * wrong (without the file name). */
bool
checkPcdHeader(const std::string& path, std::uintmax_t file_size, std::string& problem);

} // namespace visfeat_tools
