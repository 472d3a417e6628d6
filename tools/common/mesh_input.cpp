// Mesh input of the visfeat tools; see mesh_input.h.

#include "common/mesh_input.h"

#include "common/arguments.h"
#include "common/cloud_input.h"
#include "common/double_xyz_cloud.h"
#include "common/obj_check.h"
#include "common/tool_main.h"

#include <visfeat/core/common/error.h>

#include <pcl/common/io.h>
#include <pcl/conversions.h>
#include <pcl/io/obj_io.h>
#include <pcl/io/ply_io.h>
#include <pcl/io/vtk_lib_io.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <memory>
#include <sstream>
#include <vector>

#include <unistd.h>

namespace visfeat_tools {

bool
isMeshFile(const std::string& path)
{
  const std::string ext = lowerExtension(path);
  if (ext == ".obj" || ext == ".off" || ext == ".stl")
    return true;
  if (ext != ".ply")
    return false;
  std::ifstream in(path, std::ios::binary);
  std::string line;
  for (int n = 0; n < 256 && std::getline(in, line); ++n) {
    if (!line.empty() && line.back() == '\r')
      line.pop_back();
    if (line == "end_header")
      break;
    std::istringstream words(line);
    std::string keyword, element;
    long long count = 0;
    if (words >> keyword >> element >> count && keyword == "element" &&
        element == "face")
      return count > 0;
  }
  return false;
}

bool
toSurfaceMesh(const pcl::PolygonMesh& in, visfeat::SurfaceMesh& out, std::string& error)
{
  const std::size_t n = static_cast<std::size_t>(in.cloud.width) * in.cloud.height;
  if (in.cloud.data.size() < n * in.cloud.point_step) {
    error = "the mesh's vertex data is truncated";
    return false;
  }
  std::string problem;
  if (!hasXYZ(in.cloud, problem)) {
    error = "the mesh's vertices have " + problem;
    return false;
  }
  const pcl::PCLPointField* f[3];
  for (int a = 0; a < 3; ++a)
    f[a] = &in.cloud.fields[static_cast<std::size_t>(
      pcl::getFieldIndex(in.cloud, std::string(1, static_cast<char>('x' + a))))];
  out.vertices.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint8_t* base = in.cloud.data.data() + i * in.cloud.point_step;
    for (int a = 0; a < 3; ++a)
      out.vertices[i][a] = readScalar(base + f[a]->offset, f[a]->datatype);
  }
  out.triangles.clear();
  for (std::size_t p = 0; p < in.polygons.size(); ++p) {
    const auto& v = in.polygons[p].vertices;
    if (v.size() < 3) {
      error = "face " + std::to_string(p) + " has " + std::to_string(v.size()) +
              " vertices (at least 3 needed)";
      return false;
    }
    for (const auto index : v)
      if (index < 0 || static_cast<std::size_t>(index) >= n) {
        error = "face " + std::to_string(p) + ": vertex index " +
                std::to_string(index) + " out of range (" + std::to_string(n) +
                " vertices, counting from 0)";
        return false;
      }
    auto at = [&v](std::size_t i) { return static_cast<std::uint32_t>(v[i]); };
    for (std::size_t i = 1; i + 1 < v.size(); ++i)
      out.triangles.push_back({at(0), at(i), at(i + 1)});
  }
  return true;
}

