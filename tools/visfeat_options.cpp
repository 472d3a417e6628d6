// The options of the visfeat tool; see visfeat_options.h.

#include "visfeat_options.h"

#include "common/output_files.h"

#include <visfeat/core/band/point_smoothing.h>
#include <visfeat/core/grid/grid_spec.h>
#include <visfeat/core/grid/resolution.h>
#include <visfeat/core/grid/resolution_search.h>
#include <visfeat/core/visibility/visibility_map.h>
#include <visfeat/surface_fill.h>
#include <visfeat/visibility_feature_estimation.h>

#include <pcl/console/print.h>

#include <limits>
#include <vector>

using namespace pcl::console;
using Estimator = visfeat::VisibilityFeatureEstimation<pcl::PointXYZ>;

namespace visfeat_tools {

const std::set<std::string>&
valueOptions()
{
  // (in columns: clang-format lists one a line with the longest name)
  // clang-format off
  static const std::set<std::string> names{
    "-resolution",      "-max_radius",     "-min_radius",
    "-vertex_cells",    "-dimensionality", "-min_crease_angle",
    "-opacity",         "-smooth",         "-threads",
    "-memory_limit_mb", "-voxels",         "-graph",
    "-mesh_points",     "-mesh_spacing",   "-png",
    "-png_radius",      "-png_size",       "-fill",
    "-fill_neighbours", "-fill_gap",       "-fill_edge",
    "-fill_inset",      "-fill_votes",     "-narrow_persistence",
    "-max_search_resolution", "-flat_variation"};
  // clang-format on
  return names;
}

const std::set<std::string>&
switchOptions()
{
  static const std::set<std::string> names{
    "-no_repair",  "-raw",           "-no_regions", "-noise_mode", "-paper_noise",
    "-flat_cores", "-no_flat_cores", "-q",          "-h",          "--help"};
  return names;
}

namespace {

/** The options of the components, the regions and the per-point labels. */
void
printSegmentationHelp()
{
  print_info(
    "    -min_radius R     = cells with radius >= R form components (default: ");
  print_value("%d", kDefaultMinRadius);
  print_info(" rings; the paper used 11)\n");
  print_info("    -max_radius R     = cap of the visibility radius (default: ");
  print_value("min_radius");
  print_info("; %d-%d rings, >= min_radius)\n",
             visfeat::VisibilityMap::Parameters::kMaxRadiusRange.min,
             visfeat::VisibilityMap::Parameters::kMaxRadiusRange.max);
  print_info("    -vertex_cells N   = components of <= N cells are vertex candidates "
             "(default: ");
  print_value("%d", kDefaultVertexCells);
  print_info(" cells)\n");
  print_info(
    "    -narrow_persistence P = a face too narrow for a core gets one when its "
    "peak of the map stands P rings above its creases' valleys (default: ");
  print_value("%d", kDefaultNarrowPersistence);
  print_info(" rings; 0 = off)\n");
  print_info("    -dimensionality D = raw mode: edge if mean same-component "
             "6-neighbours < D (default: ");
  print_value("%g", kDefaultDimensionality);
  print_info(")\n");
  print_info("    -min_crease_angle A = an edge whose sides, fitted by planes "
             "within %g cells, turn by less than A degrees is a blend or a shallow "
             "facet, not a crease: it joins its faces (default: ",
             visfeat::CreaseAngleParameters::kDefaultWindowCells);
  print_value("%g", visfeat::CreaseAngleParameters::kDefaultMinCreaseAngle);
  print_info(" degrees; %g-%g, 0 = off)\n",
             visfeat::CreaseAngleParameters::kMinCreaseAngleRange.min,
             visfeat::CreaseAngleParameters::kMinCreaseAngleRange.max);
  print_info("    -flat_variation V = an edge or vertex point whose points within "
             "point_feature_distance + %g cell (at least %d of them) have a surface "
             "variation (PCL's curvature) of at most V lies on flat ground: it goes to "
             "the nearest face; the graph is unchanged (default: ",
             visfeat::FlatPointParameters::kMargin,
             visfeat::FlatPointParameters::kDefaultMinPoints);
  print_value("%g", visfeat::FlatPointParameters::kDefaultMaxSurfaceVariation);
  print_info("; %g-%g, 0 = off)\n",
             visfeat::FlatPointParameters::kMaxSurfaceVariationRange.min,
             visfeat::FlatPointParameters::kMaxSurfaceVariationRange.max);
  print_info("    -raw              = the paper's literal components (no regions, no "
             "clean-up)\n");
  print_info("    -no_regions       = label the components' cores only, not every "
             "point\n");
  print_info("    -no_flat_cores    = a core thinner than a face is an edge, flat "
             "across or not (default: a flat one is the middle of a face between two "
             "creases about 2 min_radius cells apart; see README, Thin face cores; "
             "-flat_cores, the default, is accepted)\n");
}

} // namespace

void
printHelp(const char* program)
{
  print_error(
    "Syntax is: %s input.{pcd,ply,xyz,txt,obj,off,stl} output.pcd <options>\n",
    program);
  print_info(
    "  Labels every point with the visibility radius of its voxel-band cell (Chica et "
    "al.,\n"
    "  \"Visibility-Based Feature Extraction From Discrete Models\"). The output "
    "holds\n"
    "  every field of the input plus visibility_radius (float), label (uint32) and\n"
    "  feature_class (uint8: 0 none, 1 vertex, 2 edge, 3 face); an existing field of\n"
    "  one of these names is overwritten. label is the region id (0 = none).\n"
    "  Text clouds (.xyz, .txt: x y z per line) are read in double; a cloud far from\n"
    "  the origin (survey coordinates) is recentred in double before the computation,\n"
    "  which is in float; the output keeps the input's coordinates.\n");
  print_info(
    "  A mesh (.obj, .off, .stl, or .ply with faces) gives the band directly: its\n"
    "  triangles are rasterised into the cells (-fill mesh, the default for meshes); "
    "the output\n"
    "  points are sampled on it uniformly by area, with a fixed seed (the same mesh\n"
    "  always gives the same cloud; -mesh_points, -mesh_spacing).\n");
  print_info("  where options are:\n");
  print_info("    -resolution N     = cells along the longest side of the "
             "bounding box (default: ");
  print_value("automatic");
  print_info(
    ": %g point spacings per cell, the spacing estimated from k-NN "
    "distances, at least %d where the band is filled between the points and "
    "%d for a mesh; then doubled, up to %d (-max_search_resolution), while the "
    "map shows narrow faces or creases merged into faces, or a closed surface's graph "
    "(a closed mesh, or a cloud all around a solid) has gaps, as far as the fill "
    "allows; %d-%d cells)\n",
    visfeat::kSpacingsPerCell, visfeat::kTopologyResolution,
    visfeat::kTopologyResolution, visfeat::kMaxSearchResolution,
    visfeat::GridSpec::kResolutionRange.min, visfeat::GridSpec::kResolutionRange.max);
  print_info("    -max_search_resolution N = the automatic resolution's search goes no "
             "finer (default: ");
  print_value("%d", visfeat::kMaxSearchResolution);
  print_info(" cells; 2048 resolves narrower faces, at a cost in time and memory, "
             "and may split a mesh's coarse facets; see README)\n");
  printSegmentationHelp();
  print_info("    -opacity D        = blocked length tolerated between two "
             "cells (default: ");
  print_value("%g", kDefaultOpacity);
  print_info(" cell edges = exact)\n");
  print_info("    -paper_noise      = the paper's setting for noise (its Section 6): "
             "-opacity ");
  print_value("%g", Estimator::kPaperNoiseOpacity);
  print_info(", no smoothing; -noise_mode does better on our measurements\n");
  print_info("    -noise_mode       = noisy scans (Gaussian noise up to ~0.5 cell): "
             "-smooth %g, feature points within %g cells of a curve (default: ",
             Estimator::kNoiseSmoothingRadius, Estimator::kNoisePointDistance);
  print_value("off");
  print_info(")\n");
  print_info("    -smooth R         = project every point onto the plane of its "
             "neighbours within R cells first (default: ");
  print_value("0");
  print_info(" = off, ");
  print_value("%g", Estimator::kNoiseSmoothingRadius);
  print_info(" with -noise_mode; %g-%g cells)\n",
             visfeat::SmoothingParameters::kRadiusRange.min,
             visfeat::SmoothingParameters::kRadiusRange.max);
  print_info("    -threads T        = threads of the visibility map and the "
             "segmentation (default: ");
  print_value("%d", kDefaultThreads);
  print_info(" = all)\n");
  print_info("    -no_repair        = do not add cells to make the band "
             "6-connected (default: ");
  print_value("repair on");
  print_info(")\n");
  print_info(
    "    -fill F           = where the band comes from: points (the cells of the\n"
    "                        points), triangles (also the cells between\n"
    "                        neighbouring points, for clouds sparser than the\n"
    "                        cells), grid (an organized cloud's pixel grid, cut at\n"
    "                        depth jumps), mesh (the input mesh's triangles), auto\n"
    "                        (default: mesh for a mesh, grid for an organized\n"
    "                        cloud, triangles where the points lie over %g\n"
    "                        cells apart or their cells leave holes, else points)\n",
    visfeat::kFillSpacingCells);
  print_info("    -fill_neighbours K = neighbours a point's triangles join (default: ");
  print_value("%d", visfeat::LocalTriangleParameters{}.neighbours);
  print_info(")\n");
  print_info("    -fill_gap DEG     = wider angular gaps between neighbours stay open, "
             "a scan's\n"
             "                        border (default: ");
  print_value("%g", visfeat::LocalTriangleParameters{}.max_gap_degrees);
  print_info(" degrees)\n");
  print_info("    -fill_edge S      = longest triangle edge in local point spacings "
             "(default: ");
  print_value("%g", visfeat::LocalTriangleParameters{}.max_edge_spacings);
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
  print_value("%zu", MeshDensity().points);
  print_info(" points; 1-%zu)\n", kMaxMeshPoints);
  print_info(
    "    -mesh_spacing S   = mesh input: sample area / S^2 points instead, S = "
    "mean spacing (default: ");
  print_value("unset");
  print_info("; world units)\n");
  printPictureHelp();
  print_info("    -q                = quiet: warnings and errors only\n");
  print_info("  Outputs are written to a temporary file and renamed when complete.\n");
}

namespace {

/** \brief The numeric options and the settings that exclude each other. */
bool
readValues(const Arguments& args, Options& opt, std::string& error)
{
  // Types and signs here; ranges with the library's own limits, before the (possibly
  // long) load.
  using Components = visfeat::ComponentParameters;
  using Visibility = visfeat::VisibilityMap::Parameters;
  const auto integer = [&](const char* name, const visfeat::ParameterRange<int>& range,
                           auto& value) {
    return args.getInteger(name, range.min, range.max, value, error);
  };
  const auto real = [&](const char* name, const visfeat::ParameterRange<double>& range,
                        double& value) {
    return args.getReal(name, range.min, range.max, value, error);
  };
  if (!integer("-resolution", visfeat::GridSpec::kResolutionRange, opt.resolution) ||
      !integer("-max_search_resolution", visfeat::GridSpec::kResolutionRange,
               opt.max_search_resolution) ||
      !integer("-max_radius", Visibility::kMaxRadiusRange, opt.max_radius) ||
      !integer("-min_radius", Components::kMinRadiusRange, opt.min_radius) ||
      !integer("-vertex_cells", Components::kVertexMaxCellsRange, opt.vertex_cells) ||
      !integer("-narrow_persistence", Components::kNarrowFacePersistenceRange,
               opt.narrow_persistence) ||
      !real("-dimensionality", Components::kDimensionalityRange, opt.dimensionality) ||
      !real("-min_crease_angle", visfeat::CreaseAngleParameters::kMinCreaseAngleRange,
            opt.min_crease_angle) ||
      !real("-flat_variation", visfeat::FlatPointParameters::kMaxSurfaceVariationRange,
            opt.flat_variation) ||
      !real("-opacity", Visibility::kOpacityRange, opt.opacity) ||
      !real("-smooth", visfeat::SmoothingParameters::kRadiusRange, opt.smooth) ||
      !integer("-threads", Visibility::kThreadsRange, opt.threads) ||
      !args.getInteger("-memory_limit_mb", 0, 1LL << 40, opt.memory_limit_mb, error) ||
      !args.getInteger("-mesh_points", 1, static_cast<long long>(kMaxMeshPoints),
                       opt.mesh.points, error) ||
      !args.getReal("-mesh_spacing", -std::numeric_limits<double>::max(),
                    std::numeric_limits<double>::max(), opt.mesh.spacing, error))
    return false;
  using Fill = visfeat::LocalTriangleParameters;
  if (!integer("-fill_neighbours", Fill::kNeighboursRange,
               opt.fill_triangles.neighbours) ||
      !real("-fill_gap", Fill::kMaxGapRange, opt.fill_triangles.max_gap_degrees) ||
      !real("-fill_edge", Fill::kMaxEdgeRange, opt.fill_triangles.max_edge_spacings) ||
      !integer("-fill_votes", Fill::kMinVotesRange, opt.fill_triangles.min_votes))
    return false;
  if (args.has("-fill") && !visfeat::parseSurfaceFill(args.value("-fill"), opt.fill)) {
    error = "-fill expects auto, points, triangles, grid or mesh, got '" +
            args.value("-fill") + "'";
    return false;
  }
  if (opt.paper_noise && opt.noise_mode) {
    error = "-paper_noise and -noise_mode are two settings for noise: give one";
    return false;
  }
  if (opt.paper_noise && args.has("-opacity")) {
    error = "-paper_noise sets the opacity: give -paper_noise or -opacity";
    return false;
  }
  if (opt.paper_noise && args.has("-smooth")) {
    error = "-paper_noise is the paper's setting without smoothing: give -paper_noise "
            "or -smooth";
    return false;
  }
  if (opt.paper_noise)
    opt.opacity = Estimator::kPaperNoiseOpacity;
  if (args.has("-mesh_spacing") && !(opt.mesh.spacing > 0.0)) {
    error = "-mesh_spacing must be positive, got " + args.value("-mesh_spacing");
    return false;
  }
  if (args.has("-mesh_spacing") && args.has("-mesh_points")) {
    error = "give -mesh_points or -mesh_spacing, not both";
    return false;
  }
  opt.repair = !args.has("-no_repair");
  opt.raw = args.has("-raw");
  opt.regions = !args.has("-no_regions");
  opt.flat_cores = !args.has("-no_flat_cores");
  if (args.has("-flat_cores") && args.has("-no_flat_cores")) {
    error = "-flat_cores and -no_flat_cores contradict each other: give one";
    return false;
  }
  if (opt.max_radius != 0 && opt.min_radius > opt.max_radius) {
    error = "-min_radius " + std::to_string(opt.min_radius) + " exceeds -max_radius " +
            std::to_string(opt.max_radius) + ": components need radii up to min_radius";
    return false;
  }
  return true;
}

/** \brief The output cloud, -voxels and -graph: the right extensions, writable,
 * distinct; checked before any work. */
bool
readOutputs(const Arguments& args, Options& opt, std::string& error)
{
  opt.voxels = args.value("-voxels");
  if (args.has("-voxels") && opt.voxels.empty()) {
    error = "-voxels needs a file name";
    return false;
  }
  for (const std::string& path : {opt.output, opt.voxels}) {
    if (path.empty())
      continue;
    if (lowerExtension(path) != ".pcd") {
      error = "output '" + path + "' must have the extension .pcd";
      return false;
    }
    if (!checkWritable(path, error))
      return false;
  }
  if (!opt.voxels.empty() && sameFile(opt.voxels, opt.output)) {
    error = "the -voxels file must differ from the output file";
    return false;
  }
  opt.graph = args.value("-graph");
  if (args.has("-graph")) {
    const std::string ext = lowerExtension(opt.graph);
    if (opt.graph.empty()) {
      error = "-graph needs a file name";
      return false;
    }
    if (ext != ".dot" && ext != ".gv" && ext != ".json") {
      error =
        "graph output '" + opt.graph + "' must have the extension .dot, .gv or .json";
      return false;
    }
    if (!checkWritable(opt.graph, error))
      return false;
    if (sameFile(opt.graph, opt.output) || sameFile(opt.graph, opt.voxels)) {
      error = "the -graph file must differ from the other outputs";
      return false;
    }
  }
  return true;
}

} // namespace

bool
readOptions(const Arguments& args, Options& opt, std::string& error)
{
  if (args.positional().size() != 2) {
    error = "expected an input (.pcd, .ply, .xyz, .txt, .obj, .off or .stl) and an "
            "output (.pcd), got " +
            std::to_string(args.positional().size()) + " file argument(s) (see -h)";
    return false;
  }
  opt.input = args.positional()[0];
  opt.output = args.positional()[1];
  return readValues(args, opt, error) && readOutputs(args, opt, error) &&
         parsePictureRequests(args, {opt.output, opt.voxels, opt.graph}, opt.pictures,
                              error);
}

/** \brief A message of the library in the tool's terms: its setters become the
 * options that set them. */
std::string
inToolTerms(std::string message)
{
  static const std::pair<const char*, const char*> kTerms[] = {
    {"call setInputMesh() first",
     "give a mesh (.obj, .off, .stl, or .ply with faces) as input"},
    {"as a mesh (setInputMesh())", "as a mesh (.obj, .off, .stl, or .ply with faces)"},
    {"setResolution()", "-resolution"},
    {"setMaxSearchResolution()", "-max_search_resolution"},
    {"setSurfaceFill()", "-fill"},
    {"setNoiseMode(true)", "-noise_mode"},
  };
  for (const auto& [library, tool] : kTerms)
    for (std::size_t at = message.find(library); at != std::string::npos;
         at = message.find(library, at + std::char_traits<char>::length(tool)))
      message.replace(at, std::char_traits<char>::length(library), tool);
  return message;
}

std::vector<std::string>
topLevelParts(const std::string& text)
{
  std::vector<std::string> parts;
  std::string part;
  int depth = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    depth += (c == '(' || c == '[') ? 1 : (c == ')' || c == ']') ? -1 : 0;
    if (depth == 0 && c == ';' && i + 1 < text.size() && text[i + 1] == ' ') {
      parts.push_back(part);
      part.clear();
      ++i; // the space after the separator
      continue;
    }
    part += c;
  }
  if (!part.empty() || parts.empty())
    parts.push_back(part);
  return parts;
}

} // namespace visfeat_tools
