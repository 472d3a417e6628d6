// Input side of the visfeat tool (not installed, not public API): meshes (.ply with
// faces, .obj, .off) sampled to a cloud, the shape of a cloud (collinear, coplanar)
// and the point spacing behind the automatic resolution.
#pragma once

#include "tool_utils.h"

#include <pcl/console/time.h>

#include <visfeat/core/common/error.h>
#include <visfeat/core/grid/grid_spec.h>
#include <visfeat/core/mesh/mesh_sampling.h>

#include <pcl/PolygonMesh.h>
#include <pcl/common/point_tests.h>
#include <pcl/io/obj_io.h>
#include <pcl/io/ply_io.h>
#include <pcl/kdtree/kdtree_flann.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace visfeat_tools {

/** \brief Seed of the mesh sampling: fixed, so a mesh always gives the same cloud. */
constexpr std::uint64_t kMeshSeed = 1;

/** \brief True when `path` is a mesh to sample: .obj, .off, or a .ply whose header
 * declares at least one face. A .ply that cannot be read stays a "cloud", so the cloud
 * reader reports what is wrong with it. */
inline bool
isMeshFile(const std::string& path)
{
  const std::string ext = lowerExtension(path);
  if (ext == ".obj" || ext == ".off")
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

/** \brief A pcl::PolygonMesh as a visfeat::SurfaceMesh: vertex coordinates whatever
 * their numeric type, polygons fanned from their first vertex. */
inline bool
toSurfaceMesh(const pcl::PolygonMesh& in, visfeat::SurfaceMesh& out, std::string& error)
{
  std::string problem;
  if (!hasXYZ(in.cloud, problem)) {
    error = "the mesh's vertices have " + problem;
    return false;
  }
  const std::size_t n = static_cast<std::size_t>(in.cloud.width) * in.cloud.height;
  if (in.cloud.data.size() < n * in.cloud.point_step) {
    error = "the mesh's vertex data is truncated";
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

/** \brief Read a mesh file (.off by visfeat::readOff, .ply and .obj by PCL). */
inline bool
loadMesh(const std::string& path, visfeat::SurfaceMesh& mesh, std::string& error)
{
  const std::string ext = lowerExtension(path);
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
  const int rc = quietly([&] {
    return ext == ".ply" ? pcl::io::loadPLYFile(path, polygons)
                         : pcl::io::loadOBJFile(path, polygons);
  });
  const std::string format = ext == ".ply" ? "PLY" : "OBJ";
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

/** \brief How densely to sample a mesh: a point count, or a mean spacing (world units)
 * when spacing > 0. */
struct MeshDensity
{
  std::size_t points = 1000000;
  double spacing = 0.0;
};

/** \brief The most points a mesh is sampled to. */
constexpr std::size_t kMaxMeshPoints = 1000000000;

/** \brief Load a mesh and sample it (area-weighted, seed kMeshSeed) into an x y z
 * cloud. `summary` says what was done, for the tool to print. */
inline bool
loadMeshAsCloud(const std::string& path,
                const MeshDensity& density,
                pcl::PCLPointCloud2& cloud,
                std::string& summary,
                std::string& error)
{
  visfeat::SurfaceMesh mesh;
  if (!loadMesh(path, mesh, error))
    return false;
  try {
    visfeat::validateMesh(mesh);
    if (mesh.triangles.empty())
      throw visfeat::Error("the mesh has no faces");
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
    pcl::PointCloud<pcl::PointXYZ> xyz;
    xyz.resize(samples.size());
    for (std::size_t i = 0; i < samples.size(); ++i)
      xyz[i].getVector3fMap() = samples[i].position;
    xyz.width = static_cast<std::uint32_t>(xyz.size());
    xyz.height = 1;
    xyz.is_dense = true;
    pcl::toPCLPointCloud2(xyz, cloud);
    std::ostringstream s;
    s << "Sampled " << samples.size() << " points from " << mesh.triangles.size()
      << " triangles (" << mesh.vertices.size() << " vertices, area " << area;
    if (density.spacing > 0.0)
      s << ", mean spacing " << density.spacing;
    else
      s << ", mean spacing " << std::sqrt(area / static_cast<double>(count));
    s << "; area-weighted uniform, seed " << kMeshSeed << ")";
    summary = s.str();
  } catch (const visfeat::Error& e) {
    error = "'" + path + "': " + e.what();
    return false;
  }
  return true;
}

/** \brief Finite points of a cloud, their bounding box and principal widths. */
struct CloudShape
{
  std::size_t finite = 0;
  /** Longest side of the bounding box (the grid's extent). */
  double extent = 0.0;
  /** Width of the points along their three principal axes, largest first. */
  Eigen::Vector3d widths = Eigen::Vector3d::Zero();
};

inline CloudShape
cloudShape(const pcl::PointCloud<pcl::PointXYZ>& cloud)
{
  CloudShape shape;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::max());
  Eigen::Vector3d hi = -lo;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const auto& p : cloud) {
    if (!pcl::isXYZFinite(p))
      continue;
    const Eigen::Vector3d v = p.getVector3fMap().cast<double>();
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
    sum += v;
    ++shape.finite;
  }
  if (shape.finite < 2)
    return shape;
  shape.extent = (hi - lo).maxCoeff();
  const Eigen::Vector3d mean = sum / static_cast<double>(shape.finite);
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const auto& p : cloud)
    if (pcl::isXYZFinite(p)) {
      const Eigen::Vector3d d = p.getVector3fMap().cast<double>() - mean;
      covariance += d * d.transpose();
    }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
  // Eigenvalues ascending: axis 2 is the main one.
  Eigen::Vector3d pmin = Eigen::Vector3d::Constant(std::numeric_limits<double>::max());
  Eigen::Vector3d pmax = -pmin;
  for (const auto& p : cloud)
    if (pcl::isXYZFinite(p)) {
      const Eigen::Vector3d q =
        solver.eigenvectors().transpose() * (p.getVector3fMap().cast<double>() - mean);
      pmin = pmin.cwiseMin(q);
      pmax = pmax.cwiseMax(q);
    }
  const Eigen::Vector3d w = pmax - pmin;
  shape.widths = Eigen::Vector3d(w[2], w[1], w[0]);
  return shape;
}

/** \brief The point spacing of a cloud: the mean distance between neighbours as
 * visfeat_generate defines it (spacing^2 = surface area per point), estimated from the
 * median distance r to the k-th nearest neighbour over a deterministic subsample
 * (every n/queries-th finite point): k neighbours cover a disc of area pi r^2, so
 * spacing = r sqrt(pi / (k - 1/3)) (k - 1/3: the median of the count for uniform
 * random samples). The median ignores edges and outliers; k = 8 ignores a few
 * duplicate points. */
struct SpacingEstimate
{
  double spacing = 0.0;
  std::size_t queries = 0;
  int k = 0;
};

inline bool
estimateSpacing(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                std::size_t max_queries,
                SpacingEstimate& estimate,
                std::string& error)
{
  auto finite = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  finite->reserve(cloud.size());
  for (const auto& p : cloud)
    if (pcl::isXYZFinite(p))
      finite->push_back(p);
  const std::size_t n = finite->size();
  if (n < 2) {
    error = "too few finite points to estimate the point spacing";
    return false;
  }
  estimate.k = static_cast<int>(std::min<std::size_t>(8, n - 1));
  pcl::KdTreeFLANN<pcl::PointXYZ> tree;
  tree.setInputCloud(finite);
  const std::size_t stride = std::max<std::size_t>(1, n / max_queries);
  std::vector<double> radii;
  pcl::Indices indices;
  std::vector<float> sqr_distances;
  for (std::size_t i = 0; i < n && radii.size() < max_queries; i += stride) {
    // k + 1: the query point itself comes back too.
    if (tree.nearestKSearch((*finite)[i], estimate.k + 1, indices, sqr_distances) <= 0)
      continue;
    radii.push_back(std::sqrt(static_cast<double>(sqr_distances.back())));
  }
  estimate.queries = radii.size();
  if (radii.empty()) {
    error = "the nearest-neighbour search found no neighbours";
    return false;
  }
  auto middle = radii.begin() + static_cast<std::ptrdiff_t>(radii.size() / 2);
  std::nth_element(radii.begin(), middle, radii.end());
  const double r = *middle;
  if (!(r > 0.0)) {
    error = "cannot estimate the point spacing: most points have " +
            std::to_string(estimate.k) + " or more duplicates";
    return false;
  }
  // For uniform random samples pi r^2 / spacing^2 is Gamma(k, 1) distributed, whose
  // median is about k - 1/3.
  estimate.spacing = r * std::sqrt(3.14159265358979323846 / (estimate.k - 1.0 / 3.0));
  return true;
}

/** \brief Cells per point spacing of the automatic resolution: a cell of 2 spacings
 * holds ~4 points per face crossing it, so the band has no holes; visfeat_generate
 * samples at 0.5 cell by default, so its clouds come back at their own resolution. */
constexpr double kSpacingsPerCell = 2.0;

/** \brief extent / (kSpacingsPerCell spacing), rounded, clamped to GridSpec's range. */
inline int
resolutionForSpacing(double extent, double spacing)
{
  const double r = std::round(extent / (kSpacingsPerCell * spacing));
  if (!(r >= visfeat::GridSpec::kMinResolution))
    return visfeat::GridSpec::kMinResolution;
  if (r > visfeat::GridSpec::kMaxResolution)
    return visfeat::GridSpec::kMaxResolution;
  return static_cast<int>(r);
}

/** \brief Points the automatic resolution queries for their spacing. */
constexpr std::size_t kSpacingQueries = 10000;

/** \brief Refuse clouds without a surface and, when the user gave no -resolution,
 * choose it from the point spacing (printing what was chosen and why).
 *
 * - All points on a line (the second principal width below 1e-5 of the first), or
 *   within 2 cells of one at the resolution: refused, there is no surface to label.
 * - All points in a plane: processed (one face: the outline of a flat patch is a
 *   boundary, not a crease), with a note.
 * - No finite point, a single one, or all coincident: left to the estimator, whose
 *   message says so. */
inline bool
checkShapeAndResolution(const std::string& input,
                        const pcl::PointCloud<pcl::PointXYZ>& xyz,
                        bool user_resolution,
                        int& resolution,
                        std::string& error)
{
  using namespace pcl::console;
  const CloudShape shape = cloudShape(xyz);
  if (shape.finite < 2 || !(shape.extent > 0.0)) {
    if (!user_resolution)
      resolution = visfeat::GridSpec::kMinResolution; // the estimator refuses it
    return true;
  }
  const double relative = 1e-5;
  if (shape.widths[1] <= relative * shape.widths[0]) {
    error = "'" + input + "': all " + std::to_string(shape.finite) +
            " finite points lie on a line (collinear): there is no surface to label";
    return false;
  }
  if (!user_resolution) {
    TicToc tt;
    tt.tic();
    print_highlight("Estimating the point spacing ");
    SpacingEstimate estimate;
    if (!estimateSpacing(xyz, kSpacingQueries, estimate, error)) {
      print_info("\n");
      error = "'" + input + "': " + error + "; give -resolution";
      return false;
    }
    resolution = resolutionForSpacing(shape.extent, estimate.spacing);
    print_info("[done, ");
    print_value("%g", tt.toc());
    print_info(" ms]\n");
    print_info("Resolution ");
    print_value("%d", resolution);
    print_info(" chosen: point spacing ");
    print_value("%.6g", estimate.spacing);
    print_info(" (median distance to the %d%s nearest neighbour over ", estimate.k,
               estimate.k == 1   ? "st"
               : estimate.k == 2 ? "nd"
               : estimate.k == 3 ? "rd"
                                 : "th");
    print_value("%zu", estimate.queries);
    print_info(" points), %g spacings per cell, extent ", kSpacingsPerCell);
    print_value("%.6g", shape.extent);
    const double wanted =
      std::round(shape.extent / (kSpacingsPerCell * estimate.spacing));
    if (wanted < visfeat::GridSpec::kMinResolution ||
        wanted > visfeat::GridSpec::kMaxResolution)
      print_info(" (clamped from %.0f)", wanted);
    print_info("; -resolution overrides\n");
  }
  const double cell = shape.extent / resolution;
  if (shape.widths[1] < 2.0 * cell) {
    std::ostringstream s;
    s << "'" << input << "': the points lie within " << shape.widths[1] / cell
      << " cells of a line at resolution " << resolution
      << ": a surface needs at least 2 cells across; raise -resolution";
    error = s.str();
    return false;
  }
  if (shape.widths[2] <= relative * shape.widths[0])
    print_info("Note: all points lie in a plane: expect one face and no edges or "
               "vertices (the outline of a flat patch is a boundary, not a crease)\n");
  return true;
}

} // namespace visfeat_tools