std::string
stlProblem(const std::string& path)
{
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in)
    return "cannot be opened";
  const auto size = static_cast<std::uint64_t>(in.tellg());
  in.seekg(0);
  // binary: an 80-byte header, a 32-bit little-endian triangle count, 50 bytes each
  if (size >= kStlHeaderBytes + 4) {
    unsigned char header[kStlHeaderBytes + 4];
    in.read(reinterpret_cast<char*>(header), sizeof header);
    const std::uint64_t count =
      std::uint64_t(header[80]) | std::uint64_t(header[81]) << 8 |
      std::uint64_t(header[82]) << 16 | std::uint64_t(header[83]) << 24;
    const std::uint64_t expected = kStlHeaderBytes + 4 + kStlTriangleBytes * count;
    if (size == expected)
      return count == 0 ? "a binary STL without triangles" : "";
    // text has no NUL byte; a binary STL's count and coordinates nearly always do
    const std::string head(reinterpret_cast<const char*>(header), sizeof header);
    if (head.find('\0') != std::string::npos)
      return "a binary STL of " + std::to_string(size) + " bytes whose count says " +
             std::to_string(count) + " triangles (" + std::to_string(expected) +
             " bytes): truncated or not an STL";
  }
  // ASCII: solid ... facet normal ... outer loop, vertex x y z (3 times), endloop,
  // endfacet ... endsolid
  in.clear();
  in.seekg(0);
  std::string word;
  if (!(in >> word) || word != "solid")
    return "neither a binary STL (its size does not match its triangle count) nor an "
           "ASCII one (it does not start with 'solid')";
  // VTK picks its ASCII or binary reader from the bytes (vtksys DetectFileType): a
  // "solid" file with NUL or 8-bit bytes went to the binary reader, whose triangle
  // count from bytes 80-83 asked for gigabytes. An ASCII STL is text throughout.
  in.clear();
  in.seekg(0);
  std::uint64_t offset = 0;
  for (std::istreambuf_iterator<char> it(in), end; it != end; ++it, ++offset) {
    const auto c = static_cast<unsigned char>(*it);
    if (!(c >= 0x20 && c < 0x7f) && c != '\n' && c != '\r' && c != '\t')
      return "an ASCII STL with a byte that is not text at offset " +
             std::to_string(offset) +
             " (binary data, or a binary STL of the wrong size)";
  }
  in.clear();
  in.seekg(0);
  in >> word;
  std::uint64_t vertices = 0;
  bool ended = false;
  while (in >> word) {
    if (word == "vertex") {
      double x, y, z;
      if (!(in >> x >> y >> z) || !std::isfinite(x) || !std::isfinite(y) ||
          !std::isfinite(z))
        return "an ASCII STL with a vertex that is not three finite numbers";
      ++vertices;
    } else if (word == "endsolid") {
      ended = true;
    }
  }
  if (!ended)
    return "an ASCII STL without 'endsolid' (truncated?)";
  if (vertices == 0 || vertices % 3 != 0)
    return "an ASCII STL with " + std::to_string(vertices) +
           " vertices (3 a triangle, at least one triangle)";
  return "";
}

namespace {

/** A copy of an OBJ file for PCL 1.13's reader, removed with this object: lines of only
 * spaces, tabs or CRs emptied (the reader takes a token from them: a crash, found by
 * fuzzing; CRLF files often have such lines) and the material lines (mtllib, usemtl)
 * emptied too, as the band needs the geometry only; line numbers are kept, so the
 * guard's messages name the user's lines. */
class ObjGeometryCopy
{
public:
  explicit ObjGeometryCopy(const std::string& path)
  {
    static int serial = 0;
    const std::filesystem::path copy = std::filesystem::temp_directory_path() /
                                       ("visfeat_obj_" + std::to_string(::getpid()) +
                                        "_" + std::to_string(serial++) + ".obj");
    std::ifstream in(path, std::ios::binary);
    std::ofstream out(copy, std::ios::binary);
    if (!in || !out)
      return;
    std::string line;
    while (std::getline(in, line)) {
      const std::size_t first = line.find_first_not_of(" \t\r");
      const bool blank = first == std::string::npos;
      const bool material = !blank && (line.compare(first, 7, "mtllib ") == 0 ||
                                       line.compare(first, 7, "mtllib\t") == 0 ||
                                       line.compare(first, 7, "usemtl ") == 0 ||
                                       line.compare(first, 7, "usemtl\t") == 0 ||
                                       line == "mtllib" || line == "usemtl");
      out << (blank || material ? std::string() : line) << '\n';
    }
    if (in.bad() || !out.flush())
      return;
    path_ = copy.string();
  }
  ~ObjGeometryCopy()
  {
    std::error_code ignored;
    if (!path_.empty())
      std::filesystem::remove(path_, ignored);
  }
  ObjGeometryCopy(const ObjGeometryCopy&) = delete;
  ObjGeometryCopy& operator=(const ObjGeometryCopy&) = delete;

