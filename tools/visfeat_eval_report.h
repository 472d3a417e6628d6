// visfeat_eval's rows and their report: the table on stdout and the JSON file.
#pragma once

#include <support/evaluation.h>
#include <visfeat/core/band/local_triangles.h>

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace visfeat_eval {

namespace ev = visfeat::evaluation;

/** \brief Sample spacing without -points (cells). */
constexpr double kSpacingCells = 0.5;
/** \brief Neighbours of PCL's surface variation. */
constexpr int kPclK = 30;
/** \brief CGAL VCM's offset and convolution radii (cells). */
constexpr double kVcmOffsetCells = 4.0;
constexpr double kVcmConvolutionCells = 2.0;

#ifdef VISFEAT_HAVE_CGAL
constexpr bool kHaveCgal = true;
#else
constexpr bool kHaveCgal = false;
#endif

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

/** \brief The table's header line (stdout). */
void printHeader();

/** \brief One row of the table, printed when the row is complete (stdout). */
void printRow(const Row& r);

/** \brief Every row and the settings as JSON to s.json. False + `error` when it cannot
 * be written. */
bool writeJson(const Settings& s, const std::vector<Row>& rows, std::string& error);

} // namespace visfeat_eval
