// Unit tests of common/progress_printer.h: the lines the tool prints while the map
// runs, written to a temporary stream with no delay.

#include "common/progress_printer.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

namespace vt = visfeat_tools;

namespace {

/** Everything written to \a f so far. */
std::string
written(std::FILE* f)
{
  std::fflush(f);
  std::rewind(f);
  std::string text;
  for (int c = std::fgetc(f); c != EOF; c = std::fgetc(f))
    text.push_back(static_cast<char>(c));
  return text;
}

TEST(ProgressPrinter, NamesEachMapAfterTheFirst)
{
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  {
    vt::ProgressPrinter progress(f, false, 0.0);
    progress(0, 100);
    progress(100, 100); // the first map ends
    progress(0, 400);   // the search's map at the next resolution
    progress(400, 400);
    progress(0, 1600);
    progress(1600, 1600);
    progress.finish();
  }
  const std::string text = written(f);
  std::fclose(f);
  EXPECT_NE(text.find("visibility map: 100% (100 / 100 cells"), std::string::npos)
    << text;
  // the start of a map within 0.5 s of the last line is not printed, its end is
  EXPECT_NE(text.find("visibility map 2, another resolution: 100% (400 / 400 cells"),
            std::string::npos)
    << text;
  EXPECT_NE(text.find("visibility map 3, another resolution: 100% (1600 / 1600 cells"),
            std::string::npos)
    << text;
  EXPECT_EQ(text.find("visibility map: 100% (400"), std::string::npos) << text;
}

TEST(ProgressPrinter, OneMapKeepsItsPlainName)
{
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  {
    vt::ProgressPrinter progress(f, false, 0.0);
    progress(0, 100);
    progress(100, 100);
    progress(100, 100); // the estimator's closing call repeats done == total
    progress.finish();
  }
  const std::string text = written(f);
  std::fclose(f);
  const std::size_t end = text.find("visibility map: 100%");
  EXPECT_NE(end, std::string::npos) << text;
  EXPECT_EQ(text.find("visibility map: 100%", end + 1), std::string::npos)
    << "the end of a map printed twice:\n"
    << text;
  EXPECT_EQ(text.find("another resolution"), std::string::npos) << text;
}

TEST(ProgressPrinter, SilentBeforeItsDelay)
{
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  {
    vt::ProgressPrinter progress(f, false, 3600.0);
    progress(0, 100);
    progress(100, 100);
    progress.finish();
  }
  EXPECT_EQ(written(f), "");
  std::fclose(f);
}

} // namespace
