// visfeat: per-point visibility features of a point cloud, in the manner of PCL's
// tools/normal_estimation.cpp. Every input field survives; visibility_radius, label and
// feature_class are added, and the result is written as binary compressed PCD.

#include "render_picture.h"
#include "tool_input.h"
#include "tool_utils.h"

#include <fstream>
#include <visfeat/core/common/error.h>
#include <visfeat/core/common/memory_budget.h>
#include <visfeat/core/grid/grid_spec.h>
#include <visfeat/core/visibility/visibility_map.h>
#include <visfeat/point_types.h>
#include <visfeat/visibility_feature_estimation.h>

#include <pcl/console/parse.h>
#include <pcl/console/print.h>
#include <pcl/console/time.h>

#include <chrono>
#include <cstdio>
#include <memory>
#include <mutex>
#include <new>
#include <string>
#include <vector>

#include <unistd.h>

using namespace pcl::console;
namespace vt = visfeat_tools;

namespace {

const char* const kProgram = "visfeat";

// No default resolution: without -resolution it follows from the point spacing
// (kSpacingsPerCell spacings per cell, tool_input.h).
constexpr int kDefaultMinRadius = 16;
constexpr int kDefaultVertexCells = 25;
constexpr double kDefaultDimensionality = 3.5;
constexpr double kDefaultOpacity = 0.0;
constexpr int kDefaultThreads = 0;

void
printHelp(const char* program)
{
  print_error("Syntax is: %s input.{pcd,ply,obj,off} output.pcd <options>\n", program);
  print_info(
    "  Labels every point with the visibility radius of its voxel-band cell (Chica et "
    "al.,\n"
    "  \"Visibility-Based Feature Extraction From Discrete Models\"). The output "
    "holds\n"
    "  every field of the input plus visibility_radius (float), label (uint32) and\n"
    "  feature_class (uint8: 0 none, 1 vertex, 2 edge, 3 face); an existing field of\n"
    "  one of these names is overwritten. label is the region id (0 = none).\n");
  print_info(
    "  A mesh (.obj, .off, or .ply with faces) is first sampled to a cloud: uniformly\n"
    "  by area, with a fixed seed (the same mesh always gives the same cloud).\n");
  print_info("  where options are:\n");
  print_info("    -resolution N     = cells along the longest side of the "
             "bounding box (default: ");
  print_value("automatic");
  print_info(": %g point spacings per cell, the spacing estimated from k-NN "
             "distances; %d-%d cells)\n",
             vt::kSpacingsPerCell, visfeat::GridSpec::kMinResolution,
             visfeat::GridSpec::kMaxResolution);
  print_info(
    "    -min_radius R     = cells with radius >= R form components (default: ");
  print_value("%d", kDefaultMinRadius);
  print_info(" rings; the paper used 11)\n");
  print_info("    -max_radius R     = cap of the visibility radius (default: ");
  print_value("min_radius");
  print_info("; %d-%d rings, >= min_radius)\n", 1, visfeat::VisibilityMap::kMaxRadius);
  print_info("    -vertex_cells N   = components of <= N cells are vertex candidates "
             "(default: ");
  print_value("%d", kDefaultVertexCells);
  print_info(" cells)\n");
  print_info("    -dimensionality D = raw mode: edge if mean same-component "
             "6-neighbours < D (default: ");
  print_value("%g", kDefaultDimensionality);
  print_info(")\n");
  print_info("    -raw              = the paper's literal components (no regions, no "
             "clean-up)\n");
  print_info("    -no_regions       = label the components' cores only, not every "
             "point\n");
  print_info("    -opacity D        = blocked length tolerated between two "
             "cells (default: ");
  print_value("%g", kDefaultOpacity);
  print_info(" cell edges = exact)\n");
  print_info("    -paper_noise      = the paper's setting for noise (its Section 6): "
             "-opacity ");
  print_value("%g",
              visfeat::VisibilityFeatureEstimation<pcl::PointXYZ>::kPaperNoiseOpacity);
  print_info(", no smoothing; -noise_mode does better on our measurements\n");
  print_info("    -noise_mode       = noisy scans (Gaussian noise up to ~0.5 cell): "
             "-smooth 2, feature points within 1.25 cells of a curve (default: ");
  print_value("off");
  print_info(")\n");
  print_info("    -smooth R         = project every point onto the plane of its "
             "neighbours within R cells first (default: ");
  print_value("0");
  print_info(" = off, ");
  print_value("2");
  print_info(" with -noise_mode; 0-8 cells)\n");
  print_info("    -threads T        = threads of the visibility map (default: ");
  print_value("%d", kDefaultThreads);
  print_info(" = all)\n");
  print_info("    -no_repair        = do not add cells to make the band "
             "6-connected (default: ");
  print_value("repair on");
  print_info(")\n");
  print_info("    -memory_limit_mb M = refuse grids needing more memory (default: ");
  print_value("0");
  print_info(" = 3/4 of physical memory, MiB)\n");
  print_info("    -voxels cells.pcd = also write one point per band cell "
             "(cell centre, i j k, visibility_radius, label, feature_class)\n");
  print_info(
    "    -graph g.{dot,json} = also write the topology graph: GraphViz DOT, or JSON "
    "with the grid and every parameter\n");
  print_info("    -mesh_points N    = mesh input: number of points to sample "
             "(default: ");
  print_value("%zu", vt::MeshDensity().points);
  print_info(" points; 1-%zu)\n", vt::kMaxMeshPoints);
  print_info(
    "    -mesh_spacing S   = mesh input: sample area / S^2 points instead, S = "
    "mean spacing (default: ");
  print_value("unset");
  print_info("; world units)\n");
  vt::printPictureHelp();
  print_info("    -q                = quiet: errors only\n");
  print_info("  Outputs are written to a temporary file and renamed when complete.\n");
}

/** \brief Progress of the visibility map on stderr: only after the first 2 s, at most
 * every 0.5 s; one line rewritten with \r on a terminal, plain lines otherwise. The
 * callback may be called from several threads at once. */
class ProgressPrinter
{
public:
  ProgressPrinter()
      : start_(Clock::now())
      , last_(start_)
      , tty_(isatty(fileno(stderr)) != 0)
  {}

