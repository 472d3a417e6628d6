// TopologyGraph's outputs: DOT with every node and arc, JSON parsed strictly and
// holding the graph, writeFile by extension.

#include "graph_fixtures.h"

#include <visfeat/core/common/error.h>
#include <visfeat/core/graph/topology_graph.h>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace visfeat_test::graph;

TEST(TopologyGraph, DotHasEveryNodeAndArc)
{
  const Sheet s;
  const TopologyGraph g = buildGraph(s.band, s.labels, s.classes, 1);
  const std::string dot = dotOf(g);
  EXPECT_EQ(dot.rfind("graph ", 0), 0u) << dot;
  EXPECT_EQ(dot.back(), '\n');
  EXPECT_NE(dot.find("}\n"), std::string::npos);
  EXPECT_NE(dot.find("  1 [label=\"F1\", shape=ellipse, fillcolor=yellow"),
            std::string::npos)
    << dot;
  EXPECT_NE(dot.find("  2 [label=\"E2\", shape=box, fillcolor=orange"),
            std::string::npos);
  EXPECT_NE(dot.find("  4 [label=\"V4\", shape=circle, fillcolor=red"),
            std::string::npos);
  EXPECT_NE(dot.find("  6 [label=\"E6\""), std::string::npos);
  EXPECT_NE(dot.find("cells=" + std::to_string(g.node(1).cells) + ", points="),
            std::string::npos);
  std::size_t arc_lines = 0;
  for (std::size_t at = dot.find(" -- "); at != std::string::npos;
       at = dot.find(" -- ", at + 1))
    ++arc_lines;
  EXPECT_EQ(arc_lines, g.arcCount());
  for (const auto& arc : g.arcs())
    EXPECT_NE(dot.find("  " + std::to_string(arc.first) + " -- " +
                       std::to_string(arc.second) + ";\n"),
              std::string::npos);
}

