// visfeat_eval's report: see visfeat_eval_report.h.

#include "visfeat_eval_report.h"

#include "common/output_files.h"

#include <core/common/json_document.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace visfeat_eval {

namespace vt = visfeat_tools;
using visfeat::json_document::Json;

namespace {

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

} // namespace

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

} // namespace visfeat_eval
