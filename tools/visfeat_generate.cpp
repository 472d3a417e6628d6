// visfeat_generate: a point cloud sampled from a synthetic shape (a Platonic solid
// under a random rotation), for trying visfeat and for tests. Binary PCD of PointXYZ.

#include "tool_utils.h"

#include <visfeat/error.h>
#include <visfeat/grid_spec.h>
#include <visfeat/memory_budget.h>
#include <visfeat/synthetic_shapes.h>

#include <pcl/console/parse.h>
#include <pcl/console/print.h>
#include <pcl/console/time.h>
#include <pcl/io/pcd_io.h>

#include <cstdint>
#include <new>
#include <random>
#include <string>

using namespace pcl::console;
namespace vt = visfeat_tools;

namespace {

const char* const kProgram = "visfeat_generate";

constexpr int kDefaultResolution = 256;
constexpr double kDefaultSpacing = 0.5;
constexpr long long kDefaultSeed = 1;
constexpr double kDefaultNoise = 0.0;
constexpr long long kMaxPoints = 2000000000LL;

std::string
shapeList()
{
  std::string list;
  for (const auto& name : visfeat::synthetic::shapeNames())
    list += (list.empty() ? "" : ", ") + name;
  return list;
}

void
printHelp(const char* program)
{
  print_error("Syntax is: %s <shape> output.pcd <options>\n", program);
  print_info(
    "  Samples points uniformly over the surface of a synthetic shape under a random\n"
    "  rotation and writes them as binary PCD (PointXYZ).\n");
  print_info("  where <shape> is one of: ");
  print_value("%s\n", shapeList().c_str());
  print_info("  and options are:\n");
  print_info("    -resolution N = grid the spacing and noise refer to: cells "
             "along the longest side (default: ");
  print_value("%d", kDefaultResolution);
  print_info(" cells)\n");
  print_info("    -spacing S    = mean distance between samples (default: ");
  print_value("%g", kDefaultSpacing);
  print_info(" cells)\n");
  print_info("    -points N     = number of points (overrides -spacing)\n");
  print_info("    -seed K       = rotation, sampling and noise seed (default: ");
  print_value("%lld", kDefaultSeed);
  print_info(")\n");
  print_info("    -noise SIGMA  = Gaussian noise per coordinate (default: ");
  print_value("%g", kDefaultNoise);
  print_info(" cells)\n");
  print_info("    -q            = quiet: errors only\n");
  print_info(
    "  A cell is the longest bounding-box side of the rotated shape / resolution.\n");
}

int
fail(const std::string& message)
{
  vt::printError(kProgram, message);
  return 1;
}

int
run(int argc, char** argv)
{
  const vt::Arguments args(argc, argv,
                           {"-resolution", "-spacing", "-points", "-seed", "-noise"},
                           {"-q", "-h", "--help"});
  if (!args.ok())
    return fail(args.error());
  if (args.has("-q"))
    vt::beQuiet();
  if (args.positional().size() != 2)
    return fail("expected a shape and an output .pcd, got " +
                std::to_string(args.positional().size()) + " argument(s) (see -h)");
  const std::string shape = args.positional()[0];
  const std::string output = args.positional()[1];

  int resolution = kDefaultResolution;
  double spacing = kDefaultSpacing;
  long long points = 0;
  long long seed = kDefaultSeed;
  double noise = kDefaultNoise;
  std::string error;
  if (!args.getInteger("-resolution", visfeat::GridSpec::kMinResolution,
                       visfeat::GridSpec::kMaxResolution, resolution, error) ||
      !args.getReal("-spacing", 1e-3, 1e3, spacing, error) ||
      !args.getInteger("-points", 1, kMaxPoints, points, error) ||
      !args.getInteger("-seed", 0, std::numeric_limits<long long>::max(), seed,
                       error) ||
      !args.getReal("-noise", 0.0, 1e6, noise, error))
    return fail(error);
  if (args.has("-points") && args.has("-spacing"))
    print_warn("-points given: -spacing is ignored\n");

  bool known = false;
  for (const auto& name : visfeat::synthetic::shapeNames())
    known = known || name == shape;
  if (!known)
    return fail("unknown shape '" + shape + "' (known: " + shapeList() + ")");
  if (vt::lowerExtension(output) != ".pcd")
    return fail("output '" + output + "' must have the extension .pcd");
  if (!vt::checkWritable(output, error))
    return fail(error);

  TicToc tt;
  tt.tic();
  print_highlight("Generating ");
  print_value("%s ", shape.c_str());
  const std::uint64_t seed64 = static_cast<std::uint64_t>(seed);
  const visfeat::synthetic::TriangleMesh mesh = visfeat::synthetic::rotated(
    visfeat::synthetic::shapeByName(shape), visfeat::synthetic::randomRotation(seed64));
  const double cell = mesh.bounds().sizes().maxCoeff() / resolution;
  const std::size_t count =
    points > 0 ? static_cast<std::size_t>(points)
               : visfeat::synthetic::samplesForSpacing(mesh, resolution, spacing);
  if (count == 0)
    return fail("no points to generate (spacing too large?)");
  // The samples, the cloud and PCL's write buffer.
  visfeat::checkMemory(static_cast<std::uint64_t>(count) *
                         (sizeof(Eigen::Vector3f) + sizeof(pcl::PointXYZ) + 12),
                       0, std::to_string(count) + " points");
  const std::vector<Eigen::Vector3f> samples =
    visfeat::synthetic::sampleSurface(mesh, count, seed64);

  pcl::PointCloud<pcl::PointXYZ> cloud;
  cloud.resize(samples.size());
  std::mt19937_64 rng(seed64 ^
                      0x9E3779B97F4A7C15ull); // a stream apart from the sampling
  std::normal_distribution<double> gauss(0.0, noise * cell);
  for (std::size_t i = 0; i < samples.size(); ++i) {
    Eigen::Vector3d p = samples[i].cast<double>();
    if (noise > 0.0)
      p += Eigen::Vector3d(gauss(rng), gauss(rng), gauss(rng));
    cloud[i].x = static_cast<float>(p.x());
    cloud[i].y = static_cast<float>(p.y());
    cloud[i].z = static_cast<float>(p.z());
  }
  cloud.width = static_cast<std::uint32_t>(cloud.size());
  cloud.height = 1;
  cloud.is_dense = true;
  print_info("[done, ");
  print_value("%g", tt.toc());
  print_info(" ms : ");
  print_value("%zu", cloud.size());
  print_info(" points; resolution ");
  print_value("%d", resolution);
  print_info(", cell ");
  print_value("%g", cell);
  if (points > 0)
    print_info(", count given");
  else {
    print_info(", spacing ");
    print_value("%g", spacing);
    print_info(" cells");
  }
  print_info(", noise ");
  print_value("%g", noise);
  print_info(" cells, seed ");
  print_value("%lld", seed);
  print_info("]\n");

  tt.tic();
  print_highlight("Saving ");
  print_value("%s ", output.c_str());
  pcl::PCDWriter writer;
  const int rc =
    vt::quietly([&] { return writer.writeBinary(vt::temporaryPath(output), cloud); });
  if (rc < 0) {
    vt::discardOutput(output);
    print_info("\n");
    return fail("cannot write '" + output + "' (disk full or not writable?)");
  }
  if (!vt::commitOutput(output, error))
    return fail(error);
  print_info("[done, ");
  print_value("%g", tt.toc());
  print_info(" ms]\n");
  return 0;
}

} // namespace

int
main(int argc, char** argv)
{
  if (argc < 2) {
    printHelp(argv[0]);
    return 1;
  }
  if (find_switch(argc, argv, "-h") || find_switch(argc, argv, "--help")) {
    printHelp(argv[0]);
    return 0;
  }
  try {
    return run(argc, argv);
  } catch (const std::bad_alloc&) {
    return fail("out of memory");
  } catch (const std::exception& e) {
    return fail(e.what());
  }
}
