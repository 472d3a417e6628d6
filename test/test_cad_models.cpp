// The synthetic CAD models (cad_models.h): truth counts and incidences, the Euler
// characteristic, face areas, JSON, errors. Their sampling, distances, rotations and
// noise: test_cad_sampling.cpp.

#include "cad_fixtures.h"
#include <support/cad_models.h>
#include <support/synthetic_shapes.h>
#include <visfeat/core/common/error.h>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace {

namespace syn = visfeat::synthetic;
using namespace visfeat_test::cad;

struct Counts
{
  std::size_t vertices, segments, circles, faces;
};

const std::map<std::string, Counts>&
expectedCounts()
{
  static const std::map<std::string, Counts> counts{
    {"cube", {8, 12, 0, 6}},          {"tetrahedron", {4, 6, 0, 4}},
    {"icosahedron", {12, 30, 0, 20}}, {"triangular_prism", {6, 9, 0, 5}},
    {"u_prism", {16, 24, 0, 10}},     {"box_with_hole", {8, 12, 2, 7}},
    {"cylinder", {0, 0, 2, 3}},
  };
  return counts;
}

std::size_t
countCurves(const syn::CadModel& model, syn::CadCurve::Kind kind)
{
  return static_cast<std::size_t>(
    std::count_if(model.curves.begin(), model.curves.end(),
                  [&](const syn::CadCurve& c) { return c.kind == kind; }));
}

bool
isPolyhedron(const syn::CadModel& model)
{
  return countCurves(model, syn::CadCurve::Kind::kCircle) == 0;
}

TEST(CadModels, NamesAndTruthCounts)
{
  const std::vector<std::string> names = syn::cadModelNames();
  ASSERT_EQ(names.size(), expectedCounts().size());
  for (const std::string& name : names) {
    SCOPED_TRACE(name);
    ASSERT_EQ(expectedCounts().count(name), 1u);
    const Counts& expected = expectedCounts().at(name);
    const syn::CadModel model = syn::cadModelByName(name);
    EXPECT_EQ(model.name, name);
    EXPECT_NO_THROW(syn::checkCadModel(model));
    EXPECT_EQ(model.vertices.size(), expected.vertices);
    EXPECT_EQ(countCurves(model, syn::CadCurve::Kind::kSegment), expected.segments);
    EXPECT_EQ(countCurves(model, syn::CadCurve::Kind::kCircle), expected.circles);
    EXPECT_EQ(model.curves.size(), expected.segments + expected.circles);
    EXPECT_EQ(model.faces.size(), expected.faces);
    for (std::size_t i = 0; i < model.curves.size(); ++i)
      EXPECT_EQ(model.curves[i].id, static_cast<int>(i));
    for (std::size_t i = 0; i < model.faces.size(); ++i)
      EXPECT_EQ(model.faces[i].id, static_cast<int>(i));
    // Centred at the origin.
    EXPECT_LT(model.bounds().center().norm(), 1e-12);
  }
}

