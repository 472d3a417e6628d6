// The options of the visfeat tool (not installed, not public API): their defaults, the
// help text, and reading and checking them before any work (values in range, settings
// that exclude each other, output files writable and distinct).
#pragma once

#include "common/arguments.h"
#include "common/mesh_input.h"
#include "picture/picture_requests.h"

#include <visfeat/core/common/parameters.h>
#include <visfeat/core/graph/crease_angles.h>
#include <visfeat/core/grid/resolution_search.h>
#include <visfeat/core/segmentation/components.h>
#include <visfeat/core/segmentation/flat_feature_points.h>
#include <visfeat/core/visibility/visibility_map.h>
#include <visfeat/surface_fill.h>

#include <set>
#include <string>
#include <vector>

namespace visfeat_tools {

// The defaults are the library's (visfeat/core/.../*.h), not restated here. No default
// resolution: without -resolution it follows from the point spacing
// (visfeat::estimateResolution, common/automatic_resolution.h).
constexpr int kDefaultMinRadius = visfeat::kDefaultMinRadius;
constexpr int kDefaultNarrowPersistence =
  visfeat::ComponentParameters::kDefaultNarrowFacePersistence;
constexpr int kDefaultVertexCells =
  visfeat::ComponentParameters::kDefaultVertexMaxCells;
constexpr double kDefaultDimensionality =
  visfeat::ComponentParameters::kDefaultDimensionality;
constexpr double kDefaultOpacity = visfeat::VisibilityMap::Parameters{}.opacity;
constexpr int kDefaultThreads = visfeat::VisibilityMap::Parameters{}.threads;

/** \brief The visfeat tool's command line, read and checked. */
struct Options
{
  std::string input;
  std::string output;
  int resolution = 0; // 0 = automatic
  int max_search_resolution = visfeat::kMaxSearchResolution;
  int min_radius = kDefaultMinRadius;
  int max_radius = 0; // 0 = min_radius (the estimator's automatic cap)
  int vertex_cells = kDefaultVertexCells;
  int narrow_persistence = kDefaultNarrowPersistence;
  double dimensionality = kDefaultDimensionality;
  double min_crease_angle = visfeat::CreaseAngleParameters::kDefaultMinCreaseAngle;
  double flat_variation = visfeat::FlatPointParameters::kDefaultMaxSurfaceVariation;
  bool raw = false;
  bool regions = true;
  bool flat_cores = true;
  double opacity = kDefaultOpacity;
  bool noise_mode = false;
  bool paper_noise = false;
  double smooth = -1.0; // -1 = as the mode says
  int threads = kDefaultThreads;
  bool repair = true;
  visfeat::SurfaceFill fill = visfeat::SurfaceFill::kAuto;
  visfeat::LocalTriangleParameters fill_triangles;
  long long memory_limit_mb = 0;
  std::string voxels;
  std::string graph;
  MeshDensity mesh;
  bool quiet = false;
  PictureRequests pictures;
};

/** \brief The options that take a value, for Arguments. */
const std::set<std::string>& valueOptions();

/** \brief The options without a value (switches), for Arguments. */
const std::set<std::string>& switchOptions();

/** \brief Print the help: syntax and every option with its default. */
void printHelp(const char* program);

/** \brief Read the file arguments and every option of `args` into `options` (whose
 * quiet, noise_mode and paper_noise the caller has set) and check them: ranges with the
 * library's own limits, settings that exclude each other, outputs with the right
 * extensions, writable and distinct, pictures possible here. On failure `error` is one
 * line. */
bool readOptions(const Arguments& args, Options& options, std::string& error);

/** \brief A message of the library in the tool's terms: its setters become the
 * options that set them (printed lines and the graph JSON). */
std::string inToolTerms(std::string message);

/** \brief The parts of `text` between the separators "; " that stand outside every
 * bracket pair, (...) or [...]; the resolution's reason is a chain of such
 * parts (the first choice, then each step of the automatic search), which the tool
 * prints one a line. Unbalanced brackets leave the rest of the text one part. */
std::vector<std::string> topLevelParts(const std::string& text);

} // namespace visfeat_tools
