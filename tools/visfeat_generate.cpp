// visfeat_generate: a point cloud sampled from a synthetic CAD model (a polyhedron, a
// box with a hole, a cylinder) under a random rotation, with its ground truth: per
// point the distance to the nearest true sharp curve and the face it was sampled from;
// and, on request, the model's vertices, edges, faces and incidences as JSON.

#include "common/arguments.h"
#include "common/output_files.h"
#include "common/tool_main.h"

#include <support/cad_models.h>
#include <support/synthetic_shapes.h>
#include <visfeat/core/common/error.h>
#include <visfeat/core/common/memory_budget.h>
#include <visfeat/core/grid/grid_spec.h>

#include <pcl/console/parse.h>
#include <pcl/console/print.h>
#include <pcl/console/time.h>
#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>
#include <pcl/register_point_struct.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <new>
#include <string>
#include <system_error>

namespace visfeat_tools {

/** \brief A generated point: x y z, the distance of its noise-free position to the
 * nearest true sharp curve (world units) and the id of the face it was sampled from. */
struct EIGEN_ALIGN16 PointGenerated
{
  PCL_ADD_POINT4D;
  float curve_distance;
  std::uint32_t face_id;

  PCL_MAKE_ALIGNED_OPERATOR_NEW
};

} // namespace visfeat_tools

POINT_CLOUD_REGISTER_POINT_STRUCT(visfeat_tools::PointGenerated,
                                  (float, x, x)(float, y, y)(float, z, z)(
                                    float,
                                    curve_distance,
                                    curve_distance)(std::uint32_t, face_id, face_id))

using namespace pcl::console;
namespace vt = visfeat_tools;
namespace syn = visfeat::synthetic;

