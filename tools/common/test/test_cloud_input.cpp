// Unit tests of common/cloud_input.h: PCD header checks, loading errors, x y z of any
// type, fields removed.

#include "common/cloud_input.h"

#include "pcd_header_test.h"
#include "temp_dir.h"

#include <pcl/common/io.h>
#include <pcl/io/pcd_io.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

namespace fs = std::filesystem;
namespace vt = visfeat_tools;

namespace {

using CloudInput = vt::test::TempDirTest;

/** \brief A PCD header of x y z floats with `points` points, then `data`. */
std::string
pcd(const std::string& type, int points, const std::string& data)
{
  return "# .PCD v0.7 - Point Cloud Data file format\n"
         "VERSION 0.7\n"
         "FIELDS x y z\n"
         "SIZE 4 4 4\n"
         "TYPE F F F\n"
         "COUNT 1 1 1\n"
         "WIDTH " +
         std::to_string(points) +
         "\n"
         "HEIGHT 1\n"
         "VIEWPOINT 0 0 0 1 0 0 0\n"
         "POINTS " +
         std::to_string(points) + "\nDATA " + type + "\n" + data;
}

const std::string kTwoPoints = pcd("ascii", 2, "1 2 3\n4 5 6\n");

using PcdHeader = vt::test::PcdHeaderTest;

/** \brief `header` with the line starting with `key` replaced by `line` ("" drops
 * it). */
std::string
replaceLine(const std::string& header, const std::string& key, const std::string& line)
{
  const std::size_t at = header.find("\n" + key) + 1;
  const std::size_t end = header.find('\n', at) + 1;
  return header.substr(0, at) + (line.empty() ? "" : line + "\n") + header.substr(end);
}

TEST_F(PcdHeader, AcceptsValidHeaders)
{
  EXPECT_EQ(problemOf(kTwoPoints), "");
  EXPECT_EQ(problemOf(pcd("binary", 2, std::string(24, '\0'))), "");
  EXPECT_EQ(problemOf(replaceLine(kTwoPoints, "COUNT", "")), "") << "COUNT optional";
  EXPECT_EQ(problemOf(replaceLine(kTwoPoints, "FIELDS", "COLUMNS x y z")), "");
  EXPECT_EQ(problemOf(pcd("binary_compressed", 0, "")), "");
}

TEST_F(PcdHeader, RefusesWhatIsNotAPcdHeader)
{
  EXPECT_EQ(problemOf("hello world\n"),
            "not a PCD file (unexpected header line 'hello world')");
  EXPECT_EQ(problemOf("# only a comment\n"),
            "not a PCD file (no DATA line in the header)");
  EXPECT_EQ(problemOf("VERSION 0.7\nFIELDS x\001 y\n"),
            "not a PCD file (binary data in the header, line 2)");
  EXPECT_EQ(problemOf(replaceLine(kTwoPoints, "DATA", "")),
            "not a PCD file (unexpected header line '1 2 3')");
}

TEST_F(PcdHeader, RefusesInconsistentHeaders)
{
  EXPECT_EQ(problemOf(replaceLine(kTwoPoints, "FIELDS", "")),
            "invalid PCD header: no FIELDS line");
  EXPECT_EQ(problemOf(replaceLine(kTwoPoints, "SIZE", "SIZE 4 3 4")),
            "invalid PCD header: field size 3 in SIZE");
  EXPECT_EQ(problemOf(replaceLine(kTwoPoints, "SIZE", "SIZE 4 four 4")),
            "invalid PCD header: bad SIZE line");
  EXPECT_EQ(problemOf(replaceLine(kTwoPoints, "TYPE", "TYPE F X F")),
            "invalid PCD header: field type 'X' in TYPE");
  EXPECT_EQ(problemOf(replaceLine(kTwoPoints, "COUNT", "COUNT 1 -1 1")),
            "invalid PCD header: bad COUNT line");
  EXPECT_EQ(problemOf(replaceLine(kTwoPoints, "SIZE", "SIZE 4 4")),
            "invalid PCD header: FIELDS, SIZE, TYPE and COUNT disagree");
  EXPECT_EQ(problemOf(replaceLine(kTwoPoints, "COUNT", "COUNT 1 1")),
            "invalid PCD header: FIELDS, SIZE, TYPE and COUNT disagree");
  EXPECT_EQ(problemOf(replaceLine(kTwoPoints, "WIDTH", "")),
            "invalid PCD header: no WIDTH line");
  EXPECT_EQ(problemOf(replaceLine(kTwoPoints, "POINTS", "")),
            "invalid PCD header: no POINTS line");
  EXPECT_EQ(problemOf(replaceLine(kTwoPoints, "WIDTH", "WIDTH -2")),
            "invalid PCD header: bad WIDTH line");
  EXPECT_EQ(problemOf(replaceLine(kTwoPoints, "HEIGHT", "HEIGHT 1 1")),
            "invalid PCD header: bad HEIGHT line");
  EXPECT_EQ(problemOf(replaceLine(kTwoPoints, "POINTS", "POINTS 3")),
            "invalid PCD header: WIDTH x HEIGHT differs from POINTS");
  EXPECT_EQ(problemOf(pcd("text", 2, "")),
            "invalid PCD header: unknown DATA type 'text'");
}

TEST_F(PcdHeader, RefusesTruncatedData)
{
  EXPECT_EQ(problemOf(pcd("binary", 10, std::string(12 * 9, '\0'))),
            "PCD data is truncated (the header announces 10 points)");
  EXPECT_EQ(problemOf(pcd("binary", 10, std::string(12 * 10, '\0'))), "");
  EXPECT_EQ(problemOf(pcd("binary_compressed", 10, "1234567")),
            "PCD data is truncated (no compressed block)");
}

TEST_F(CloudInput, LoadsAnAsciiPcdWithItsViewpoint)
{
  const std::string p =
    write("two.PCD", replaceLine(kTwoPoints, "VIEWPOINT", "VIEWPOINT 1 2 3 1 0 0 0"));
  pcl::PCLPointCloud2 cloud;
  Eigen::Vector4f origin;
  Eigen::Quaternionf orientation;
  std::string error;
  ASSERT_TRUE(vt::loadCloud(p, cloud, origin, orientation, error)) << error;
  EXPECT_EQ(cloud.width * cloud.height, 2u);
  EXPECT_EQ(pcl::getFieldsList(cloud), "x y z");
  EXPECT_EQ(origin, Eigen::Vector4f(1, 2, 3, 0));
  pcl::PointCloud<pcl::PointXYZ> xyz;
  vt::toXYZ(cloud, xyz);
  ASSERT_EQ(xyz.size(), 2u);
  EXPECT_EQ(xyz[1].getVector3fMap(), Eigen::Vector3f(4, 5, 6));
}

TEST_F(CloudInput, LoadsABinaryPcdWrittenByPcl)
{
  pcl::PointCloud<pcl::PointXYZ> points;
  points.push_back(pcl::PointXYZ(0.5f, -1.f, 2.f));
  points.push_back(pcl::PointXYZ(3.f, 4.f, 5.f));
  const std::string p = path("b.pcd");
  ASSERT_EQ(pcl::io::savePCDFileBinaryCompressed(p, points), 0);
  pcl::PCLPointCloud2 cloud;
  Eigen::Vector4f origin;
  Eigen::Quaternionf orientation;
  std::string error;
  ASSERT_TRUE(vt::loadCloud(p, cloud, origin, orientation, error)) << error;
  pcl::PointCloud<pcl::PointXYZ> xyz;
  vt::toXYZ(cloud, xyz);
  ASSERT_EQ(xyz.size(), 2u);
  EXPECT_EQ(xyz[0].getVector3fMap(), Eigen::Vector3f(0.5f, -1.f, 2.f));
}

TEST_F(CloudInput, LoadErrorsNameTheFileAndTheProblem)
{
  pcl::PCLPointCloud2 cloud;
  Eigen::Vector4f origin;
  Eigen::Quaternionf orientation;
  auto errorOf = [&](const std::string& p) {
    std::string error;
    EXPECT_FALSE(vt::loadCloud(p, cloud, origin, orientation, error)) << p;
    return error;
  };
  const std::string las = write("c.las", "1 2 3\n");
  EXPECT_EQ(errorOf(las), "'" + las +
                            "': unknown extension '.las' (expected .pcd, .ply, .xyz, "
                            ".txt, .obj, .off or .stl)");
  const std::string xyz = write("c.xyz", "1 2 3\n4 5\n");
  EXPECT_EQ(errorOf(xyz),
            "'" + xyz +
              "': not a valid text cloud: line 2 has 2 columns, line 1 has 3");
  EXPECT_EQ(errorOf(path("none.pcd")), "'" + path("none.pcd") + "': no such file");
  fs::create_directory(path("dir.pcd"));
  EXPECT_EQ(errorOf(path("dir.pcd")), "'" + path("dir.pcd") + "': is a directory");
  const std::string empty = write("empty.ply", "");
  EXPECT_EQ(errorOf(empty), "'" + empty + "': file is empty");
  const std::string text = write("text.pcd", "hello\n");
  EXPECT_EQ(errorOf(text),
            "'" + text + "': not a PCD file (unexpected header line 'hello')");
  const std::string ply = write("bad.ply", "ply\nformat nonsense 1.0\nend_header\n");
  EXPECT_EQ(errorOf(ply), "'" + ply +
                            "': not a valid PLY file (header or data could not be "
                            "parsed)");
}

/** \brief A PCLPointCloud2 of `points` zeroed points with the given fields (offsets
 * and point_step as given). */
pcl::PCLPointCloud2
makeCloud(const std::vector<pcl::PCLPointField>& fields,
          std::uint32_t point_step,
          std::size_t points)
{
  pcl::PCLPointCloud2 c;
  c.fields = fields;
  c.point_step = point_step;
  c.width = static_cast<std::uint32_t>(points);
  c.height = 1;
  c.row_step = point_step * c.width;
  c.data.assign(points * point_step, 0);
  return c;
}

pcl::PCLPointField
field(const std::string& name,
      std::uint32_t offset,
      std::uint8_t datatype,
      std::uint32_t count = 1)
{
  pcl::PCLPointField f;
  f.name = name;
  f.offset = offset;
  f.datatype = datatype;
  f.count = count;
  return f;
}

template <typename T>
void
put(pcl::PCLPointCloud2& c, std::size_t point, std::uint32_t offset, T value)
{
  std::memcpy(c.data.data() + point * c.point_step + offset, &value, sizeof(T));
}

TEST(HasXYZ, NamesTheMissingOrNonScalarField)
{
  using F = pcl::PCLPointField;
  std::string problem;
  EXPECT_TRUE(
    vt::hasXYZ(makeCloud({field("x", 0, F::FLOAT32), field("y", 4, F::FLOAT32),
                          field("z", 8, F::FLOAT32)},
                         12, 1),
               problem));
  EXPECT_FALSE(vt::hasXYZ(
    makeCloud({field("x", 0, F::FLOAT32), field("y", 4, F::FLOAT32)}, 8, 1), problem));
  EXPECT_EQ(problem, "no 'z' field (fields: x y)");
  EXPECT_FALSE(
    vt::hasXYZ(makeCloud({field("x", 0, F::FLOAT32, 3), field("y", 12, F::FLOAT32),
                          field("z", 16, F::FLOAT32)},
                         20, 1),
               problem));
  EXPECT_EQ(problem, "field 'x' is not a scalar");
}

TEST(ReadScalar, ReadsEveryDatatype)
{
  using F = pcl::PCLPointField;
  std::uint8_t bytes[8];
  auto read = [&](auto value, std::uint8_t datatype) {
    std::memcpy(bytes, &value, sizeof(value));
    return vt::readScalar(bytes, datatype);
  };
  EXPECT_EQ(read(std::int8_t{-5}, F::INT8), -5.0);
  EXPECT_EQ(read(std::uint8_t{250}, F::UINT8), 250.0);
  EXPECT_EQ(read(std::int16_t{-300}, F::INT16), -300.0);
  EXPECT_EQ(read(std::uint16_t{60000}, F::UINT16), 60000.0);
  EXPECT_EQ(read(std::int32_t{-70000}, F::INT32), -70000.0);
  EXPECT_EQ(read(std::uint32_t{4000000000u}, F::UINT32), 4000000000.0);
  EXPECT_EQ(read(1.5f, F::FLOAT32), 1.5);
  EXPECT_EQ(read(-2.25, F::FLOAT64), -2.25);
  EXPECT_TRUE(std::isnan(read(std::int32_t{1}, 0)));
  EXPECT_TRUE(std::isnan(read(std::int32_t{1}, 99)));
}

TEST(ToXYZ, ConvertsDoubleCoordinatesAndMarksNaN)
{
  using F = pcl::PCLPointField;
  pcl::PCLPointCloud2 c = makeCloud(
    {field("x", 0, F::FLOAT64), field("y", 8, F::FLOAT64), field("z", 16, F::INT16)},
    18, 2);
  put(c, 0, 0, 1.25);
  put(c, 0, 8, -2.5);
  put(c, 0, 16, std::int16_t{7});
  put(c, 1, 0, std::nan(""));
  pcl::PointCloud<pcl::PointXYZ> xyz;
  vt::toXYZ(c, xyz);
  ASSERT_EQ(xyz.size(), 2u);
  EXPECT_EQ(xyz.width, 2u);
  EXPECT_EQ(xyz[0].getVector3fMap(), Eigen::Vector3f(1.25f, -2.5f, 7.f));
  EXPECT_TRUE(std::isnan(xyz[1].x));
  EXPECT_FALSE(xyz.is_dense);
}

// Survey coordinates: the offset is subtracted in double before the cast to float.
TEST(Recentring, FarCloudsAreMovedByARoundOffsetBeforeTheCastToFloat)
{
  using F = pcl::PCLPointField;
  const std::vector<pcl::PCLPointField> fields{
    field("x", 0, F::FLOAT64), field("y", 8, F::FLOAT64), field("z", 16, F::FLOAT64)};
  // a part 10 m across near (512345, 4312345, 120), millimetre digits
  pcl::PCLPointCloud2 c = makeCloud(fields, 24, 3);
  const double points[3][3] = {{512341.501, 4312341.252, 115.503},
                               {512350.499, 4312350.748, 124.497},
                               {512345.123, 4312345.456, 120.789}};
  for (std::size_t i = 0; i < 3; ++i)
    for (std::uint32_t a = 0; a < 3; ++a)
      put(c, i, 8 * a, points[i][a]);
  const Eigen::Vector3d offset = vt::recentringOffset(c);
  EXPECT_EQ(offset, Eigen::Vector3d(512350.0, 4312350.0, 120.0));
  pcl::PointCloud<pcl::PointXYZ> xyz;
  vt::toXYZ(c, xyz, offset);
  for (std::size_t i = 0; i < 3; ++i)
    for (int a = 0; a < 3; ++a)
      EXPECT_NEAR(double(xyz[i].data[a]) + offset[a], points[i][a], 1e-5)
        << "point " << i << " axis " << a;
  // without the offset the float cast loses the millimetres (0.5 m steps at 4e6)
  pcl::PointCloud<pcl::PointXYZ> lossy;
  vt::toXYZ(c, lossy);
  EXPECT_GT(std::abs(double(lossy[0].y) - points[0][1]), 1e-3);

  // near the origin (within 16 extents): nothing moves
  pcl::PCLPointCloud2 near = makeCloud(fields, 24, 2);
  put(near, 0, 0, 30.0);
  put(near, 1, 0, 32.0);
  EXPECT_EQ(vt::recentringOffset(near), Eigen::Vector3d::Zero());
  put(near, 0, 0, 40.0);
  put(near, 1, 0, 41.2);
  EXPECT_EQ(vt::recentringOffset(near), Eigen::Vector3d(40.0, 0.0, 0.0));
  // no finite point: zero
  pcl::PCLPointCloud2 none = makeCloud(fields, 24, 1);
  put(none, 0, 0, std::nan(""));
  EXPECT_EQ(vt::recentringOffset(none), Eigen::Vector3d::Zero());
}

TEST(WithoutFields, RemovesFieldsAndPaddingAndPacksTheRest)
{
  using F = pcl::PCLPointField;
  // x, label, y, padding, z: 4 + 4 + 4 + 4 + 4 bytes.
  pcl::PCLPointCloud2 c =
    makeCloud({field("z", 16, F::FLOAT32), field("x", 0, F::FLOAT32),
               field("label", 4, F::UINT32), field("y", 8, F::FLOAT32),
               field("_", 12, F::UINT8, 4)},
              20, 2);
  for (std::size_t i = 0; i < 2; ++i) {
    put(c, i, 0, 1.f + i);
    put(c, i, 4, std::uint32_t{99});
    put(c, i, 8, 10.f + i);
    put(c, i, 16, 100.f + i);
  }
  const pcl::PCLPointCloud2 out = vt::withoutFields(c, {"label"});
  EXPECT_EQ(pcl::getFieldsList(out), "x y z");
  EXPECT_EQ(out.point_step, 12u);
  EXPECT_EQ(out.row_step, 24u);
  ASSERT_EQ(out.data.size(), 24u);
  pcl::PointCloud<pcl::PointXYZ> xyz;
  vt::toXYZ(out, xyz);
  ASSERT_EQ(xyz.size(), 2u);
  EXPECT_EQ(xyz[1].getVector3fMap(), Eigen::Vector3f(2.f, 11.f, 101.f));

  const pcl::PCLPointCloud2 same = vt::withoutFields(c, {"absent"});
  EXPECT_EQ(pcl::getFieldsList(same), pcl::getFieldsList(c))
    << "unchanged, padding too";
  EXPECT_EQ(same.point_step, 20u);
  EXPECT_EQ(same.data, c.data);
}

} // namespace