TEST(CadModels, EulerCharacteristic)
{
  for (const std::string& name : syn::cadModelNames()) {
    SCOPED_TRACE(name);
    const syn::CadModel model = syn::cadModelByName(name);
    if (isPolyhedron(model)) {
      // V - E + F = 2: every polyhedron here is a topological sphere.
      EXPECT_EQ(static_cast<int>(model.vertices.size()) -
                  static_cast<int>(model.curves.size()) +
                  static_cast<int>(model.faces.size()),
                2);
      EXPECT_EQ(syn::eulerCharacteristic(model), 2);
    }
  }
  // box_with_hole: a torus (genus 1), chi = 0 = V - S + sum(1 - holes) over planar
  // faces + 0 for the wall: 8 - 12 + (4 + 0 + 0) + 0. V - E + F = 8 - 14 + 7 = 1 does
  // not apply (faces with holes are not discs, circles have no vertex). The straight
  // edges alone form the box's wireframe (every vertex of degree 3) and the two circles
  // are vertex-free loops, each between a holed face and the wall.
  const syn::CadModel box = syn::cadModelByName("box_with_hole");
  EXPECT_EQ(syn::eulerCharacteristic(box), 0);
  for (const auto& curves : syn::vertexCurves(box))
    EXPECT_EQ(curves.size(), 3u);
  for (const syn::CadCurve& c : box.curves)
    if (c.kind == syn::CadCurve::Kind::kCircle) {
      EXPECT_EQ(c.vertices[0], -1);
      EXPECT_EQ(c.vertices[1], -1);
      const syn::CadFace& a = box.faces[static_cast<std::size_t>(c.faces[0])];
      const syn::CadFace& b = box.faces[static_cast<std::size_t>(c.faces[1])];
      EXPECT_EQ(a.kind, syn::CadFace::Kind::kPlanar);
      EXPECT_EQ(a.circles.size(), 1u);
      EXPECT_EQ(a.polygon.size(), 4u);
      EXPECT_EQ(b.kind, syn::CadFace::Kind::kCylindrical);
      EXPECT_TRUE(b.hole);
    }
  // cylinder: a sphere (chi 2) = 0 vertices - 0 segments + 2 discs + 0 (lateral);
  // the curve network is two vertex-free circles, each between a disc and the lateral.
  const syn::CadModel cyl = syn::cadModelByName("cylinder");
  EXPECT_EQ(syn::eulerCharacteristic(cyl), 2);
  for (const syn::CadCurve& c : cyl.curves) {
    EXPECT_EQ(c.kind, syn::CadCurve::Kind::kCircle);
    EXPECT_EQ(cyl.faces[static_cast<std::size_t>(c.faces[1])].kind,
              syn::CadFace::Kind::kCylindrical);
    EXPECT_FALSE(cyl.faces[static_cast<std::size_t>(c.faces[1])].hole);
  }
}

TEST(CadModels, SmallFeatureModelsTruthAndFeatureSizes)
{
  // issue 14's models with features closer than 2 min_radius cells at 256
  const std::map<std::string, Counts> expected{
    {"stepped_block", {16, 24, 0, 10}},
    {"chamfered_box", {16, 24, 0, 10}},
    {"thin_plate_with_hole", {8, 12, 2, 7}},
    {"parallel_creases", {14, 21, 0, 9}},
  };
  ASSERT_EQ(syn::smallFeatureModelNames().size(), expected.size());
  for (const std::string& name : syn::smallFeatureModelNames()) {
    SCOPED_TRACE(name);
    ASSERT_EQ(expected.count(name), 1u);
    const syn::CadModel model = syn::cadModelByName(name);
    EXPECT_NO_THROW(syn::checkCadModel(model));
    EXPECT_EQ(model.vertices.size(), expected.at(name).vertices);
    EXPECT_EQ(countCurves(model, syn::CadCurve::Kind::kSegment),
              expected.at(name).segments);
    EXPECT_EQ(countCurves(model, syn::CadCurve::Kind::kCircle),
              expected.at(name).circles);
    EXPECT_EQ(model.faces.size(), expected.at(name).faces);
    EXPECT_EQ(syn::eulerCharacteristic(model), isPolyhedron(model) ? 2 : 0);
    EXPECT_LT(model.bounds().center().norm(), 1e-12);
  }
  // feature sizes in cells of 256 along the 2-unit side (the unrotated models)
  const double cell = 2.0 / 256.0;
  const syn::CadModel chamfered = syn::cadModelByName("chamfered_box");
  EXPECT_NEAR(chamfered.bounds().sizes().maxCoeff(), 2.0, 1e-12);
  std::multiset<long> widths; // chamfer faces: the sides of the octagon along z
  for (const syn::CadFace& f : chamfered.faces)
    if (std::abs(f.normal.z()) < 1e-9 && std::abs(f.normal.x()) > 1e-9 &&
        std::abs(f.normal.y()) > 1e-9) {
      // the face's width: its polygon's extent across z
      double w = 0.0;
      for (int a : f.polygon)
        for (int b : f.polygon) {
          Eigen::Vector3d d = chamfered.vertices[static_cast<std::size_t>(a)] -
                              chamfered.vertices[static_cast<std::size_t>(b)];
          d.z() = 0.0;
          w = std::max(w, d.norm());
        }
      widths.insert(std::lround(w / cell));
    }
  EXPECT_EQ(widths, (std::multiset<long>{6, 10, 14, 20}));

  const syn::CadModel plate = syn::cadModelByName("thin_plate_with_hole");
  EXPECT_NEAR(plate.bounds().sizes().z() / cell, 12.0, 1e-9);
  EXPECT_NEAR(plate.bounds().sizes().maxCoeff(), 2.0, 1e-12);

  // three creases along z, 10 cells apart, turning by 30, 60 and 30 degrees
  const syn::CadModel creases = syn::cadModelByName("parallel_creases");
  std::vector<std::pair<double, double>> top; // (x, turn in degrees)
  for (const syn::CadCurve& c : creases.curves) {
    const Eigen::Vector3d a = creases.vertices[static_cast<std::size_t>(c.vertices[0])];
    const Eigen::Vector3d b = creases.vertices[static_cast<std::size_t>(c.vertices[1])];
    const Eigen::Vector3d& n0 =
      creases.faces[static_cast<std::size_t>(c.faces[0])].normal;
    const Eigen::Vector3d& n1 =
      creases.faces[static_cast<std::size_t>(c.faces[1])].normal;
    const double turn = std::acos(std::clamp(n0.dot(n1), -1.0, 1.0)) * 180.0 / kPi;
    if (std::abs(a.z() - b.z()) > 0.5 && turn < 89.0) // along z, not a box edge
      top.emplace_back(a.x(), turn);
  }
  std::sort(top.begin(), top.end());
  ASSERT_EQ(top.size(), 3u);
  EXPECT_NEAR((top[1].first - top[0].first) / cell, 10.0, 1e-9);
  EXPECT_NEAR((top[2].first - top[1].first) / cell, 10.0, 1e-9);
  EXPECT_NEAR(top[0].second, 30.0, 1e-9);
  EXPECT_NEAR(top[1].second, 60.0, 1e-9);
  EXPECT_NEAR(top[2].second, 30.0, 1e-9);
}

