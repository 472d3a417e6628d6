// Output files of the visfeat tools; see output_files.h.

#include "common/output_files.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <system_error>

namespace visfeat_tools {

namespace fs = std::filesystem;

std::string
temporaryPath(const std::string& path)
{
  return path + ".tmp";
}

bool
sameFile(const std::string& a, const std::string& b)
{
  if (a.empty() || b.empty())
    return false;
  std::error_code ec;
  if (fs::exists(a, ec) && fs::exists(b, ec) && fs::equivalent(a, b, ec) && !ec)
    return true;
  const fs::path ca = fs::weakly_canonical(fs::absolute(a, ec), ec);
  const fs::path cb = fs::weakly_canonical(fs::absolute(b, ec), ec);
  return ca == cb || a == b;
}

bool
checkWritable(const std::string& path, std::string& error)
{
  std::error_code ec;
  const fs::path p(path);
  if (fs::is_directory(p, ec)) {
    error = "output '" + path + "' is a directory";
    return false;
  }
  const fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
  if (!fs::is_directory(dir, ec)) {
    error = "output directory '" + dir.string() + "' of '" + path + "' does not exist";
    return false;
  }
  const std::string tmp = temporaryPath(path);
  const bool existed = fs::exists(tmp, ec);
  {
    std::ofstream probe(tmp, std::ios::binary | std::ios::app);
    if (!probe) {
      error = "cannot write '" + path + "': " + std::strerror(errno);
      return false;
    }
  }
  if (!existed)
    fs::remove(tmp, ec);
  return true;
}

bool
commitOutput(const std::string& path, std::string& error)
{
  std::error_code ec;
  fs::rename(temporaryPath(path), path, ec);
  if (ec) {
    error =
      "cannot rename '" + temporaryPath(path) + "' to '" + path + "': " + ec.message();
    fs::remove(temporaryPath(path), ec);
    return false;
  }
  return true;
}

void
discardOutput(const std::string& path)
{
  std::error_code ec;
  fs::remove(temporaryPath(path), ec);
}

} // namespace visfeat_tools
