// Cloud input of the visfeat tools; see cloud_input.h.

#include "common/cloud_input.h"

#include "common/arguments.h"
#include "common/mesh_input.h"
#include "common/text_cloud_input.h"
#include "common/tool_main.h"

#include <pcl/common/io.h>
#include <pcl/conversions.h>
#include <pcl/io/pcd_io.h>
#include <pcl/io/ply_io.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <locale>
#include <sstream>
#include <system_error>
#include <vector>

namespace visfeat_tools {

namespace fs = std::filesystem;

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

/** \brief visit(p) for every point of `in` whose x, y, z (any numeric type) are all
 * finite, in double precision. */
template <typename Visit>
void
forEachXYZ(const pcl::PCLPointCloud2& in, Visit visit)
{
  const int ix = pcl::getFieldIndex(in, "x"), iy = pcl::getFieldIndex(in, "y"),
            iz = pcl::getFieldIndex(in, "z");
  if (ix < 0 || iy < 0 || iz < 0)
    return;
  const pcl::PCLPointField& fx = in.fields[static_cast<std::size_t>(ix)];
  const pcl::PCLPointField& fy = in.fields[static_cast<std::size_t>(iy)];
  const pcl::PCLPointField& fz = in.fields[static_cast<std::size_t>(iz)];
  const std::size_t n = static_cast<std::size_t>(in.width) * in.height;
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint8_t* base = in.data.data() + i * in.point_step;
    const Eigen::Vector3d p(readScalar(base + fx.offset, fx.datatype),
                            readScalar(base + fy.offset, fy.datatype),
                            readScalar(base + fz.offset, fz.datatype));
    if (p.allFinite())
      visit(p);
  }
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

bool
checkInputFile(const std::string& path, std::uintmax_t& size, std::string& error)
{
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
  // a FIFO or a device would block or never end (PCL's readers loop until EOF)
  if (!fs::is_regular_file(status)) {
    error = "'" + path + "': not a regular file";
    return false;
  }
  if (!std::ifstream(path, std::ios::binary)) {
    error = "'" + path + "': cannot open: " + std::strerror(errno);
    return false;
  }
  size = fs::file_size(path, ec);
  if (ec || size == 0) {
    error = "'" + path + "': file is empty";
    return false;
  }
  return true;
}

bool
loadCloud(const std::string& path,
          pcl::PCLPointCloud2& cloud,
          Eigen::Vector4f& origin,
          Eigen::Quaternionf& orientation,
          std::string& error)
{
  origin = Eigen::Vector4f::Zero();
  orientation = Eigen::Quaternionf::Identity();
  const std::string ext = lowerExtension(path);
  if (ext != ".pcd" && ext != ".ply" && !isTextCloudFile(path)) {
    error = "'" + path + "': unknown extension '" + ext +
            "' (expected .pcd, .ply, .xyz, .txt, .obj, .off or .stl)";
    return false;
  }
  std::uintmax_t size = 0;
  if (!checkInputFile(path, size, error))
    return false;
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
  } else if (isTextCloudFile(path)) {
    std::ifstream in(path, std::ios::binary);
    std::string problem;
    if (!readTextCloud(in, cloud, problem)) {
      error = "'" + path + "': not a valid text cloud: " + problem;
      return false;
    }
  } else {
    const std::string problem = plyProblem(path);
    if (!problem.empty()) {
      error = "'" + path + "': not a valid PLY file: " + problem;
      return false;
    }
    if (quietly(
          [&] { return pcl::io::loadPLYFile(path, cloud, origin, orientation); }) < 0) {
      error =
        "'" + path + "': not a valid PLY file (header or data could not be parsed)";
      return false;
    }
  }
  // what PCL made of the file must hold together before anything reads the points
  const std::string problem = layoutProblem(cloud);
  if (!problem.empty()) {
    error = "'" + path + "': " + (ext == ".pcd" ? "PCD" : "PLY") +
            " data is inconsistent: " + problem;
    return false;
  }
  return true;
}

