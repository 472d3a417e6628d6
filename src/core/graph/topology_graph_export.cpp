// TopologyGraph's export: GraphViz DOT and JSON (writeDot, writeJson, writeFile).

#include <visfeat/core/common/error.h>
#include <visfeat/core/graph/topology_graph.h>

#include "../common/json_document.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <locale>
#include <ostream>
#include <sstream>

namespace visfeat {
namespace {

/** A parameter's value as JSON: a JSON number or true/false as such (strict JSON: no
 * leading zeros, no trailing dot), anything else as a string. */
json_document::Json
parameterValue(const std::string& value)
{
  json_document::Json parsed = json_document::Json::parse(value, nullptr, false);
  if (!parsed.is_discarded() && (parsed.is_number() || parsed.is_boolean()))
    return parsed;
  return value;
}

char
classLetter(FeatureClass cls)
{
  switch (cls) {
  case FeatureClass::kVertex:
    return 'V';
  case FeatureClass::kEdge:
    return 'E';
  case FeatureClass::kFace:
    return 'F';
  default:
    return 'N';
  }
}

std::string
lowerExtension(const std::string& path)
{
  const std::size_t slash = path.find_last_of("/\\");
  const std::size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
    return {};
  std::string ext = path.substr(dot);
  for (char& c : ext)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

} // namespace

// --- Export ------------------------------------------------------------------

void
TopologyGraph::writeDot(std::ostream& stream) const
{
  // Built in a classic-locale buffer: no digit grouping whatever the stream's locale.
  std::ostringstream out;
  out.imbue(std::locale::classic());
  out << "graph visfeat_topology {\n";
  out << "  node [style=filled, fontname=\"Helvetica\"];\n";
  for (std::size_t v = 0; v < size(); ++v) {
    const GraphNode& n = graph_[v];
    const char* shape = "diamond";
    const char* colour = "lightgrey";
    switch (n.feature_class) {
    case FeatureClass::kVertex:
      shape = "circle";
      colour = "red";
      break;
    case FeatureClass::kEdge:
      shape = "box";
      colour = "orange";
      break;
    case FeatureClass::kFace:
      shape = "ellipse";
      colour = "yellow";
      break;
    default:
      break;
    }
    out << "  " << n.id << " [label=\"" << classLetter(n.feature_class) << n.id
        << "\", shape=" << shape << ", fillcolor=" << colour << ", feature_class=\""
        << className(n.feature_class) << "\", cells=" << n.cells
        << ", points=" << n.points << "];\n";
  }
  for (const auto& arc : arcs())
    out << "  " << arc.first << " -- " << arc.second << ";\n";
  out << "}\n";
  stream << out.str();
}

void
TopologyGraph::writeDot(std::ostream& stream, const GraphMetadata& meta) const
{
  std::ostringstream out;
  out.imbue(std::locale::classic());
  out.precision(9);
  // one comment line each: a line break inside would end the comment
  const auto comment = [&](const std::string& what, const std::string& text) {
    std::string line = text;
    std::replace(line.begin(), line.end(), '\n', ' ');
    std::replace(line.begin(), line.end(), '\r', ' ');
    out << "// " << what << ": " << line << "\n";
  };
  out << "// visfeat topology graph (every parameter, the nodes' positions and the "
         "edges' crease angles are in its JSON form)\n";
  if (!meta.source.empty())
    comment("source", meta.source);
  out << "// cell: " << meta.grid.cell_size << " (world units)\n";
  for (const auto& [name, value] : meta.parameters)
    if (name == "resolution" || name == "resolution_reason")
      comment(name, value);
  for (const std::string& w : meta.warnings)
    comment("warning", w);
  for (const std::string& n : meta.notes)
    comment("note", n);
  stream << out.str();
  writeDot(stream);
}

void
TopologyGraph::writeJson(std::ostream& out, const GraphMetadata& meta) const
{
  using json = json_document::Json;
  json parameters = json::object();
  for (const auto& [name, value] : meta.parameters)
    parameters[name] = parameterValue(value);
  json nodes = json::array();
  for (std::size_t v = 0; v < size(); ++v) {
    const GraphNode& n = graph_[v];
    nodes.push_back({{"id", n.id},
                     {"class", className(n.feature_class)},
                     {"cells", n.cells},
                     {"points", n.points},
                     {"centroid", json_document::vector3(n.centroid + meta.offset)},
                     {"min", json_document::vector3(n.min + meta.offset)},
                     {"max", json_document::vector3(n.max + meta.offset)}});
    if (n.feature_class == FeatureClass::kEdge)
      nodes.back()["crease_angle"] =
        std::isfinite(n.crease_angle) ? json(n.crease_angle) : json(nullptr);
  }
  json all_arcs = json::array();
  for (const auto& [a, b] : arcs())
    all_arcs.push_back({a, b});
  const json grid = {
    {"origin", json_document::vector3(meta.grid.origin + meta.offset)},
    {"cell_size", meta.grid.cell_size},
    {"dims", {meta.grid.dims.x(), meta.grid.dims.y(), meta.grid.dims.z()}}};
  const json counts = {{"vertices", classCount(FeatureClass::kVertex)},
                       {"edges", classCount(FeatureClass::kEdge)},
                       {"faces", classCount(FeatureClass::kFace)},
                       {"arcs", all_arcs.size()}};
  json document;
  document["format"] = "visfeat-topology-graph";
  document["version"] = 1;
  document["source"] = meta.source;
  document["offset"] = json_document::vector3(meta.offset);
  document["grid"] = grid;
  document["parameters"] = parameters;
  document["warnings"] = meta.warnings;
  document["notes"] = meta.notes;
  document["counts"] = counts;
  document["nodes"] = nodes;
  document["arcs"] = all_arcs;
  json_document::write(out, document);
}

bool
TopologyGraph::writeFile(const std::string& path, const GraphMetadata& meta) const
{
  const std::string ext = lowerExtension(path);
  const bool dot = ext == ".dot" || ext == ".gv";
  if (!dot && ext != ".json") {
    throw Error("cannot write the topology graph to '" + path +
                "': use the extension .dot, .gv (GraphViz) or .json");
  }
  std::ofstream out(path, std::ios::out | std::ios::trunc);
  if (!out)
    throw Error("cannot open '" + path + "' for writing");
  if (dot)
    writeDot(out, meta);
  else
    writeJson(out, meta);
  out.flush();
  if (!out)
    throw Error("failed writing the topology graph to '" + path + "'");
  return true;
}

} // namespace visfeat
