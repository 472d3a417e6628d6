// Text point clouds for the visfeat tools; see text_cloud_input.h.

#include "common/text_cloud_input.h"

#include "common/arguments.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <set>
#include <vector>

namespace visfeat_tools {

namespace {

/** \brief The tokens of a line split at spaces, tabs, commas and semicolons. */
std::vector<std::string>
splitColumns(const std::string& line)
{
  std::vector<std::string> tokens;
  std::string token;
  for (char c : line) {
    if (c == ' ' || c == '\t' || c == ',' || c == ';' || c == '\r') {
      if (!token.empty())
        tokens.push_back(token);
      token.clear();
    } else {
      token += c;
    }
  }
  if (!token.empty())
    tokens.push_back(token);
  return tokens;
}

/** \brief The whole token as a double (nan and inf accepted); false when it is not a
 * number or overflows. */
bool
parseNumber(const std::string& token, double& value)
{
  errno = 0;
  char* end = nullptr;
  value = std::strtod(token.c_str(), &end);
  return end == token.c_str() + token.size() && !token.empty() &&
         !(errno == ERANGE && std::isinf(value));
}

/** \brief A token for a message: at most 20 characters, printable. */
std::string
shown(const std::string& token)
{
  std::string out;
  for (char c : token.substr(0, 20))
    out += std::isprint(static_cast<unsigned char>(c)) ? c : '?';
  return token.size() > 20 ? out + "..." : out;
}

/** \brief Column names from a header line (comment markers stripped): lower-cased,
 * unique, with x y z; false + problem otherwise. */
bool
namesFromHeader(std::string line, std::vector<std::string>& names, std::string& problem)
{
  line.erase(0, line.find_first_not_of("#/ \t"));
  names = splitColumns(line);
  const std::string first = names.empty() ? line : names.front();
  std::set<std::string> seen;
  for (std::string& name : names) {
    std::transform(name.begin(), name.end(), name.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (!seen.insert(name).second) {
      problem = "column '" + shown(name) + "' is named twice in the header line";
      return false;
    }
  }
  for (const char* axis : {"x", "y", "z"})
    if (!seen.count(axis)) {
      problem = "'" + shown(first) +
                "' is not a number, and the line is no header naming x, y and z (no '" +
                axis + "')";
      return false;
    }
  return true;
}

/** \brief The cloud's fields: one FLOAT64 per column. */
void
setFields(const std::vector<std::string>& names, pcl::PCLPointCloud2& cloud)
{
  cloud.fields.clear();
  for (std::size_t c = 0; c < names.size(); ++c) {
    pcl::PCLPointField field;
    field.name = names[c];
    field.offset = static_cast<std::uint32_t>(8 * c);
    field.datatype = pcl::PCLPointField::FLOAT64;
    field.count = 1;
    cloud.fields.push_back(field);
  }
  cloud.point_step = static_cast<std::uint32_t>(8 * names.size());
}

bool
isComment(const std::string& line)
{
  const std::size_t first = line.find_first_not_of(" \t");
  return first != std::string::npos &&
         (line[first] == '#' || line.compare(first, 2, "//") == 0);
}

} // namespace

bool
isTextCloudFile(const std::string& path)
{
  const std::string ext = lowerExtension(path);
  return ext == ".xyz" || ext == ".txt";
}

bool
readTextCloud(std::istream& in, pcl::PCLPointCloud2& cloud, std::string& problem)
{
  cloud = pcl::PCLPointCloud2();
  std::vector<std::string> names;
  std::vector<double> values;
  std::size_t columns = 0, first_line = 0, points = 0, line_number = 0;
  bool dense = true;
  std::string line;
  while (std::getline(in, line)) {
    ++line_number;
    const std::vector<std::string> tokens = splitColumns(line);
    if (tokens.empty())
      continue;
    const bool before_data = columns == 0;
    double value = 0.0;
    if (isComment(line)) {
      // a comment before the data that names x, y and z is the header ("//X Y Z")
      std::vector<std::string> candidate;
      std::string ignored;
      if (before_data && namesFromHeader(line, candidate, ignored)) {
        names = candidate;
        columns = names.size();
        first_line = line_number;
      }
      continue;
    }
    if (before_data && !parseNumber(tokens[0], value)) {
      // a first line of names: "x y z", "X Y Z Intensity"; binary data is none
      const bool binary = std::any_of(line.begin(), line.end(), [](char c) {
        return c != '\t' && c != '\r' && !std::isprint(static_cast<unsigned char>(c));
      });
      if (binary) {
        problem = "line " + std::to_string(line_number) + ": '" + shown(tokens[0]) +
                  "' is not a number (binary data: not a text cloud)";
        return false;
      }
      if (!namesFromHeader(line, names, problem)) {
        problem = "line " + std::to_string(line_number) + ": " + problem;
        return false;
      }
      columns = names.size();
      first_line = line_number;
      continue;
    }
    if (columns == 0) {
      columns = tokens.size();
      first_line = line_number;
      if (columns < 3) {
        problem = "line " + std::to_string(line_number) + " has " +
                  std::to_string(columns) + " column" + (columns == 1 ? "" : "s") +
                  ", expected at least 3 (x y z)";
        return false;
      }
    } else if (tokens.size() != columns) {
      problem = "line " + std::to_string(line_number) + " has " +
                std::to_string(tokens.size()) + " columns, line " +
                std::to_string(first_line) + " has " + std::to_string(columns);
      return false;
    }
    for (const std::string& token : tokens) {
      if (!parseNumber(token, value)) {
        problem = "line " + std::to_string(line_number) + ": '" + shown(token) +
                  "' is not a number";
        return false;
      }
      dense = dense && std::isfinite(value);
      values.push_back(value);
    }
    ++points;
  }
  if (points == 0) {
    problem = "no points (a text cloud has one point a line: x y z ...)";
    return false;
  }
  if (names.empty()) {
    names = {"x", "y", "z"};
    for (std::size_t c = 3; c < columns; ++c)
      names.push_back("column_" + std::to_string(c + 1));
  }
  setFields(names, cloud);
  cloud.width = static_cast<std::uint32_t>(points);
  cloud.height = 1;
  cloud.row_step = cloud.point_step * cloud.width;
  cloud.is_bigendian = false;
  cloud.is_dense = dense;
  cloud.data.resize(values.size() * sizeof(double));
  std::memcpy(cloud.data.data(), values.data(), cloud.data.size());
  return true;
}

} // namespace visfeat_tools