TEST(CadModels, Incidences)
{
  for (const std::string& name : syn::cadModelNames()) {
    SCOPED_TRACE(name);
    const syn::CadModel model = syn::cadModelByName(name);
    const auto vertex_curves = syn::vertexCurves(model);
    const auto vertex_faces = syn::vertexFaces(model);
    const auto face_curves = syn::faceCurves(model);
    std::size_t degree_sum = 0;
    for (std::size_t v = 0; v < model.vertices.size(); ++v) {
      // A corner of a solid: as many faces as edges, at least 3.
      EXPECT_GE(vertex_curves[v].size(), 3u);
      EXPECT_EQ(vertex_faces[v].size(), vertex_curves[v].size());
      for (int c : vertex_curves[v])
        EXPECT_NEAR(syn::curveDistance(model, c, model.vertices[v]), 0.0, 1e-12);
      degree_sum += vertex_curves[v].size();
    }
    EXPECT_EQ(degree_sum, 2 * countCurves(model, syn::CadCurve::Kind::kSegment));
    for (const syn::CadCurve& c : model.curves) {
      EXPECT_NE(c.faces[0], c.faces[1]);
      for (int f : c.faces) {
        const auto& fc = face_curves[static_cast<std::size_t>(f)];
        EXPECT_TRUE(std::find(fc.begin(), fc.end(), c.id) != fc.end());
      }
      if (c.kind != syn::CadCurve::Kind::kSegment)
        continue;
      // A straight edge links exactly its two vertices, both on both of its faces.
      EXPECT_NE(c.vertices[0], c.vertices[1]);
      for (int v : c.vertices)
        for (int f : c.faces) {
          const auto& vf = vertex_faces[static_cast<std::size_t>(v)];
          EXPECT_TRUE(std::find(vf.begin(), vf.end(), f) != vf.end());
        }
    }
  }
  const auto cube_faces = syn::vertexFaces(syn::cadModelByName("cube"));
  for (const auto& faces : cube_faces)
    EXPECT_EQ(faces.size(), 3u);
  for (const auto& faces : syn::vertexFaces(syn::cadModelByName("icosahedron")))
    EXPECT_EQ(faces.size(), 5u);
}