namespace {

const char* const kProgram = "visfeat_generate";

constexpr int kDefaultResolution = 256;
constexpr double kDefaultSpacing = 0.5;
constexpr long long kDefaultSeed = 1;
constexpr double kDefaultNoise = 0.0;
constexpr long long kMaxPoints = 2000000000LL;

std::string
modelList()
{
  std::string list;
  for (const auto& name : syn::cadModelNames())
    list += (list.empty() ? "" : ", ") + name;
  return list;
}

void
printHelp(const char* program)
{
  print_error("Syntax is: %s <model> output.pcd <options>\n", program);
  print_info(
    "  Samples points uniformly (by area) over the surface of a synthetic CAD model\n"
    "  under a random rotation and writes them as binary PCD with the fields\n"
    "  x y z curve_distance face_id: curve_distance = distance of the noise-free\n"
    "  sample to the nearest true sharp curve (world units), face_id = the true face\n"
    "  it was sampled from.\n");
  print_info("  where <model> is one of: ");
  print_value("%s\n", modelList().c_str());
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
  print_info(
    "    -truth F.json = also write the rotated model's truth: vertices, edges\n"
    "                    (straight or circle), faces, incidences, counts\n");
  print_info("    -q            = quiet: errors only\n");
  print_info(
    "  A cell is the longest bounding-box side of the rotated model / resolution.\n");
}

int
fail(const std::string& message)
{
  vt::printError(kProgram, message);
  return 1;
}

/** \brief Write the truth JSON to the temporary name of `path`. */
bool
writeTruth(const std::string& path, const syn::CadModel& model, std::string& error)
{
  {
    std::ofstream out(vt::temporaryPath(path), std::ios::binary | std::ios::trunc);
    out << syn::cadModelJson(model);
    out.flush();
    if (out)
      return true;
  }
  vt::discardOutput(path);
  error = "cannot write '" + path + "' (disk full or not writable?)";
  return false;
}

/** \brief The command line, read and checked. */
struct Options
{
  std::string name;
  std::string output;
  std::string truth;
  int resolution = kDefaultResolution;
  double spacing = kDefaultSpacing;
  long long points = 0; // 0 = from the spacing
  long long seed = kDefaultSeed;
  double noise = kDefaultNoise;
};

/** \brief Read and check the options, the model name and the outputs (the right
 * extensions, writable, distinct) before any work. */
bool
readOptions(const vt::Arguments& args, Options& opt, std::string& error)
{
  if (args.positional().size() != 2) {
    error = "expected a model and an output .pcd, got " +
            std::to_string(args.positional().size()) + " argument(s) (see -h)";
    return false;
  }
  opt.name = args.positional()[0];
  opt.output = args.positional()[1];
  opt.truth = args.value("-truth");
  if (!args.getInteger("-resolution", visfeat::GridSpec::kMinResolution,
                       visfeat::GridSpec::kMaxResolution, opt.resolution, error) ||
      !args.getReal("-spacing", 1e-3, 1e3, opt.spacing, error) ||
      !args.getInteger("-points", 1, kMaxPoints, opt.points, error) ||
      !args.getInteger("-seed", 0, std::numeric_limits<long long>::max(), opt.seed,
                       error) ||
      !args.getReal("-noise", 0.0, 1e6, opt.noise, error))
    return false;
  if (args.has("-points") && args.has("-spacing"))
    print_warn("-points given: -spacing is ignored\n");
  if (args.has("-truth") && opt.truth.empty()) {
    error = "-truth expects a file name";
    return false;
  }
  bool known = false;
  for (const auto& n : syn::cadModelNames())
    known = known || n == opt.name;
  if (!known) {
    error = "unknown model '" + opt.name + "' (known: " + modelList() + ")";
    return false;
  }
  if (vt::lowerExtension(opt.output) != ".pcd") {
    error = "output '" + opt.output + "' must have the extension .pcd";
    return false;
  }
  if (!vt::checkWritable(opt.output, error))
    return false;
  if (opt.truth.empty())
    return true;
  if (vt::lowerExtension(opt.truth) != ".json") {
    error = "truth output '" + opt.truth + "' must have the extension .json";
    return false;
  }
  if (opt.truth == opt.output) {
    error = "the truth and the cloud cannot be the same file";
    return false;
  }
  return vt::checkWritable(opt.truth, error);
}

/** \brief The model under its random rotation, sampled into `cloud`, printing what
 * was generated. */
bool
generate(const Options& opt,
         syn::CadModel& model,
         pcl::PointCloud<vt::PointGenerated>& cloud,
         std::string& error)
{
  TicToc tt;
  tt.tic();
  print_highlight("Generating ");
  print_value("%s ", opt.name.c_str());
  const std::uint64_t seed64 = static_cast<std::uint64_t>(opt.seed);
  model = syn::rotated(syn::cadModelByName(opt.name), syn::randomRotation(seed64));
  const double cell = syn::cellSize(model, opt.resolution);
  const std::size_t count =
    opt.points > 0 ? static_cast<std::size_t>(opt.points)
                   : syn::samplesForSpacing(model, opt.resolution, opt.spacing);
  if (count == 0) {
    error = "no points to generate (spacing too large?)";
    return false;
  }
  if (count > static_cast<std::size_t>(kMaxPoints)) {
    error = std::to_string(count) +
            " points: too many (spacing too small?); the limit is " +
            std::to_string(kMaxPoints);
    return false;
  }
  // The samples with their truth, the cloud and PCL's write buffer.
  visfeat::checkMemory(static_cast<std::uint64_t>(count) *
                         (sizeof(Eigen::Vector3f) + sizeof(int) + sizeof(double) +
                          sizeof(vt::PointGenerated) + 20),
                       0, std::to_string(count) + " points");
  syn::SamplingOptions options;
  options.count = count;
  options.seed = seed64;
  options.noise_sigma = opt.noise * cell;
  const syn::CadSamples samples = syn::sampleCadModel(model, options);

  cloud.resize(samples.points.size());
  for (std::size_t i = 0; i < samples.points.size(); ++i) {
    vt::PointGenerated& p = cloud[i];
    p.x = samples.points[i].x();
    p.y = samples.points[i].y();
    p.z = samples.points[i].z();
    p.data[3] = 1.0f;
    p.curve_distance = static_cast<float>(samples.curve_distance[i]);
    p.face_id = static_cast<std::uint32_t>(samples.face[i]);
  }
  cloud.width = static_cast<std::uint32_t>(cloud.size());
  cloud.height = 1;
  cloud.is_dense = true;
  print_info("[done, ");
  print_value("%g", tt.toc());
  print_info(" ms : ");
  print_value("%zu", cloud.size());
  print_info(" points; resolution ");
  print_value("%d", opt.resolution);
  print_info(", cell ");
  print_value("%g", cell);
  if (opt.points > 0)
    print_info(", count given");
  else {
    print_info(", spacing ");
    print_value("%g", opt.spacing);
    print_info(" cells");
  }
  print_info(", noise ");
  print_value("%g", opt.noise);
  print_info(" cells, seed ");
  print_value("%lld", opt.seed);
  print_info("]\n");
  return true;
}

/** \brief The model's counts: vertices, edges by kind, faces, Euler characteristic. */
void
printTruth(const syn::CadModel& model)
{
  std::size_t circles = 0;
  for (const auto& c : model.curves)
    circles += c.kind == syn::CadCurve::Kind::kCircle ? 1 : 0;
  print_info("Truth: ");
  print_value("%zu", model.vertices.size());
  print_info(" vertices, ");
  print_value("%zu", model.curves.size());
  print_info(" edges (");
  print_value("%zu", model.curves.size() - circles);
  print_info(" straight, ");
  print_value("%zu", circles);
  print_info(" circular), ");
  print_value("%zu", model.faces.size());
  print_info(" faces; Euler characteristic ");
  print_value("%d", syn::eulerCharacteristic(model));
  print_info("\n");
}

/** \brief Write the cloud and the truth under temporary names and rename them only
 * when both are complete, so a failure leaves neither. */
bool
writeOutputs(const Options& opt,
             const syn::CadModel& model,
             const pcl::PointCloud<vt::PointGenerated>& cloud,
             std::string& error)
{
  TicToc tt;
  tt.tic();
  print_highlight("Saving ");
  print_value("%s ", opt.output.c_str());
  if (!opt.truth.empty())
    print_value("%s ", opt.truth.c_str());
  pcl::PCDWriter writer;
  const int rc = vt::quietly(
    [&] { return writer.writeBinary(vt::temporaryPath(opt.output), cloud); });
  if (rc < 0) {
    vt::discardOutput(opt.output);
    print_info("\n");
    error = "cannot write '" + opt.output + "' (disk full or not writable?)";
    return false;
  }
  if (!opt.truth.empty() && !writeTruth(opt.truth, model, error)) {
    vt::discardOutput(opt.output);
    print_info("\n");
    return false;
  }
  if (!vt::commitOutput(opt.output, error)) {
    if (!opt.truth.empty())
      vt::discardOutput(opt.truth);
    return false;
  }
  if (!opt.truth.empty() && !vt::commitOutput(opt.truth, error)) {
    std::error_code ec;
    std::filesystem::remove(opt.output, ec);
    return false;
  }
  print_info("[done, ");
  print_value("%g", tt.toc());
  print_info(" ms]\n");
  return true;
}

int
run(int argc, char** argv)
{
  const vt::Arguments args(
    argc, argv, {"-resolution", "-spacing", "-points", "-seed", "-noise", "-truth"},
    {"-q", "-h", "--help"});
  if (!args.ok())
    return fail(args.error());
  if (args.has("-q"))
    vt::beQuiet();
  Options opt;
  std::string error;
  if (!readOptions(args, opt, error))
    return fail(error);
  syn::CadModel model;
  pcl::PointCloud<vt::PointGenerated> cloud;
  if (!generate(opt, model, cloud, error))
    return fail(error);
  printTruth(model);
  if (!writeOutputs(opt, model, cloud, error))
    return fail(error);
  return 0;
}

} // namespace

int
main(int argc, char** argv)
{
  return vt::toolMain(argc, argv, kProgram, true, printHelp, run);
}
