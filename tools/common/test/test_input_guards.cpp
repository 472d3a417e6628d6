// Unit tests of the checks in front of PCL's and VTK's readers that fuzzing
// (test/fuzz) showed missing: each input here crashed, hung or overran a buffer before
// (the same files are regression files of the fuzz corpus).

#include "common/cloud_input.h"
#include "common/mesh_input.h"
#include "common/obj_check.h"

#include "pcd_header_test.h"
#include "temp_dir.h"

#include <visfeat/core/common/error.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <sstream>
#include <string>

namespace fs = std::filesystem;
namespace vt = visfeat_tools;

namespace {

using InputGuards = vt::test::TempDirTest;

const char* const kTriangleObj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";

TEST_F(InputGuards, ObjProblemAcceptsCommonObjFiles)
{
  EXPECT_EQ(vt::objProblem(write("a.obj", kTriangleObj)), "");
  EXPECT_EQ(vt::objProblem(write("b.obj", "# c\r\nv 0 0 0 1\r\nv 1 0 0\r\nv 0 1 0\r\n"
                                          "vn 0 0 1\r\nvt 0 0\r\ng g\r\n"
                                          "f 1/1/1 2//1 -1\r\n")),
            "");
  write("m.mtl", "newmtl red\nKd 1 0 0\nillum 2\n");
  EXPECT_EQ(
    vt::objProblem(write("c.obj", std::string("mtllib m.mtl\n") + kTriangleObj)), "");
  EXPECT_EQ(
    vt::objProblem(write("d.obj", std::string("mtllib gone.mtl\n") + kTriangleObj)),
    "");
}

TEST_F(InputGuards, ObjProblemRefusesWhatPclsReaderOverruns)
{
  EXPECT_EQ(vt::objProblem(write("a.obj", "v 0  5\nf 1 2\n")),
            "line 1: 'v' needs 3 finite coordinates");
  EXPECT_EQ(vt::objProblem(write("b.obj", "v\t0 0 0\n")),
            "line 1: 'v' and its coordinates must be separated by a space");
  EXPECT_EQ(vt::objProblem(write("c.obj", "v 0 0 0\nvn 0 0 1\nvn 0 0 1\n")),
            "line 3: more vertex normals than vertices");
  EXPECT_EQ(vt::objProblem(write("d.obj", "v 0 0 0\nf 1 x 1\n")),
            "line 2: face vertex 'x' does not start with an index");
  EXPECT_EQ(vt::objProblem(write("e.obj", "v 0 0 0\nf 1 99999999999 1\n")),
            "line 2: face vertex '99999999999' does not start with an index");
  EXPECT_EQ(vt::objProblem(write("f.obj", "mtllib\nv 0 0 0\n")),
            "line 1: 'mtllib' without a file name");
  EXPECT_EQ(vt::objProblem(write("g.obj", "v 1 nan 0\n")),
            "line 1: 'v' needs 3 finite coordinates");
  EXPECT_EQ(vt::objProblem(write("h.obj", "# nothing\n")),
            "no vertex ('v x y z' line)");
}

TEST_F(InputGuards, ObjProblemRefusesFaceIndicesOutOfRangeInTheFilesNumbering)
{
  // OBJ counts vertices from 1: the message gives the index and line as in the file
  // (before, "face 0: vertex index 8 out of range (3 vertices, counting from 0)" from
  // PCL's 0-based mesh, for 'f 1 2 9')
  EXPECT_EQ(vt::objProblem(write("a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 1 2 9\n")),
            "line 5: face vertex index 9 out of range (the file has 3 vertices, "
            "counting from 1)");
  EXPECT_EQ(vt::objProblem(write("b.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n")),
            "line 4: face vertex index 0 (OBJ counts vertices from 1)");
  EXPECT_EQ(vt::objProblem(write("c.obj", "v 0 0 0\nv 1 0 0\nf -1 -2 -3\nv 0 1 0\n")),
            "line 3: face vertex index -3 reaches before the first vertex (2 vertices "
            "so far)");
  // faces before their vertices, and the largest index exactly the last vertex: fine
  EXPECT_EQ(vt::objProblem(write("d.obj", "f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n")), "");
}

TEST_F(InputGuards, ObjProblemRefusesMaterialLibrariesPclCannotRead)
{
  fs::create_directory(path("dir"));
  EXPECT_EQ(vt::objProblem(write("a.obj", std::string("mtllib dir\n") + kTriangleObj)),
            "line 1: material library 'dir' is not a regular file");
  write("bad.mtl", "Kd 1 0 0\n");
  EXPECT_EQ(
    vt::objProblem(write("b.obj", std::string("mtllib bad.mtl\n") + kTriangleObj)),
    "line 1: material library 'bad.mtl' line 1: 'Kd' before any 'newmtl'");
  write("noname.mtl", "newmtl\n");
  EXPECT_EQ(
    vt::objProblem(write("c.obj", std::string("mtllib noname.mtl\n") + kTriangleObj)),
    "line 1: material library 'noname.mtl' line 1: 'newmtl' without a value");
}

TEST_F(InputGuards, LoadMeshRefusesDirectoriesAndBadObjWithOneLine)
{
  fs::create_directory(path("dir.obj"));
  visfeat::SurfaceMesh mesh;
  std::string error;
  EXPECT_FALSE(vt::loadMesh(path("dir.obj"), mesh, error)); // PCL looped forever
  EXPECT_EQ(error, "'" + path("dir.obj") + "': is a directory");
  const std::string bad = write("bad.obj", "v 0  5\nf 1 2\n");
  EXPECT_FALSE(vt::loadMesh(bad, mesh, error));
  EXPECT_EQ(error, "'" + bad +
                     "': not a valid OBJ mesh: line 1: 'v' needs 3 finite coordinates");
  EXPECT_TRUE(vt::loadMesh(write("ok.obj", kTriangleObj), mesh, error)) << error;
  EXPECT_EQ(mesh.triangles.size(), 1u);
}

TEST_F(InputGuards, StlProblemRefusesAsciiWithBinaryBytes)
{
  const std::string facet = "facet normal 0 0 1\n outer loop\n  vertex 0 0 0\n"
                            "  vertex 1 0 0\n  vertex 0 1 0\n endloop\nendfacet\n";
  EXPECT_EQ(vt::stlProblem(write("a.stl", "solid t\n" + facet + "endsolid t\n")), "");
  // VTK's reader took it for binary and asked for gigabytes
  const std::string nul = "solid t\n" + facet + "endsolid t\n" + std::string(45, '\0');
  EXPECT_EQ(
    vt::stlProblem(write("b.stl", nul)),
    "an ASCII STL with a byte that is not text at offset 113 (binary data, or a "
    "binary STL of the wrong size)");
}

TEST_F(InputGuards, ObjMeshesAreReadWithoutBlankAndMaterialLines)
{
  // a CRLF file with blank lines, and material libraries that are missing or not
  // files (PCL looped forever on 'mtllib .'): loadMesh hands PCL a copy without those
  // lines and reads the geometry
  visfeat::SurfaceMesh mesh;
  std::string error;
  const std::string crlf = "\r\nv 0 0 0\r\n \t\r\nv 1 0 0\r\nv 0 1 0\r\nf 1 2 3\r\n";
  ASSERT_TRUE(vt::loadMesh(write("crlf.obj", crlf), mesh, error)) << error;
  EXPECT_EQ(mesh.vertices.size(), 3u);
  EXPECT_EQ(mesh.triangles.size(), 1u);
  for (const std::string lib : {"mtllib .\n", "mtllib gone.mtl\nusemtl red\n"}) {
    ASSERT_TRUE(vt::loadMesh(write("lib.obj", lib + kTriangleObj), mesh, error))
      << lib << error;
    EXPECT_EQ(mesh.triangles.size(), 1u);
  }
  // the guard still names the user's line numbers
  EXPECT_FALSE(vt::loadMesh(write("short.obj", "\r\nv 0 0\n"), mesh, error));
  EXPECT_NE(error.find("line 2"), std::string::npos) << error;
}

TEST_F(InputGuards, ObjProblemRefusesLinesOfOnlySpacesTabsOrCRs)
{
  // PCL 1.13 read the first token of a line that has none: a null dereference on a
  // first line, a use after free on a later one (fuzz_ply_obj)
  const std::string blank =
    "a line of only spaces, tabs or CRs (PCL's reader fails on it: make it empty)";
  EXPECT_EQ(vt::objProblem(write("a.obj", std::string("\r\n") + kTriangleObj)),
            "line 1: " + blank);
  EXPECT_EQ(vt::objProblem(write("b.obj", std::string("#") + std::string(40, 'a') +
                                            "\n \t\n" + kTriangleObj)),
            "line 2: " + blank);
  write("m.mtl", "newmtl red\n\r\nKd 1 0 0\n");
  EXPECT_EQ(
    vt::objProblem(write("c.obj", std::string("mtllib m.mtl\n") + kTriangleObj)),
    "line 1: material library 'm.mtl' line 2: " + blank);
  // empty lines, and a vertical tab (not a separator for PCL), are fine
  EXPECT_EQ(vt::objProblem(write("d.obj", std::string("\n\v\n") + kTriangleObj)), "");
}

TEST_F(InputGuards, PlyProblemRefusesAListPropertyOfTheVertexElement)
{
  // PCL 1.13 aborted (assert) when its length varied from vertex to vertex
  const std::string head = "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\n"
                           "property float y\nproperty float z\n";
  EXPECT_EQ(
    vt::plyProblem(write("a.ply", head + "property list uchar int idx\n"
                                         "end_header\n0 0 0 1 1\n1 1 1 2 1 1\n")),
    "line 7: a list property ('idx') of the vertex element (PCL's reader aborts "
    "when its length varies)");
  // faces have lists, and a header keyword after end_header is data
  EXPECT_EQ(
    vt::plyProblem(write("b.ply", head + "element face 1\n"
                                         "property list uchar int vertex_indices\n"
                                         "end_header\n0 0 0\n1 0 0\n3 0 1 0\n")),
    "");
  EXPECT_EQ(vt::plyProblem(write("c.ply", head + "end_header\nproperty list a b c\n"
                                                 "0 0 0\n")),
            "");
  // 'blue' without 'red': the next property was written past the point (assertion)
  EXPECT_EQ(
    vt::plyProblem(write("d.ply", head + "property uchar blue\nproperty float nx\n"
                                         "end_header\n0 0 0 0 0\n1 1 1 0 0\n")),
    "line 7: a 'blue' property of the vertex element without a 'red' before it "
    "(PCL's reader aborts on it)");
  EXPECT_EQ(
    vt::plyProblem(write("e.ply", head + "property uchar red\nproperty uchar "
                                         "green\nproperty uchar blue\nend_header\n"
                                         "0 0 0 0 0 0\n1 1 1 0 0 0\n")),
    "");
}

TEST_F(InputGuards, PlyProblemRefusesCountsTheFileCannotHold)
{
  // PCL allocated the declared vertices first: 36 bytes declaring 10^9 vertices took
  // 58 s and 11.7 GB before it failed
  const std::string props = "property float x\nproperty float y\nproperty float z\n";
  const std::string data(36, '\0');
  EXPECT_EQ(vt::plyProblem(write("big.ply", "ply\nformat binary_little_endian 1.0\n"
                                            "element vertex 1000000000\n" +
                                              props + "end_header\n" + data)),
            "the header declares elements needing at least 12000000000 bytes of data, "
            "but the file holds 36 after its header (truncated, or its counts are "
            "wrong)");
  // three vertices fit in 36 bytes; a face list needs its count byte per face
  const std::string three = "ply\nformat binary_little_endian 1.0\nelement vertex 3\n" +
                            props + "end_header\n" + data;
  EXPECT_EQ(vt::plyProblem(write("three.ply", three)), "");
  const std::string faces = "ply\nformat binary_little_endian 1.0\nelement vertex 3\n" +
                            props +
                            "element face 5\nproperty list uchar int vertex_indices\n"
                            "end_header\n" +
                            data + "\x03";
  EXPECT_NE(vt::plyProblem(write("faces.ply", faces)), "");
  // ASCII: two characters a property at least
  EXPECT_NE(vt::plyProblem(write("text.ply", "ply\nformat ascii 1.0\n"
                                             "element vertex 1000000\n" +
                                               props + "end_header\n0 0 0\n")),
            "");
  EXPECT_EQ(vt::plyProblem(write("text2.ply", "ply\nformat ascii 1.0\n"
                                              "element vertex 2\n" +
                                                props + "end_header\n0 0 0\n1 1 1\n")),
            "");
  // ASCII lines long enough for the byte count, but fewer than the elements (a fresh
  // user's truncated file got "could not be parsed" without a count)
  EXPECT_EQ(vt::plyProblem(write("short.ply", "ply\nformat ascii 1.0\n"
                                              "element vertex 5\n" +
                                                props +
                                                "end_header\n0.000 0.000 0.000\n"
                                                "1.000 1.000 1.000\n\n"
                                                "2.000 2.000 2.000\n")),
            "the header declares 5 elements (one a line), but the file holds 3 data "
            "lines after its header (truncated, or its counts are wrong)");
}

TEST(ReadOff, RefusesAFaceCountThatWrapsAround)
{
  // n + 1 wrapped to 0 and the indices were read past the line's tokens
  std::istringstream in("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n"
                        "18446744073709551615 0 1 2\n");
  EXPECT_THROW(visfeat::readOff(in), visfeat::Error);
}

using PcdGuards = vt::test::PcdHeaderTest;

const std::string kXYZ = "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\n";

TEST_F(PcdGuards, RefusesRepeatedKeywordsAndImpossibleFields)
{
  EXPECT_EQ(problemOf(kXYZ + "WIDTH 1\nPOINTS 1\nDATA ascii\n1 2 3\n"), "");
  // a second FIELDS / SIZE line made PCL lay the fields outside the points
  EXPECT_EQ(problemOf(kXYZ + "WIDTH 1\nFIELDS x y z\nPOINTS 1\nDATA ascii\n1 2 3\n"),
            "invalid PCD header: a second FIELDS line");
  EXPECT_EQ(problemOf(kXYZ + "COLUMNS x y z\nWIDTH 1\nPOINTS 1\nDATA ascii\n1 2 3\n"),
            "invalid PCD header: a second COLUMNS line");
  EXPECT_EQ(problemOf(kXYZ + "COUNT 1 0 1\nWIDTH 1\nPOINTS 1\nDATA ascii\n1 2 3\n"),
            "invalid PCD header: a field of COUNT 0");
  EXPECT_EQ(problemOf("FIELDS x y z\nSIZE 2 4 4\nTYPE F F F\nWIDTH 1\nPOINTS 1\n"
                      "DATA ascii\n1 2 3\n"),
            "invalid PCD header: a float field (TYPE F) of SIZE 2 (4 or 8)");
  EXPECT_EQ(
    problemOf(kXYZ + "COUNT 1 1 99999999999\nWIDTH 1\nPOINTS 1\nDATA ascii\n1\n"),
    "invalid PCD header: COUNT 99999999999 is larger than the file");
  EXPECT_EQ(problemOf(kXYZ + "WIDTH 4294967296\nHEIGHT 4294967296\nPOINTS 0\n"
                             "DATA ascii\n"),
            "invalid PCD header: WIDTH x HEIGHT differs from POINTS");
}

TEST_F(PcdGuards, RefusesDataTooShortForItsPointsBeforePclAllocatesThem)
{
  EXPECT_EQ(problemOf(kXYZ + "WIDTH 9000000\nPOINTS 9000000\nDATA ascii\n1 2 3\n"),
            "PCD data is truncated (the header announces 9000000 points)");
  EXPECT_EQ(problemOf(kXYZ + "WIDTH 3\nPOINTS 3\nDATA ascii\n1 2 3\n4 5 6\n"),
            "PCD data is truncated or corrupt (the header announces 3 points of 3 "
            "values)");
  // binary_compressed: the sizes after the header must fit the file and the points
  const std::string head = kXYZ + "WIDTH 2\nPOINTS 2\nDATA binary_compressed\n";
  EXPECT_EQ(problemOf(head + std::string("\x40\x00\x00\x00\x18\x00\x00\x00", 8)),
            "PCD data is truncated (the compressed block has 64 bytes)");
  EXPECT_EQ(
    problemOf(head + std::string("\x01\x00\x00\x00\xff\xff\xff\xff", 8) + "x"),
    "PCD data is corrupt (the compressed block unpacks to 4294967295 bytes, the "
    "points take 24)");
}

TEST_F(PcdGuards, RefusesWhatPclReadsAsHeaderAfterDataOrBeforeIt)
{
  const std::string head = kXYZ + "WIDTH 1\nPOINTS 1\n";
  // PCL 1.13 reads header lines on after DATA: a later DATA line moved the body (an
  // ascii file read as binary_compressed, a huge allocation found by fuzzing)
  EXPECT_EQ(problemOf(head + "DATA ascii\nVERSION .7\nDATA binary_compressed\n" +
                      std::string(8, '\0')),
            "invalid PCD header: a VERSION line after DATA (line 7)");
  EXPECT_EQ(problemOf(head + "DATA ascii\n\n# c\nDATA binary\n1 2 3\n"),
            "invalid PCD header: a second DATA line (line 9)");
  // keywords match by prefix
  EXPECT_EQ(problemOf(head + "DATA ascii\nPOINTSX 9\n1 2 3\n"),
            "invalid PCD header: a POINTS line after DATA (line 7)");
  // empty lines and comments after DATA are skipped by both; the first other line
  // ends the header
  EXPECT_EQ(problemOf(head + "DATA ascii\n\n# c\n1 2 3\nDATA binary\n"), "");
  EXPECT_EQ(problemOf(head + "DATA binary\n" + std::string("\x01\0\0\0DATA\n", 9) +
                      std::string(4, '\0')),
            "");
  // a blank line that is not empty (a lone CR) ends PCL's header before DATA
  EXPECT_EQ(problemOf("FIELDS x y z\r\n\r\nSIZE 4 4 4\r\nTYPE F F F\r\nWIDTH 1\r\n"
                      "POINTS 1\r\nDATA ascii\r\n1 2 3\r\n"),
            "invalid PCD header: a blank line that is not empty before DATA (line 2)");
  EXPECT_EQ(problemOf("FIELDS x y z\r\nSIZE 4 4 4\r\nTYPE F F F\r\nWIDTH 1\r\n"
                      "POINTS 1\r\nDATA ascii\r\n1 2 3\r\n"),
            "");
}

TEST(LayoutProblem, NamesWhatDoesNotHoldTogether)
{
  pcl::PCLPointCloud2 cloud;
  EXPECT_EQ(vt::layoutProblem(cloud), "");
  EXPECT_EQ(vt::fieldsList(cloud), "none"); // pcl::getFieldsList read out of bounds
  cloud.fields.resize(1);
  cloud.fields[0].name = "x";
  cloud.fields[0].datatype = pcl::PCLPointField::FLOAT32;
  cloud.fields[0].count = 1;
  cloud.fields[0].offset = 4;
  cloud.point_step = 4;
  EXPECT_EQ(vt::layoutProblem(cloud), "field 'x' lies outside its point");
  cloud.fields[0].offset = 0;
  cloud.width = 2;
  cloud.height = 1;
  cloud.data.resize(4);
  EXPECT_EQ(vt::layoutProblem(cloud), "the data holds fewer than its 2 points");
  cloud.data.resize(8);
  EXPECT_EQ(vt::layoutProblem(cloud), "");
  EXPECT_EQ(vt::fieldsList(cloud), "x");
  std::string problem;
  cloud.fields[0].datatype = 0;
  EXPECT_FALSE(vt::hasXYZ(cloud, problem));
  EXPECT_EQ(problem, "field 'x' has an unknown type");
}

} // namespace