TEST(CadModels, FaceAreasAndBounds)
{
  const syn::CadModel cube = syn::cadModelByName("cube");
  const double side = 2.0 / std::sqrt(3.0);
  EXPECT_NEAR(cube.area(), 6 * side * side, 1e-12);
  EXPECT_TRUE(cube.bounds().sizes().isApprox(Eigen::Vector3d::Constant(side), 1e-12));

  const syn::CadModel box = syn::cadModelByName("box_with_hole");
  EXPECT_NEAR(box.area(),
              2 * (4.0 - kPi * 0.25) + 4 * (2.0 * 1.5) + 2 * kPi * 0.5 * 1.5, 1e-12);
  EXPECT_TRUE(box.bounds().sizes().isApprox(Eigen::Vector3d(2, 2, 1.5), 1e-12));

  const syn::CadModel cyl = syn::cadModelByName("cylinder");
  EXPECT_NEAR(cyl.area(), 2 * kPi + 2 * kPi * 2, 1e-12);
  EXPECT_TRUE(cyl.bounds().sizes().isApprox(Eigen::Vector3d(2, 2, 2), 1e-12));

  // u_prism: every face at least 20% of the longest side wide (here: 1 of 3).
  const syn::CadModel u = syn::cadModelByName("u_prism");
  EXPECT_NEAR(u.area(), 2 * (9.0 - 2.0) + 1.5 * 16.0, 1e-12);
  const double longest = u.bounds().sizes().maxCoeff();
  for (const syn::CadCurve& c : u.curves)
    EXPECT_GE(syn::curveLength(u, c.id), 0.2 * longest);

  // The rotated bounds are exact: reached (nearly) by samples, never exceeded.
  for (const char* name : {"cylinder", "box_with_hole", "u_prism"}) {
    SCOPED_TRACE(name);
    const syn::CadModel m =
      syn::rotated(syn::cadModelByName(name), syn::randomRotation(17));
    const Eigen::AlignedBox3d box3 = m.bounds();
    const syn::CadSamples s = sample(m, 20000, 3);
    Eigen::AlignedBox3d reached;
    for (const Eigen::Vector3f& p : s.points) {
      reached.extend(p.cast<double>());
      EXPECT_TRUE(box3.exteriorDistance(p.cast<double>()) < 1e-6);
    }
    EXPECT_LT((reached.sizes() - box3.sizes()).cwiseAbs().maxCoeff(),
              0.03 * box3.sizes().maxCoeff());
  }
}

TEST(CadModels, Json)
{
  const std::string text = syn::cadModelJson(syn::cadModelByName("box_with_hole"));
  nlohmann::json json;
  ASSERT_NO_THROW(json = nlohmann::json::parse(text)) << text; // well-formed
  EXPECT_EQ(json.at("name"), "box_with_hole");
  EXPECT_EQ(json.at("counts"), nlohmann::json::parse(R"({"vertices": 8, "edges": 14,
    "straight_edges": 12, "circular_edges": 2, "faces": 7})"));
  EXPECT_EQ(json.at("euler_characteristic"), 0);
  std::size_t circles = 0, rims_of_face_0 = 0;
  for (const auto& edge : json.at("edges"))
    if (edge.at("kind") == "circle") {
      ++circles;
      EXPECT_TRUE(edge.at("vertices").empty());
      rims_of_face_0 += edge.at("faces") == nlohmann::json::array({0, 6});
    }
  EXPECT_EQ(circles, 2u);
  EXPECT_EQ(rims_of_face_0, 1u); // the hole's rim on face 0, with the hole's wall
  std::size_t cylindrical = 0;
  for (const auto& face : json.at("faces"))
    cylindrical += face.at("kind") == "cylindrical";
  EXPECT_EQ(cylindrical, 1u);
}

