// Unit tests of common/text_cloud_input.h: .xyz / .txt clouds in double precision,
// header lines, and one clear line for every bad file.

#include "common/text_cloud_input.h"

#include "common/cloud_input.h"

#include <pcl/common/io.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

namespace vt = visfeat_tools;

namespace {

/** \brief The cloud read from `text`; fails the test when it is refused. */
pcl::PCLPointCloud2
read(const std::string& text)
{
  std::istringstream in(text);
  pcl::PCLPointCloud2 cloud;
  std::string problem;
  EXPECT_TRUE(vt::readTextCloud(in, cloud, problem)) << problem;
  return cloud;
}

/** \brief The problem readTextCloud() reports for `text` ("" when it is accepted). */
std::string
problemOf(const std::string& text)
{
  std::istringstream in(text);
  pcl::PCLPointCloud2 cloud;
  std::string problem;
  if (vt::readTextCloud(in, cloud, problem))
    return "";
  return problem;
}

double
value(const pcl::PCLPointCloud2& c, std::size_t point, const std::string& name)
{
  const int f = pcl::getFieldIndex(c, name);
  EXPECT_GE(f, 0) << name;
  if (f < 0)
    return std::nan("");
  const auto& field = c.fields[static_cast<std::size_t>(f)];
  EXPECT_EQ(field.datatype, pcl::PCLPointField::FLOAT64) << name;
  double v = 0.0;
  std::memcpy(&v, c.data.data() + point * c.point_step + field.offset, sizeof(v));
  return v;
}

TEST(TextCloud, ReadsSurveyCoordinatesInDoublePrecision)
{
  const pcl::PCLPointCloud2 c = read("512345.678 4312345.123 120.456\n"
                                     "  512345.679\t4312345.124   120.457  \r\n"
                                     "\n"
                                     "# a comment\n"
                                     "512345.680,4312345.125,120.458\n");
  ASSERT_EQ(c.width, 3u);
  EXPECT_EQ(c.height, 1u);
  EXPECT_EQ(pcl::getFieldsList(c), "x y z");
  EXPECT_EQ(value(c, 0, "x"), 512345.678);
  EXPECT_EQ(value(c, 1, "y"), 4312345.124);
  EXPECT_EQ(value(c, 2, "z"), 120.458);
  EXPECT_TRUE(c.is_dense);
  std::string problem;
  EXPECT_TRUE(vt::hasXYZ(c, problem)) << problem;
}

TEST(TextCloud, HeaderLinesNameTheColumns)
{
  const pcl::PCLPointCloud2 named =
    read("//X,Y,Z,R,G,B\n1,2,3,255,0,0\n4,5,6,0,255,0\n");
  EXPECT_EQ(pcl::getFieldsList(named), "x y z r g b");
  EXPECT_EQ(value(named, 1, "g"), 255.0);
  const pcl::PCLPointCloud2 words = read("Z Y X Intensity\n1 2 3 0.5\n");
  EXPECT_EQ(pcl::getFieldsList(words), "z y x intensity");
  EXPECT_EQ(value(words, 0, "x"), 3.0);
  // without a header: x y z, then the columns by number; a first comment is no header
  const pcl::PCLPointCloud2 plain = read("# exported\n1 2 3 4 5\n");
  EXPECT_EQ(pcl::getFieldsList(plain), "x y z column_4 column_5");
  EXPECT_EQ(value(plain, 0, "column_5"), 5.0);
  // NaN points are kept (the estimator skips them), the cloud is then not dense
  const pcl::PCLPointCloud2 nan = read("nan nan nan\n1 2 3\n");
  EXPECT_FALSE(nan.is_dense);
  EXPECT_TRUE(std::isnan(value(nan, 0, "x")));
}

TEST(TextCloud, EveryBadFileGetsOneLine)
{
  EXPECT_EQ(problemOf(""), "no points (a text cloud has one point a line: x y z ...)");
  EXPECT_EQ(problemOf("# only a comment\n\n"),
            "no points (a text cloud has one point a line: x y z ...)");
  EXPECT_EQ(problemOf("x y z\n"),
            "no points (a text cloud has one point a line: x y z ...)");
  EXPECT_EQ(problemOf("1 2\n3 4\n"),
            "line 1 has 2 columns, expected at least 3 (x y z)");
  EXPECT_EQ(problemOf("1 2 3\n4 5 6 7\n"), "line 2 has 4 columns, line 1 has 3");
  EXPECT_EQ(problemOf("x y z\n1 2\n"), "line 2 has 2 columns, line 1 has 3");
  EXPECT_EQ(problemOf("1 2 3\n4 abc 6\n"), "line 2: 'abc' is not a number");
  EXPECT_EQ(problemOf("1 2 3\n4 5 1e999\n"), "line 2: '1e999' is not a number");
  EXPECT_EQ(problemOf("1 2 3\n4 5 6x\n"), "line 2: '6x' is not a number");
  EXPECT_EQ(problemOf("a b c\n1 2 3\n"),
            "line 1: 'a' is not a number, and the line is no header naming x, y and z "
            "(no 'x')");
  EXPECT_EQ(problemOf("x y y\n1 2 3\n"),
            "line 1: column 'y' is named twice in the header line");
  EXPECT_EQ(problemOf(std::string("\x89PNG\r\n\x1a\n\0\0\0", 11)),
            "line 1: '?PNG' is not a number (binary data: not a text cloud)");
  EXPECT_EQ(problemOf("1 2 3\nx y z\n"), "line 2: 'x' is not a number");
}

TEST(TextCloud, Extensions)
{
  EXPECT_TRUE(vt::isTextCloudFile("a.xyz"));
  EXPECT_TRUE(vt::isTextCloudFile("dir/A.TXT"));
  EXPECT_FALSE(vt::isTextCloudFile("a.pcd"));
  EXPECT_FALSE(vt::isTextCloudFile("a.csv"));
}

} // namespace