TEST(TopologyGraph, JsonParsesAndHoldsTheGraph)
{
  const Sheet s;
  const TopologyGraph g = buildGraph(s.band, s.labels, s.classes, 1);
  GraphMetadata meta;
  meta.grid = s.grid;
  meta.source = "C:\\scans\\\"part\" 1.pcd\n\ttab\x01";
  meta.parameters = {{"resolution", "256"}, {"opacity", "-0.5"}, {"tiny", "1e-3"},
                     {"raw", "false"},      {"repair", "true"},  {"name", "abc"},
                     {"octal", "016"},      {"nan", "nan"},      {"empty", ""},
                     {"quote\"key", "2."}};
  meta.warnings = {"no face found: raise the resolution", "second \"one\""};
  meta.notes = {"the cloud is flat"};
  const std::string text = jsonOf(g, meta);
  Json j;
  ASSERT_NO_THROW(j = parseJson(text)) << text;
  EXPECT_EQ(j.at("format"), "visfeat-topology-graph");
  ASSERT_EQ(j.at("warnings").size(), 2u);
  EXPECT_EQ(j.at("warnings")[0], meta.warnings[0]);
  EXPECT_EQ(j.at("warnings")[1], meta.warnings[1]);
  ASSERT_EQ(j.at("notes").size(), 1u);
  EXPECT_EQ(j.at("notes")[0], "the cloud is flat");
  EXPECT_EQ(j.at("version"), 1);
  EXPECT_EQ(j.at("source"), meta.source);
  EXPECT_EQ(j.at("grid").at("origin").size(), 3u);
  EXPECT_EQ(j.at("grid").at("origin")[0], -1.5);
  EXPECT_EQ(j.at("grid").at("origin")[2], 0.25);
  EXPECT_EQ(j.at("grid").at("cell_size"), 0.5);
  EXPECT_EQ(j.at("grid").at("dims")[1], 16);

  const Json& params = j.at("parameters");
  EXPECT_TRUE(params.at("resolution").is_number());
  EXPECT_EQ(params.at("resolution"), 256);
  EXPECT_EQ(params.at("opacity"), -0.5);
  EXPECT_EQ(params.at("tiny"), 1e-3);
  EXPECT_TRUE(params.at("raw").is_boolean());
  EXPECT_EQ(params.at("raw"), false);
  EXPECT_EQ(params.at("repair"), true);
  EXPECT_TRUE(params.at("name").is_string());
  EXPECT_TRUE(params.at("octal").is_string());
  EXPECT_EQ(params.at("octal"), "016");
  EXPECT_TRUE(params.at("nan").is_string());
  EXPECT_TRUE(params.at("empty").is_string());
  EXPECT_TRUE(params.at("quote\"key").is_string());

  EXPECT_EQ(j.at("counts").at("vertices"), 2);
  EXPECT_EQ(j.at("counts").at("edges"), 2);
  EXPECT_EQ(j.at("counts").at("faces"), 2);
  EXPECT_EQ(j.at("counts").at("arcs"), g.arcCount());

  const Json& nodes = j.at("nodes");
  ASSERT_EQ(nodes.size(), g.size());
  for (std::uint32_t id = 1; id <= g.size(); ++id) {
    const Json& n = nodes[id - 1];
    const visfeat::GraphNode& node = g.node(id);
    EXPECT_EQ(n.at("id"), id);
    EXPECT_EQ(n.at("class"), TopologyGraph::className(node.feature_class));
    EXPECT_EQ(n.at("cells"), node.cells);
    EXPECT_EQ(n.at("points"), node.points);
    for (const char* key : {"centroid", "min", "max"}) {
      ASSERT_EQ(n.at(key).size(), 3u);
      const Eigen::Vector3d& v = std::string(key) == "centroid" ? node.centroid
                                 : std::string(key) == "min"    ? node.min
                                                                : node.max;
      for (int a = 0; a < 3; ++a) {
        const Json& x = n.at(key)[static_cast<std::size_t>(a)];
        if (std::isnan(v[a])) {
          EXPECT_TRUE(x.is_null());
        } else { // exact round trip
          EXPECT_EQ(x.get<double>(), v[a]) << key;
        }
      }
    }
  }
  EXPECT_TRUE(nodes[5].at("centroid")[0].is_null());
  EXPECT_EQ(nodes[0].at("class"), "face");
  EXPECT_EQ(nodes[1].at("class"), "edge");
  EXPECT_EQ(nodes[3].at("class"), "vertex");

  const Json& arcs = j.at("arcs");
  ASSERT_EQ(arcs.size(), g.arcCount());
  const Arcs expected = g.arcs();
  for (std::size_t i = 0; i < expected.size(); ++i) {
    ASSERT_EQ(arcs[i].size(), 2u);
    EXPECT_EQ(arcs[i][0], expected[i].first);
    EXPECT_EQ(arcs[i][1], expected[i].second);
  }

  // Doubles that need 17 digits, infinities and a stream locale do not break it.
  TopologyGraph h = g;
  h.setPointGeometry(1, 5, Eigen::Vector3d(0.1, 1.0 / 3.0, -2.5e-300),
                     Eigen::Vector3d(-std::numeric_limits<double>::infinity(), 0, 0),
                     Eigen::Vector3d(1e300, 0, 0));
  GraphMetadata odd;
  odd.grid.cell_size = std::numeric_limits<double>::quiet_NaN();
  const Json k = parseJson(jsonOf(h, odd));
  EXPECT_EQ(k.at("nodes")[0].at("centroid")[0].get<double>(), 0.1);
  EXPECT_EQ(k.at("nodes")[0].at("centroid")[1].get<double>(), 1.0 / 3.0);
  EXPECT_EQ(k.at("nodes")[0].at("centroid")[2].get<double>(), -2.5e-300);
  EXPECT_TRUE(k.at("nodes")[0].at("min")[0].is_null());
  EXPECT_EQ(k.at("nodes")[0].at("max")[0].get<double>(), 1e300);
  EXPECT_TRUE(k.at("grid").at("cell_size").is_null());
  EXPECT_EQ(k.at("source"), "");
  EXPECT_TRUE(k.at("parameters").is_object() && k.at("parameters").empty());
  EXPECT_EQ(k.at("offset"), Json::array({0.0, 0.0, 0.0}));

  // A recentred cloud: every coordinate in the input's frame, the offset stated.
  meta.offset = Eigen::Vector3d(512350.0, 4312350.0, 120.0);
  const Json survey = parseJson(jsonOf(g, meta));
  EXPECT_EQ(survey.at("offset"), Json::array({512350.0, 4312350.0, 120.0}));
  EXPECT_EQ(survey.at("grid").at("origin")[1], 4312350.0 + s.grid.origin.y());
  EXPECT_EQ(survey.at("nodes")[0].at("centroid")[0], 512350.0 + g.node(1).centroid.x());
  EXPECT_EQ(survey.at("nodes")[0].at("max")[2], 120.0 + g.node(1).max.z());
}

