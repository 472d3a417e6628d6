// Helpers shared by the visfeat command-line programs (not installed, not public API):
// strict option parsing, safe loading of .pcd/.ply files into pcl::PCLPointCloud2,
// and output files that appear only when they are complete.
#pragma once

#include <pcl/PCLPointCloud2.h>
#include <pcl/common/io.h>
#include <pcl/console/parse.h>
#include <pcl/console/print.h>
#include <pcl/conversions.h>
#include <pcl/io/pcd_io.h>
#include <pcl/io/ply_io.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <new>
#include <set>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

namespace visfeat_tools {

namespace fs = std::filesystem;

/** \brief The extension of a path, lower case, with its dot ("" when none). */
inline std::string
lowerExtension(const std::string& path)
{
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

/** \brief Strict integer parse: the whole string, base 10, no overflow. */
inline bool
parseInteger(const std::string& text, long long& value)
{
  if (text.empty() || std::isspace(static_cast<unsigned char>(text[0])))
    return false;
  errno = 0;
  char* end = nullptr;
  const long long v = std::strtoll(text.c_str(), &end, 10);
  if (errno != 0 || end == text.c_str() || *end != '\0')
    return false;
  value = v;
  return true;
}

/** \brief Strict real parse: the whole string, finite. */
inline bool
parseReal(const std::string& text, double& value)
{
  if (text.empty() || std::isspace(static_cast<unsigned char>(text[0])))
    return false;
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (errno != 0 || end == text.c_str() || *end != '\0' || !std::isfinite(v))
    return false;
  value = v;
  return true;
}

/** \brief "a,b,c" -> {"a", "b", "c"} (empty items kept, so "a,,b" can be refused). */
inline std::vector<std::string>
splitList(const std::string& text)
{
  std::vector<std::string> items;
  std::string item;
  std::istringstream stream(text);
  while (std::getline(stream, item, ','))
    items.push_back(item);
  if (!text.empty() && text.back() == ',')
    items.emplace_back();
  return items;
}

/** \brief The command line split into positional arguments, options with a value and
 * switches, refusing unknown options and options without their value.
 *
 * pcl::console::parse_argument() returns -1 alike for an absent option, a missing
 * value and a value that is not a number (and strtoul takes "-1" for 4294967295), so
 * the tools parse the values themselves and say what is wrong. When an option is
 * repeated the last value wins. */
class Arguments
{
public:
  Arguments(int argc,
            char** argv,
            const std::set<std::string>& value_options,
            const std::set<std::string>& switches)
  {
    for (int i = 1; i < argc; ++i) {
      const std::string arg = argv[i];
      if (value_options.count(arg)) {
        if (i + 1 >= argc) {
          error_ = "option " + arg + " needs a value";
          return;
        }
        values_[arg] = argv[++i];
      } else if (switches.count(arg)) {
        switches_.insert(arg);
      } else if (arg.size() > 1 && arg[0] == '-' &&
                 !std::isdigit(static_cast<unsigned char>(arg[1])) && arg[1] != '.') {
        error_ = "unknown option " + arg + " (see -h)";
        return;
      } else {
        positional_.push_back(arg);
      }
    }
  }

  bool ok() const { return error_.empty(); }

  const std::string& error() const { return error_; }

  const std::vector<std::string>& positional() const { return positional_; }

  bool has(const std::string& name) const
  {
    return values_.count(name) > 0 || switches_.count(name) > 0;
  }

  /** \brief The raw value of an option, or "" when absent. */
  std::string value(const std::string& name) const
  {
    const auto it = values_.find(name);
    return it == values_.end() ? std::string() : it->second;
  }

  /** \brief Integer option in [min, max]; untouched when absent. False + message on a
   * bad value. */
  template <typename Int>
  bool getInteger(const std::string& name,
                  long long min,
                  long long max,
                  Int& out,
                  std::string& error) const
  {
    const auto it = values_.find(name);
    if (it == values_.end())
      return true;
    long long v = 0;
    if (!parseInteger(it->second, v)) {
      error = name + " expects an integer, got '" + it->second + "'";
      return false;
    }
    if (v < min || v > max) {
      error = name + " must be in [" + std::to_string(min) + ", " +
              std::to_string(max) + "], got " + it->second;
      return false;
    }
    out = static_cast<Int>(v);
    return true;
  }

  /** \brief Real option in [min, max]; untouched when absent. */
  bool getReal(const std::string& name,
               double min,
               double max,
               double& out,
               std::string& error) const
  {
    const auto it = values_.find(name);
    if (it == values_.end())
      return true;
    double v = 0.0;
    if (!parseReal(it->second, v)) {
      error = name + " expects a number, got '" + it->second + "'";
      return false;
    }
    if (v < min || v > max) {
      std::ostringstream s;
      s << name << " must be in [" << min << ", " << max << "], got " << it->second;
      error = s.str();
      return false;
    }
    out = v;
    return true;
  }

private:
  std::map<std::string, std::string> values_;
  std::set<std::string> switches_;
  std::vector<std::string> positional_;
  std::string error_;
};

/** \brief -q: errors only. print_highlight() and print_value() ignore the verbosity
 * level, so stdout itself is sent to /dev/null; errors go to stderr. */
inline void
beQuiet()
{
  pcl::console::setVerbosityLevel(pcl::console::L_ERROR);
  std::fflush(stdout);
  if (!std::freopen("/dev/null", "w", stdout))
    std::fclose(stdout);
}

/** \brief Print one error line (PCL style, red on a terminal) to stderr. */
/** \brief Monotonic seconds, for timing phases of a tool run. */
inline double
secondsNow()
{
  return std::chrono::duration<double>(
           std::chrono::steady_clock::now().time_since_epoch())
    .count();
}

inline void
printError(const std::string& program, const std::string& message)
{
  pcl::console::print_error("%s: error: %s\n", program.c_str(), message.c_str());
}

/** \brief The shared main() of the tools: -h / --help print the help (exit 0), no
 * argument at all prints it too (exit 1) when `arguments_required`, and any exception
 * escaping `run` becomes one error line and exit code 1, never a crash. */
template <typename Help, typename Run>
int
toolMain(int argc,
         char** argv,
         const std::string& program,
         bool arguments_required,
         Help&& print_help,
         Run&& run)
{
  if (arguments_required && argc < 2) {
    print_help(argv[0]);
    return 1;
  }
  if (pcl::console::find_switch(argc, argv, "-h") ||
      pcl::console::find_switch(argc, argv, "--help")) {
    print_help(argv[0]);
    return 0;
  }
  try {
    return run(argc, argv);
  } catch (const std::bad_alloc&) {
    printError(program, "out of memory");
  } catch (const std::exception& e) {
    printError(program, e.what());
  }
  return 1;
}

/** \brief The temporary name an output is written to before being renamed into place.
 */
inline std::string
temporaryPath(const std::string& path)
{
  return path + ".tmp";
}

/** \brief Check, before any work, that `path` can be created: its directory exists and
 * is writable, and `path` is not a directory. Creates and removes the temporary file.
 */
inline bool
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

/** \brief Move the finished temporary file into place (same directory: atomic). */
inline bool
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

/** \brief Remove a temporary file left by a failed write. */
inline void
discardOutput(const std::string& path)
{
  std::error_code ec;
  fs::remove(temporaryPath(path), ec);
}

/** \brief Run a PCL reader with its console messages silenced (the tools print one line
 * of their own instead), restoring the verbosity afterwards. */
template <typename Function>
int
quietly(Function&& function)
{
  const pcl::console::VERBOSITY_LEVEL level = pcl::console::getVerbosityLevel();
  pcl::console::setVerbosityLevel(pcl::console::L_ALWAYS);
  const int result = function();
  pcl::console::setVerbosityLevel(level);
  return result;
}

/** \brief Validate a PCD header before PCL reads the file.
 *
 * PCL 1.13's PCDReader dereferences garbage when the header has no FIELDS line or is
 * not a PCD header at all (a text file or an empty file renamed .pcd crashes it), so
 * the header is checked first: the keywords FIELDS, SIZE, TYPE, WIDTH, POINTS and
 * DATA, consistent counts, and for DATA binary a file long enough for the points. */
inline bool
checkPcdHeader(const std::string& path, std::uintmax_t file_size, std::string& problem)
{
  std::ifstream in(path, std::ios::binary);
  std::string line;
  std::size_t fields = 0, sizes = 0, types = 0, counts = 0;
  std::vector<long long> size_values, count_values;
  bool have_width = false, have_points = false;
  long long width = 0, height = 1, points = -1;
  std::uintmax_t consumed = 0;
  for (int line_number = 1; line_number <= 64 && std::getline(in, line);
       ++line_number) {
    consumed += line.size() + 1;
    if (!line.empty() && line.back() == '\r')
      line.pop_back();
    if (line.empty() || line[0] == '#')
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
    auto integers = [&](std::vector<long long>& out) {
      for (const auto& v : values) {
        long long n = 0;
        if (!parseInteger(v, n) || n < 0)
          return false;
        out.push_back(n);
      }
      return true;
    };
    std::vector<long long> numbers;
    if (key == "VERSION" || key == "VIEWPOINT")
      continue;
    if (key == "FIELDS" || key == "COLUMNS")
      fields = values.size();
    else if (key == "SIZE") {
      sizes = values.size();
      if (!integers(size_values)) {
        problem = "invalid PCD header: bad SIZE line";
        return false;
      }
      for (long long s : size_values)
        if (s != 1 && s != 2 && s != 4 && s != 8) {
          problem = "invalid PCD header: field size " + std::to_string(s) + " in SIZE";
          return false;
        }
    } else if (key == "TYPE") {
      types = values.size();
      for (const auto& t : values)
        if (t != "F" && t != "I" && t != "U") {
          problem = "invalid PCD header: field type '" + t + "' in TYPE";
          return false;
        }
    } else if (key == "COUNT") {
      counts = values.size();
      if (!integers(count_values)) {
        problem = "invalid PCD header: bad COUNT line";
        return false;
      }
    } else if (key == "WIDTH" || key == "HEIGHT" || key == "POINTS") {
      if (values.size() != 1 || !integers(numbers)) {
        problem = "invalid PCD header: bad " + key + " line";
        return false;
      }
      if (key == "WIDTH") {
        width = numbers[0];
        have_width = true;
      } else if (key == "HEIGHT")
        height = numbers[0];
      else {
        points = numbers[0];
        have_points = true;
      }
    } else if (key == "DATA") {
      if (fields == 0) {
        problem = "invalid PCD header: no FIELDS line";
        return false;
      }
      if (sizes != fields || types != fields || (counts != 0 && counts != fields)) {
        problem = "invalid PCD header: FIELDS, SIZE, TYPE and COUNT disagree";
        return false;
      }
      if (!have_width || !have_points) {
        problem = std::string("invalid PCD header: no ") +
                  (have_width ? "POINTS" : "WIDTH") + " line";
        return false;
      }
      if (width * height != points) {
        problem = "invalid PCD header: WIDTH x HEIGHT differs from POINTS";
        return false;
      }
      const std::string type = values.empty() ? std::string() : values[0];
      if (type != "ascii" && type != "binary" && type != "binary_compressed") {
        problem = "invalid PCD header: unknown DATA type '" + type + "'";
        return false;
      }
      if (type == "binary") {
        std::uintmax_t point_bytes = 0;
        for (std::size_t f = 0; f < fields; ++f)
          point_bytes += static_cast<std::uintmax_t>(size_values[f]) *
                         static_cast<std::uintmax_t>(counts ? count_values[f] : 1);
        if (consumed + point_bytes * static_cast<std::uintmax_t>(points) > file_size) {
          problem = "PCD data is truncated (the header announces " +
                    std::to_string(points) + " points)";
          return false;
        }
      } else if (type == "binary_compressed" && points > 0 &&
                 consumed + 8 > file_size) {
        problem = "PCD data is truncated (no compressed block)";
        return false;
      }
      return true;
    } else {
      problem = "not a PCD file (unexpected header line '" + line.substr(0, 40) + "')";
      return false;
    }
  }
  problem = "not a PCD file (no DATA line in the header)";
  return false;
}

/** \brief Load a .pcd or .ply file (extension checked case-insensitively) into a
 * PCLPointCloud2, keeping every field. On failure `error` is one line naming the file
 * and the problem. origin / orientation are the PCD viewpoint (identity for PLY). */
inline bool
loadCloud(const std::string& path,
          pcl::PCLPointCloud2& cloud,
          Eigen::Vector4f& origin,
          Eigen::Quaternionf& orientation,
          std::string& error)
{
  origin = Eigen::Vector4f::Zero();
  orientation = Eigen::Quaternionf::Identity();
  const std::string ext = lowerExtension(path);
  if (ext != ".pcd" && ext != ".ply") {
    error = "'" + path + "': unknown extension '" + ext +
            "' (expected .pcd, .ply, .obj or .off)";
    return false;
  }
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (!fs::exists(status)) {
    error = "'" + path + "': no such file";
    return false;
  }
  if (fs::is_directory(status)) {
    error = "'" + path + "': is a directory";
    return false;
  }
  if (!std::ifstream(path, std::ios::binary)) {
    error = "'" + path + "': cannot open: " + std::strerror(errno);
    return false;
  }
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec || size == 0) {
    error = "'" + path + "': file is empty";
    return false;
  }
  if (ext == ".pcd") {
    std::string problem;
    if (!checkPcdHeader(path, size, problem)) {
      error = "'" + path + "': " + problem;
      return false;
    }
    if (quietly(
          [&] { return pcl::io::loadPCDFile(path, cloud, origin, orientation); }) < 0) {
      error = "'" + path + "': PCD data is truncated or corrupt";
      return false;
    }
  } else {
    if (quietly(
          [&] { return pcl::io::loadPLYFile(path, cloud, origin, orientation); }) < 0) {
      error =
        "'" + path + "': not a valid PLY file (header or data could not be parsed)";
      return false;
    }
  }
  return true;
}

/** \brief Check that a cloud has scalar numeric x, y, z fields. */
inline bool
hasXYZ(const pcl::PCLPointCloud2& cloud, std::string& problem)
{
  for (const char* name : {"x", "y", "z"}) {
    const int index = pcl::getFieldIndex(cloud, name);
    if (index < 0) {
      problem = std::string("no '") + name +
                "' field (fields: " + pcl::getFieldsList(cloud) + ")";
      return false;
    }
    if (cloud.fields[static_cast<std::size_t>(index)].count != 1) {
      problem = std::string("field '") + name + "' is not a scalar";
      return false;
    }
  }
  return true;
}

/** \brief Read field f of one point as a double, whatever its numeric type. */
inline double
readScalar(const std::uint8_t* p, std::uint8_t datatype)
{
  auto get = [p](auto zero) {
    decltype(zero) v;
    std::memcpy(&v, p, sizeof(v));
    return static_cast<double>(v);
  };
  switch (datatype) {
  case pcl::PCLPointField::INT8:
    return get(std::int8_t{});
  case pcl::PCLPointField::UINT8:
    return get(std::uint8_t{});
  case pcl::PCLPointField::INT16:
    return get(std::int16_t{});
  case pcl::PCLPointField::UINT16:
    return get(std::uint16_t{});
  case pcl::PCLPointField::INT32:
    return get(std::int32_t{});
  case pcl::PCLPointField::UINT32:
    return get(std::uint32_t{});
  case pcl::PCLPointField::FLOAT32:
    return get(float{});
  case pcl::PCLPointField::FLOAT64:
    return get(double{});
  default:
    return std::numeric_limits<double>::quiet_NaN();
  }
}

/** \brief x, y, z of a PCLPointCloud2 as PointXYZ: fromPCLPointCloud2 when they are
 * float (the usual case), else converted from whatever numeric type they have (PLY
 * files often store double). Call hasXYZ() first. */
inline void
toXYZ(const pcl::PCLPointCloud2& in, pcl::PointCloud<pcl::PointXYZ>& out)
{
  const pcl::PCLPointField& fx =
    in.fields[static_cast<std::size_t>(pcl::getFieldIndex(in, "x"))];
  const pcl::PCLPointField& fy =
    in.fields[static_cast<std::size_t>(pcl::getFieldIndex(in, "y"))];
  const pcl::PCLPointField& fz =
    in.fields[static_cast<std::size_t>(pcl::getFieldIndex(in, "z"))];
  if (fx.datatype == pcl::PCLPointField::FLOAT32 &&
      fy.datatype == pcl::PCLPointField::FLOAT32 &&
      fz.datatype == pcl::PCLPointField::FLOAT32) {
    pcl::fromPCLPointCloud2(in, out);
    return;
  }
  const std::size_t n = static_cast<std::size_t>(in.width) * in.height;
  out.resize(n);
  out.width = in.width;
  out.height = in.height;
  out.is_dense = true;
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint8_t* base = in.data.data() + i * in.point_step;
    pcl::PointXYZ& p = out[i];
    p.x = static_cast<float>(readScalar(base + fx.offset, fx.datatype));
    p.y = static_cast<float>(readScalar(base + fy.offset, fy.datatype));
    p.z = static_cast<float>(readScalar(base + fz.offset, fz.datatype));
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      out.is_dense = false;
  }
}

