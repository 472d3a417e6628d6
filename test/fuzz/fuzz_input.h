// What the fuzz targets share: the tools' readers take paths, so each input is written
// to a file, and the tool's sequence of calls on it (visfeat.cpp, loadInput and
// prepareXYZ) with the readers' contract checked: a failure comes back as `false` and
// one error line naming the file, never as an exception, a crash or a sanitizer
// report.
#pragma once

#include "common/cloud_input.h"
#include "common/mesh_input.h"

#include <pcl/PCLPointCloud2.h>
#include <pcl/console/print.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <system_error>

namespace visfeat_fuzz {

/** \brief Stop the run as a crash, so that libFuzzer saves the input. */
[[noreturn]] inline void
fail(const std::string& what)
{
  std::fprintf(stderr, "visfeat fuzz: contract broken: %s\n", what.c_str());
  std::abort();
}

/** \brief A fresh directory under the system's temporary directory for the inputs of
 * this process, removed (with them) when it exits normally. */
class InputDirectory
{
public:
  InputDirectory()
  {
    std::string pattern =
      (std::filesystem::temp_directory_path() / "visfeat_fuzz.XXXXXX").string();
    if (mkdtemp(pattern.data()) == nullptr)
      fail("cannot create " + pattern);
    dir_ = pattern;
  }
  ~InputDirectory()
  {
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
  }
  InputDirectory(const InputDirectory&) = delete;
  InputDirectory& operator=(const InputDirectory&) = delete;

  const std::filesystem::path& path() const { return dir_; }

private:
  std::filesystem::path dir_;
};

/** \brief Write the input to "input<ext>" in the process's directory (replacing the
 * previous one) and return its path. */
inline std::string
writeInput(const std::uint8_t* data, std::size_t size, const std::string& ext)
{
  static const InputDirectory dir;
  const std::string path = (dir.path() / ("input" + ext)).string();
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  out.close();
  if (!out)
    fail("cannot write " + path);
  return path;
}

/** \brief A reader failed: its error must be one line starting with the quoted path. */
inline void
checkError(const std::string& path, const std::string& error)
{
  if (error.rfind("'" + path + "': ", 0) != 0 || error.size() <= path.size() + 4)
    fail("error '" + error + "' does not start with the file and say what is wrong");
  if (error.find('\n') != std::string::npos)
    fail("error '" + error + "' is more than one line");
}

/** \brief What the tool does with a loaded cloud: x y z checked, converted to
 * PointXYZ, and the input's fields kept for the output (withoutFields). */
inline void
useCloud(const pcl::PCLPointCloud2& cloud)
{
  std::string problem;
  if (!visfeat_tools::hasXYZ(cloud, problem)) {
    if (problem.empty())
      fail("hasXYZ failed without a problem");
    return;
  }
  const std::size_t n = static_cast<std::size_t>(cloud.width) * cloud.height;
  if (n == 0)
    return;
  pcl::PointCloud<pcl::PointXYZ> xyz;
  // as the tool: far clouds are recentred in double before the cast to float
  visfeat_tools::toXYZ(cloud, xyz, visfeat_tools::recentringOffset(cloud));
  if (xyz.size() != n)
    fail("toXYZ gave " + std::to_string(xyz.size()) + " points for " +
         std::to_string(n));
  const pcl::PCLPointCloud2 kept = visfeat_tools::withoutFields(
    cloud, {"visibility_radius", "label", "feature_class"});
  if (static_cast<std::size_t>(kept.width) * kept.height != n)
    fail("withoutFields changed the number of points");
}

/** \brief The tool's cloud input: loadCloud, then useCloud. */
inline void
loadCloudAsTool(const std::string& path)
{
  pcl::PCLPointCloud2 cloud;
  Eigen::Vector4f origin;
  Eigen::Quaternionf orientation;
  std::string error;
  if (!visfeat_tools::loadCloud(path, cloud, origin, orientation, error)) {
    checkError(path, error);
    return;
  }
  useCloud(cloud);
}

/** \brief The tool's mesh input: loadMeshAsCloud, sampling few points (the density
 * does not change the reading), then useCloud on the samples. */
inline void
loadMeshAsTool(const std::string& path)
{
  visfeat_tools::MeshDensity density;
  density.points = 64;
  pcl::PCLPointCloud2 cloud;
  std::shared_ptr<const visfeat::SurfaceMesh> mesh;
  Eigen::Vector3d offset;
  std::string summary, error;
  if (!visfeat_tools::loadMeshAsCloud(path, density, cloud, mesh, offset, summary,
                                      error)) {
    checkError(path, error);
    return;
  }
  if (!mesh || mesh->triangles.empty() || summary.empty())
    fail("a mesh loaded without triangles or summary");
  if (static_cast<std::size_t>(cloud.width) * cloud.height != density.points)
    fail("the mesh was sampled to " + std::to_string(cloud.width * cloud.height) +
         " points, not " + std::to_string(density.points));
  useCloud(cloud);
}

/** \brief The tool's choice (visfeat.cpp, loadInput): a mesh when isMeshFile, else a
 * cloud. */
inline void
loadInputAsTool(const std::string& path)
{
  if (visfeat_tools::isMeshFile(path))
    loadMeshAsTool(path);
  else
    loadCloudAsTool(path);
}

/** \brief Silence PCL's console (the readers already call it quietly; VTK and the
 * rest print errors otherwise) once per process. */
inline void
quietConsole()
{
  static const bool once = [] {
    pcl::console::setVerbosityLevel(pcl::console::L_ALWAYS);
    return true;
  }();
  (void)once;
}

} // namespace visfeat_fuzz