  void operator()(std::size_t done, std::size_t total)
  {
    std::unique_lock<std::mutex> lock(mutex_, std::try_to_lock);
    if (!lock.owns_lock() || total == 0)
      return;
    const Clock::time_point now = Clock::now();
    const double elapsed = seconds(now - start_);
    if (elapsed < 2.0 || (printed_ && seconds(now - last_) < 0.5))
      return;
    if (!printed_) {
      // Leave the "Computing ..." line of stdout intact when both streams share a
      // terminal or a log file.
      std::fflush(stdout);
      std::fputc('\n', stderr);
    }
    last_ = now;
    printed_ = true;
    last_total_ = total;
    std::fprintf(stderr,
                 "%s  visibility map: %3d%% (%zu / %zu cells, %.1f s since start)%s",
                 tty_ ? "\r" : "", static_cast<int>(100.0 * done / total), done, total,
                 elapsed, tty_ ? "" : "\n");
    std::fflush(stderr);
  }

  /** \brief End the progress line, if one was started. */
  void finish()
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (printed_ && tty_) {
      std::fprintf(stderr,
                   "\r  visibility map: 100%% (%zu / %zu cells, %.1f s since start)\n",
                   last_total_, last_total_, seconds(Clock::now() - start_));
      std::fflush(stderr);
    }
    printed_ = false;
  }

private:
  using Clock = std::chrono::steady_clock;

  static double seconds(Clock::duration d)
  {
    return std::chrono::duration<double>(d).count();
  }

  std::mutex mutex_;
  Clock::time_point start_;
  Clock::time_point last_;
  bool tty_;
  bool printed_ = false;
  std::size_t last_total_ = 0;
};

struct Options
{
  int resolution = 0; // 0 = automatic
  int min_radius = kDefaultMinRadius;
  int max_radius = 0; // 0 = min_radius
  int vertex_cells = kDefaultVertexCells;
  double dimensionality = kDefaultDimensionality;
  bool raw = false;
  bool regions = true;
  double opacity = kDefaultOpacity;
  bool noise_mode = false;
  bool paper_noise = false;
  double smooth = -1.0; // -1 = as the mode says
  int threads = kDefaultThreads;
  bool repair = true;
  long long memory_limit_mb = 0;
  std::string voxels;
  std::string graph;
  vt::MeshDensity mesh;
  bool quiet = false;
};

