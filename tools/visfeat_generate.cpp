// visfeat_generate: a point cloud sampled from a synthetic CAD model (a polyhedron, a
// box with a hole, a cylinder) under a random rotation, with its ground truth: per
// point the distance to the nearest true sharp curve and the face it was sampled from;
// and, on request, the model's vertices, edges, faces and incidences as JSON. Instead
// of the cloud: the model's tessellation as a PLY mesh (-mesh), or an organized depth
// view as a structured-light or time-of-flight camera takes it (-organized).

#include "common/arguments.h"
#include "common/output_files.h"
#include "common/tool_main.h"
#include "generate_views.h"
#include "generated_point.h"

#include <support/cad_models.h>
#include <support/synthetic_shapes.h>
#include <visfeat/core/common/error.h>
#include <visfeat/core/common/memory_budget.h>
#include <visfeat/core/grid/grid_spec.h>

#include <pcl/console/parse.h>
#include <pcl/console/print.h>
#include <pcl/console/time.h>
#include <pcl/io/pcd_io.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <new>
#include <string>
#include <system_error>

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
constexpr double kDefaultDensityRatio = 1.0;
constexpr double kDefaultChord = 0.05;
constexpr double kDefaultFov = 60.0;

std::string
modelList()
{
  std::string list;
  for (const auto& name : syn::allCadModelNames())
    list += (list.empty() ? "" : ", ") + name;
  return list;
}

void
printHelp(const char* program)
{
  print_error("Syntax is: %s <model> output.pcd|output.ply <options>\n", program);
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
  print_info("    -density_ratio K = face -dense_face gets K times as many points per "
             "area as\n"
             "                    the others, the total unchanged (default: ");
  print_value("%g", kDefaultDensityRatio);
  print_info(")\n");
  print_info("    -dense_face F = the face of -density_ratio (default: ");
  print_value("0");
  print_info(")\n");
  print_info(
    "    -truth F.json = also write the rotated model's truth: vertices, edges\n"
    "                    (straight or circle), faces, incidences, counts\n");
  print_info(
    "    -mesh         = write the rotated model's tessellation as a binary PLY mesh\n"
    "                    (output.ply) instead: watertight, counter-clockwise seen "
    "from\n"
    "                    outside, the same rotation as the cloud of the same seed\n");
  print_info(
    "    -chord T      = with -mesh: largest distance between a circle and its "
    "polygon\n"
    "                    (default: ");
  print_value("%g", kDefaultChord);
  print_info(" cells)\n");
  print_info(
    "    -organized WxH = write one organized depth view (output.pcd, W x H pixels,\n"
    "                    row-major, the same fields; an empty pixel has NaN x y z and\n"
    "                    curve_distance and face_id 4294967295) instead, ray cast on\n"
    "                    the exact faces; the points are in the model's frame\n");
  print_info(
    "    -fov DEG      = with -organized: horizontal field of view (default: ");
  print_value("%g", kDefaultFov);
  print_info(" degrees)\n");
  print_info(
    "    -view X,Y,Z   = with -organized: direction from the model's centre to the\n"
    "                    camera, in the model's frame before the seed's rotation (the\n"
    "                    camera turns with the model; default: ");
  print_value("1,1,1");
  print_info(", a corner)\n");
  print_info("    -distance D   = with -organized: camera distance from the centre "
             "(default:\n"
             "                    the model fills 90%% of the view; world units)\n");
  print_info("    -baseline B   = with -organized: projector offset along image x; "
             "pixels it\n"
             "                    does not light are empty (default: ");
  print_value("0");
  print_info(", no shadows; world units)\n");
  print_info(
    "    -noise_a A -noise_b B = with -organized: depth noise along the ray of "
    "sigma\n"
    "                    A + B depth^2 (default: ");
  print_value("0 0");
  print_info("; world units)\n");
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
  double density_ratio = kDefaultDensityRatio;
  int dense_face = 0;
  bool mesh = false;
  double chord = kDefaultChord; // cells
  bool organized = false;
  syn::OrganizedViewOptions view; // camera in the model's frame before the rotation
};

/** \brief Warn about the options that have no effect with the chosen product. */
void
warnUnused(const vt::Arguments& args, const Options& opt)
{
  const bool cloud = !opt.mesh && !opt.organized;
  const char* product = opt.mesh ? "-mesh" : "-organized";
  if (!cloud)
    for (const char* o :
         {"-spacing", "-points", "-noise", "-density_ratio", "-dense_face"})
      if (args.has(o))
        print_warn("%s is ignored with %s\n", o, product);
  if (!opt.mesh && args.has("-chord"))
    print_warn("-chord is ignored without -mesh\n");
  if (!opt.organized)
    for (const char* o :
         {"-fov", "-view", "-distance", "-baseline", "-noise_a", "-noise_b"})
      if (args.has(o))
        print_warn("%s is ignored without -organized\n", o);
  if (cloud && args.has("-points") && args.has("-spacing"))
    print_warn("-points given: -spacing is ignored\n");
  if (cloud && args.has("-dense_face") && !args.has("-density_ratio"))
    print_warn("-dense_face has no effect without -density_ratio\n");
}