TEST(TopologyGraph, DotWithMetadataCarriesTheWarningsAsComments)
{
  // A fresh user's trial: the DOT file had no source, warnings or parameters, so a
  // reader of the .dot alone could not know the graph was approximate.
  const Sheet s;
  const TopologyGraph g = buildGraph(s.band, s.labels, s.classes, 1);
  GraphMetadata meta;
  meta.grid = s.grid;
  meta.source = "sheet.pcd";
  meta.parameters = {{"resolution", "256"},
                     {"resolution_reason", "a mesh: 256 cells"},
                     {"min_radius", "16"}};
  meta.warnings = {"the graph is not that of a closed part\nsecond line"};
  meta.notes = {"a flat cloud"};
  std::ostringstream with;
  g.writeDot(with, meta);
  const std::string text = with.str();
  const std::string plain = dotOf(g);
  ASSERT_GE(text.size(), plain.size());
  EXPECT_EQ(text.substr(text.size() - plain.size()), plain)
    << "the graph itself unchanged";
  const std::string head = text.substr(0, text.size() - plain.size());
  std::istringstream lines(head);
  std::string line;
  std::vector<std::string> comments;
  while (std::getline(lines, line)) {
    EXPECT_EQ(line.rfind("// ", 0), 0u)
      << "every line before the graph a comment: " << line;
    comments.push_back(line);
  }
  const auto has = [&](const std::string& want) {
    return std::find(comments.begin(), comments.end(), want) != comments.end();
  };
  EXPECT_TRUE(has("// source: sheet.pcd")) << head;
  EXPECT_TRUE(has("// resolution: 256")) << head;
  EXPECT_TRUE(has("// resolution_reason: a mesh: 256 cells")) << head;
  EXPECT_TRUE(has("// warning: the graph is not that of a closed part second line"))
    << head;
  EXPECT_TRUE(has("// note: a flat cloud")) << head;
  EXPECT_EQ(head.find("min_radius"), std::string::npos) << "the rest is in the JSON";
}

TEST(TopologyGraph, WriteFileByExtension)
{
  const Sheet s;
  const TopologyGraph g = buildGraph(s.band, s.labels, s.classes, 1);
  GraphMetadata meta;
  meta.grid = s.grid;
  meta.source = "sheet";
  namespace fs = std::filesystem;
  const fs::path dir =
    fs::temp_directory_path() /
    ("visfeat_topology_graph_test_" + std::to_string(std::random_device{}()));
  fs::create_directories(dir);
  const auto slurp = [](const fs::path& p) {
    std::ifstream in(p);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
  };
  for (const char* name : {"g.json", "g.JSON", "g.dot", "g.Gv", "a.b/../g2.DOT"}) {
    const fs::path p = dir / name;
    if (p.has_parent_path())
      fs::create_directories(p.parent_path());
    EXPECT_TRUE(g.writeFile(p.string(), meta)) << name;
    const std::string text = slurp(p);
    const std::string ext = p.extension().string();
    if (ext == ".json" || ext == ".JSON")
      EXPECT_EQ(text, jsonOf(g, meta)) << name;
    else {
      std::ostringstream dot;
      g.writeDot(dot, meta);
      EXPECT_EQ(text, dot.str()) << name;
    }
  }
  for (const char* name : {"g.txt", "g", "g.json.bak", "dir.json/g", "g.dott"})
    EXPECT_THROW(g.writeFile((dir / name).string(), meta), visfeat::Error) << name;
  EXPECT_FALSE(fs::exists(dir / "g.txt"));
  EXPECT_THROW(g.writeFile((dir / "missing" / "sub" / "g.json").string(), meta),
               visfeat::Error);
  EXPECT_THROW(g.writeFile(dir.string() + "/", meta), visfeat::Error);
  fs::remove_all(dir);
}

// An edge between faces A and B along its whole length, and a face C that only
// touches the edge's end cell (the third face of a corner): the contact filter keeps
// A and B and drops C; with the filter off (0) the literal dilation keeps all three.

} // namespace