  /** The copy's path; "" when it could not be written. */
  const std::string& path() const { return path_; }

private:
  std::string path_;
};

} // namespace

bool
loadMesh(const std::string& path, visfeat::SurfaceMesh& mesh, std::string& error)
{
  const std::string ext = lowerExtension(path);
  std::uintmax_t size = 0;
  if (!checkInputFile(path, size, error))
    return false;
  if (ext == ".off") {
    std::ifstream in(path, std::ios::binary);
    try {
      mesh = visfeat::readOff(in);
    } catch (const visfeat::Error& e) {
      error = "'" + path + "': " + e.what();
      return false;
    }
    return true;
  }
  pcl::PolygonMesh polygons;
  if (ext == ".stl") {
    // VTK's reader (through PCL) has no error path of its own: check the file first
    const std::string problem = stlProblem(path);
    if (!problem.empty()) {
      error = "'" + path + "': not a valid STL mesh: " + problem;
      return false;
    }
  } else if (ext == ".ply") {
    const std::string problem = plyProblem(path);
    if (!problem.empty()) {
      error = "'" + path + "': not a valid PLY mesh: " + problem;
      return false;
    }
  }
  // PCL's OBJ reader gets a copy without blank-but-not-empty and material lines
  std::unique_ptr<ObjGeometryCopy> obj;
  if (ext == ".obj") {
    obj = std::make_unique<ObjGeometryCopy>(path);
    if (obj->path().empty()) {
      error = "'" + path + "': cannot copy the OBJ file's geometry to " +
              std::filesystem::temp_directory_path().string();
      return false;
    }
    // PCL's OBJ reader reads past its buffers on some lines: check them first
    const std::string problem = objProblem(obj->path());
    if (!problem.empty()) {
      error = "'" + path + "': not a valid OBJ mesh: " + problem;
      return false;
    }
  }
  // PCL's readers also throw (std::length_error from an OBJ line fuzzing found):
  // that is a file they could not parse, not an error of the tool
  int rc = -1;
  try {
    rc = quietly([&] {
      if (ext == ".stl")
        return pcl::io::loadPolygonFileSTL(path, polygons) > 0 ? 0 : -1;
      return ext == ".ply" ? pcl::io::loadPLYFile(path, polygons)
                           : pcl::io::loadOBJFile(obj->path(), polygons);
    });
  } catch (const std::exception&) {
    rc = -1;
  }
  const std::string format = ext == ".ply" ? "PLY" : ext == ".stl" ? "STL" : "OBJ";
  if (rc < 0) {
    error = "'" + path + "': not a valid " + format +
            " mesh (header or data could not be parsed)";
    return false;
  }
  if (!toSurfaceMesh(polygons, mesh, error)) {
    error = "'" + path + "': " + format + " mesh: " + error;
    return false;
  }
  return true;
}

namespace {

/** OBJ (PCL's reader) and STL (VTK's; binary STL is float32 by format) come in as
 * 32-bit floats: far from the origin their coordinates step by |c| 2^-23, and the part
 * is already rounded when the recentring comes. A step above this fraction of the
 * part's extent (0.01 cell at 1,000 cells) is refused: a 100-unit part near 4.3e6
 * (survey coordinates) reads in steps of 0.5 and gave 13/44/29 for 20/33/21 without a
 * word. */
constexpr double kMaxFloatStepOfExtent = 1e-5;

void
checkFloatPrecision(const std::string& ext,
                    const Eigen::Vector3d& lo,
                    const Eigen::Vector3d& hi)
{
  const double extent = (hi - lo).maxCoeff();
  const double magnitude = lo.cwiseAbs().cwiseMax(hi.cwiseAbs()).maxCoeff();
  const double step = magnitude * std::ldexp(1.0, -23);
  if (!(step <= kMaxFloatStepOfExtent * extent)) {
    std::ostringstream msg;
    msg << (ext == ".obj" ? "OBJ" : "STL") << " coordinates are read as 32-bit floats"
        << (ext == ".obj" ? " (PCL's OBJ reader)"
                          : " (VTK's STL reader; binary STL is float32 by format)")
        << ", and this mesh lies " << magnitude << " from the origin with an extent of "
        << extent << ": its vertices are rounded to steps of " << step
        << ", too coarse for its features; move it near the origin, or give it as "
           ".ply (double properties) or .off, which are read in double and recentred";
    throw visfeat::Error(msg.str());
  }
}

} // namespace

