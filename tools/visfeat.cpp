// visfeat: per-point visibility features of a point cloud, in the manner of PCL's
// tools/normal_estimation.cpp. Every input field survives; visibility_radius, label and
// feature_class are added, and the result is written as binary compressed PCD.
//
// run(): read the options (visfeat_options.h), load the input, compute with progress,
// print a summary, then write every output under its temporary name (cloud, -voxels,
// -graph, pictures) and rename them into place only when all are complete.

#include "common/automatic_resolution.h"
#include "common/cloud_input.h"
#include "common/mesh_input.h"
#include "common/progress_printer.h"
#include "common/tool_main.h"
#include "visfeat_options.h"
#include "visfeat_outputs.h"

#include <visfeat/core/grid/grid_spec.h>
#include <visfeat/core/visibility/visibility_map.h>
#include <visfeat/point_types.h>
#include <visfeat/visibility_feature_estimation.h>

#include <pcl/common/io.h>
#include <pcl/console/print.h>
#include <pcl/console/time.h>

#include <cstdio>
#include <memory>
#include <new>
#include <string>
#include <vector>

using namespace pcl::console;
namespace vt = visfeat_tools;

namespace {

const char* const kProgram = "visfeat";

using vt::Estimator;

int
fail(const std::string& message)
{
  vt::printError(kProgram, message);
  return 1;
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

/** \brief The input as loaded: every field, the PCD viewpoint, and x y z as PointXYZ.
 */
struct Input
{
  pcl::PCLPointCloud2 cloud;
  Eigen::Vector4f origin = Eigen::Vector4f::Zero();
  Eigen::Quaternionf orientation = Eigen::Quaternionf::Identity();
  std::shared_ptr<pcl::PointCloud<pcl::PointXYZ>> xyz;
  std::shared_ptr<const visfeat::SurfaceMesh> mesh; // mesh input: its triangles
  /** \brief Subtracted from x y z before the cast to float (vt::recentringOffset). */
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();
  /** \brief Mesh input: the offset its vertices were recentred by (loadMeshAsCloud). */
  Eigen::Vector3d mesh_offset = Eigen::Vector3d::Zero();
};

/** \brief Load the input cloud, or sample the input mesh, printing what was loaded. */
bool
loadInput(const vt::Options& opt,
          const vt::Arguments& args,
          Input& in,
          std::string& error)
{
  TicToc tt;
  tt.tic();
  print_highlight("Loading ");
  print_value("%s ", opt.input.c_str());
  const bool mesh = vt::isMeshFile(opt.input);
  if (mesh && opt.fill == visfeat::SurfaceFill::kOrganized) {
    print_info("\n");
    error = "-fill grid needs an organized cloud (height > 1); a mesh gives its own "
            "triangles: give -fill mesh or auto (the default)";
    return false;
  }
  std::string summary;
  if (mesh ? !vt::loadMeshAsCloud(opt.input, opt.mesh, in.cloud, in.mesh,
                                  in.mesh_offset, summary, error)
           : !vt::loadCloud(opt.input, in.cloud, in.origin, in.orientation, error)) {
    print_info("\n");
    return false;
  }
  print_info("[done, ");
  print_value("%g", tt.toc());
  print_info(" ms : ");
  print_value("%zu", static_cast<std::size_t>(in.cloud.width) * in.cloud.height);
  print_info(" points]\n");
  if (mesh)
    print_info("%s\n", summary.c_str());
  else if (args.has("-mesh_points") || args.has("-mesh_spacing"))
    print_warn("-mesh_points / -mesh_spacing ignored: '%s' is a point cloud\n",
               opt.input.c_str());
  print_info("Available dimensions: ");
  print_value("%s\n", vt::fieldsList(in.cloud).c_str());
  return true;
}

/** \brief x y z of the input, checked for a surface; the resolution chosen from the
 * point spacing when the user gave none. */
bool
prepareXYZ(vt::Options& opt, bool user_resolution, Input& in, std::string& error)
{
  std::string problem;
  if (!vt::hasXYZ(in.cloud, problem)) {
    error = "'" + opt.input + "': " + problem;
    return false;
  }
  if (in.cloud.width * static_cast<std::size_t>(in.cloud.height) == 0) {
    error = "'" + opt.input + "': the cloud has no points";
    return false;
  }
  in.xyz = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  // far from the origin (survey coordinates): recentred in double, then cast to float
  // (a mesh was recentred when it was loaded, and its samples are given back in the
  // input's frame: the same offset takes them to the recentred mesh)
  in.offset = in.mesh ? in.mesh_offset : vt::recentringOffset(in.cloud);
  vt::toXYZ(in.cloud, *in.xyz, in.offset);
  if (!in.offset.isZero()) {
    print_info("Recentred: the computation runs on x y z minus (");
    print_value("%.17g %.17g %.17g", in.offset.x(), in.offset.y(), in.offset.z());
    print_info("); the output keeps the input's coordinates, the graph JSON's are "
               "the input's and give this \"offset\"\n");
  }
  // the sensor pose: the grid fill of an organized cloud casts its rays from it
  in.xyz->sensor_origin_ =
    in.origin - Eigen::Vector4f(static_cast<float>(in.offset.x()),
                                static_cast<float>(in.offset.y()),
                                static_cast<float>(in.offset.z()), 0.f);
  in.xyz->sensor_orientation_ = in.orientation;
  return vt::checkShapeAndResolution(opt.input, *in.xyz, user_resolution,
                                     opt.resolution, error);
}

void
configureEstimator(Estimator& estimator,
                   const vt::Options& opt,
                   const Input& in,
                   const std::shared_ptr<vt::ProgressPrinter>& progress)
{
  estimator.setInputCloud(in.xyz);
  estimator.setInputMesh(in.mesh);
  estimator.setResolution(opt.resolution);
  estimator.setMaxSearchResolution(opt.max_search_resolution);
  estimator.setMaxRadius(opt.max_radius);
  estimator.setMinRadius(opt.min_radius);
  estimator.setVertexMaxCells(opt.vertex_cells);
  estimator.setNarrowFacePersistence(opt.narrow_persistence);
  estimator.setFlatCoreFaces(opt.flat_cores);
  estimator.setDimensionality(opt.dimensionality);
  estimator.setMinCreaseAngle(opt.min_crease_angle);
  estimator.setFlatPointVariation(opt.flat_variation);
  estimator.setRawMode(opt.raw);
  estimator.setCompleteRegions(opt.regions);
  estimator.setOpacity(opt.opacity);
  estimator.setNoiseMode(opt.noise_mode);
  if (opt.smooth >= 0.0)
    estimator.setSmoothingRadius(opt.smooth);
  estimator.setNumberOfThreads(static_cast<unsigned int>(opt.threads));
  estimator.setBandRepair(opt.repair);
  estimator.setSurfaceFill(opt.fill);
  estimator.setLocalTriangleParameters(opt.fill_triangles);
  estimator.setMemoryLimit(static_cast<std::uint64_t>(opt.memory_limit_mb) * 1024u *
                           1024u);
  if (!opt.quiet)
    estimator.setProgressCallback(
      [progress](std::size_t done, std::size_t total) { (*progress)(done, total); });
}

/** \brief Run the estimator, printing its settings, progress and time. */
bool
compute(Estimator& estimator,
        const vt::Options& opt,
        vt::ProgressPrinter& progress,
        pcl::PointCloud<visfeat::PointVisibility>& result,
        std::string& error)
{
  print_highlight("Computing visibility features ");
  print_info("(resolution ");
  if (opt.resolution == 0)
    print_value("auto");
  else
    print_value("%d", opt.resolution);
  print_info(", fill ");
  print_value("%s", visfeat::surfaceFillName(opt.fill));
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
  TicToc tt;
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
      progress.finish();
      print_info("\n");
      error = "out of memory; lower -resolution or -max_radius";
      return false;
    } catch (const std::exception& e) {
      setVerbosityLevel(level);
      progress.finish();
      print_info("\n");
      error = vt::inToolTerms(e.what());
      return false;
    }
    setVerbosityLevel(level);
  }
  progress.finish();
  if (result.empty()) {
    print_info("\n");
    const std::string why = vt::inToolTerms(estimator.getErrorMessage());
    error =
      "'" + opt.input + "': " + (why.empty() ? std::string("computation failed") : why);
    return false;
  }
  print_info("[done, ");
  print_value("%g", tt.toc());
  print_info(" ms]\n");
  return true;
}