int
fail(const std::string& message)
{
  vt::printError(kProgram, message);
  return 1;
}

/** \brief Write a PCLPointCloud2 as binary compressed PCD to the temporary name of
 * `path`; commitOutput() moves it into place. */
bool
writeTemporary(const std::string& path,
               const pcl::PCLPointCloud2& cloud,
               const Eigen::Vector4f& origin,
               const Eigen::Quaternionf& orientation,
               std::string& error)
{
  pcl::PCDWriter writer;
  const int rc = vt::quietly([&] {
    return writer.writeBinaryCompressed(vt::temporaryPath(path), cloud, origin,
                                        orientation);
  });
  if (rc < 0) {
    vt::discardOutput(path);
    error = "cannot write '" + path + "' (disk full or not writable?)";
    return false;
  }
  return true;
}

/** \brief The -voxels cloud: one PointVoxel per band cell, at the cell centre. */
pcl::PointCloud<visfeat::PointVoxel>
voxelCloud(const visfeat::VoxelBand& band,
           const visfeat::VisibilityMap& map,
           const visfeat::FeatureSegmentation& segmentation)
{
  pcl::PointCloud<visfeat::PointVoxel> cells;
  cells.resize(band.size());
  const bool have_radii = map.radii().size() == band.size();
  for (std::size_t id = 0; id < band.size(); ++id) {
    const visfeat::CellCoord& c = band.coord(static_cast<visfeat::CellId>(id));
    const Eigen::Vector3d centre = band.grid().cellCenter(c);
    visfeat::PointVoxel& v = cells[id];
    v.x = static_cast<float>(centre.x());
    v.y = static_cast<float>(centre.y());
    v.z = static_cast<float>(centre.z());
    v.i = c.x();
    v.j = c.y();
    v.k = c.z();
    v.visibility_radius =
      have_radii ? static_cast<float>(map.radius(static_cast<visfeat::CellId>(id)))
                 : 0.f;
    const bool labeled = segmentation.cellLabels().size() == band.size();
    v.label = labeled ? segmentation.cellLabels()[id] : 0u;
    v.feature_class = static_cast<std::uint8_t>(
      labeled ? segmentation.cellClass(static_cast<visfeat::CellId>(id))
              : visfeat::FeatureClass::kNone);
  }
  cells.width = static_cast<std::uint32_t>(cells.size());
  cells.height = 1;
  cells.is_dense = true;
  return cells;
}

void
printHistogram(const visfeat::VisibilityMap& map, int max_radius)
{
  std::vector<std::size_t> counts(static_cast<std::size_t>(std::max(max_radius, 0)) + 1,
                                  0);
  for (std::uint8_t r : map.radii())
    ++counts[std::min<std::size_t>(r, counts.size() - 1)];
  print_info("Visibility radius (rings: cells):");
  int shown = 0;
  for (std::size_t r = 0; r < counts.size(); ++r) {
    if (counts[r] == 0)
      continue;
    if (shown > 0 && shown % 8 == 0)
      print_info("\n                                 ");
    print_info(" ");
    print_value("%zu", r);
    print_info(":");
    print_value("%zu", counts[r]);
    ++shown;
  }
  if (shown == 0)
    print_info(" none");
  print_info("  (radii without cells omitted)\n");
}