/** \brief Read the options of -mesh, -organized and -density_ratio. */
bool
readProductOptions(const vt::Arguments& args, Options& opt, std::string& error)
{
  opt.mesh = args.has("-mesh");
  opt.organized = args.has("-organized");
  if (opt.mesh && opt.organized) {
    error = "give -mesh or -organized, not both";
    return false;
  }
  if (opt.organized && !vt::parseImageSize(args.value("-organized"), opt.view.width,
                                           opt.view.height, error))
    return false;
  if (args.has("-view") &&
      !vt::parseDirection(args.value("-view"), opt.view.camera_direction, error))
    return false;
  if (!args.getReal("-density_ratio", 1e-3, 1e3, opt.density_ratio, error) ||
      !args.getInteger("-dense_face", 0, std::numeric_limits<int>::max(),
                       opt.dense_face, error) ||
      !args.getReal("-chord", 1e-6, 1e3, opt.chord, error) ||
      !args.getReal("-fov", 1.0, 179.0, opt.view.horizontal_fov, error) ||
      !args.getReal("-distance", 0.0, 1e6, opt.view.distance, error) ||
      !args.getReal("-baseline", -1e6, 1e6, opt.view.baseline, error) ||
      !args.getReal("-noise_a", 0.0, 1e6, opt.view.noise_a, error) ||
      !args.getReal("-noise_b", 0.0, 1e6, opt.view.noise_b, error))
    return false;
  const auto faces = syn::cadModelByName(opt.name).faces.size();
  if (opt.dense_face >= static_cast<int>(faces)) {
    error = "-dense_face " + std::to_string(opt.dense_face) + " is not a face of '" +
            opt.name + "' (0 to " + std::to_string(faces - 1) + ")";
    return false;
  }
  const std::string extension = opt.mesh ? ".ply" : ".pcd";
  if (vt::lowerExtension(opt.output) != extension) {
    error = "output '" + opt.output + "' must have the extension " + extension +
            (opt.mesh ? " (with -mesh)" : "");
    return false;
  }
  warnUnused(args, opt);
  return true;
}

/** \brief Read and check the options, the model name and the outputs (the right
 * extensions, writable, distinct) before any work. */
