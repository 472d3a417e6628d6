// A fresh directory under the system's temporary directory for one test, removed with
// everything in it when the test ends.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

namespace visfeat_tools {
namespace test {

class TempDirTest : public ::testing::Test
{
protected:
  void SetUp() override
  {
    std::string pattern =
      (std::filesystem::temp_directory_path() / "visfeat_tool_common.XXXXXX").string();
    ASSERT_NE(mkdtemp(pattern.data()), nullptr) << "cannot create " << pattern;
    dir_ = pattern;
  }

  void TearDown() override
  {
    std::error_code ec;
    std::filesystem::permissions(dir_, std::filesystem::perms::owner_all,
                                 std::filesystem::perm_options::add, ec);
    std::filesystem::remove_all(dir_, ec);
  }

  /** \brief The path of `name` in the test's directory. */
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  /** \brief Write `content` (bytes, as given) to `name` in the test's directory and
   * return its path. */
  std::string write(const std::string& name, const std::string& content) const
  {
    const std::string p = path(name);
    std::ofstream out(p, std::ios::binary | std::ios::trunc);
    out << content;
    return p;
  }

  std::filesystem::path dir_;
};

} // namespace test
} // namespace visfeat_tools
