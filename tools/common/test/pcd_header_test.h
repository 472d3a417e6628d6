// The fixture of the PCD header check's tests (test_cloud_input, test_input_guards).
#pragma once

#include "common/pcd_check.h"
#include "temp_dir.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace visfeat_tools {
namespace test {

/** \brief checkPcdHeader() on `content` written to a file: "" when it passes, else
 * the problem (which must not be empty). */
class PcdHeaderTest : public TempDirTest
{
protected:
  std::string problemOf(const std::string& content)
  {
    const std::string p = write("h.pcd", content);
    std::string problem;
    if (checkPcdHeader(p, std::filesystem::file_size(p), problem))
      return "";
    EXPECT_NE(problem, "");
    return problem;
  }
};

} // namespace test
} // namespace visfeat_tools