/** \brief The grid, the time of each phase, the radius histogram, the region counts. */
void
printSummary(const Estimator& estimator, const vt::Options& opt)
{
  const visfeat::GridSpec& grid = estimator.getGrid();
  const visfeat::VoxelBand& band = estimator.getVoxelBand();
  const visfeat::ResolutionEstimate& resolution = estimator.getResolutionEstimate();
  if (opt.resolution == 0) {
    print_info("Resolution ");
    print_value("%d", resolution.resolution);
    // one line a part: the first choice, then each step of the automatic search
    const std::vector<std::string> parts =
      vt::topLevelParts(vt::inToolTerms(resolution.reason));
    if (parts.size() == 1)
      print_info(" chosen: %s; -resolution overrides\n", parts.front().c_str());
    else {
      print_info(" chosen (-resolution overrides):\n");
      for (const std::string& part : parts)
        print_info("  %s\n", part.c_str());
    }
  }
  print_info("Band from ");
  print_value("%s", visfeat::surfaceFillName(estimator.getSurfaceFillUsed()));
  // the choice of -fill auto, which -fill F replaces; a fill set by -fill says so
  const bool chosen = estimator.getSurfaceFill() == visfeat::SurfaceFill::kAuto;
  print_info(": %s%s\n", vt::inToolTerms(estimator.getSurfaceFillReason()).c_str(),
             chosen ? " (chosen by -fill auto; -fill F sets another)" : "");
  for (const std::string& note : estimator.getNotes())
    print_info("Note: %s\n", vt::inToolTerms(note).c_str());
  print_info("Grid: origin (");
  print_value("%g %g %g", grid.origin.x(), grid.origin.y(), grid.origin.z());
  print_info("), cell ");
  print_value("%g", grid.cell_size);
  print_info(", dims ");
  print_value("%d x %d x %d", grid.dims.x(), grid.dims.y(), grid.dims.z());
  // a fresh user read the dims against the resolution and missed the padding
  print_info(" (the box plus %d cells a side)", visfeat::GridSpec::kPadding);
  print_info(", mixed cells ");
  print_value("%zu", band.size());
  print_info(" (repair cells ");
  print_value("%zu", band.repairCellCount());
  if (band.fillCellCount() > 0) {
    print_info(", fill cells ");
    print_value("%zu", band.fillCellCount());
  }
  print_info(")");
  if (band.roughness() >= 0.0) {
    print_info(", roughness ");
    print_value("%.3f", band.roughness());
    print_info(" cells");
  }
  if (estimator.getPointNoise() >= 0.0) {
    print_info(", point noise ");
    print_value("%.3f", estimator.getPointNoise());
    print_info(" cells");
  }
  print_info("\n");
  const visfeat::PhaseTimes& times = estimator.getPhaseTimes();
  print_info("Phases: shape checks and resolution ");
  print_value("%.1f", times.shape_ms);
  print_info(" ms, grid ");
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
  if (times.search_ms > 0.0) {
    print_info(" ms, coarser runs of the resolution search ");
    print_value("%.1f", times.search_ms);
  }
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
  // warnings go to stderr: what stdout holds comes first, also when it is a pipe
  std::fflush(stdout);
  // -q silences the rest, never these: a result that cannot be trusted says so
  for (const std::string& warning : estimator.getWarnings())
    if (opt.quiet)
      std::fprintf(stderr, "visfeat: warning: %s\n", vt::inToolTerms(warning).c_str());
    else
      print_warn("Warning: %s\n", vt::inToolTerms(warning).c_str());
}