std::string
fieldsList(const pcl::PCLPointCloud2& cloud)
{
  if (cloud.fields.empty())
    return "none";
  std::string list = cloud.fields[0].name;
  for (std::size_t f = 1; f < cloud.fields.size(); ++f)
    list += " " + cloud.fields[f].name;
  return list;
}

std::string
layoutProblem(const pcl::PCLPointCloud2& cloud)
{
  const std::size_t n = static_cast<std::size_t>(cloud.width) * cloud.height;
  if (cloud.point_step != 0 && n > cloud.data.size() / cloud.point_step)
    return "the data holds fewer than its " + std::to_string(n) + " points";
  for (const auto& f : cloud.fields) {
    const std::uint64_t size = pcl::getFieldSize(f.datatype);
    if (size == 0)
      return "field '" + f.name + "' has an unknown type";
    if (std::uint64_t(f.offset) + size * f.count > cloud.point_step)
      return "field '" + f.name + "' lies outside its point";
  }
  return "";
}

bool
hasXYZ(const pcl::PCLPointCloud2& cloud, std::string& problem)
{
  problem = layoutProblem(cloud);
  if (!problem.empty())
    return false;
  for (const char* name : {"x", "y", "z"}) {
    const int index = pcl::getFieldIndex(cloud, name);
    if (index < 0) {
      problem =
        std::string("no '") + name + "' field (fields: " + fieldsList(cloud) + ")";
      return false;
    }
    if (cloud.fields[static_cast<std::size_t>(index)].count != 1) {
      problem = std::string("field '") + name + "' is not a scalar";
      return false;
    }
  }
  return true;
}

double
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
  case pcl::PCLPointField::INT64:
    return get(std::int64_t{});
  case pcl::PCLPointField::UINT64:
    return get(std::uint64_t{});
  case pcl::PCLPointField::FLOAT32:
    return get(float{});
  case pcl::PCLPointField::FLOAT64:
    return get(double{});
  default:
    return std::numeric_limits<double>::quiet_NaN();
  }
}

Eigen::Vector3d
recentringOffset(const pcl::PCLPointCloud2& in)
{
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::max());
  Eigen::Vector3d hi = -lo;
  forEachXYZ(in, [&](const Eigen::Vector3d& p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  });
  if (!(lo.array() <= hi.array()).all())
    return Eigen::Vector3d::Zero(); // no finite point
  const double extent = (hi - lo).maxCoeff();
  const double farthest = lo.cwiseAbs().cwiseMax(hi.cwiseAbs()).maxCoeff();
  if (!(farthest > kRecentreExtents * extent))
    return Eigen::Vector3d::Zero();
  // a round number: the centre to a multiple of the power of ten >= the extent
  const double unit =
    extent > 0.0 ? std::pow(10.0, std::ceil(std::log10(extent))) : 1.0;
  const Eigen::Vector3d centre = 0.5 * (lo + hi);
  return (centre / unit).array().round().matrix() * unit;
}

void
toXYZ(const pcl::PCLPointCloud2& in,
      pcl::PointCloud<pcl::PointXYZ>& out,
      const Eigen::Vector3d& offset)
{
  const pcl::PCLPointField& fx =
    in.fields[static_cast<std::size_t>(pcl::getFieldIndex(in, "x"))];
  const pcl::PCLPointField& fy =
    in.fields[static_cast<std::size_t>(pcl::getFieldIndex(in, "y"))];
  const pcl::PCLPointField& fz =
    in.fields[static_cast<std::size_t>(pcl::getFieldIndex(in, "z"))];
  if (offset.isZero() && fx.datatype == pcl::PCLPointField::FLOAT32 &&
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
    // the offset goes in double precision, before the cast to float
    p.x = static_cast<float>(readScalar(base + fx.offset, fx.datatype) - offset.x());
    p.y = static_cast<float>(readScalar(base + fy.offset, fy.datatype) - offset.y());
    p.z = static_cast<float>(readScalar(base + fz.offset, fz.datatype) - offset.z());
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      out.is_dense = false;
  }
}

pcl::PCLPointCloud2
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
