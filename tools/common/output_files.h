// Output files of the visfeat tools (not installed, not public API): every output is
// written to a temporary name next to it and renamed into place only when all the
// outputs of a run are complete, so a failure leaves no partial file.
#pragma once

#include <string>

namespace visfeat_tools {

/** \brief The temporary name an output is written to before being renamed into place:
 * `path` + ".tmp". */
std::string temporaryPath(const std::string& path);

/** \brief Check, before any work, that `path` can be created: its directory exists and
 * is writable, and `path` is not a directory. Creates the temporary file and removes
 * it again unless it existed before. On failure `error` is one line. */
bool checkWritable(const std::string& path, std::string& error);

/** \brief Whether two output paths name the same file: equal once made absolute and
 * resolved (".", "..", symbolic links of the existing part), or, where both exist,
 * the same file (hard links). "o.pcd", "./o.pcd" and "$PWD/o.pcd" are one file: two
 * outputs written there would leave only the last (and the second rename fails). */
bool sameFile(const std::string& a, const std::string& b);

/** \brief Move the finished temporary file into place (same directory: atomic). On
 * failure the temporary file is removed and `error` is one line. */
bool commitOutput(const std::string& path, std::string& error);

/** \brief Remove a temporary file left by a failed write (nothing when there is none).
 */
void discardOutput(const std::string& path);

} // namespace visfeat_tools