bool
readOptions(const vt::Arguments& args, Options& opt, std::string& error)
{
  if (args.positional().size() != 2) {
    error = "expected a model and an output .pcd or .ply, got " +
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
  if (args.has("-truth") && opt.truth.empty()) {
    error = "-truth expects a file name";
    return false;
  }
  bool known = false;
  for (const auto& n : syn::allCadModelNames())
    known = known || n == opt.name;
  if (!known) {
    error = "unknown model '" + opt.name + "' (known: " + modelList() + ")";
    return false;
  }
  if (!readProductOptions(args, opt, error))
    return false;
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

/** \brief The rotated model sampled into `cloud`, printing what was generated. */
bool
generateCloud(const Options& opt,
              const syn::CadModel& model,
              pcl::PointCloud<vt::PointGenerated>& cloud,
              std::string& error)
{
  TicToc tt;
  tt.tic();
  print_highlight("Generating ");
  print_value("%s ", opt.name.c_str());
  const std::uint64_t seed64 = static_cast<std::uint64_t>(opt.seed);
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
  if (opt.density_ratio != 1.0)
    options.face_density = syn::denseFace(model, opt.dense_face, opt.density_ratio);
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
  print_info(" cells");
  if (opt.density_ratio != 1.0) {
    print_info(", face ");
    print_value("%d", opt.dense_face);
    print_info(" denser by ");
    print_value("%g", opt.density_ratio);
  }
  print_info(", seed ");
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

/** \brief The rotated model's tessellation, printing what was generated. */
pcl::PolygonMesh
generateMesh(const Options& opt, const syn::CadModel& model)
{
  TicToc tt;
  tt.tic();
  print_highlight("Tessellating ");
  print_value("%s ", opt.name.c_str());
  const double cell = syn::cellSize(model, opt.resolution);
  const syn::CadMesh mesh = syn::tessellateCadModel(model, opt.chord * cell);
  pcl::PolygonMesh out = vt::toPolygonMesh(mesh);
  print_info("[done, ");
  print_value("%g", tt.toc());
  print_info(" ms : ");
  print_value("%zu", mesh.mesh.vertices.size());
  print_info(" vertices, ");
  print_value("%zu", mesh.mesh.triangles.size());
  print_info(" triangles; resolution ");
  print_value("%d", opt.resolution);
  print_info(", cell ");
  print_value("%g", cell);
  print_info(", chord ");
  print_value("%g", opt.chord);
  print_info(" cells, seed ");
  print_value("%lld", opt.seed);
  print_info("]\n");
  return out;
}

/** \brief One organized view of the rotated model, its camera turned with the model
 * (`rotation`), into `cloud`, printing what was generated. */
void
generateView(const Options& opt,
             const syn::CadModel& model,
             const Eigen::Matrix3d& rotation,
             pcl::PointCloud<vt::PointGenerated>& cloud)
{
  TicToc tt;
  tt.tic();
  print_highlight("Viewing ");
  print_value("%s ", opt.name.c_str());
  syn::OrganizedViewOptions view = opt.view;
  view.camera_direction = rotation * opt.view.camera_direction.normalized();
  view.up = rotation * opt.view.up;
  view.seed = static_cast<std::uint64_t>(opt.seed);
  visfeat::checkMemory(
    static_cast<std::uint64_t>(view.width) * static_cast<std::uint64_t>(view.height) *
      (sizeof(Eigen::Vector3f) + sizeof(int) + sizeof(double) +
       sizeof(vt::PointGenerated) + 20),
    0, std::to_string(view.width) + "x" + std::to_string(view.height) + " pixels");
  const syn::OrganizedView result = syn::renderOrganizedView(model, view);
  vt::toOrganizedCloud(result, cloud);
  std::size_t hits = 0;
  for (int f : result.face)
    hits += f >= 0 ? 1 : 0;
  print_info("[done, ");
  print_value("%g", tt.toc());
  print_info(" ms : ");
  print_value("%dx%d", result.width, result.height);
  print_info(" pixels, ");
  print_value("%zu", hits);
  print_info(" hits; camera at ");
  print_value("%g", (result.camera_position - view.target).norm());
  print_info(", baseline ");
  print_value("%g", view.baseline);
  print_info(", noise ");
  print_value("%g + %g depth^2", view.noise_a, view.noise_b);
  print_info(" world units, seed ");
  print_value("%lld", opt.seed);
  print_info("]\n");
}

/** \brief Write the product (`write_output`: to the temporary name of opt.output) and
 * the truth under temporary names and rename them only when both are complete, so a
 * failure leaves neither. */
template <typename WriteOutput>
bool
writeOutputs(const Options& opt,
             const syn::CadModel& model,
             WriteOutput&& write_output,
             std::string& error)
{
  TicToc tt;
  tt.tic();
  print_highlight("Saving ");
  print_value("%s ", opt.output.c_str());
  if (!opt.truth.empty())
    print_value("%s ", opt.truth.c_str());
  if (!write_output(error)) {
    print_info("\n");
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

/** \brief Write a cloud as binary PCD to the temporary name of `path`. */
bool
writeCloud(const std::string& path,
           const pcl::PointCloud<vt::PointGenerated>& cloud,
           std::string& error)
{
  pcl::PCDWriter writer;
  const int rc =
    vt::quietly([&] { return writer.writeBinary(vt::temporaryPath(path), cloud); });
  if (rc >= 0)
    return true;
  vt::discardOutput(path);
  error = "cannot write '" + path + "' (disk full or not writable?)";
  return false;
}

int
run(int argc, char** argv)
{
  const vt::Arguments args(argc, argv,
                           {"-resolution", "-spacing", "-points", "-seed", "-noise",
                            "-truth", "-density_ratio", "-dense_face", "-chord",
                            "-organized", "-fov", "-view", "-distance", "-baseline",
                            "-noise_a", "-noise_b"},
                           {"-q", "-h", "--help", "-mesh"});
  if (!args.ok())
    return fail(args.error());
  if (args.has("-q"))
    vt::beQuiet();
  Options opt;
  std::string error;
  if (!readOptions(args, opt, error))
    return fail(error);
  const Eigen::Matrix3d rotation =
    syn::randomRotation(static_cast<std::uint64_t>(opt.seed));
  const syn::CadModel model = syn::rotated(syn::cadModelByName(opt.name), rotation);
  if (opt.mesh) {
    const pcl::PolygonMesh mesh = generateMesh(opt, model);
    printTruth(model);
    if (!writeOutputs(
          opt, model,
          [&](std::string& e) { return vt::writeMeshPly(opt.output, mesh, e); }, error))
      return fail(error);
    return 0;
  }
  pcl::PointCloud<vt::PointGenerated> cloud;
  if (opt.organized)
    generateView(opt, model, rotation, cloud);
  else if (!generateCloud(opt, model, cloud, error))
    return fail(error);
  printTruth(model);
  if (!writeOutputs(
        opt, model, [&](std::string& e) { return writeCloud(opt.output, cloud, e); },
        error))
    return fail(error);
  return 0;
}

} // namespace

int
main(int argc, char** argv)
{
  return vt::toolMain(argc, argv, kProgram, true, printHelp, run);
}
