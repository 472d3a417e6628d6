// Unit tests of common/mesh_input.h: which files are meshes, PolygonMesh conversion
// and its errors, reading and sampling meshes.

#include "common/mesh_input.h"

#include "temp_dir.h"

#include <pcl/common/io.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

namespace vt = visfeat_tools;

namespace {

using MeshInput = vt::test::TempDirTest;

const char* const kTetrahedronOff = "OFF\n"
                                    "4 4 0\n"
                                    "0 0 0\n"
                                    "1 0 0\n"
                                    "0 1 0\n"
                                    "0 0 1\n"
                                    "3 0 2 1\n"
                                    "3 0 1 3\n"
                                    "3 0 3 2\n"
                                    "3 1 2 3\n";

/** What loadMeshAsCloud() gives back for a file sampled to `points` points. */
struct SampledMesh
{
  bool ok = false;
  pcl::PCLPointCloud2 cloud;
  std::shared_ptr<const visfeat::SurfaceMesh> mesh;
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();
  std::string summary, error;
};

SampledMesh
sampleMesh(const std::string& path, std::size_t points)
{
  vt::MeshDensity density;
  density.points = points;
  SampledMesh out;
  out.ok = vt::loadMeshAsCloud(path, density, out.cloud, out.mesh, out.offset,
                               out.summary, out.error);
  return out;
}

std::string
plyHeader(const std::string& elements)
{
  return "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float "
         "y\nproperty float z\n" +
         elements + "end_header\n";
}

TEST_F(MeshInput, IsMeshFileByExtensionAndPlyFaces)
{
  EXPECT_TRUE(vt::isMeshFile(path("absent.obj")));
  EXPECT_TRUE(vt::isMeshFile(path("absent.OFF")));
  EXPECT_FALSE(vt::isMeshFile(path("absent.pcd")));
  EXPECT_FALSE(vt::isMeshFile(path("absent.ply"))) << "unreadable: left to the reader";
  EXPECT_TRUE(vt::isMeshFile(
    write("faces.ply",
          plyHeader("element face 2\nproperty list uchar int vertex_indices\n"))));
  EXPECT_FALSE(vt::isMeshFile(
    write("no_faces.ply",
          plyHeader("element face 0\nproperty list uchar int vertex_indices\n"))));
  EXPECT_FALSE(vt::isMeshFile(write("cloud.ply", plyHeader(""))));
  EXPECT_FALSE(
    vt::isMeshFile(write("after_header.ply", plyHeader("") + "element face 2\n")));
}

/** \brief A PolygonMesh of a unit square in z = 0 with double x y z. */
pcl::PolygonMesh
square()
{
  pcl::PolygonMesh mesh;
  pcl::PCLPointCloud2& c = mesh.cloud;
  for (int a = 0; a < 3; ++a) {
    pcl::PCLPointField f;
    f.name = std::string(1, static_cast<char>('x' + a));
    f.offset = static_cast<std::uint32_t>(8 * a);
    f.datatype = pcl::PCLPointField::FLOAT64;
    f.count = 1;
    c.fields.push_back(f);
  }
  c.point_step = 24;
  c.width = 4;
  c.height = 1;
  c.row_step = 96;
  const std::array<std::array<double, 3>, 4> corners{
    {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}};
  c.data.resize(96);
  std::memcpy(c.data.data(), corners.data(), 96);
  pcl::Vertices quad;
  quad.vertices = {0, 1, 2, 3};
  mesh.polygons.push_back(quad);
  return mesh;
}

TEST(ToSurfaceMesh, FansPolygonsAndReadsDoubleVertices)
{
  visfeat::SurfaceMesh out;
  std::string error;
  ASSERT_TRUE(vt::toSurfaceMesh(square(), out, error)) << error;
  ASSERT_EQ(out.vertices.size(), 4u);
  EXPECT_EQ(out.vertices[2], Eigen::Vector3d(1, 1, 0));
  using Triangle = std::array<std::uint32_t, 3>;
  EXPECT_EQ(out.triangles, (std::vector<Triangle>{{0, 1, 2}, {0, 2, 3}}));
}

TEST(ToSurfaceMesh, NamesWhatIsWrong)
{
  visfeat::SurfaceMesh out;
  std::string error;

  pcl::PolygonMesh no_z = square();
  no_z.cloud.fields.pop_back();
  EXPECT_FALSE(vt::toSurfaceMesh(no_z, out, error));
  EXPECT_EQ(error, "the mesh's vertices have no 'z' field (fields: x y)");

  pcl::PolygonMesh short_data = square();
  short_data.cloud.data.resize(95);
  EXPECT_FALSE(vt::toSurfaceMesh(short_data, out, error));
  EXPECT_EQ(error, "the mesh's vertex data is truncated");

  pcl::PolygonMesh two = square();
  two.polygons.push_back(pcl::Vertices());
  two.polygons.back().vertices = {0, 1};
  EXPECT_FALSE(vt::toSurfaceMesh(two, out, error));
  EXPECT_EQ(error, "face 1 has 2 vertices (at least 3 needed)");

  pcl::PolygonMesh far = square();
  far.polygons[0].vertices[3] = 4;
  EXPECT_FALSE(vt::toSurfaceMesh(far, out, error));
  EXPECT_EQ(error, "face 0: vertex index 4 out of range (4 vertices, counting from 0)");
}

TEST_F(MeshInput, LoadsAnOffMesh)
{
  visfeat::SurfaceMesh mesh;
  std::string error;
  ASSERT_TRUE(vt::loadMesh(write("t.off", kTetrahedronOff), mesh, error)) << error;
  EXPECT_EQ(mesh.vertices.size(), 4u);
  EXPECT_EQ(mesh.triangles.size(), 4u);
  EXPECT_EQ(mesh.vertices[3], Eigen::Vector3d(0, 0, 1));
}

TEST_F(MeshInput, LoadErrorsNameTheFile)
{
  visfeat::SurfaceMesh mesh;
  std::string error;
  const std::string off = write("bad.off", "COFF\n");
  EXPECT_FALSE(vt::loadMesh(off, mesh, error));
  EXPECT_EQ(error.rfind("'" + off + "': OFF", 0), 0u) << error;

  const std::string ply = write("bad.ply", "ply\nformat nonsense 1.0\nend_header\n");
  EXPECT_FALSE(vt::loadMesh(ply, mesh, error));
  EXPECT_EQ(error,
            "'" + ply + "': not a valid PLY mesh (header or data could not be parsed)");
}

/** The tetrahedron of kTetrahedronOff as an ASCII STL (one facet per face, each
 * vertex written three times). */
std::string
tetrahedronAsciiStl()
{
  const char* const v[4] = {"0 0 0", "1 0 0", "0 1 0", "0 0 1"};
  const int faces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  std::string stl = "solid tetrahedron\n";
  for (const auto& f : faces) {
    stl += " facet normal 0 0 0\n  outer loop\n";
    for (const int i : f)
      stl += std::string("   vertex ") + v[i] + "\n";
    stl += "  endloop\n endfacet\n";
  }
  return stl + "endsolid tetrahedron\n";
}

/** The same as a binary STL: 80-byte header (starting with "solid", as many exporters
 * write it), the count, 50 bytes a triangle. */
std::string
tetrahedronBinaryStl()
{
  const float v[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const int faces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  std::string stl(80, ' ');
  stl.replace(0, 5, "solid");
  const std::uint32_t count = 4;
  for (int b = 0; b < 4; ++b)
    stl += static_cast<char>((count >> (8 * b)) & 0xff);
  for (const auto& f : faces) {
    float record[12] = {};
    for (int c = 0; c < 3; ++c)
      for (int a = 0; a < 3; ++a)
        record[3 + 3 * c + a] = v[f[c]][a];
    stl.append(reinterpret_cast<const char*>(record), sizeof record);
    stl.append(2, '\0'); // attribute byte count
  }
  return stl;
}

TEST_F(MeshInput, LoadsAsciiAndBinaryStl)
{
  EXPECT_TRUE(vt::isMeshFile(path("absent.STL")));
  for (const auto& [name, text] :
       {std::pair<std::string, std::string>{"ascii.stl", tetrahedronAsciiStl()},
        {"binary.stl", tetrahedronBinaryStl()}}) {
    visfeat::SurfaceMesh mesh;
    std::string error;
    const std::string file = write(name, text);
    EXPECT_EQ(vt::stlProblem(file), "") << name;
    ASSERT_TRUE(vt::loadMesh(file, mesh, error)) << name << ": " << error;
    EXPECT_EQ(mesh.vertices.size(), 4u) << name << ": shared corners are merged";
    EXPECT_EQ(mesh.triangles.size(), 4u) << name;
    EXPECT_NO_THROW(visfeat::validateMesh(mesh)) << name;
  }
}

TEST_F(MeshInput, BrokenStlFilesAreRefusedBeforeTheReader)
{
  const std::string ascii = tetrahedronAsciiStl(), binary = tetrahedronBinaryStl();
  const std::pair<std::string, std::string> cases[] = {
    {ascii.substr(0, ascii.size() / 2), "without 'endsolid'"},
    {"solid x\n facet normal 0 0 0\n outer loop\n vertex 0 0 nan\n endsolid x\n",
     "not three finite numbers"},
    {"solid x\n facet normal 0 0 0\n outer loop\n vertex 0 0 0\n endsolid x\n",
     "with 1 vertices"},
    {binary.substr(0, binary.size() - 7),
     "a binary STL of 277 bytes whose count says 4 triangles (284 bytes)"},
    {binary.substr(0, 84).replace(80, 4, std::string(4, '\0')), "without triangles"},
    {"x", "neither a binary STL"},
  };
  for (const auto& [text, expected] : cases) {
    const std::string file = write("broken.stl", text);
    visfeat::SurfaceMesh mesh;
    std::string error;
    EXPECT_FALSE(vt::loadMesh(file, mesh, error)) << expected;
    EXPECT_EQ(error.rfind("'" + file + "': not a valid STL mesh: ", 0), 0u) << error;
    EXPECT_NE(error.find(expected), std::string::npos)
      << error << " (expected: " << expected << ")";
  }
  // an empty file is refused before the STL check, as every input
  const std::string empty = write("empty.stl", "");
  visfeat::SurfaceMesh mesh;
  std::string error;
  EXPECT_FALSE(vt::loadMesh(empty, mesh, error));
  EXPECT_EQ(error, "'" + empty + "': file is empty");
}

TEST_F(MeshInput, SamplesAMeshIntoACloud)
{
  EXPECT_EQ(vt::MeshDensity{}.points, 1000000u) << "the documented default";
  const SampledMesh sampled = sampleMesh(write("t.off", kTetrahedronOff), 1000);
  ASSERT_TRUE(sampled.ok) << sampled.error;
  const pcl::PCLPointCloud2& cloud = sampled.cloud;
  const auto& mesh = sampled.mesh;
  const std::string& summary = sampled.summary;
  EXPECT_EQ(sampled.offset, Eigen::Vector3d::Zero())
    << "near the origin: not recentred";
  EXPECT_EQ(cloud.width * cloud.height, 1000u);
  // the mesh itself is kept for the band
  ASSERT_TRUE(mesh);
  EXPECT_EQ(mesh->vertices.size(), 4u);
  EXPECT_EQ(mesh->triangles.size(), 4u);
  EXPECT_EQ(pcl::getFieldsList(cloud), "x y z");
  EXPECT_EQ(summary.rfind("Sampled 1000 points from 4 triangles (4 vertices, area ", 0),
            0u)
    << summary;
  const std::string tail = "; area-weighted uniform, seed 1)";
  EXPECT_EQ(summary.substr(summary.size() - tail.size()), tail) << summary;

  // The same mesh gives the same cloud.
  const SampledMesh again = sampleMesh(path("t.off"), 1000);
  ASSERT_TRUE(again.ok) << again.error;
  EXPECT_EQ(again.cloud.data, cloud.data);
}

/** The vertex lines of kTetrahedronOff's tetrahedron, scaled by 9 and moved by
 * `shift`, printed to 17 digits after `prefix` ("" for OFF, "v " for OBJ). */
std::string
tetrahedronVerticesAt(const Eigen::Vector3d& shift, const char* prefix)
{
  const Eigen::Vector3d v[4] = {Eigen::Vector3d::Zero(), 9.0 * Eigen::Vector3d::UnitX(),
                                9.0 * Eigen::Vector3d::UnitY(),
                                9.0 * Eigen::Vector3d::UnitZ()};
  std::string text;
  char line[128];
  for (const Eigen::Vector3d& p : v) {
    const Eigen::Vector3d q = p + shift;
    std::snprintf(line, sizeof(line), "%s%.17g %.17g %.17g\n", prefix, q.x(), q.y(),
                  q.z());
    text += line;
  }
  return text;
}

/** An OFF file of that tetrahedron. */
std::string
tetrahedronOffAt(const Eigen::Vector3d& shift)
{
  return "OFF\n4 4 0\n" + tetrahedronVerticesAt(shift, "") +
         "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
}

/** An OBJ file of that tetrahedron (the same faces, counted from 1). */
std::string
tetrahedronObjAt(const Eigen::Vector3d& shift)
{
  return tetrahedronVerticesAt(shift, "v ") + "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
}

TEST_F(MeshInput, AFloatFormatInSurveyCoordinatesIsRefused)
{
  // OBJ comes in as 32-bit floats (PCL): near 4.3e6 in steps of 0.5, for a 9-unit
  // part; OFF (double) is recentred instead (the test below)
  const Eigen::Vector3d survey(512345.678, 4312345.123, 120.456);
  const SampledMesh far = sampleMesh(write("far.obj", tetrahedronObjAt(survey)), 2000);
  EXPECT_FALSE(far.ok);
  const std::string& error = far.error;
  EXPECT_NE(error.find("OBJ coordinates are read as 32-bit floats"), std::string::npos)
    << error;
  EXPECT_NE(error.find(".ply (double properties) or .off"), std::string::npos) << error;
}

TEST_F(MeshInput, AMeshInSurveyCoordinatesIsRecentredBeforeSampling)
{
  // the tetrahedron near (512345.678, 4312345.123, 120.456): float there resolves
  // 0.25-0.5 m; recentred, the samples keep micrometres
  const Eigen::Vector3d survey(512345.678, 4312345.123, 120.456);
  const SampledMesh far = sampleMesh(write("far.off", tetrahedronOffAt(survey)), 2000);
  ASSERT_TRUE(far.ok) << far.error;
  const pcl::PCLPointCloud2& cloud = far.cloud;
  const auto& mesh = far.mesh;
  const Eigen::Vector3d& offset = far.offset;
  // the bounding box's centre rounded to tens (extent 9)
  EXPECT_EQ(offset, Eigen::Vector3d(512350.0, 4312350.0, 120.0));
  ASSERT_TRUE(mesh);
  EXPECT_LT(
    (mesh->vertices[1] - (survey + 9.0 * Eigen::Vector3d::UnitX() - offset)).norm(),
    1e-9);
  // the cloud is in the input's frame, in double
  for (const pcl::PCLPointField& f : cloud.fields)
    EXPECT_EQ(f.datatype, pcl::PCLPointField::FLOAT64) << f.name;
  // the same samples as the mesh already at its recentred place, moved by the offset
  const SampledMesh sampled_near =
    sampleMesh(write("near.off", tetrahedronOffAt(survey - offset)), 2000);
  ASSERT_TRUE(sampled_near.ok) << sampled_near.error;
  const pcl::PCLPointCloud2& near = sampled_near.cloud;
  EXPECT_EQ(sampled_near.offset, Eigen::Vector3d::Zero());
  ASSERT_EQ(cloud.width, near.width);
  double worst = 0.0;
  for (std::size_t i = 0; i < cloud.width; ++i) {
    double far_p[3];
    float near_p[3];
    std::memcpy(far_p, cloud.data.data() + i * cloud.point_step, sizeof(far_p));
    std::memcpy(near_p, near.data.data() + i * near.point_step, sizeof(near_p));
    for (int a = 0; a < 3; ++a)
      worst = std::max(worst, std::abs(far_p[a] - (double(near_p[a]) + offset[a])));
  }
  EXPECT_LT(worst, 1e-5) << "world units";
}

TEST_F(MeshInput, RefusesMeshesWithoutArea)
{
  const std::string none = write("none.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n");
  const SampledMesh faceless = sampleMesh(none, 10);
  EXPECT_FALSE(faceless.ok);
  EXPECT_EQ(faceless.error, "'" + none +
                              "': the mesh has no faces: if its 3 vertices are a point "
                              "cloud, give them as .ply, .pcd or .xyz, which are read "
                              "as clouds");
  const std::string flat =
    write("flat.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n2 0 0\n3 0 1 2\n");
  const SampledMesh flat_mesh = sampleMesh(flat, 10);
  EXPECT_FALSE(flat_mesh.ok);
  EXPECT_FALSE(flat_mesh.mesh);
  EXPECT_EQ(flat_mesh.error, "'" + flat +
                               "': the mesh has zero area (all 1 triangles are "
                               "degenerate)");
}

} // namespace