bool
loadMeshAsCloud(const std::string& path,
                const MeshDensity& density,
                pcl::PCLPointCloud2& cloud,
                std::shared_ptr<const visfeat::SurfaceMesh>& mesh_out,
                Eigen::Vector3d& offset,
                std::string& summary,
                std::string& error)
{
  auto loaded = std::make_shared<visfeat::SurfaceMesh>();
  visfeat::SurfaceMesh& mesh = *loaded;
  if (!loadMesh(path, mesh, error))
    return false;
  try {
    visfeat::validateMesh(mesh);
    // survey coordinates: the mesh is recentred in double before anything is a float
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::max());
    Eigen::Vector3d hi = -lo;
    for (const Eigen::Vector3d& v : mesh.vertices) {
      lo = lo.cwiseMin(v);
      hi = hi.cwiseMax(v);
    }
    offset = recentringOffset(lo, hi);
    const std::string ext = lowerExtension(path);
    if (ext == ".obj" || ext == ".stl")
      checkFloatPrecision(ext, lo, hi);
    if (!offset.isZero())
      for (Eigen::Vector3d& v : mesh.vertices)
        v -= offset;
    if (mesh.triangles.empty())
      throw visfeat::Error(
        "the mesh has no faces: if its " + std::to_string(mesh.vertices.size()) +
        " vertices are a point cloud, give them as .ply, .pcd or .xyz, which are "
        "read as clouds");
    const double area = visfeat::meshArea(mesh);
    if (!(area > 0.0))
      throw visfeat::Error("the mesh has zero area (all " +
                           std::to_string(mesh.triangles.size()) +
                           " triangles are degenerate)");
    const std::size_t count =
      density.spacing > 0.0
        ? visfeat::samplesForSpacing(area, density.spacing, kMaxMeshPoints)
        : density.points;
    const std::vector<visfeat::MeshSample> samples =
      visfeat::sampleMesh(mesh, count, kMeshSeed);
    if (offset.isZero()) {
      pcl::PointCloud<pcl::PointXYZ> xyz;
      xyz.resize(samples.size());
      for (std::size_t i = 0; i < samples.size(); ++i)
        xyz[i].getVector3fMap() = samples[i].position;
      xyz.width = static_cast<std::uint32_t>(xyz.size());
      xyz.height = 1;
      xyz.is_dense = true;
      pcl::toPCLPointCloud2(xyz, cloud);
    } else {
      std::vector<Eigen::Vector3d> positions(samples.size());
      for (std::size_t i = 0; i < samples.size(); ++i)
        positions[i] = samples[i].position.cast<double>();
      cloud = doubleXYZCloud(positions, offset);
    }
    std::ostringstream s;
    s << "Sampled " << samples.size() << " points from " << mesh.triangles.size()
      << " triangles (" << mesh.vertices.size() << " vertices, area " << area;
    if (density.spacing > 0.0)
      s << ", mean spacing " << density.spacing;
    else
      s << ", mean spacing " << std::sqrt(area / static_cast<double>(count));
    s << "; area-weighted uniform, seed " << kMeshSeed << ")";
    summary = s.str();
    mesh_out = std::move(loaded);
  } catch (const visfeat::Error& e) {
    error = "'" + path + "': " + e.what();
    return false;
  }
  return true;
}

} // namespace visfeat_tools
