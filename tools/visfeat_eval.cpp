// visfeat_eval: score visfeat on the generated CAD models with noise against their
// ground truth -- regions found against the true vertices / curves / faces, the
// topology graph's arcs, and the per-point precision / recall / F1 of the edge+vertex
// labels -- beside the best F1 of PCL's surface variation and (when built with CGAL)
// CGAL's Voronoi Covariance Measure on the same cloud in the same run.

#include "common/arguments.h"
#include "common/output_files.h"
#include "common/tool_main.h"
#include "peers.h"

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

#ifdef _OPENMP
#endif

using namespace pcl::console;
namespace vt = visfeat_tools;
namespace syn = visfeat::synthetic;
namespace ev = visfeat::evaluation;

namespace {

const char* const kProgram = "visfeat_eval";

constexpr double kSpacingCells = 0.5;
constexpr int kPclK = 30;
constexpr double kVcmOffsetCells = 4.0;
constexpr double kVcmConvolutionCells = 2.0;
#ifdef VISFEAT_HAVE_CGAL
constexpr bool kHaveCgal = true;
#else
constexpr bool kHaveCgal = false;
#endif

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

struct Settings
{
  std::vector<std::string> models;
  std::vector<double> noise{0.0, 0.22, 0.32, 0.45};
  int resolution = 256;
  bool set_resolution = false;
  std::size_t points = 0; // 0: 0.5-cell spacing at the resolution
  visfeat::LocalTriangleParameters fill;
  long long seed = 1;
  bool set_opacity = false, set_min_radius = false, set_max_radius = false;
  bool noise_mode = false;
  double opacity = 0.0;
  int min_radius = 0, max_radius = 0;
  int threads = 0;
  bool pcl = true, cgal = kHaveCgal;
  std::size_t cgal_max_points = 0;
  std::size_t quantiles = 0;
  std::string json;
};

/** \brief A peer's best threshold, or why there is none. */
struct PeerRow
{
  bool run = false;
  std::string note; // why not run, or the error
  ev::ThresholdSweep sweep;
  double seconds = 0.0;
};

struct Row
{
  std::string model;
  double sigma = 0.0;
  std::size_t points = 0;
  double cell = 0.0;
  std::string error;
  ev::TopologyComparison topology;
  ev::PointScores scores;
  double seconds = 0.0;
  PeerRow pcl, cgal;
};

// Table: one row per model and sigma, printed when the row is complete.
void
printHeader()
{
  std::printf("%-16s %5s %8s | %-9s %-9s %-6s | %5s %5s %5s %7s | %5s %7s %9s | %5s "
              "%7s %9s\n",
              "model", "sigma", "points", "V/E/F", "true", "arcs", "P", "R", "F1",
              "time_s", "PCL", "time_s", "thr", "CGAL", "time_s", "thr");
  std::fflush(stdout);
}

std::string
countsText(const std::array<std::size_t, 3>& c)
{
  return std::to_string(c[0]) + "/" + std::to_string(c[1]) + "/" + std::to_string(c[2]);
}

std::string
peerText(const PeerRow& p)
{
  char text[64];
  if (!p.run)
    std::snprintf(text, sizeof(text), "%5s %7s %9s", "-", "-", "-");
  else
    std::snprintf(text, sizeof(text), "%5.3f %7.2f %9.3g", p.sweep.scores.f1(),
                  p.seconds, p.sweep.threshold);
  return text;
}

void
printRow(const Row& r)
{
  if (!r.error.empty()) {
    std::printf("%-16s %5.2f %8zu | FAILED: %s\n", r.model.c_str(), r.sigma, r.points,
                r.error.c_str());
    std::fflush(stdout);
    return;
  }
  // arcs: "ok" when every true curve's region links exactly its faces and end
  // vertices, else how many curves do.
  const std::string arcs = r.topology.arcsCorrect()
                             ? "ok"
                             : std::to_string(r.topology.curves_linked) + "/" +
                                 std::to_string(r.topology.truth[1]);
  std::printf("%-16s %5.2f %8zu | %-9s %-9s %-6s | %5.3f %5.3f %5.3f %7.2f | %s | %s\n",
              r.model.c_str(), r.sigma, r.points, countsText(r.topology.found).c_str(),
              countsText(r.topology.truth).c_str(), arcs.c_str(), r.scores.precision(),
              r.scores.recall(), r.scores.f1(), r.seconds, peerText(r.pcl).c_str(),
              peerText(r.cgal).c_str());
  std::fflush(stdout);
}

using visfeat::json_document::Json;

/** A number, or null when it is undefined (a score of nothing, NaN). */
Json
jsonNumber(double v)
{
  return std::isfinite(v) ? Json(v) : Json(nullptr);
}

Json
scoresJson(const ev::PointScores& s)
{
  return {{"precision", jsonNumber(s.precision())},
          {"recall", jsonNumber(s.recall())},
          {"f1", jsonNumber(s.f1())},
          {"labeled", s.labeled},
          {"labeled_near", s.labeled_near},
          {"near", s.near},
          {"near_labeled", s.near_labeled}};
}

Json
peerJson(const PeerRow& p)
{
  if (!p.run)
    return {{"run", false}, {"note", p.note}};
  Json peer = {{"run", true},
               {"threshold", jsonNumber(p.sweep.threshold)},
               {"thresholds_tried", p.sweep.candidates},
               {"seconds", jsonNumber(p.seconds)}};
  peer.update(scoresJson(p.sweep.scores));
  return peer;
}

Json
visfeatJson(const Row& r)
{
  const ev::TopologyComparison& t = r.topology;
  Json v = {
    {"seconds", jsonNumber(r.seconds)},
    {"found", {{"vertices", t.found[0]}, {"edges", t.found[1]}, {"faces", t.found[2]}}},
    {"truth", {{"vertices", t.truth[0]}, {"edges", t.truth[1]}, {"faces", t.truth[2]}}},
    {"counts_exact", t.countsExact()},
    {"arcs_correct", t.arcsCorrect()},
    {"curves_matched", t.curves_matched},
    {"vertices_matched", t.vertices_matched},
    {"faces_matched", t.faces_matched},
    {"curves_linked", t.curves_linked}};
  v.update(scoresJson(r.scores));
  v["problems"] = t.problems;
  return v;
}

bool
writeJson(const Settings& s, const std::vector<Row>& rows, std::string& error)
{
  if (!vt::checkWritable(s.json, error))
    return false;
  Json document = {{"format", "visfeat-eval"},
                   {"version", 1},
                   {"resolution", s.resolution},
                   {"seed", s.seed},
                   {"spacing_cells", kSpacingCells},
                   {"pcl_k", kPclK},
                   {"vcm_offset_cells", kVcmOffsetCells},
                   {"vcm_convolution_cells", kVcmConvolutionCells},
                   {"recall_cells", 1},
                   {"precision_cells", 2},
                   {"rows", Json::array()}};
  for (const Row& r : rows) {
    Json row = {{"model", r.model},
                {"sigma_cells", jsonNumber(r.sigma)},
                {"points", r.points},
                {"cell", jsonNumber(r.cell)}};
    if (!r.error.empty()) {
      row["error"] = r.error;
    } else {
      row["visfeat"] = visfeatJson(r);
      row["pcl_surface_variation"] = peerJson(r.pcl);
      row["cgal_vcm"] = peerJson(r.cgal);
    }
    document["rows"].push_back(row);
  }
  {
    std::ofstream out(vt::temporaryPath(s.json));
    visfeat::json_document::write(out, document);
    if (!out) {
      vt::discardOutput(s.json);
      error = "cannot write '" + s.json + "'";
      return false;
    }
  }
  return vt::commitOutput(s.json, error);
}

/** Progress on stderr, so stdout stays the table. */
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

  const std::vector<std::string> known = syn::cadModelNames();
  if (args.has("-models")) {
    for (const std::string& name : vt::splitList(args.value("-models"))) {
      if (std::find(known.begin(), known.end(), name) == known.end())
        return fail("-models: unknown model '" + name + "' (known: " + joined(known) +
                    ")");
      s.models.push_back(name);
    }
  } else
    s.models = known;
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
