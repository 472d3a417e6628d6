// visfeat_benchmark: time VisibilityFeatureEstimation on synthetic CAD models at
// several resolutions, phase by phase, against PCL's NormalEstimationOMP (k = 30) on
// the same cloud -- the target is to cost no more than normal estimation.

#include "common/arguments.h"
#include "common/tool_main.h"

#include <support/cad_models.h>
#include <support/synthetic_shapes.h>
#include <visfeat/core/common/error.h>
#include <visfeat/core/common/threads.h>
#include <visfeat/core/grid/grid_spec.h>
#include <visfeat/core/visibility/free_space.h>
#include <visfeat/core/visibility/visibility_map.h>
#include <visfeat/point_types.h>
#include <visfeat/surface_fill.h>
#include <visfeat/visibility_feature_estimation.h>

#include <pcl/console/parse.h>
#include <pcl/console/print.h>
#include <pcl/features/normal_3d_omp.h>
#include <pcl/search/kdtree.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <limits>
#include <memory>
#include <new>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <sys/resource.h>
#ifdef __GLIBC__
#include <malloc.h>
#endif
#ifdef _OPENMP
#endif

using namespace pcl::console;
namespace vt = visfeat_tools;

namespace {

const char* const kProgram = "visfeat_benchmark";

constexpr int kDefaultMaxRadius = visfeat::kDefaultMinRadius; // the estimator's cap
constexpr double kDefaultOpacity = visfeat::VisibilityMap::Parameters{}.opacity;
constexpr double kSpacingCells = 0.5; // the default; -spacing changes it
constexpr int kBaselineK = 30;

void
printHelp(const char* program)
{
  print_error("Syntax is: %s <options>\n", program);
  print_info(
    "  Samples synthetic CAD models (random rotation, %g-cell spacing) and times "
    "visfeat "
    "on\n"
    "  them, phase by phase, next to pcl::NormalEstimationOMP (k = %d, kd-tree build\n"
    "  included) on the same cloud. Sampling is not timed.\n",
    kSpacingCells, kBaselineK);
  print_info("  where options are:\n");
  print_info("    -shapes a,b,...     = CAD models (default: ");
  std::string all;
  for (const auto& name : visfeat::synthetic::cadModelNames())
    all += (all.empty() ? "" : ",") + name;
  print_value("%s", all.c_str());
  print_info(")\n");
  print_info("    -resolutions a,b,.. = cells along the longest side (default: ");
  print_value("128,256,512");
  print_info(")\n");
  print_info("    -threads T          = threads for both methods (default: ");
  print_value("0");
  print_info(" = all)\n");
  print_info("    -repeat N           = runs per measurement, best reported "
             "(default: ");
  print_value("1");
  print_info(")\n");
  print_info("    -max_radius R       = cap of the visibility radius (default: ");
  print_value("%d", kDefaultMaxRadius);
  print_info(" rings)\n");
  print_info("    -opacity D          = opacity (default: ");
  print_value("%g", kDefaultOpacity);
  print_info(" cell edges)\n");
  print_info("    -seed K             = rotation and sampling seed (default: ");
  print_value("1");
  print_info(")\n");
  print_info("    -spacing S          = point spacing in cells (default: ");
  print_value("%g", kSpacingCells);
  print_info("; up to 0.7 keeps the band connected, e.g. for 2048 cells where\n"
             "                          0.5 would not fit in memory)\n");
  print_info(
    "    -fill F             = where the band comes from: auto (default: the "
    "estimator's\n"
    "                          choice; triangles for points over 0.55 cells "
    "apart), points,\n"
    "                          triangles, or mesh (the model's tessellation, "
    "0.05 cells,\n"
    "                          rasterised; the points only take the labels)\n");
  print_info("    -no_baseline        = skip PCL's normal estimation\n");
  print_info("    -csv                = comma-separated output (notes go to "
             "stderr)\n");
  print_info(
    "  Columns: seconds per phase (grid = shape checks, resolution and grid; band; "
    "free\n"
    "  space; visibility; seg = segmentation and graph; output), total = wall\n"
    "  time of compute(); Mcell/s = mixed cells / visibility seconds; tests = pair "
    "tests\n"
    "  (millions); peak_MiB = peak resident memory during the run (see the note "
    "printed);\n"
    "  data_MiB = band + free-space mask + radii; B/cell, pk_B/c = data_MiB and "
    "peak_MiB\n"
    "  in bytes per mixed cell; ratio = visfeat total / normals total.\n");
}

int
fail(const std::string& message)
{
  vt::printError(kProgram, message);
  return 1;
}

/** \brief Peak resident memory. Linux lets a process reset its high-water mark
 * (/proc/self/clear_refs, "5"); when that works each run reports its own peak (VmHWM),
 * otherwise getrusage's ru_maxrss, the peak of the whole process so far. Either way
 * the peak includes what is resident when the run starts (the input cloud). */
class PeakMemory
{
public:
  PeakMemory() { per_run_ = reset() && readHwmKiB() > 0; }

