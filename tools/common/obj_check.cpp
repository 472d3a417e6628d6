// The check of an .obj file before PCL's OBJ reader; see obj_check.h.

#include "common/obj_check.h"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <system_error>
#include <vector>

namespace visfeat_tools {

namespace fs = std::filesystem;

namespace {

/** \brief PCL 1.13's OBJ and MTL readers split a line that is not empty with
 * pcl::split at spaces, tabs and CRs, which gives no token at all for a line of only
 * those, and read its first token anyway: a crash on the first line (a CRLF file
 * starting with a blank line), a use after free later (found by fuzzing). */
bool
blankButNotEmpty(const std::string& line)
{
  return !line.empty() && line.find_first_not_of(" \t\r") == std::string::npos;
}

const char* const kBlankLine =
  "a line of only spaces, tabs or CRs (PCL's reader fails on it: make it empty)";

/** \brief A line as PCL's OBJ and MTL readers see it (refuse blankButNotEmpty() lines
 * first): trimmed of white space, the text between the trimmed ends in `trimmed`,
 * split at spaces, tabs and carriage returns with runs merged: at least one token. */
std::vector<std::string>
pclTokens(const std::string& line, std::string& trimmed)
{
  std::size_t begin = 0, end = line.size();
  while (begin < end && std::isspace(static_cast<unsigned char>(line[begin])))
    ++begin;
  while (end > begin && std::isspace(static_cast<unsigned char>(line[end - 1])))
    --end;
  trimmed = line.substr(begin, end - begin);
  std::vector<std::string> tokens(1);
  for (char c : trimmed) {
    if (c == ' ' || c == '\t' || c == '\r') {
      if (!tokens.back().empty())
        tokens.emplace_back();
    } else {
      tokens.back() += c;
    }
  }
  return tokens;
}

/** \brief A whole token that is a finite number in float's range. */
bool
finiteFloat(const std::string& token)
{
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(token.c_str(), &end);
  return errno == 0 && end != token.c_str() && *end == '\0' && std::isfinite(v) &&
         std::fabs(v) <= std::numeric_limits<float>::max();
}

/** \brief A face token PCL reads with sscanf("%d"): an integer in int's range first
 * (v, v/vt, v/vt/vn or v//vn). */
bool
faceIndex(const std::string& token)
{
  const std::size_t digit = token[0] == '-' || token[0] == '+' ? 1 : 0;
  if (digit >= token.size() || !std::isdigit(static_cast<unsigned char>(token[digit])))
    return false;
  errno = 0;
  const long long v = std::strtoll(token.c_str(), nullptr, 10);
  return errno == 0 && v >= std::numeric_limits<int>::min() &&
         v <= std::numeric_limits<int>::max();
}

/** \brief What is wrong with a material library for pcl::MTLReader, empty when
 * nothing is. A missing library is not (PCL only warns). */
std::string
mtlProblem(const fs::path& path)
{
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (!fs::exists(status))
    return "";
  const std::string name = "material library '" + path.filename().string() + "'";
  if (!fs::is_regular_file(status))
    return name + " is not a regular file";
  std::ifstream in(path, std::ios::binary);
  std::string line, trimmed;
  bool material = false;
  for (std::size_t n = 1; std::getline(in, line); ++n) {
    if (line.empty())
      continue;
    if (blankButNotEmpty(line))
      return name + " line " + std::to_string(n) + ": " + kBlankLine;
    const std::vector<std::string> t = pclTokens(line, trimmed);
    const std::string& key = t[0];
    const bool attribute = key == "Ka" || key == "Kd" || key == "Ks" ||
                           key == "illum" || key == "d" || key == "Tr" || key == "Ns" ||
                           key == "map_Kd";
    if (key != "newmtl" && !attribute)
      continue;
    if (t.size() < 2 || t[1].empty())
      return name + " line " + std::to_string(n) + ": '" + key + "' without a value";
    if (attribute && !material)
      return name + " line " + std::to_string(n) + ": '" + key +
             "' before any 'newmtl'";
    material = true;
  }
  return "";
}

/** \brief The largest face vertex index of the file (OBJ counts from 1) and its line:
 * checked against the vertices once all are read. */
struct LargestFaceIndex
{
  long long index = 0;
  std::size_t line = 0;
};

/** \brief What is wrong with one line (number `n`) of the .obj file at `path`;
 * `vertices` and `normals` count the lines read so far, `largest` the faces' largest
 * index. */
std::string
objLineProblem(const fs::path& path,
               const std::string& line,
               std::size_t n,
               std::size_t& vertices,
               std::size_t& normals,
               LargestFaceIndex& largest)
{
  const std::string where = "line " + std::to_string(n) + ": ";
  if (blankButNotEmpty(line))
    return where + kBlankLine;
  std::string trimmed;
  const std::vector<std::string> t = pclTokens(line, trimmed);
  const std::string& key = t[0];
  if (key == "v" || key == "vn") {
    if (t.size() < 4 || !finiteFloat(t[1]) || !finiteFloat(t[2]) || !finiteFloat(t[3]))
      return where + "'" + key + "' needs 3 finite coordinates";
    if (key == "v" && trimmed[1] != ' ')
      return where + "'v' and its coordinates must be separated by a space";
    ++(key == "v" ? vertices : normals);
    if (normals > vertices)
      return where + "more vertex normals than vertices";
  } else if (key == "f") {
    for (std::size_t i = 1; i < t.size(); ++i) {
      if (!faceIndex(t[i]))
        return where + "face vertex '" + t[i].substr(0, 20) +
               "' does not start with an index";
      // OBJ counts from 1; a negative index counts back from the last vertex so far
      const long long v = std::strtoll(t[i].c_str(), nullptr, 10);
      if (v == 0)
        return where + "face vertex index 0 (OBJ counts vertices from 1)";
      if (v < 0 && static_cast<unsigned long long>(-v) > vertices)
        return where + "face vertex index " + std::to_string(v) +
               " reaches before the " + "first vertex (" + std::to_string(vertices) +
               " vertices so far)";
      if (v > largest.index)
        largest = {v, n};
    }
  } else if (trimmed.compare(0, 6, "mtllib") == 0) {
    if (t.size() < 2)
      return where + "'mtllib' without a file name";
    const std::string problem = mtlProblem(path.parent_path() / t[1]);
    if (!problem.empty())
      return where + problem;
  }
  return "";
}

} // namespace

std::string
objProblem(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
    return "cannot be opened";
  std::string line;
  std::size_t vertices = 0, normals = 0;
  LargestFaceIndex largest;
  for (std::size_t n = 1; std::getline(in, line); ++n) {
    if (line.empty())
      continue;
    const std::string problem =
      objLineProblem(path, line, n, vertices, normals, largest);
    if (!problem.empty())
      return problem;
  }
  if (in.bad())
    return "read error";
  if (vertices == 0)
    return "no vertex ('v x y z' line)";
  if (static_cast<unsigned long long>(largest.index) > vertices)
    return "line " + std::to_string(largest.line) + ": face vertex index " +
           std::to_string(largest.index) + " out of range (the file has " +
           std::to_string(vertices) + " vertices, counting from 1)";
  return "";
}

} // namespace visfeat_tools