TEST(CadModels, Errors)
{
  try {
    syn::cadModelByName("dodecahedron");
    FAIL() << "no exception";
  } catch (const visfeat::Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("dodecahedron"), std::string::npos);
    for (const std::string& name : syn::cadModelNames())
      EXPECT_NE(what.find(name), std::string::npos) << name;
  }
  const syn::CadModel cube = syn::cadModelByName("cube");
  syn::SamplingOptions options; // neither a count nor a spacing
  EXPECT_THROW(syn::sampleCadModel(cube, options), visfeat::Error);
  options.count = 10;
  options.noise_sigma = -1.0;
  EXPECT_THROW(syn::sampleCadModel(cube, options), visfeat::Error);
  options.noise_sigma = std::nan("");
  EXPECT_THROW(syn::sampleCadModel(cube, options), visfeat::Error);
  EXPECT_THROW(syn::samplesForSpacing(cube, 64, 0.0), visfeat::Error);
  EXPECT_THROW(syn::cellSize(cube, 0), visfeat::Error);

  // An open mesh (a cube without its last face) and a broken incidence.
  syn::PolygonMesh open = syn::platonicSolid("cube");
  open.faces.pop_back();
  EXPECT_THROW(syn::polyhedralModel("open", open), visfeat::Error);
  syn::PolygonMesh flipped = syn::platonicSolid("cube");
  std::reverse(flipped.faces[0].begin(), flipped.faces[0].end());
  EXPECT_THROW(syn::polyhedralModel("flipped", flipped), visfeat::Error);
  syn::CadModel broken = cube; // curve 0 given a face it does not bound
  for (int f = 0; f < 6; ++f)
    if (f != broken.curves[0].faces[0] && f != broken.curves[0].faces[1]) {
      broken.curves[0].faces[1] = f;
      break;
    }
  EXPECT_THROW(syn::checkCadModel(broken), visfeat::Error);
  syn::CadModel box = syn::cadModelByName("box_with_hole");
  box.curves.back().radius = 0.6; // the wall's circles differ
  EXPECT_THROW(syn::checkCadModel(box), visfeat::Error);
}

TEST(SyntheticShapes, PolygonMeshesAndHull)
{
  const std::map<std::string, std::pair<std::size_t, std::size_t>> expected{
    {"tetrahedron", {4, 3}},
    {"cube", {6, 4}},
    {"octahedron", {8, 3}},
    {"icosahedron", {20, 3}}};
  for (const auto& [name, faces] : expected) {
    SCOPED_TRACE(name);
    const syn::PolygonMesh mesh = syn::platonicSolid(name);
    ASSERT_EQ(mesh.faces.size(), faces.first);
    for (const auto& f : mesh.faces)
      EXPECT_EQ(f.size(), faces.second);
    for (const auto& v : mesh.vertices)
      EXPECT_NEAR(v.norm(), 1.0, 1e-12);
    const syn::TriangleMesh tri = syn::shapeByName(name);
    EXPECT_EQ(tri.triangles.size(), faces.first * (faces.second - 2));
    EXPECT_NEAR(tri.area(), syn::polyhedralModel(name, mesh).area(), 1e-12);
  }
  // A hull away from the origin, with coplanar points merged into quads.
  std::vector<Eigen::Vector3d> corners;
  for (int i = 0; i < 8; ++i)
    corners.emplace_back(5 + (i & 1), 5 + (i & 2 ? 2 : 0), 5 + (i & 4 ? 3 : 0));
  const syn::PolygonMesh box = syn::convexHull(corners);
  EXPECT_EQ(box.faces.size(), 6u);
  const syn::CadModel model = syn::polyhedralModel("box", box);
  EXPECT_NEAR(model.area(), 2 * (1 * 2 + 2 * 3 + 1 * 3), 1e-12);
  EXPECT_THROW(syn::shapeByName("dodecahedron"), visfeat::Error);
}

} // namespace