  bool perRun() const { return per_run_; }

  /** Returns the heap the previous runs freed to the system first (glibc keeps it
   * otherwise, and it would count in this run's resident peak), then resets. */
  void startRun() const
  {
#ifdef __GLIBC__
    malloc_trim(0);
#endif
    if (per_run_)
      reset();
  }

  double peakMiB() const
  {
    if (per_run_)
      return readHwmKiB() / 1024.0;
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_maxrss) / 1024.0; // KiB on Linux
  }

private:
  static bool reset()
  {
    std::ofstream f("/proc/self/clear_refs");
    f << "5";
    f.flush();
    return static_cast<bool>(f);
  }

  static double readHwmKiB()
  {
    std::ifstream f("/proc/self/status");
    std::string line;
    while (std::getline(f, line))
      if (line.rfind("VmHWM:", 0) == 0) {
        std::istringstream s(line.substr(6));
        double kib = 0;
        s >> kib;
        return kib;
      }
    return 0.0;
  }

  bool per_run_ = false;
};

struct Row
{
  std::string shape;
  int resolution = 0;
  std::string method;
  std::size_t points = 0;
  bool visfeat = true;
  std::size_t mixed = 0;
  std::size_t repair = 0;
  visfeat::PhaseTimes phases; // ms
  double total_s = 0.0;
  double cells_per_s = 0.0;
  std::uint64_t tests = 0;
  double peak_mib = 0.0;
  double data_mib = 0.0;
  std::uint64_t mask_bytes = 0; // the free-space mask, part of data_mib
  double ratio = 0.0;           // baseline rows: visfeat total / this total
  std::string error;
};

class Table
{
public:
  explicit Table(bool csv)
      : csv_(csv)
  {}

  void header() const
  {
    if (csv_) {
      std::printf(
        "shape,resolution,method,points,mixed_cells,repair_cells,grid_s,band_s,"
        "free_space_s,visibility_s,segmentation_s,output_s,phase_sum_s,total_s,mixed_"
        "cells_per_s,"
        "pair_tests,peak_rss_mib,structures_mib,structure_bytes_per_mixed_cell,"
        "peak_bytes_per_mixed_cell,ratio_visfeat_over_normals,error\n");
      return;
    }
    std::printf(
      "%-16s %5s %-8s %9s %9s %7s %7s %7s %7s %7s %7s %7s %8s %8s %9s %8s %8s %6s "
      "%6s %6s\n",
      "shape", "res", "method", "points", "mixed", "repair", "grid_s", "band_s",
      "free_s", "vis_s", "seg_s", "out_s", "total_s", "Mcell/s", "tests(M)", "peak_MiB",
      "data_MiB", "B/cell", "pk_B/c", "ratio");
  }

