// The PCD header check of the visfeat tools; see pcd_check.h.

#include "common/pcd_check.h"

#include "common/arguments.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <locale>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace visfeat_tools {
namespace {

/** \brief What the header lines before DATA announce. */
struct PcdHeader
{
  std::size_t fields = 0, sizes = 0, types = 0, counts = 0;
  std::vector<long long> size_values, count_values;
  std::vector<std::string> type_values;
  std::set<std::string> keys; // the keywords seen: each may come once
  bool have_width = false, have_points = false;
  long long width = 0, height = 1, points = -1;
};

/** \brief Append every value, parsed as an integer >= 0, to `out`; false at the first
 * one that is not. */
bool
nonNegativeIntegers(const std::vector<std::string>& values, std::vector<long long>& out)
{
  for (const auto& v : values) {
    long long n = 0;
    if (!parseInteger(v, n) || n < 0)
      return false;
    out.push_back(n);
  }
  return true;
}

/** \brief Record one header line other than DATA (`key` and its `values`) in `header`;
 * false + `problem` when it is malformed or not a PCD header line. */
bool
readHeaderLine(const std::string& line,
               const std::string& key,
               const std::vector<std::string>& values,
               PcdHeader& header,
               std::string& problem)
{
  // PCL reads every line it knows, so a second FIELDS (or SIZE, ...) line redefined the
  // fields after the check had counted the first: a cloud whose fields lay outside its
  // points (heap overflow found by fuzzing)
  if (!header.keys.insert(key == "COLUMNS" ? "FIELDS" : key).second) {
    problem = "invalid PCD header: a second " + key + " line";
    return false;
  }
  if (key == "VERSION" || key == "VIEWPOINT")
    return true;
  if (key == "FIELDS" || key == "COLUMNS") {
    header.fields = values.size();
  } else if (key == "SIZE") {
    header.sizes = values.size();
    if (!nonNegativeIntegers(values, header.size_values)) {
      problem = "invalid PCD header: bad SIZE line";
      return false;
    }
    for (long long s : header.size_values)
      if (s != 1 && s != 2 && s != 4 && s != 8) {
        problem = "invalid PCD header: field size " + std::to_string(s) + " in SIZE";
        return false;
      }
  } else if (key == "TYPE") {
    header.types = values.size();
    header.type_values = values;
    for (const auto& t : values)
      if (t != "F" && t != "I" && t != "U") {
        problem = "invalid PCD header: field type '" + t + "' in TYPE";
        return false;
      }
  } else if (key == "COUNT") {
    header.counts = values.size();
    if (!nonNegativeIntegers(values, header.count_values)) {
      problem = "invalid PCD header: bad COUNT line";
      return false;
    }
    for (long long c : header.count_values)
      if (c == 0) {
        problem = "invalid PCD header: a field of COUNT 0";
        return false;
      }
  } else if (key == "WIDTH" || key == "HEIGHT" || key == "POINTS") {
    std::vector<long long> numbers;
    if (values.size() != 1 || !nonNegativeIntegers(values, numbers)) {
      problem = "invalid PCD header: bad " + key + " line";
      return false;
    }
    if (key == "WIDTH") {
      header.width = numbers[0];
      header.have_width = true;
    } else if (key == "HEIGHT") {
      header.height = numbers[0];
    } else {
      header.points = numbers[0];
      header.have_points = true;
    }
  } else {
    problem = "not a PCD file (unexpected header line '" + line.substr(0, 40) + "')";
    return false;
  }
  return true;
}

/** \brief The block of a binary_compressed PCD after the header (`consumed` bytes of
 * the file at `path`): its compressed and uncompressed sizes (32-bit little endian)
 * must fit the file and the points (`data_bytes`). PCL allocates the uncompressed
 * size it reads there. */
bool
checkCompressedBlock(const std::string& path,
                     std::uintmax_t consumed,
                     std::uintmax_t file_size,
                     std::uintmax_t data_bytes,
                     std::string& problem)
{
  unsigned char sizes[8] = {};
  std::ifstream in(path, std::ios::binary);
  if (consumed + 8 > file_size || !in.seekg(static_cast<std::streamoff>(consumed)) ||
      !in.read(reinterpret_cast<char*>(sizes), sizeof sizes)) {
    problem = "PCD data is truncated (no compressed block)";
    return false;
  }
  auto le32 = [&sizes](int at) {
    return std::uintmax_t(sizes[at]) | std::uintmax_t(sizes[at + 1]) << 8 |
           std::uintmax_t(sizes[at + 2]) << 16 | std::uintmax_t(sizes[at + 3]) << 24;
  };
  const std::uintmax_t compressed = le32(0), uncompressed = le32(4);
  if (consumed + 8 + compressed > file_size) {
    problem = "PCD data is truncated (the compressed block has " +
              std::to_string(compressed) + " bytes)";
    return false;
  }
  if (uncompressed != data_bytes) {
    problem = "PCD data is corrupt (the compressed block unpacks to " +
              std::to_string(uncompressed) + " bytes, the points take " +
              std::to_string(data_bytes) + ")";
    return false;
  }
  return true;
}

/** \brief The DATA line ends the header: the lines before it must agree, its type must
 * be known, and the file (`file_size` bytes, the header `consumed` of them) must be
 * long enough for the announced points. */
bool
checkDataLine(const std::string& path,
              const PcdHeader& header,
              const std::vector<std::string>& values,
              std::uintmax_t consumed,
              std::uintmax_t file_size,
              std::string& problem)
{
  const std::size_t fields = header.fields;
  if (fields == 0) {
    problem = "invalid PCD header: no FIELDS line";
    return false;
  }
  if (header.sizes != fields || header.types != fields ||
      (header.counts != 0 && header.counts != fields)) {
    problem = "invalid PCD header: FIELDS, SIZE, TYPE and COUNT disagree";
    return false;
  }
  if (!header.have_width || !header.have_points) {
    problem = std::string("invalid PCD header: no ") +
              (header.have_width ? "POINTS" : "WIDTH") + " line";
    return false;
  }
  for (std::size_t f = 0; f < fields; ++f)
    if (header.type_values[f] == "F" && header.size_values[f] < 4) {
      problem = "invalid PCD header: a float field (TYPE F) of SIZE " +
                std::to_string(header.size_values[f]) + " (4 or 8)";
      return false;
    }
  // the counts come from the file: keep the products below in range (every value of
  // every point takes at least a byte, whatever the DATA type)
  const auto limit = static_cast<long long>(std::min<std::uintmax_t>(
    file_size, static_cast<std::uintmax_t>(std::numeric_limits<int>::max())));
  for (std::size_t f = 0; f < header.count_values.size(); ++f)
    if (header.count_values[f] > limit) {
      problem = "invalid PCD header: COUNT " + std::to_string(header.count_values[f]) +
                " is larger than the file";
      return false;
    }
  if (header.points > static_cast<long long>(file_size)) {
    problem = "PCD data is truncated (the header announces " +
              std::to_string(header.points) + " points)";
    return false;
  }
  if ((header.height != 0 &&
       header.width > std::numeric_limits<long long>::max() / header.height) ||
      header.width * header.height != header.points) {
    problem = "invalid PCD header: WIDTH x HEIGHT differs from POINTS";
    return false;
  }
  const std::string type = values.empty() ? std::string() : values[0];
  if (type != "ascii" && type != "binary" && type != "binary_compressed") {
    problem = "invalid PCD header: unknown DATA type '" + type + "'";
    return false;
  }
  std::uintmax_t point_bytes = 0, point_values = 0;
  for (std::size_t f = 0; f < fields; ++f) {
    const auto count =
      static_cast<std::uintmax_t>(header.counts ? header.count_values[f] : 1);
    point_bytes += static_cast<std::uintmax_t>(header.size_values[f]) * count;
    point_values += count;
  }
  const auto points = static_cast<std::uintmax_t>(header.points);
  if (type == "ascii" && points > 0 &&
      consumed + 2 * point_values * points > file_size + 1) {
    // n values take at least 2n - 1 bytes: PCL would first allocate the points
    problem = "PCD data is truncated or corrupt (the header announces " +
              std::to_string(header.points) + " points of " +
              std::to_string(point_values) + " values)";
    return false;
  }
  if (type == "binary") {
    if (consumed + point_bytes * static_cast<std::uintmax_t>(header.points) >
        file_size) {
      problem = "PCD data is truncated (the header announces " +
                std::to_string(header.points) + " points)";
      return false;
    }
  } else if (type == "binary_compressed" && header.points > 0) {
    return checkCompressedBlock(path, consumed, file_size, point_bytes * points,
                                problem);
  }
  return true;
}

/** \brief PCL 1.13's PCDReader::readHeader does not stop at DATA: it reads on while a
 * line is empty, a comment (its first word starts with '#') or starts with a keyword,
 * matched by prefix ("WIDTHS" is WIDTH), and a later FIELDS, POINTS or DATA line
 * redefines the cloud or moves its body (an ascii header then read as binary: a huge
 * allocation found by fuzzing). After the DATA line the check validated (line
 * `line_number`), the first line PCL reads on that is neither empty nor a comment must
 * not start with a keyword. */
bool
checkAfterData(std::istream& in, int line_number, std::string& problem)
{
  static const char* const keywords[] = {"VERSION",   "FIELDS", "COLUMNS", "SIZE",
                                         "TYPE",      "COUNT",  "WIDTH",   "HEIGHT",
                                         "VIEWPOINT", "POINTS", "DATA"};
  for (std::string line; std::getline(in, line);) {
    ++line_number;
    if (line.empty())
      continue;
    std::istringstream words(line);
    words.imbue(std::locale::classic());
    std::string first;
    words >> first;
    if (!first.empty() && first[0] == '#')
      continue;
    for (const std::string keyword : keywords)
      if (first.compare(0, keyword.size(), keyword) == 0) {
        problem = "invalid PCD header: " +
                  (keyword == "DATA" ? std::string("a second DATA line")
                                     : "a " + keyword + " line after DATA") +
                  " (line " + std::to_string(line_number) + ")";
        return false;
      }
    return true;
  }
  return true;
}

} // namespace

