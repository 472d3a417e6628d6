// visfeat_eval: score visfeat on the generated CAD models with noise against their
// ground truth -- regions found against the true vertices / curves / faces, the
// topology graph's arcs, and the per-point precision / recall / F1 of the edge+vertex
// labels -- beside the best F1 of PCL's surface variation and (when built with CGAL)
// CGAL's Voronoi Covariance Measure on the same cloud in the same run.

#include "common/arguments.h"
#include "common/output_files.h"
#include "common/tool_main.h"
#include "peers.h"
#include "visfeat_eval_report.h"

#include <core/common/json_document.h>

#include <support/cad_models.h>
#include <support/evaluation.h>
#include <support/synthetic_shapes.h>
#include <visfeat/core/common/feature_class.h>
#include <visfeat/core/common/threads.h>
#include <visfeat/core/grid/grid_spec.h>
#include <visfeat/core/visibility/visibility_map.h>
#include <visfeat/point_types.h>
#include <visfeat/visibility_feature_estimation.h>

#include <pcl/console/print.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

using namespace pcl::console;
namespace vt = visfeat_tools;
namespace syn = visfeat::synthetic;
namespace ev = visfeat::evaluation;

namespace {

const char* const kProgram = "visfeat_eval";

using visfeat_eval::kHaveCgal;
using visfeat_eval::kPclK;
using visfeat_eval::kSpacingCells;
using visfeat_eval::kVcmConvolutionCells;
using visfeat_eval::kVcmOffsetCells;
using visfeat_eval::PeerRow;
using visfeat_eval::printHeader;
using visfeat_eval::printRow;
using visfeat_eval::Row;
using visfeat_eval::Settings;
using visfeat_eval::writeJson;

std::string
joined(const std::vector<std::string>& items)
{
  std::string text;
  for (const auto& item : items)
    text += (text.empty() ? "" : ",") + item;
  return text;
}

void
printHelp(const char* program)
{
  print_error("Syntax is: %s <options>\n", program);
  print_info(
    "  Samples the CAD models (random rotation, %g-cell spacing) with Gaussian noise "
    "and\n"
    "  scores visfeat against their truth: regions found (V/E/F) against the true\n"
    "  vertices / curves / faces, whether every curve's region links its true faces "
    "and\n"
    "  end vertices, and per point the precision (edge/vertex points within 2 cells "
    "of a\n"
    "  true sharp curve), recall (points within 1 cell labeled edge/vertex) and F1. "
    "On\n"
    "  the same cloud, the peers: PCL's surface variation (NormalEstimationOMP, k = "
    "%d)\n"
    "  and CGAL's VCM (compute_vcm, offset radius %g cells, convolution radius %g "
    "cells),\n"
    "  each thresholded at its best F1. Times: visfeat's whole compute(), PCL's "
    "normal\n"
    "  estimation (kd-tree included), CGAL's compute_vcm (single-threaded).\n",
    kSpacingCells, kPclK, kVcmOffsetCells, kVcmConvolutionCells);
  print_info("  where options are:\n");
  print_info("    -models a,b,...    = CAD models (default: ");
  print_value("%s", joined(syn::cadModelNames()).c_str());
  print_info(")\n");
  print_info("    -noise s,...       = noise sigmas in cells (default: ");
  print_value("0,0.22,0.32,0.45");
  print_info(")\n");
  print_info("    -resolution N      = cells along the longest side (default: ");
  print_value("256");
  print_info(")\n");
  print_info("    -seed K            = rotation, sampling and noise seed (default: ");
  print_value("1");
  print_info(")\n");
  print_info("    -opacity D         = visfeat's opacity (default: the estimator's, ");
  print_value("0");
  print_info(" cell edges)\n");
  print_info("    -noise_mode        = visfeat's noise mode (smoothing %g cells, "
             "feature points within %g cells; default: ",
             visfeat::VisibilityFeatureEstimation<pcl::PointXYZ>::kNoiseSmoothingRadius,
             visfeat::VisibilityFeatureEstimation<pcl::PointXYZ>::kNoisePointDistance);
  print_value("off");
  print_info(")\n");
  print_info("    -min_radius R      = visfeat's min_radius (default: the "
             "estimator's)\n");
  print_info("    -max_radius R      = visfeat's visibility cap (default: the "
             "estimator's)\n");
  print_info("    -threads T         = threads for visfeat and PCL (default: ");
  print_value("0");
  print_info(" = all; CGAL's VCM is single-threaded)\n");
  print_info("    -peers a,b         = peers to run: pcl, cgal, none (default: all "
             "built: ");
  print_value("%s", kHaveCgal ? "pcl,cgal" : "pcl");
  print_info(")\n");
  print_info(
    "    -cgal_max_points N = skip CGAL on clouds with more points (default: ");
  print_value("0");
  print_info(" = no limit)\n");
  print_info("    -quantiles Q       = peer thresholds tried: the Q quantiles of the "
             "scores; 0 = every distinct value, the exact best (default: ");
  print_value("0");
  print_info(")\n");
  print_info("    -json out.json     = also write the results as JSON\n");
  if (!kHaveCgal)
    print_info("  CGAL peer not built (install libcgal-dev and re-run CMake).\n");
}

int
fail(const std::string& message)
{
  vt::printError(kProgram, message);
  return 1;
}

void progress(const char* format, ...) __attribute__((format(printf, 1, 2)));

void
progress(const char* format, ...)
{
  va_list args;
  va_start(args, format);
  std::vfprintf(stderr, format, args);
  va_end(args);
  std::fflush(stderr);
}

PeerRow
sweepPeer(const vt::PeerScore& peer,
          const std::vector<double>& distance_cells,
          std::size_t quantiles)
{
  PeerRow row;
  if (!peer.error.empty()) {
    row.note = peer.error;
    return row;
  }
  row.run = true;
  row.seconds = peer.seconds;
  row.sweep = ev::sweepThreshold(peer.score, distance_cells, quantiles);
  return row;
}

Row
evaluate(const Settings& s, const std::string& name, double sigma)
{
  Row row;
  row.model = name;
  row.sigma = sigma;
  const std::uint64_t seed = static_cast<std::uint64_t>(s.seed);
  const syn::CadModel model =
    syn::rotated(syn::cadModelByName(name), syn::randomRotation(seed));
  // The model's nominal cell: noise, tolerances and the VCM radii are in it (visfeat's
  // own grid is a little coarser with noise, its box being larger).
  double cell = syn::cellSize(model, s.resolution);
  syn::SamplingOptions options;
  options.count = s.points > 0
                    ? s.points
                    : syn::samplesForSpacing(model, s.resolution, kSpacingCells);
  options.seed = seed;
  options.noise_sigma = sigma * cell;
  const syn::CadSamples samples = syn::sampleCadModel(model, options);
  row.points = samples.points.size();
  auto cloud = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  cloud->resize(samples.points.size());
  for (std::size_t i = 0; i < samples.points.size(); ++i)
    (*cloud)[i].getVector3fMap() = samples.points[i];
  cloud->width = static_cast<std::uint32_t>(cloud->size());
  cloud->height = 1;
  cloud->is_dense = true;
  std::vector<double> distance_cells(samples.curve_distance.size());
  progress("# %s sigma %.2f: %zu points; visfeat...", name.c_str(), sigma, row.points);

  {
    visfeat::VisibilityFeatureEstimation<pcl::PointXYZ, visfeat::PointVisibility> est;
    est.setInputCloud(cloud);
    // -points without -resolution: the library's automatic resolution and fill
    est.setResolution(s.points > 0 && !s.set_resolution ? 0 : s.resolution);
    est.setLocalTriangleParameters(s.fill);
    est.setNoiseMode(s.noise_mode);
    if (s.set_opacity)
      est.setOpacity(s.opacity);
    if (s.set_max_radius)
      est.setMaxRadius(s.max_radius);
    if (s.set_min_radius)
      est.setMinRadius(s.min_radius);
    est.setNumberOfThreads(static_cast<unsigned int>(s.threads));
    pcl::PointCloud<visfeat::PointVisibility> out;
    const double t0 = vt::secondsNow();
    vt::quietly([&] {
      est.compute(out);
      return 0;
    });
    row.seconds = vt::secondsNow() - t0;
    if (out.empty()) {
      row.error =
        est.getErrorMessage().empty() ? "compute() failed" : est.getErrorMessage();
      progress(" failed\n");
      return row;
    }
    // distances in cells, or in point spacings where the cells are finer
    if (s.points > 0)
      cell = std::max(est.getGrid().cell_size,
                      std::sqrt(model.area() / static_cast<double>(s.points)));
    for (std::size_t i = 0; i < distance_cells.size(); ++i)
      distance_cells[i] = samples.curve_distance[i] / cell;
    std::vector<std::uint32_t> labels(out.size());
    std::vector<std::uint8_t> classes(out.size()), feature(out.size());
    for (std::size_t i = 0; i < out.size(); ++i) {
      labels[i] = out[i].label;
      classes[i] = out[i].feature_class;
      const auto cls = static_cast<visfeat::FeatureClass>(out[i].feature_class);
      feature[i] =
        cls == visfeat::FeatureClass::kEdge || cls == visfeat::FeatureClass::kVertex;
    }
    row.scores = ev::scoreFeaturePoints(feature, distance_cells);
    row.topology = ev::compareTopology(model, samples.points, samples.face, labels,
                                       classes, est.getTopologyGraph(), cell);
    progress(" %.2f s, F1 %.3f", row.seconds, row.scores.f1());
  }
  row.cell = cell;

  if (s.pcl) {
    progress("; PCL...");
    row.pcl = sweepPeer(
      vt::pclSurfaceVariation(cloud, kPclK, static_cast<unsigned int>(s.threads)),
      distance_cells, s.quantiles);
    if (row.pcl.run)
      progress(" %.2f s, F1 %.3f", row.pcl.seconds, row.pcl.sweep.scores.f1());
  } else
    row.pcl.note = "not requested";

  if (!s.cgal)
    row.cgal.note = kHaveCgal ? "not requested" : "not built";
  else if (s.cgal_max_points > 0 && row.points > s.cgal_max_points) {
    row.cgal.note = "skipped: more than -cgal_max_points points";
    progress("; CGAL skipped (%zu > %zu points)", row.points, s.cgal_max_points);
  } else {
#ifdef VISFEAT_HAVE_CGAL
    progress("; CGAL VCM (single-threaded)...");
    row.cgal = sweepPeer(
      vt::cgalVcm(*cloud, kVcmOffsetCells * cell, kVcmConvolutionCells * cell),
      distance_cells, s.quantiles);
    if (row.cgal.run)
      progress(" %.2f s, F1 %.3f", row.cgal.seconds, row.cgal.sweep.scores.f1());
#endif
  }
  progress("\n");
  return row;
}

int
run(int argc, char** argv)
{
  const vt::Arguments args(
    argc, argv,
    {"-models", "-noise", "-resolution", "-seed", "-opacity", "-min_radius",
     "-max_radius", "-threads", "-peers", "-cgal_max_points", "-quantiles", "-json",
     "-points", "-fill_edge", "-fill_neighbours", "-fill_votes", "-fill_crease"},
    {"-noise_mode", "-h", "--help"});
  if (!args.ok())
    return fail(args.error());
  if (!args.positional().empty())
    return fail("unexpected argument '" + args.positional()[0] + "' (see -h)");

  Settings s;
  std::string error;
  if (!args.getInteger("-resolution", visfeat::GridSpec::kMinResolution,
                       visfeat::GridSpec::kMaxResolution, s.resolution, error) ||
      !args.getInteger("-seed", 0, std::numeric_limits<long long>::max(), s.seed,
                       error) ||
      !args.getReal("-opacity", 0.0, visfeat::VisibilityMap::kMaxOpacity, s.opacity,
                    error) ||
      !args.getInteger("-min_radius", 1, visfeat::VisibilityMap::kMaxRadius,
                       s.min_radius, error) ||
      !args.getInteger("-max_radius", 1, visfeat::VisibilityMap::kMaxRadius,
                       s.max_radius, error) ||
      !args.getInteger("-threads", 0, visfeat::VisibilityMap::kMaxThreads, s.threads,
                       error) ||
      !args.getInteger("-cgal_max_points", 0, std::numeric_limits<long long>::max(),
                       s.cgal_max_points, error) ||
      !args.getInteger("-quantiles", 0, 1000000, s.quantiles, error) ||
      !args.getInteger("-points", 0, 1LL << 31, s.points, error) ||
      !args.getReal("-fill_edge", 1.0, 10.0, s.fill.max_edge_spacings, error) ||
      !args.getInteger("-fill_neighbours", 4, 64, s.fill.neighbours, error) ||
      !args.getInteger("-fill_votes", 1, 3, s.fill.min_votes, error) ||
      !args.getReal("-fill_crease", 1.0, 180.0, s.fill.crease_degrees, error))
    return fail(error);
  s.set_resolution = args.has("-resolution");
  s.set_opacity = args.has("-opacity");
  s.noise_mode = args.has("-noise_mode");
  s.set_min_radius = args.has("-min_radius");
  s.set_max_radius = args.has("-max_radius");

  const std::vector<std::string> known = syn::allCadModelNames();
  if (args.has("-models")) {
    for (const std::string& name : vt::splitList(args.value("-models"))) {
      if (std::find(known.begin(), known.end(), name) == known.end())
        return fail("-models: unknown model '" + name + "' (known: " + joined(known) +
                    ")");
      s.models.push_back(name);
    }
  } else
    s.models = syn::cadModelNames();
  if (args.has("-noise")) {
    s.noise.clear();
    for (const std::string& item : vt::splitList(args.value("-noise"))) {
      double sigma = 0.0;
      if (!vt::parseReal(item, sigma) || sigma < 0.0 || sigma > 100.0)
        return fail("-noise: '" + item + "' is not a number in [0, 100] (cells)");
      s.noise.push_back(sigma);
    }
  }
  if (args.has("-peers")) {
    s.pcl = s.cgal = false;
    for (const std::string& item : vt::splitList(args.value("-peers"))) {
      if (item == "pcl")
        s.pcl = true;
      else if (item == "cgal") {
        if (!kHaveCgal)
          return fail("-peers cgal: CGAL peer not built (install libcgal-dev, e.g. "
                      "scripts/install_deps.sh --peers, and re-run CMake)");
        s.cgal = true;
      } else if (item != "none")
        return fail("-peers: unknown peer '" + item + "' (known: pcl, cgal, none)");
    }
  }
  if (args.has("-json")) {
    s.json = args.value("-json");
    if (!vt::checkWritable(s.json, error))
      return fail(error);
  }

  const int omp_threads = visfeat::resolveThreads(0);
  std::printf(
    "# visfeat_eval: resolution %d, spacing %g cells, seed %lld, threads %d%s "
    "(%u hardware); opacity %s%s; recall within 1 cell, precision within 2 "
    "cells of a true sharp curve; peers at their best threshold (%s)\n",
    s.resolution, kSpacingCells, s.seed, s.threads == 0 ? omp_threads : s.threads,
    s.threads == 0 ? " (all)" : "", std::thread::hardware_concurrency(),
    s.set_opacity ? std::to_string(s.opacity).c_str() : "default",
    s.noise_mode ? ", noise mode" : "",
    s.quantiles == 0 ? "every distinct score tried"
                     : (std::to_string(s.quantiles) + " quantiles tried").c_str());
  std::printf("# PCL: NormalEstimationOMP k=%d, score lambda0/sum, time with kd-tree; "
              "CGAL: %s\n",
              kPclK,
              kHaveCgal ? "compute_vcm R=4 r=2 cells, score lambda1/sum (ascending), "
                          "single-threaded"
                        : "peer not built (install libcgal-dev)");
  std::printf("# arcs: ok = every true curve's region links exactly its two faces "
              "and end vertices; else how many curves do\n");
  printHeader();

  std::vector<Row> rows;
  int status = 0;
  for (const std::string& name : s.models)
    for (double sigma : s.noise) {
      Row row;
      try {
        row = evaluate(s, name, sigma);
      } catch (const std::bad_alloc&) {
        row.model = name;
        row.sigma = sigma;
        row.error = "out of memory";
      } catch (const std::exception& e) {
        row.model = name;
        row.sigma = sigma;
        row.error = e.what();
      }
      if (!row.error.empty())
        status = 1;
      printRow(row);
      rows.push_back(row);
    }
  if (!s.json.empty() && !writeJson(s, rows, error))
    return fail(error);
  return status;
}

} // namespace

int
main(int argc, char** argv)
{
  return vt::toolMain(argc, argv, kProgram, false, printHelp, run);
}