  void row(const Row& r) const
  {
    const visfeat::PhaseTimes& p = r.phases;
    if (csv_) {
      if (r.visfeat)
        std::printf(
          "%s,%d,%s,%zu,%zu,%zu,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.1f,%llu,%.1f,"
          "%.2f,%.1f,%.1f,,%s\n",
          r.shape.c_str(), r.resolution, r.method.c_str(), r.points, r.mixed, r.repair,
          prepSeconds(p), p.band_ms / 1e3, p.free_space_ms / 1e3, p.visibility_ms / 1e3,
          segmentationSeconds(p), p.output_ms / 1e3, p.total() / 1e3, r.total_s,
          r.cells_per_s, static_cast<unsigned long long>(r.tests), r.peak_mib,
          r.data_mib, bytesPerCell(r.data_mib, r.mixed),
          bytesPerCell(r.peak_mib, r.mixed), csvText(r.error).c_str());
      else
        std::printf("%s,%d,%s,%zu,,,,,,,,,,%.6f,,,%.1f,,,,%s,%s\n", r.shape.c_str(),
                    r.resolution, r.method.c_str(), r.points, r.total_s, r.peak_mib,
                    r.ratio > 0 ? std::to_string(r.ratio).c_str() : "",
                    csvText(r.error).c_str());
      std::fflush(stdout);
      return;
    }
    if (!r.error.empty())
      std::printf("%-16s %5d %-8s %9zu  FAILED: %s\n", r.shape.c_str(), r.resolution,
                  r.method.c_str(), r.points, r.error.c_str());
    else if (r.visfeat)
      std::printf(
        "%-16s %5d %-8s %9zu %9zu %7zu %7.3f %7.3f %7.3f %7.3f %7.3f %7.3f %8.3f "
        "%8.3f %9.1f %8.1f %8.1f %6.0f %6.0f %6s\n",
        r.shape.c_str(), r.resolution, r.method.c_str(), r.points, r.mixed, r.repair,
        prepSeconds(p), p.band_ms / 1e3, p.free_space_ms / 1e3, p.visibility_ms / 1e3,
        segmentationSeconds(p), p.output_ms / 1e3, r.total_s, r.cells_per_s / 1e6,
        static_cast<double>(r.tests) / 1e6, r.peak_mib, r.data_mib,
        bytesPerCell(r.data_mib, r.mixed), bytesPerCell(r.peak_mib, r.mixed), "-");
    else {
      char ratio[32] = "-";
      if (r.ratio > 0)
        std::snprintf(ratio, sizeof(ratio), "%.2f", r.ratio);
      std::printf(
        "%-16s %5d %-8s %9zu %9s %7s %7s %7s %7s %7s %7s %7s %8.3f %8s %9s %8.1f %8s "
        "%6s %6s %6s\n",
        r.shape.c_str(), r.resolution, r.method.c_str(), r.points, "-", "-", "-", "-",
        "-", "-", "-", "-", r.total_s, "-", "-", r.peak_mib, "-", "-", "-", ratio);
    }
    std::fflush(stdout);
  }

private:
  /** Shape checks, automatic resolution, grid and (noise mode) smoothing. */
  static double prepSeconds(const visfeat::PhaseTimes& p)
  {
    return (p.shape_ms + p.grid_ms + p.smoothing_ms) / 1e3;
  }

  /** Components, regions, classes and the topology graph. */
  static double segmentationSeconds(const visfeat::PhaseTimes& p)
  {
    return (p.segmentation_ms + p.graph_ms) / 1e3;
  }

  static double bytesPerCell(double mib, std::size_t cells)
  {
    return cells > 0 ? mib * 1024.0 * 1024.0 / static_cast<double>(cells) : 0.0;
  }

  static std::string csvText(std::string text)
  {
    for (char& c : text)
      if (c == ',' || c == '\n' || c == '"')
        c = ';';
    return text;
  }

  bool csv_;
};

struct Settings
{
  std::vector<std::string> shapes;
  std::vector<int> resolutions{128, 256, 512};
  int threads = 0;
  int repeat = 1;
  int max_radius = kDefaultMaxRadius;
  double opacity = kDefaultOpacity;
  long long seed = 1;
  double spacing = kSpacingCells; // cells
  /** kMesh: the model's tessellation gives the band (setInputMesh()). */
  visfeat::SurfaceFill fill = visfeat::SurfaceFill::kAuto;
  bool baseline = true;
  bool csv = false;
};

Row
runVisfeat(const Settings& s,
           int resolution,
           const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& cloud,
           const std::shared_ptr<const visfeat::SurfaceMesh>& mesh,
           const PeakMemory& memory)
{
  Row best;
  best.resolution = resolution;
  best.method = "visfeat";
  best.points = cloud->size();
  best.total_s = std::numeric_limits<double>::infinity();
  double peak = 0.0;
  for (int run = 0; run < s.repeat; ++run) {
    visfeat::VisibilityFeatureEstimation<pcl::PointXYZ, visfeat::PointVisibility>
      estimator;
    estimator.setInputCloud(cloud);
    if (mesh)
      estimator.setInputMesh(mesh);
    estimator.setSurfaceFill(s.fill);
    estimator.setResolution(resolution);
    estimator.setMaxRadius(s.max_radius);
    estimator.setMinRadius(s.max_radius); // components up to the cap
    estimator.setOpacity(s.opacity);
    estimator.setNumberOfThreads(static_cast<unsigned int>(s.threads));
    pcl::PointCloud<visfeat::PointVisibility> out;
    memory.startRun();
    const double t0 = vt::secondsNow();
    vt::quietly([&] {
      estimator.compute(out);
      return 0;
    });
    const double seconds = vt::secondsNow() - t0;
    peak = std::max(peak, memory.peakMiB());
    if (out.empty()) {
      best.error = estimator.getErrorMessage().empty() ? "compute() failed"
                                                       : estimator.getErrorMessage();
      return best;
    }
    if (seconds < best.total_s) {
      const visfeat::VoxelBand& band = estimator.getVoxelBand();
      best.total_s = seconds;
      best.phases = estimator.getPhaseTimes();
      best.mixed = band.size();
      best.repair = band.repairCellCount();
      best.tests = estimator.getVisibilityMap().testsPerformed();
      best.cells_per_s =
        best.phases.visibility_ms > 0
          ? static_cast<double>(band.size()) / (best.phases.visibility_ms / 1e3)
          : 0.0;
      // The estimator releases its FreeSpace after the map; its size follows from
      // the band (exactly).
      best.mask_bytes = visfeat::FreeSpace::estimateBytes(band);
      best.data_mib = static_cast<double>(band.memoryBytes() + best.mask_bytes +
                                          estimator.getVisibilityMap().radii().size()) /
                      (1024.0 * 1024.0);
    }
  }
  best.peak_mib = peak;
  return best;
}