bool
checkPcdHeader(const std::string& path, std::uintmax_t file_size, std::string& problem)
{
  std::ifstream in(path, std::ios::binary);
  std::string line;
  PcdHeader header;
  std::uintmax_t consumed = 0;
  for (int line_number = 1; line_number <= 64 && std::getline(in, line);
       ++line_number) {
    consumed += line.size() + 1;
    if (line.empty())
      continue;
    if (line.back() == '\r')
      line.pop_back();
    // PCL skips only empty lines: one of spaces (or a lone CR) ends its header, before
    // DATA, and it reads no points
    if (line.find_first_not_of(" \t\v\f\r") == std::string::npos) {
      problem =
        "invalid PCD header: a blank line that is not empty before DATA (line " +
        std::to_string(line_number) + ")";
      return false;
    }
    if (line[0] == '#')
      continue;
    for (char c : line)
      if (c != '\t' && !std::isprint(static_cast<unsigned char>(c))) {
        problem = "not a PCD file (binary data in the header, line " +
                  std::to_string(line_number) + ")";
        return false;
      }
    std::istringstream words(line);
    std::string key;
    words >> key;
    std::vector<std::string> values;
    for (std::string w; words >> w;)
      values.push_back(w);
    if (key == "DATA")
      return checkDataLine(path, header, values, consumed, file_size, problem) &&
             checkAfterData(in, line_number, problem);
    if (!readHeaderLine(line, key, values, header, problem))
      return false;
  }
  problem = "not a PCD file (no DATA line in the header)";
  return false;
}

} // namespace visfeat_tools
