// The visfeat tool on survey coordinates: a generated part 9.8 m across, stored near
// (512345, 4312345, 120) as a binary PLY with double coordinates, a PCD with F 8 x y z
// and a text .xyz cloud, against the same points centred at the origin (a float PCD).
// The tool recentres in double before the cast to float, so the labels are those of
// the centred run; the output keeps the input's double coordinates, and the graph JSON
// is in the input's frame with its "offset". A mesh (.off) in survey coordinates gives
// the centred mesh's graph and samples. About 30 s on 2 cores: label tools.

#include "common/double_xyz_cloud.h"
#include "common/test/temp_dir.h"

#include <support/cad_models.h>
#include <support/cad_tessellation.h>

#include <pcl/common/io.h>
#include <pcl/io/pcd_io.h>
#include <pcl/io/ply_io.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#ifndef VISFEAT_TOOL_PATH
#error "VISFEAT_TOOL_PATH (the visfeat executable) must be defined"
#endif

namespace syn = visfeat::synthetic;

namespace {

/** The survey position of the part's centre (world units, metres). */
const Eigen::Vector3d kSurvey(512345.678, 4312345.123, 120.456);

class SurveyCoordinates : public visfeat_tools::test::TempDirTest
{
protected:
  /** Run the tool on `input` (output out_<stem>.pcd, graph <stem>.json); its exit
   * code, its stdout in `log`. */
  int runTool(const std::string& input, const std::string& stem, std::string& log)
  {
    const std::string command = std::string("'") + VISFEAT_TOOL_PATH + "' '" + input +
                                "' '" + path("out_" + stem + ".pcd") + "' -graph '" +
                                path(stem + ".json") + "' > '" + path(stem + ".log") +
                                "' 2>&1";
    const int rc = std::system(command.c_str());
    std::ifstream in(path(stem + ".log"));
    std::stringstream text;
    text << in.rdbuf();
    log = text.str();
    return rc;
  }
};

/** x y z as FLOAT64 fields, the points plus `shift`. */
pcl::PCLPointCloud2
doubleCloud(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& shift)
{
  return visfeat_tools::doubleXYZCloud(points, shift);
}

/** Field `name` of every point of a PCD file, as double. */
std::vector<double>
column(const pcl::PCLPointCloud2& c, const std::string& name, std::uint8_t* type)
{
  const int f = pcl::getFieldIndex(c, name);
  std::vector<double> values;
  if (f < 0) {
    ADD_FAILURE() << "no field " << name;
    return values;
  }
  const pcl::PCLPointField& field = c.fields[static_cast<std::size_t>(f)];
  *type = field.datatype;
  for (std::size_t i = 0; i < std::size_t(c.width) * c.height; ++i) {
    const std::uint8_t* p = c.data.data() + i * c.point_step + field.offset;
    if (field.datatype == pcl::PCLPointField::FLOAT64) {
      double v;
      std::memcpy(&v, p, 8);
      values.push_back(v);
    } else if (field.datatype == pcl::PCLPointField::FLOAT32) {
      float v;
      std::memcpy(&v, p, 4);
      values.push_back(v);
    } else if (field.datatype == pcl::PCLPointField::UINT32) {
      std::uint32_t v;
      std::memcpy(&v, p, 4);
      values.push_back(v);
    } else {
      std::uint8_t v = *p;
      values.push_back(v);
    }
  }
  return values;
}

nlohmann::json
readJson(const std::string& path)
{
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

TEST_F(SurveyCoordinates, SameLabelsAndTheInputsCoordinatesBack)
{
  // box_with_hole (2 x 2 x 1.5), rotated, scaled to a part 9.8 m across, 40,000 points
  const syn::CadModel model =
    syn::rotated(syn::cadModelByName("box_with_hole"), syn::randomRotation(71));
  syn::SamplingOptions options;
  options.count = 40000;
  options.seed = 71;
  const syn::CadSamples samples = syn::sampleCadModel(model, options);
  std::vector<Eigen::Vector3d> points;
  pcl::PointCloud<pcl::PointXYZ> centred;
  Eigen::AlignedBox3f box;
  for (const Eigen::Vector3f& p : samples.points)
    box.extend(p);
  const float scale = 9.8f / box.sizes().maxCoeff();
  for (const Eigen::Vector3f& p : samples.points) {
    const Eigen::Vector3f scaled = scale * p;
    points.push_back(scaled.cast<double>());
    centred.push_back(pcl::PointXYZ(scaled.x(), scaled.y(), scaled.z()));
  }
  ASSERT_EQ(pcl::io::savePCDFileBinary(path("centred.pcd"), centred), 0);
  const pcl::PCLPointCloud2 survey = doubleCloud(points, kSurvey);
  ASSERT_EQ(pcl::io::savePLYFile(path("survey.ply"), survey, Eigen::Vector4f::Zero(),
                                 Eigen::Quaternionf::Identity(), true),
            0);
  ASSERT_EQ(pcl::io::savePCDFile(path("survey.pcd"), survey, Eigen::Vector4f::Zero(),
                                 Eigen::Quaternionf::Identity(), true),
            0);
  {
    std::ofstream xyz(path("survey.xyz"));
    char line[128];
    for (const Eigen::Vector3d& p : points) {
      const Eigen::Vector3d q = p + kSurvey;
      std::snprintf(line, sizeof(line), "%.6f %.6f %.6f\n", q.x(), q.y(), q.z());
      xyz << line;
    }
  }

  std::string log;
  ASSERT_EQ(runTool(path("centred.pcd"), "centred", log), 0) << log;
  EXPECT_EQ(log.find("Recentred"), std::string::npos) << log;
  pcl::PCLPointCloud2 reference;
  ASSERT_EQ(pcl::io::loadPCDFile(path("out_centred.pcd"), reference), 0);
  std::uint8_t type = 0;
  const std::vector<double> labels = column(reference, "label", &type);
  const std::vector<double> classes = column(reference, "feature_class", &type);
  const nlohmann::json graph = readJson(path("centred.json"));
  EXPECT_EQ(graph["offset"], nlohmann::json::array({0.0, 0.0, 0.0}));

  for (const char* input : {"survey.ply", "survey.pcd", "survey.xyz"}) {
    SCOPED_TRACE(input);
    const std::string stem = std::string(input).replace(6, 1, "_");
    ASSERT_EQ(runTool(path(input), stem, log), 0) << log;
    EXPECT_NE(log.find("Recentred: the computation runs on x y z minus (512350 "
                       "4312350 120)"),
              std::string::npos)
      << log;
    pcl::PCLPointCloud2 out;
    ASSERT_EQ(pcl::io::loadPCDFile(path("out_" + stem + ".pcd"), out), 0);
    // the input's coordinates, double, to 1 mm (the .xyz file holds 6 decimals)
    for (int a = 0; a < 3; ++a) {
      const std::vector<double> v = column(out, std::string(1, char('x' + a)), &type);
      EXPECT_EQ(type, pcl::PCLPointField::FLOAT64);
      ASSERT_EQ(v.size(), points.size());
      double worst = 0.0;
      for (std::size_t i = 0; i < v.size(); ++i)
        worst = std::max(worst, std::abs(v[i] - (points[i][a] + kSurvey[a])));
      EXPECT_LT(worst, 1e-3) << "axis " << a;
    }
    // the centred run's labels: the recentred coordinates are the centred ones moved
    // by kSurvey - offset (about 4 m), so float rounding may put a point exactly on a
    // cell boundary on the other side, and region ids may come in another order; each
    // region is matched to the centred region most of its points have
    const std::vector<double> l = column(out, "label", &type);
    const std::vector<double> k = column(out, "feature_class", &type);
    ASSERT_EQ(l.size(), labels.size());
    std::map<double, std::map<double, std::size_t>> votes;
    for (std::size_t i = 0; i < l.size(); ++i)
      ++votes[l[i]][labels[i]];
    std::map<double, double> match; // survey region -> centred region
    std::set<double> matched;
    for (const auto& [region, counts] : votes) {
      auto best = counts.begin();
      for (auto it = counts.begin(); it != counts.end(); ++it)
        if (it->second > best->second)
          best = it;
      match[region] = best->first;
      EXPECT_TRUE(matched.insert(best->first).second)
        << "two regions on " << best->first;
    }
    std::size_t differ = 0;
    for (std::size_t i = 0; i < l.size(); ++i)
      differ += match[l[i]] != labels[i] || k[i] != classes[i];
    EXPECT_LE(differ, l.size() / 10000) << differ << " of " << l.size();
    std::printf("%s: %zu of %zu points labelled otherwise than centred\n", input,
                differ, l.size());
    const nlohmann::json g = readJson(path(stem + ".json"));
    EXPECT_EQ(g["offset"], nlohmann::json::array({512350.0, 4312350.0, 120.0}));
    EXPECT_EQ(g["counts"], graph["counts"]);
    std::set<std::pair<int, int>> arcs, reference_arcs;
    for (const auto& arc : g["arcs"]) {
      const int a = int(match[arc[0].get<double>()]),
                b = int(match[arc[1].get<double>()]);
      arcs.insert({std::min(a, b), std::max(a, b)});
    }
    for (const auto& arc : graph["arcs"])
      reference_arcs.insert({arc[0].get<int>(), arc[1].get<int>()});
    EXPECT_EQ(arcs, reference_arcs);
    // the nodes on the map: the centred run's moved by kSurvey, within a third of a
    // cell (the few points labelled otherwise move a centroid by ~1 mm)
    const double cell = graph["grid"]["cell_size"].get<double>();
    ASSERT_EQ(g["nodes"].size(), graph["nodes"].size());
    for (std::size_t n = 0; n < g["nodes"].size(); ++n) {
      const std::size_t m = std::size_t(match[double(n + 1)]) - 1;
      for (int a = 0; a < 3; ++a)
        EXPECT_NEAR(g["nodes"][n]["centroid"][a].get<double>(),
                    graph["nodes"][m]["centroid"][a].get<double>() + kSurvey[a],
                    cell / 3)
          << "node " << n << " axis " << a;
    }
    EXPECT_NEAR(g["grid"]["origin"][0].get<double>(),
                graph["grid"]["origin"][0].get<double>() + kSurvey[0], 1e-3);
  }
}

/** An OFF file of `mesh` moved by `shift`, vertices to 17 digits. */
void
writeOff(const std::string& file,
         const visfeat::SurfaceMesh& mesh,
         const Eigen::Vector3d& shift)
{
  std::ofstream out(file);
  out << "OFF\n" << mesh.vertices.size() << " " << mesh.triangles.size() << " 0\n";
  char line[160];
  for (const Eigen::Vector3d& v : mesh.vertices) {
    const Eigen::Vector3d q = v + shift;
    std::snprintf(line, sizeof(line), "%.17g %.17g %.17g\n", q.x(), q.y(), q.z());
    out << line;
  }
  for (const auto& t : mesh.triangles)
    out << "3 " << t[0] << " " << t[1] << " " << t[2] << "\n";
}

TEST_F(SurveyCoordinates, AMeshIsRecentredLikeACloud)
{
  // the box with hole's tessellation, 9.8 m across, centred and near kSurvey (OFF)
  syn::CadMesh tessellation = syn::tessellateCadModel(
    syn::rotated(syn::cadModelByName("box_with_hole"), syn::randomRotation(72)), 1e-3);
  visfeat::SurfaceMesh& mesh = tessellation.mesh;
  Eigen::AlignedBox3d box;
  for (const Eigen::Vector3d& v : mesh.vertices)
    box.extend(v);
  for (Eigen::Vector3d& v : mesh.vertices)
    v = (v - box.center()) * (9.8 / box.sizes().maxCoeff());
  writeOff(path("centred.off"), mesh, Eigen::Vector3d::Zero());
  writeOff(path("survey.off"), mesh, kSurvey);

  std::string log;
  ASSERT_EQ(runTool(path("centred.off"), "centred", log), 0) << log;
  EXPECT_EQ(log.find("Recentred"), std::string::npos) << log;
  ASSERT_EQ(runTool(path("survey.off"), "survey", log), 0) << log;
  EXPECT_NE(log.find("Recentred: the computation runs on x y z minus (512350 "
                     "4312350 120)"),
            std::string::npos)
    << log;
  const nlohmann::json centred = readJson(path("centred.json"));
  const nlohmann::json survey = readJson(path("survey.json"));
  EXPECT_EQ(survey["offset"], nlohmann::json::array({512350.0, 4312350.0, 120.0}));
  EXPECT_EQ(survey["counts"], centred["counts"]);

  pcl::PCLPointCloud2 a, b;
  ASSERT_EQ(pcl::io::loadPCDFile(path("out_centred.pcd"), a), 0);
  ASSERT_EQ(pcl::io::loadPCDFile(path("out_survey.pcd"), b), 0);
  std::uint8_t type = 0;
  // the same samples (same seed, the recentred mesh is the centred one moved), in the
  // input's frame, in double
  for (int axis = 0; axis < 3; ++axis) {
    const std::string name(1, char('x' + axis));
    const std::vector<double> u = column(a, name, &type);
    const std::vector<double> v = column(b, name, &type);
    EXPECT_EQ(type, pcl::PCLPointField::FLOAT64);
    ASSERT_EQ(u.size(), v.size());
    double worst = 0.0;
    for (std::size_t i = 0; i < u.size(); ++i)
      worst = std::max(worst, std::abs(v[i] - (u[i] + kSurvey[axis])));
    EXPECT_LT(worst, 1e-3) << "axis " << axis;
  }
  const std::vector<double> ka = column(a, "feature_class", &type);
  const std::vector<double> kb = column(b, "feature_class", &type);
  ASSERT_EQ(ka.size(), kb.size());
  std::size_t differ = 0;
  for (std::size_t i = 0; i < ka.size(); ++i)
    differ += ka[i] != kb[i];
  EXPECT_LE(differ, ka.size() / 1000) << differ << " of " << ka.size();
}

} // namespace