int
run(int argc, char** argv)
{
  const vt::Arguments args(
    argc, argv,
    {"-resolution", "-max_radius", "-min_radius", "-vertex_cells", "-dimensionality",
     "-opacity", "-smooth", "-threads", "-memory_limit_mb", "-voxels", "-graph",
     "-mesh_points", "-mesh_spacing", "-png", "-png_radius", "-png_size"},
    {"-no_repair", "-raw", "-no_regions", "-noise_mode", "-paper_noise", "-q", "-h",
     "--help"});
  if (!args.ok())
    return fail(args.error());

  Options opt;
  opt.quiet = args.has("-q");
  opt.noise_mode = args.has("-noise_mode");
  opt.paper_noise = args.has("-paper_noise");
  if (opt.quiet)
    vt::beQuiet();
  else
    print_info(
      "Estimate visibility features of a point cloud. For more information, use: %s "
      "-h\n",
      argv[0]);

  if (args.positional().size() != 2)
    return fail("expected an input (.pcd, .ply, .obj or .off) and an output (.pcd), "
                "got " +
                std::to_string(args.positional().size()) +
                " file argument(s) (see -h)");
  const std::string input = args.positional()[0];
  const std::string output = args.positional()[1];

  // Option values: types and signs here; ranges with the library's own limits, before
  // the (possibly long) load.
  std::string error;
  if (!args.getInteger("-resolution", visfeat::GridSpec::kMinResolution,
                       visfeat::GridSpec::kMaxResolution, opt.resolution, error) ||
      !args.getInteger("-max_radius", 1, visfeat::VisibilityMap::kMaxRadius,
                       opt.max_radius, error) ||
      !args.getInteger("-min_radius", 1, visfeat::VisibilityMap::kMaxRadius,
                       opt.min_radius, error) ||
      !args.getInteger("-vertex_cells", 0, 100000, opt.vertex_cells, error) ||
      !args.getReal("-dimensionality", 0.0, 6.0, opt.dimensionality, error) ||
      !args.getReal("-opacity", 0.0, visfeat::VisibilityMap::kMaxOpacity, opt.opacity,
                    error) ||
      !args.getReal("-smooth", 0.0, 8.0, opt.smooth, error) ||
      !args.getInteger("-threads", 0, visfeat::VisibilityMap::kMaxThreads, opt.threads,
                       error) ||
      !args.getInteger("-memory_limit_mb", 0, 1LL << 40, opt.memory_limit_mb, error) ||
      !args.getInteger("-mesh_points", 1, static_cast<long long>(vt::kMaxMeshPoints),
                       opt.mesh.points, error) ||
      !args.getReal("-mesh_spacing", -std::numeric_limits<double>::max(),
                    std::numeric_limits<double>::max(), opt.mesh.spacing, error))
    return fail(error);
  if (opt.paper_noise && opt.noise_mode)
    return fail("-paper_noise and -noise_mode are two settings for noise: give one");
  if (opt.paper_noise && args.has("-opacity"))
    return fail("-paper_noise sets the opacity: give -paper_noise or -opacity");
  if (opt.paper_noise)
    opt.opacity =
      visfeat::VisibilityFeatureEstimation<pcl::PointXYZ>::kPaperNoiseOpacity;
  if (args.has("-mesh_spacing") && !(opt.mesh.spacing > 0.0))
    return fail("-mesh_spacing must be positive, got " + args.value("-mesh_spacing"));
  if (args.has("-mesh_spacing") && args.has("-mesh_points"))
    return fail("give -mesh_points or -mesh_spacing, not both");
  opt.repair = !args.has("-no_repair");
  opt.raw = args.has("-raw");
  opt.regions = !args.has("-no_regions");
  if (opt.max_radius == 0)
    opt.max_radius = opt.min_radius;
  if (opt.min_radius > opt.max_radius)
    return fail("-min_radius " + std::to_string(opt.min_radius) +
                " exceeds -max_radius " + std::to_string(opt.max_radius) +
                ": components need radii up to min_radius");
  opt.voxels = args.value("-voxels");
  if (args.has("-voxels") && opt.voxels.empty())
    return fail("-voxels needs a file name");

  // Outputs: .pcd, writable, checked before any work.
  const std::vector<std::string> outputs{output, opt.voxels};
  for (const std::string& path : outputs) {
    if (path.empty())
      continue;
    if (vt::lowerExtension(path) != ".pcd")
      return fail("output '" + path + "' must have the extension .pcd");
    if (!vt::checkWritable(path, error))
      return fail(error);
  }
  if (!opt.voxels.empty() && opt.voxels == output)
    return fail("the -voxels file must differ from the output file");
  opt.graph = args.value("-graph");
  if (args.has("-graph")) {
    const std::string ext = vt::lowerExtension(opt.graph);
    if (opt.graph.empty())
      return fail("-graph needs a file name");
    if (ext != ".dot" && ext != ".gv" && ext != ".json")
      return fail("graph output '" + opt.graph +
                  "' must have the extension .dot, .gv or .json");
    if (!vt::checkWritable(opt.graph, error))
      return fail(error);
    if (opt.graph == output || opt.graph == opt.voxels)
      return fail("the -graph file must differ from the other outputs");
  }
  vt::PictureRequests pictures;
  if (!vt::parsePictureRequests(args, {output, opt.voxels, opt.graph}, pictures, error))
    return fail(error);

  // Load.
  TicToc tt;
  tt.tic();
  print_highlight("Loading ");
  print_value("%s ", input.c_str());
  pcl::PCLPointCloud2 cloud;
  Eigen::Vector4f origin = Eigen::Vector4f::Zero();
  Eigen::Quaternionf orientation = Eigen::Quaternionf::Identity();
  const bool mesh = vt::isMeshFile(input);
  std::string summary;
  if (mesh ? !vt::loadMeshAsCloud(input, opt.mesh, cloud, summary, error)
           : !vt::loadCloud(input, cloud, origin, orientation, error)) {
    print_info("\n");
    return fail(error);
  }
  print_info("[done, ");
  print_value("%g", tt.toc());
  print_info(" ms : ");
  print_value("%zu", static_cast<std::size_t>(cloud.width) * cloud.height);
  print_info(" points]\n");
  if (mesh)
    print_info("%s\n", summary.c_str());
  else if (args.has("-mesh_points") || args.has("-mesh_spacing"))
    print_warn("-mesh_points / -mesh_spacing ignored: '%s' is a point cloud\n",
               input.c_str());
  print_info("Available dimensions: ");
  print_value("%s\n", pcl::getFieldsList(cloud).c_str());

  std::string problem;
  if (!vt::hasXYZ(cloud, problem))
    return fail("'" + input + "': " + problem);
  if (cloud.width * static_cast<std::size_t>(cloud.height) == 0)
    return fail("'" + input + "': the cloud has no points");
  auto xyz = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  vt::toXYZ(cloud, *xyz);
  if (!vt::checkShapeAndResolution(input, *xyz, args.has("-resolution"), opt.resolution,
                                   error))
    return fail(error);

  // Compute.
  visfeat::VisibilityFeatureEstimation<pcl::PointXYZ, visfeat::PointVisibility>
    estimator;
  estimator.setInputCloud(xyz);
  estimator.setResolution(opt.resolution);
  estimator.setMaxRadius(opt.max_radius);
  estimator.setMinRadius(opt.min_radius);
  estimator.setVertexMaxCells(opt.vertex_cells);
  estimator.setDimensionality(opt.dimensionality);
  estimator.setRawMode(opt.raw);
  estimator.setCompleteRegions(opt.regions);
  estimator.setOpacity(opt.opacity);
  estimator.setNoiseMode(opt.noise_mode);
  if (opt.smooth >= 0.0)
    estimator.setSmoothingRadius(opt.smooth);
  estimator.setNumberOfThreads(static_cast<unsigned int>(opt.threads));
  estimator.setBandRepair(opt.repair);
  estimator.setMemoryLimit(static_cast<std::uint64_t>(opt.memory_limit_mb) * 1024u *
                           1024u);
  auto progress = std::make_shared<ProgressPrinter>();
  if (!opt.quiet)
    estimator.setProgressCallback(
      [progress](std::size_t done, std::size_t total) { (*progress)(done, total); });

  print_highlight("Computing visibility features ");
  print_info("(resolution ");
  print_value("%d", opt.resolution);
  print_info(", max radius ");
  print_value("%d", opt.max_radius);
  print_info(", opacity ");
  print_value("%g", opt.opacity);
  print_info(", smoothing ");
  print_value("%g", estimator.getSmoothingRadius());
  print_info(", threads ");
  print_value("%d", opt.threads);
  print_info(", repair ");
  print_value("%s", opt.repair ? "on" : "off");
  print_info(") ");
  std::fflush(stdout);
  pcl::PointCloud<visfeat::PointVisibility> result;
  tt.tic();
  {
    // compute() reports errors through getErrorMessage(); PCL_ERROR lines of its own
    // would repeat them, so only our one line is printed.
    const VERBOSITY_LEVEL level = getVerbosityLevel();
    setVerbosityLevel(L_ALWAYS);
    try {
      estimator.compute(result);
    } catch (const std::bad_alloc&) {
      setVerbosityLevel(level);
      progress->finish();
      print_info("\n");
      return fail("out of memory; lower -resolution or -max_radius");
    } catch (const std::exception& e) {
      setVerbosityLevel(level);
      progress->finish();
      print_info("\n");
      return fail(e.what());
    }
    setVerbosityLevel(level);
  }
  progress->finish();
  if (result.empty()) {
    print_info("\n");
    const std::string& why = estimator.getErrorMessage();
    return fail("'" + input +
                "': " + (why.empty() ? std::string("computation failed") : why));
  }
  print_info("[done, ");
  print_value("%g", tt.toc());
  print_info(" ms]\n");

  const visfeat::GridSpec& grid = estimator.getGrid();
  const visfeat::VoxelBand& band = estimator.getVoxelBand();
  print_info("Grid: origin (");
  print_value("%g %g %g", grid.origin.x(), grid.origin.y(), grid.origin.z());
  print_info("), cell ");
  print_value("%g", grid.cell_size);
  print_info(", dims ");
  print_value("%d x %d x %d", grid.dims.x(), grid.dims.y(), grid.dims.z());
  print_info(", mixed cells ");
  print_value("%zu", band.size());
  print_info(" (repair cells ");
  print_value("%zu", band.repairCellCount());
  print_info(")\n");
  const visfeat::PhaseTimes& times = estimator.getPhaseTimes();
  print_info("Phases: grid ");
  print_value("%.1f", times.grid_ms);
  if (times.smoothing_ms > 0.0) {
    print_info(" ms, smoothing ");
    print_value("%.1f", times.smoothing_ms);
  }
  print_info(" ms, band ");
  print_value("%.1f", times.band_ms);
  print_info(" ms, free space ");
  print_value("%.1f", times.free_space_ms);
  print_info(" ms, visibility ");
  print_value("%.1f", times.visibility_ms);
  print_info(" ms, segmentation ");
  print_value("%.1f", times.segmentation_ms);
  print_info(" ms, output ");
  print_value("%.1f", times.output_ms);
  print_info(" ms, graph ");
  print_value("%.1f", times.graph_ms);
  print_info(" ms; total ");
  print_value("%.1f", times.total());
  print_info(" ms\n");
  printHistogram(estimator.getVisibilityMap(), opt.max_radius);
  const auto counts = estimator.getSegmentation().classCounts();
  print_info("Regions%s: ", opt.raw ? " (raw components)" : "");
  print_value("%zu", counts[1]);
  print_info(" vertices, ");
  print_value("%zu", counts[2]);
  print_info(" edges, ");
  print_value("%zu", counts[3]);
  print_info(" faces\n");

  // Output: the input's fields (those named like ours removed) + the three new fields.
  if (result.size() != static_cast<std::size_t>(cloud.width) * cloud.height)
    return fail("internal error: " + std::to_string(result.size()) +
                " output points for " +
                std::to_string(static_cast<std::size_t>(cloud.width) * cloud.height) +
                " input points");
  pcl::PCLPointCloud2 features;
  pcl::toPCLPointCloud2(result, features);
  features = vt::withoutFields(features, {"x", "y", "z"});
  features.width = cloud.width;
  features.height = cloud.height;
  features.row_step = features.point_step * features.width;
  features.is_bigendian = cloud.is_bigendian;
  const pcl::PCLPointCloud2 kept =
    vt::withoutFields(cloud, {"visibility_radius", "label", "feature_class"});
  pcl::PCLPointCloud2 merged;
  // concatenateFields puts the second cloud's fields first: x y z ... then ours.
  if (!pcl::concatenateFields(features, kept, merged))
    return fail("internal error: cannot concatenate the fields");

  // Both files are written under temporary names and renamed only when both are
  // complete, so a failure leaves neither.
  tt.tic();
  print_highlight("Saving ");
  print_value("%s ", output.c_str());
  if (!writeTemporary(output, merged, origin, orientation, error)) {
    print_info("\n");
    return fail(error);
  }
  print_info("[done, ");
  print_value("%g", tt.toc());
  print_info(" ms : ");
  print_value("%u", merged.width * merged.height);
  print_info(" points; fields: ");
  print_value("%s", pcl::getFieldsList(merged).c_str());
  print_info("]\n");

  if (!opt.voxels.empty()) {
    tt.tic();
    print_highlight("Saving ");
    print_value("%s ", opt.voxels.c_str());
    const pcl::PointCloud<visfeat::PointVoxel> cells =
      voxelCloud(band, estimator.getVisibilityMap(), estimator.getSegmentation());
    pcl::PCLPointCloud2 cells2;
    pcl::toPCLPointCloud2(cells, cells2);
    if (!writeTemporary(opt.voxels, cells2, Eigen::Vector4f::Zero(),
                        Eigen::Quaternionf::Identity(), error)) {
      vt::discardOutput(output);
      print_info("\n");
      return fail(error);
    }
    print_info("[done, ");
    print_value("%g", tt.toc());
    print_info(" ms : ");
    print_value("%zu", cells.size());
    print_info(" cells]\n");
  }
  if (!opt.graph.empty()) {
    const visfeat::TopologyGraph& graph = estimator.getTopologyGraph();
    print_highlight("Saving ");
    print_value("%s ", opt.graph.c_str());
    visfeat::GraphMetadata meta;
    meta.grid = grid;
    meta.source = input;
    const auto& sp = estimator.getSegmentationParameters();
    meta.parameters = {
      {"resolution", std::to_string(opt.resolution)},
      {"min_radius", std::to_string(sp.components.min_radius)},
      {"max_radius", std::to_string(opt.max_radius)},
      {"vertex_max_cells", std::to_string(sp.components.vertex_max_cells)},
      {"dimensionality", std::to_string(sp.components.dimensionality)},
      {"face_min_depth", std::to_string(sp.components.face_min_depth)},
      {"vertex_reach", std::to_string(sp.vertex_reach)},
      {"join_distance", std::to_string(sp.join_distance)},
      {"feature_width", std::to_string(sp.feature_width)},
      {"min_piece_cells", std::to_string(sp.min_piece_cells)},
      {"raw", sp.raw ? "true" : "false"},
      {"complete_regions", sp.complete_regions ? "true" : "false"},
      {"opacity", std::to_string(opt.opacity)},
      {"noise_mode", opt.noise_mode ? "true" : "false"},
      {"paper_noise", opt.paper_noise ? "true" : "false"},
      {"smoothing_radius", std::to_string(estimator.getSmoothingRadius())},
      {"repair", opt.repair ? "true" : "false"},
      {"point_feature_distance", std::to_string(sp.point_feature_distance)},
      {"graph_dilation", std::to_string(graph.parameters().dilation_radius)},
      {"graph_min_face_contact", std::to_string(graph.parameters().min_face_contact)},
      {"graph_vertex_faces_from_edges",
       graph.parameters().vertex_faces_from_edges ? "true" : "false"}};
    std::ofstream file(vt::temporaryPath(opt.graph));
    const std::string ext = vt::lowerExtension(opt.graph);
    if (ext == ".json")
      graph.writeJson(file, meta);
    else
      graph.writeDot(file);
    file.close();
    if (!file) {
      vt::discardOutput(opt.graph);
      vt::discardOutput(output);
      if (!opt.voxels.empty())
        vt::discardOutput(opt.voxels);
      return fail("cannot write '" + opt.graph + "'");
    }
    print_info("[");
    print_value("%zu", graph.classCount(visfeat::FeatureClass::kVertex));
    print_info(" vertices, ");
    print_value("%zu", graph.classCount(visfeat::FeatureClass::kEdge));
    print_info(" edges, ");
    print_value("%zu", graph.classCount(visfeat::FeatureClass::kFace));
    print_info(" faces, ");
    print_value("%zu", graph.arcCount());
    print_info(" arcs]\n");
  }
  std::vector<std::string> outputs_done{output, opt.voxels, opt.graph};
  if (!pictures.paths().empty()) {
    vt::PictureOptions picture; // see render_picture.h
    picture.max_radius = opt.max_radius;
    picture.cell_size = grid.cell_size;
    picture.band_cells = band.size();
    picture.title = vt::fs::path(input).filename().string();
    if (!vt::writePictures(pictures, result, estimator.getTopologyGraph(), picture,
                           error)) {
      for (const std::string& path : outputs_done)
        if (!path.empty())
          vt::discardOutput(path);
      return fail(error);
    }
    for (const std::string& path : pictures.paths())
      outputs_done.push_back(path);
  }
  for (const std::string& path : outputs_done)
    if (!path.empty() && !vt::commitOutput(path, error)) {
      for (const std::string& other : outputs_done)
        if (!other.empty())
          vt::discardOutput(other);
      return fail(error);
    }
  return 0;
}

} // namespace

int
main(int argc, char** argv)
{
  return vt::toolMain(argc, argv, kProgram, true, printHelp, run);
}