Row
runNormals(const Settings& s,
           const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& cloud,
           const PeakMemory& memory)
{
  Row best;
  best.visfeat = false;
  best.method = "normals";
  best.points = cloud->size();
  best.total_s = std::numeric_limits<double>::infinity();
  double peak = 0.0;
  for (int run = 0; run < s.repeat; ++run) {
    pcl::NormalEstimationOMP<pcl::PointXYZ, pcl::Normal> ne(
      static_cast<unsigned int>(s.threads));
    ne.setInputCloud(cloud);
    ne.setSearchMethod(std::make_shared<pcl::search::KdTree<pcl::PointXYZ>>());
    ne.setKSearch(kBaselineK);
    pcl::PointCloud<pcl::Normal> normals;
    memory.startRun();
    const double t0 =
      vt::secondsNow(); // includes the kd-tree build, done inside compute()
    ne.compute(normals);
    const double seconds = vt::secondsNow() - t0;
    peak = std::max(peak, memory.peakMiB());
    if (normals.size() != cloud->size()) {
      best.error = "NormalEstimationOMP failed";
      return best;
    }
    best.total_s = std::min(best.total_s, seconds);
  }
  best.peak_mib = peak;
  return best;
}

int
run(int argc, char** argv)
{
  const vt::Arguments args(argc, argv,
                           {"-shapes", "-resolutions", "-threads", "-repeat",
                            "-max_radius", "-opacity", "-seed", "-spacing", "-fill"},
                           {"-no_baseline", "-csv", "-h", "--help"});
  if (!args.ok())
    return fail(args.error());
  if (!args.positional().empty())
    return fail("unexpected argument '" + args.positional()[0] + "' (see -h)");

  Settings s;
  std::string error;
  if (!args.getInteger("-threads", 0, visfeat::VisibilityMap::kMaxThreads, s.threads,
                       error) ||
      !args.getInteger("-repeat", 1, 1000, s.repeat, error) ||
      !args.getInteger("-max_radius", 1, visfeat::VisibilityMap::kMaxRadius,
                       s.max_radius, error) ||
      !args.getReal("-opacity", 0.0, visfeat::VisibilityMap::kMaxOpacity, s.opacity,
                    error) ||
      !args.getInteger("-seed", 0, std::numeric_limits<long long>::max(), s.seed,
                       error) ||
      !args.getReal("-spacing", 0.05, 2.0, s.spacing, error))
    return fail(error);
  if (args.has("-fill") && (!visfeat::parseSurfaceFill(args.value("-fill"), s.fill) ||
                            s.fill == visfeat::SurfaceFill::kOrganized))
    return fail("-fill expects auto, points, triangles or mesh, got '" +
                args.value("-fill") + "'");
  s.baseline = !args.has("-no_baseline");
  s.csv = args.has("-csv");

  const std::vector<std::string> known = visfeat::synthetic::cadModelNames();
  if (args.has("-shapes")) {
    for (const std::string& name : vt::splitList(args.value("-shapes"))) {
      if (std::find(known.begin(), known.end(), name) == known.end()) {
        std::string list;
        for (const auto& k : known)
          list += (list.empty() ? "" : ", ") + k;
        return fail("-shapes: unknown shape '" + name + "' (known: " + list + ")");
      }
      s.shapes.push_back(name);
    }
  } else
    s.shapes = known;
  if (args.has("-resolutions")) {
    s.resolutions.clear();
    for (const std::string& item : vt::splitList(args.value("-resolutions"))) {
      long long r = 0;
      if (!vt::parseInteger(item, r) || r < visfeat::GridSpec::kMinResolution ||
          r > visfeat::GridSpec::kMaxResolution)
        return fail("-resolutions: '" + item + "' is not an integer in [" +
                    std::to_string(visfeat::GridSpec::kMinResolution) + ", " +
                    std::to_string(visfeat::GridSpec::kMaxResolution) + "]");
      s.resolutions.push_back(static_cast<int>(r));
    }
  }

  // Notes: on stdout for the table, on stderr with -csv so stdout stays pure CSV.
  FILE* notes = s.csv ? stderr : stdout;
  const int omp_threads = visfeat::resolveThreads(0);
  const PeakMemory memory;
  std::fprintf(
    notes,
    "# machine: %u hardware threads (OpenMP: %d); threads used: %d%s; repeat %d "
    "(best reported); max_radius %d; opacity %g; seed %lld; spacing %g cells; fill "
    "%s\n",
    std::thread::hardware_concurrency(), omp_threads,
    s.threads == 0 ? omp_threads : s.threads, s.threads == 0 ? " (all)" : "", s.repeat,
    s.max_radius, s.opacity, s.seed, s.spacing,
    s.fill == visfeat::SurfaceFill::kMesh
      ? "mesh (the model's tessellation, 0.05 cells)"
      : visfeat::surfaceFillName(s.fill));
  std::fprintf(notes, "# peak_MiB: %s\n",
               memory.perRun()
                 ? "peak resident memory during each run (VmHWM, reset before "
                   "the run; includes the resident input and heap)"
                 : "getrusage ru_maxrss: the peak of the whole process so far");
  std::fflush(notes);

  const Table table(s.csv);
  table.header();
  int status = 0;
  for (const std::string& shape : s.shapes) {
    const std::uint64_t seed = static_cast<std::uint64_t>(s.seed);
    const visfeat::synthetic::CadModel model =
      visfeat::synthetic::rotated(visfeat::synthetic::cadModelByName(shape),
                                  visfeat::synthetic::randomRotation(seed));
    for (int resolution : s.resolutions) {
      auto cloud = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
      {
        visfeat::synthetic::SamplingOptions options;
        options.count =
          visfeat::synthetic::samplesForSpacing(model, resolution, s.spacing);
        options.seed = seed;
        const std::vector<Eigen::Vector3f> samples =
          visfeat::synthetic::sampleCadModel(model, options).points;
        cloud->resize(samples.size());
        for (std::size_t i = 0; i < samples.size(); ++i)
          (*cloud)[i].getVector3fMap() = samples[i];
        cloud->width = static_cast<std::uint32_t>(cloud->size());
        cloud->height = 1;
        cloud->is_dense = true;
      }

      std::shared_ptr<const visfeat::SurfaceMesh> mesh;
      if (s.fill == visfeat::SurfaceFill::kMesh)
        mesh = std::make_shared<visfeat::SurfaceMesh>(
          visfeat::synthetic::tessellateCadModel(
            model, 0.05 * visfeat::synthetic::cellSize(model, resolution))
            .mesh);
      Row v;
      try {
        v = runVisfeat(s, resolution, cloud, mesh, memory);
      } catch (const std::exception& e) {
        v.method = "visfeat";
        v.points = cloud->size();
        v.error = e.what();
      }
      v.shape = shape;
      v.resolution = resolution;
      table.row(v);
      if (v.error.empty() && v.mixed > 0) {
        std::fprintf(notes,
                     "# %s %d: free-space mask %.1f MiB, %.1f bytes per mixed cell\n",
                     shape.c_str(), resolution,
                     static_cast<double>(v.mask_bytes) / (1024.0 * 1024.0),
                     static_cast<double>(v.mask_bytes) / static_cast<double>(v.mixed));
        std::fflush(notes);
      }
      if (!v.error.empty())
        status = 1;

      if (s.baseline) {
        Row n = runNormals(s, cloud, memory);
        n.shape = shape;
        n.resolution = resolution;
        if (v.error.empty() && n.error.empty() && n.total_s > 0)
          n.ratio = v.total_s / n.total_s;
        table.row(n);
        if (!n.error.empty())
          status = 1;
      }
    }
  }
  return status;
}

} // namespace

int
main(int argc, char** argv)
{
  return vt::toolMain(argc, argv, kProgram, false, printHelp, run);
}
