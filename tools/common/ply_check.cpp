// The PLY header check of the visfeat tools; see ply_check.h.

#include "common/ply_check.h"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

namespace visfeat_tools {
namespace {

/** Bytes of a PLY scalar type in a binary file; 0 for an unknown name. */
unsigned long long
typeBytes(const std::string& type)
{
  if (type == "char" || type == "uchar" || type == "int8" || type == "uint8")
    return 1;
  if (type == "short" || type == "ushort" || type == "int16" || type == "uint16")
    return 2;
  if (type == "int" || type == "uint" || type == "float" || type == "int32" ||
      type == "uint32" || type == "float32")
    return 4;
  if (type == "double" || type == "float64")
    return 8;
  return 0;
}

} // namespace

std::string
plyProblem(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::string line, element, format;
  bool red = false;
  // the least number of data bytes the declared elements need
  unsigned long long element_count = 0, element_bytes = 0, needed = 0;
  unsigned long long declared = 0; // element instances: one line each in an ASCII file
  const auto closeElement = [&]() {
    declared += element_count;
    const unsigned long long limit = ~0ULL / 2;
    needed = element_bytes != 0 && element_count > (limit - needed) / element_bytes
               ? limit
               : needed + element_count * element_bytes;
  };
  bool ended = false;
  for (int n = 1; n <= 1024 && std::getline(in, line); ++n) {
    if (!line.empty() && line.back() == '\r')
      line.pop_back();
    std::istringstream words(line);
    std::string keyword, kind, size_type, value_type, name;
    words >> keyword;
    if (keyword == "end_header") {
      ended = true;
      break;
    }
    if (keyword == "format")
      words >> format;
    if (keyword == "element") {
      closeElement();
      element_count = 0;
      element_bytes = 0;
      words >> element >> element_count;
      red = false;
    }
    if (keyword != "property" || !(words >> kind))
      continue;
    if (kind == "list") {
      words >> size_type >> value_type >> name;
      element_bytes += format == "ascii" ? 2 : typeBytes(size_type);
    } else {
      words >> name;
      element_bytes += format == "ascii" ? 2 : typeBytes(kind);
    }
    if (element != "vertex")
      continue;
    const std::string where = "line " + std::to_string(n) + ": ";
    if (kind == "list")
      return where + "a list property ('" + name.substr(0, 40) +
             "') of the vertex element (PCL's reader aborts when its length varies)";
    red = red || name == "red";
    // PCL packs the colour into a field it adds at 'red'; 'blue' without it moved the
    // next property past the point (an assertion in PCL, found by fuzzing)
    if ((name == "green" || name == "blue") && !red)
      return where + "a '" + name +
             "' property of the vertex element without a 'red' before it (PCL's "
             "reader aborts on it)";
  }
  if (!ended)
    return "";
  closeElement();
  const std::streamoff header = in.tellg();
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  if (ec || header < 0)
    return "";
  const auto data =
    static_cast<unsigned long long>(size) -
    std::min<unsigned long long>(size, static_cast<unsigned long long>(header));
  if (needed > data)
    return "the header declares elements needing at least " + std::to_string(needed) +
           " bytes of data, but the file holds " + std::to_string(data) +
           " after its header (truncated, or its counts are wrong)";
  if (format != "ascii")
    return "";
  // an ASCII element per line: fewer lines than declared gave PCL's "could not be
  // parsed" without a count (a fresh user's truncated file)
  unsigned long long lines = 0;
  while (lines < declared && std::getline(in, line))
    if (line.find_first_not_of(" \t\r") != std::string::npos)
      ++lines;
  if (lines < declared)
    return "the header declares " + std::to_string(declared) +
           " elements (one a line), but the file holds " + std::to_string(lines) +
           " data lines after its header (truncated, or its counts are wrong)";
  return "";
}

} // namespace visfeat_tools
