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
  return recentringOffset(lo, hi);
}

Eigen::Vector3d
recentringOffset(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi)
{
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