int
run(int argc, char** argv)
{
  const vt::Arguments args(argc, argv, vt::valueOptions(), vt::switchOptions());
  if (!args.ok())
    return fail(args.error());

  vt::Options opt;
  opt.quiet = args.has("-q");
  opt.noise_mode = args.has("-noise_mode");
  opt.paper_noise = args.has("-paper_noise");
  if (opt.quiet)
    vt::beQuiet();
  else
    print_info("Estimate visibility features of a point cloud or mesh. For more "
               "information, use: %s -h\n",
               argv[0]);

  std::string error;
  if (!vt::readOptions(args, opt, error))
    return fail(error);

  Input in;
  if (!loadInput(opt, args, in, error) ||
      !prepareXYZ(opt, args.has("-resolution"), in, error))
    return fail(error);

  Estimator estimator;
  const std::shared_ptr<vt::ProgressPrinter> progress =
    vt::ProgressPrinter::forStderr();
  configureEstimator(estimator, opt, in, progress);
  // -max_radius 0 (the default) is the library's automatic cap, min_radius: what is
  // printed, drawn and written into the graph is the cap compute() uses.
  opt.max_radius = estimator.getMaxRadius();
  pcl::PointCloud<visfeat::PointVisibility> result;
  if (!compute(estimator, opt, *progress, result, error))
    return fail(error);
  printSummary(estimator, opt);

  // Every output is written under its temporary name and renamed only when all are
  // complete, so a failure leaves none.
  pcl::PCLPointCloud2 merged;
  if (!vt::mergeFields(in.cloud, result, merged, error) ||
      !vt::writeClouds(opt, merged, in.origin, in.orientation, estimator, in.offset,
                       error) ||
      (!opt.graph.empty() && !vt::writeGraph(opt, estimator, in.offset, error)) ||
      !vt::writePicturesAndCommit(opt, estimator, result, error))
    return fail(error);
  return 0;
}

} // namespace

int
main(int argc, char** argv)
{
  return vt::toolMain(argc, argv, kProgram, true, vt::printHelp, run);
}
