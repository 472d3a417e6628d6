// Unit tests of common/arguments.h: the command line, strict numbers, lists,
// extensions.

#include "common/arguments.h"

#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <vector>

namespace vt = visfeat_tools;

namespace {

/** \brief Arguments of a command line given as words (the program name first). */
vt::Arguments
parse(std::vector<std::string> words)
{
  std::vector<char*> argv;
  for (std::string& w : words)
    argv.push_back(w.data());
  argv.push_back(nullptr);
  return vt::Arguments(static_cast<int>(words.size()), argv.data(),
                       {"-resolution", "-opacity", "-voxels"}, {"-q", "-raw"});
}

TEST(Arguments, SplitsPositionalsOptionsAndSwitches)
{
  const vt::Arguments args =
    parse({"tool", "in.pcd", "-resolution", "64", "-q", "out.pcd"});
  ASSERT_TRUE(args.ok()) << args.error();
  EXPECT_EQ(args.error(), "");
  EXPECT_EQ(args.positional(), (std::vector<std::string>{"in.pcd", "out.pcd"}));
  EXPECT_TRUE(args.has("-resolution"));
  EXPECT_EQ(args.value("-resolution"), "64");
  EXPECT_TRUE(args.has("-q"));
  EXPECT_EQ(args.value("-q"), "");
  EXPECT_FALSE(args.has("-raw"));
  EXPECT_FALSE(args.has("-opacity"));
  EXPECT_EQ(args.value("-opacity"), "");
}

TEST(Arguments, RefusesAnUnknownOption)
{
  const vt::Arguments args = parse({"tool", "in.pcd", "-bogus", "out.pcd"});
  EXPECT_FALSE(args.ok());
  EXPECT_EQ(args.error(), "unknown option -bogus (see -h)");
}

TEST(Arguments, RefusesAnOptionWithoutItsValue)
{
  const vt::Arguments args = parse({"tool", "in.pcd", "-resolution"});
  EXPECT_FALSE(args.ok());
  EXPECT_EQ(args.error(), "option -resolution needs a value");
}

TEST(Arguments, TakesTheNextWordAsTheValueEvenWhenItLooksLikeAnOption)
{
  const vt::Arguments args = parse({"tool", "-voxels", "-q"});
  ASSERT_TRUE(args.ok()) << args.error();
  EXPECT_EQ(args.value("-voxels"), "-q");
  EXPECT_FALSE(args.has("-q"));
}

TEST(Arguments, NegativeNumbersAndDashAreArgumentsNotOptions)
{
  const vt::Arguments args = parse({"tool", "-5", "-.5", "-"});
  ASSERT_TRUE(args.ok()) << args.error();
  EXPECT_EQ(args.positional(), (std::vector<std::string>{"-5", "-.5", "-"}));
}

TEST(Arguments, TheLastOfARepeatedOptionWins)
{
  const vt::Arguments args = parse({"tool", "-resolution", "64", "-resolution", "128"});
  ASSERT_TRUE(args.ok()) << args.error();
  EXPECT_EQ(args.value("-resolution"), "128");
}

TEST(Arguments, GetIntegerChecksTypeAndRange)
{
  std::string error;
  int value = 7;
  EXPECT_TRUE(parse({"tool"}).getInteger("-resolution", 4, 8192, value, error));
  EXPECT_EQ(value, 7) << "an absent option leaves the value untouched";
  EXPECT_EQ(error, "");

  EXPECT_TRUE(parse({"tool", "-resolution", "256"})
                .getInteger("-resolution", 4, 8192, value, error));
  EXPECT_EQ(value, 256);

  EXPECT_FALSE(parse({"tool", "-resolution", "12a"})
                 .getInteger("-resolution", 4, 8192, value, error));
  EXPECT_EQ(error, "-resolution expects an integer, got '12a'");
  EXPECT_EQ(value, 256);

  EXPECT_FALSE(parse({"tool", "-resolution", "3"})
                 .getInteger("-resolution", 4, 8192, value, error));
  EXPECT_EQ(error, "-resolution must be in [4, 8192], got 3");

  EXPECT_FALSE(parse({"tool", "-resolution", "-1"})
                 .getInteger("-resolution", 4, 8192, value, error));
  EXPECT_EQ(error, "-resolution must be in [4, 8192], got -1");
  EXPECT_EQ(value, 256);
}

TEST(Arguments, GetRealChecksTypeAndRange)
{
  std::string error;
  double value = 0.25;
  EXPECT_TRUE(parse({"tool"}).getReal("-opacity", 0.0, 6.0, value, error));
  EXPECT_EQ(value, 0.25);

  EXPECT_TRUE(
    parse({"tool", "-opacity", "1.5"}).getReal("-opacity", 0.0, 6.0, value, error));
  EXPECT_EQ(value, 1.5);

  EXPECT_FALSE(
    parse({"tool", "-opacity", "abc"}).getReal("-opacity", 0.0, 6.0, value, error));
  EXPECT_EQ(error, "-opacity expects a number, got 'abc'");

  EXPECT_FALSE(
    parse({"tool", "-opacity", "nan"}).getReal("-opacity", 0.0, 6.0, value, error));
  EXPECT_EQ(error, "-opacity expects a number, got 'nan'");

  EXPECT_FALSE(
    parse({"tool", "-opacity", "7.5"}).getReal("-opacity", 0.0, 6.0, value, error));
  EXPECT_EQ(error, "-opacity must be in [0, 6], got 7.5");
  EXPECT_EQ(value, 1.5);
}

TEST(ParseInteger, AcceptsWholeBase10Integers)
{
  long long v = 0;
  EXPECT_TRUE(vt::parseInteger("42", v));
  EXPECT_EQ(v, 42);
  EXPECT_TRUE(vt::parseInteger("-7", v));
  EXPECT_EQ(v, -7);
  EXPECT_TRUE(vt::parseInteger("+5", v));
  EXPECT_EQ(v, 5);
  EXPECT_TRUE(vt::parseInteger("007", v));
  EXPECT_EQ(v, 7) << "base 10, not octal";
  EXPECT_TRUE(vt::parseInteger("9223372036854775807", v));
  EXPECT_EQ(v, std::numeric_limits<long long>::max());
}

TEST(ParseInteger, RefusesAnythingElseAndLeavesTheValue)
{
  for (const char* text : {"", " 1", "1 ", "1.0", "0x10", "1e3", "abc", "--1",
                           "9223372036854775808", "-9223372036854775809"}) {
    long long v = 99;
    EXPECT_FALSE(vt::parseInteger(text, v)) << "'" << text << "'";
    EXPECT_EQ(v, 99) << "'" << text << "'";
  }
}

TEST(ParseReal, AcceptsFiniteNumbers)
{
  double v = 0.0;
  EXPECT_TRUE(vt::parseReal("1e3", v));
  EXPECT_EQ(v, 1000.0);
  EXPECT_TRUE(vt::parseReal("-0.5", v));
  EXPECT_EQ(v, -0.5);
  EXPECT_TRUE(vt::parseReal(".25", v));
  EXPECT_EQ(v, 0.25);
  EXPECT_TRUE(vt::parseReal("3", v));
  EXPECT_EQ(v, 3.0);
}

TEST(ParseReal, RefusesNonFiniteOverflowAndTrailingText)
{
  for (const char* text :
       {"", " 1", "1 ", "1x", "nan", "inf", "-inf", "1e999", ".", "1,5"}) {
    double v = 99.0;
    EXPECT_FALSE(vt::parseReal(text, v)) << "'" << text << "'";
    EXPECT_EQ(v, 99.0) << "'" << text << "'";
  }
}

TEST(SplitList, KeepsEmptyItems)
{
  using List = std::vector<std::string>;
  EXPECT_EQ(vt::splitList("a,b,c"), (List{"a", "b", "c"}));
  EXPECT_EQ(vt::splitList("one"), (List{"one"}));
  EXPECT_EQ(vt::splitList(""), List{});
  EXPECT_EQ(vt::splitList("a,,b"), (List{"a", "", "b"}));
  EXPECT_EQ(vt::splitList("a,"), (List{"a", ""}));
  EXPECT_EQ(vt::splitList(",a"), (List{"", "a"}));
}

TEST(LowerExtension, IsTheLastExtensionInLowerCase)
{
  EXPECT_EQ(vt::lowerExtension("dir/Model.PCD"), ".pcd");
  EXPECT_EQ(vt::lowerExtension("cloud.ply"), ".ply");
  EXPECT_EQ(vt::lowerExtension("archive.tar.GZ"), ".gz");
  EXPECT_EQ(vt::lowerExtension("noext"), "");
  EXPECT_EQ(vt::lowerExtension("dir.d/file"), "");
  EXPECT_EQ(vt::lowerExtension(".hidden"), "");
  EXPECT_EQ(vt::lowerExtension(""), "");
}

} // namespace
