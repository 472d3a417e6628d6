// Unit tests of common/output_files.h: temporary names, the writability check, commit
// and discard.

#include "common/output_files.h"

#include "temp_dir.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <unistd.h>

namespace fs = std::filesystem;
namespace vt = visfeat_tools;

namespace {

using OutputFiles = vt::test::TempDirTest;

std::string
contents(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST(TemporaryPath, AppendsTmp)
{
  EXPECT_EQ(vt::temporaryPath("out/cloud.pcd"), "out/cloud.pcd.tmp");
  EXPECT_EQ(vt::temporaryPath("g.json"), "g.json.tmp");
}

TEST_F(OutputFiles, CheckWritableLeavesNoFileBehind)
{
  const std::string out = path("cloud.pcd");
  std::string error;
  EXPECT_TRUE(vt::checkWritable(out, error)) << error;
  EXPECT_EQ(error, "");
  EXPECT_FALSE(fs::exists(out));
  EXPECT_FALSE(fs::exists(vt::temporaryPath(out)));
}

TEST_F(OutputFiles, CheckWritableKeepsATemporaryFileThatExisted)
{
  const std::string out = path("cloud.pcd");
  write("cloud.pcd.tmp", "earlier");
  std::string error;
  EXPECT_TRUE(vt::checkWritable(out, error)) << error;
  EXPECT_EQ(contents(vt::temporaryPath(out)), "earlier");
}

TEST_F(OutputFiles, CheckWritableRefusesADirectory)
{
  fs::create_directory(path("d.pcd"));
  std::string error;
  EXPECT_FALSE(vt::checkWritable(path("d.pcd"), error));
  EXPECT_EQ(error, "output '" + path("d.pcd") + "' is a directory");
}

TEST_F(OutputFiles, CheckWritableRefusesAMissingDirectory)
{
  const std::string out = path("missing/cloud.pcd");
  std::string error;
  EXPECT_FALSE(vt::checkWritable(out, error));
  EXPECT_EQ(error, "output directory '" + path("missing") + "' of '" + out +
                     "' does not exist");
}

TEST_F(OutputFiles, CheckWritableRefusesAReadOnlyDirectory)
{
  if (geteuid() == 0)
    GTEST_SKIP() << "root writes into read-only directories";
  fs::create_directory(path("ro"));
  fs::permissions(path("ro"), fs::perms::owner_read | fs::perms::owner_exec);
  const std::string out = path("ro/cloud.pcd");
  std::string error;
  EXPECT_FALSE(vt::checkWritable(out, error));
  EXPECT_EQ(error, "cannot write '" + out + "': Permission denied");
}

TEST_F(OutputFiles, CheckWritableRefusesWhenTheTemporaryNameIsTaken)
{
  // A directory in the way of the temporary file: refused even for root.
  fs::create_directory(path("cloud.pcd.tmp"));
  const std::string out = path("cloud.pcd");
  std::string error;
  EXPECT_FALSE(vt::checkWritable(out, error));
  EXPECT_EQ(error, "cannot write '" + out + "': Is a directory");
  EXPECT_TRUE(fs::is_directory(vt::temporaryPath(out))) << "what existed is kept";
}

TEST_F(OutputFiles, CommitMovesTheTemporaryFileIntoPlace)
{
  const std::string out = path("cloud.pcd");
  write("cloud.pcd", "old");
  write("cloud.pcd.tmp", "new");
  std::string error;
  EXPECT_TRUE(vt::commitOutput(out, error)) << error;
  EXPECT_EQ(contents(out), "new");
  EXPECT_FALSE(fs::exists(vt::temporaryPath(out)));
}

TEST_F(OutputFiles, CommitWithoutATemporaryFileFails)
{
  const std::string out = path("cloud.pcd");
  std::string error;
  EXPECT_FALSE(vt::commitOutput(out, error));
  const std::string expected =
    "cannot rename '" + vt::temporaryPath(out) + "' to '" + out + "': ";
  EXPECT_EQ(error.substr(0, expected.size()), expected) << error;
  EXPECT_GT(error.size(), expected.size()) << "the reason is given";
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(OutputFiles, DiscardRemovesOnlyTheTemporaryFile)
{
  const std::string out = path("cloud.pcd");
  write("cloud.pcd", "kept");
  write("cloud.pcd.tmp", "partial");
  vt::discardOutput(out);
  EXPECT_FALSE(fs::exists(vt::temporaryPath(out)));
  EXPECT_EQ(contents(out), "kept");
  vt::discardOutput(out); // nothing left to remove: no error, no exception
  EXPECT_EQ(contents(out), "kept");
}

} // namespace