/** \brief A copy of `in` without the named fields, the others packed in offset order
 * (padding fields "_" dropped too). Returns `in` unchanged when none is present. */
inline pcl::PCLPointCloud2
withoutFields(const pcl::PCLPointCloud2& in, const std::set<std::string>& names)
{
  bool any = false;
  for (const auto& f : in.fields)
    any = any || names.count(f.name) > 0;
  if (!any)
    return in;

  std::vector<pcl::PCLPointField> kept;
  for (const auto& f : in.fields)
    if (!names.count(f.name) && f.name != "_")
      kept.push_back(f);
  std::sort(kept.begin(), kept.end(),
            [](const pcl::PCLPointField& a, const pcl::PCLPointField& b) {
              return a.offset < b.offset;
            });

  pcl::PCLPointCloud2 out;
  out.header = in.header;
  out.width = in.width;
  out.height = in.height;
  out.is_bigendian = in.is_bigendian;
  out.is_dense = in.is_dense;
  std::vector<std::uint32_t> source_offsets, sizes;
  std::uint32_t step = 0;
  for (auto f : kept) {
    const std::uint32_t size =
      f.count * static_cast<std::uint32_t>(pcl::getFieldSize(f.datatype));
    source_offsets.push_back(f.offset);
    sizes.push_back(size);
    f.offset = step;
    out.fields.push_back(f);
    step += size;
  }
  out.point_step = step;
  out.row_step = step * out.width;
  const std::size_t n = static_cast<std::size_t>(in.width) * in.height;
  out.data.resize(n * step);
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint8_t* src = in.data.data() + i * in.point_step;
    std::uint8_t* dst = out.data.data() + i * step;
    for (std::size_t f = 0; f < out.fields.size(); ++f)
      std::memcpy(dst + out.fields[f].offset, src + source_offsets[f], sizes[f]);
  }
  return out;
}

} // namespace visfeat_tools
