// The picture options of the visfeat tool; see picture_requests.h.

#include "picture/picture_requests.h"

#include "common/output_files.h"

#include <pcl/console/print.h>

#include <algorithm>
#include <cstdlib>

#include <dlfcn.h>

namespace visfeat_tools {

std::vector<std::string>
PictureRequests::paths() const
{
  std::vector<std::string> out;
  for (const std::string& p : {classes, radius})
    if (!p.empty())
      out.push_back(p);
  return out;
}

void
printPictureHelp()
{
  using namespace pcl::console;
  print_info("    -png out.png      = also render a picture: vertices red, edges blue, "
             "faces pastel, with the topology graph\n");
  print_info(
    "    -png_radius out.png = also render the visibility map (blue = smallest "
    "radius, red = max_radius)\n");
  print_info("    -png_size WxH     = size of the pictures (default: ");
  print_value("1024x768");
  print_info(" pixels)\n");
  print_info("  Pictures are rendered offscreen with VTK, which needs an X display: "
             "on a headless machine run under xvfb-run -a.%s\n",
             picturesCompiledIn() ? "" : " (Not available in this build.)");
}

bool
parsePictureSize(const std::string& text, int& width, int& height, std::string& error)
{
  const std::size_t x = text.find_first_of("xX");
  auto number = [](const std::string& s, int& value) {
    if (s.empty() || s.size() > 5 ||
        !std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; }))
      return false;
    value = std::stoi(s);
    return value >= kMinPictureSize && value <= kMaxPictureSize;
  };
  int w = 0, h = 0;
  if (x == std::string::npos || !number(text.substr(0, x), w) ||
      !number(text.substr(x + 1), h)) {
    error = "-png_size '" + text + "' must be WIDTHxHEIGHT, each " +
            std::to_string(kMinPictureSize) + "-" + std::to_string(kMaxPictureSize) +
            " pixels (e.g. 800x600)";
    return false;
  }
  width = w;
  height = h;
  return true;
}

bool
parsePictureRequests(const Arguments& args,
                     const std::vector<std::string>& other_outputs,
                     PictureRequests& requests,
                     std::string& error)
{
  requests = PictureRequests();
  if (args.has("-png_size") &&
      !parsePictureSize(args.value("-png_size"), requests.width, requests.height,
                        error))
    return false;
  for (const char* option : {"-png", "-png_radius"}) {
    if (!args.has(option))
      continue;
    const std::string path = args.value(option);
    if (path.empty()) {
      error = std::string(option) + " needs a file name";
      return false;
    }
    if (lowerExtension(path) != ".png") {
      error = "picture '" + path + "' must have the extension .png";
      return false;
    }
    for (const std::string& other : other_outputs)
      if (sameFile(path, other)) {
        error =
          std::string("the ") + option + " file must differ from the other outputs";
        return false;
      }
    if (!checkWritable(path, error))
      return false;
    (std::string(option) == "-png" ? requests.classes : requests.radius) = path;
  }
  if (!requests.classes.empty() && sameFile(requests.classes, requests.radius)) {
    error = "the -png and -png_radius files must differ";
    return false;
  }
  if (requests.paths().empty())
    return true;
  return checkPictureSupport(error);
}

bool
picturesCompiledIn()
{
#ifdef VISFEAT_HAVE_PICTURES
  return true;
#else
  return false;
#endif
}

bool
checkPictureSupport(std::string& error)
{
  if (!picturesCompiledIn()) {
    error = "this visfeat was built without PCL's visualization module (VTK), so it "
            "cannot write pictures; install libpcl-dev with VTK and rebuild";
    return false;
  }
  std::string why;
  if (xDisplay(why) == nullptr) {
    error = "cannot render pictures: " + why +
            "; VTK here needs an X display even offscreen: run under xvfb-run -a "
            "(Debian package xvfb)";
    return false;
  }
  return true;
}

void*
xDisplay(std::string& why)
{
  static std::string problem;
  static void* const display = []() -> void* {
    const char* name = std::getenv("DISPLAY");
    if (name == nullptr || *name == '\0') {
      problem = "no X display (DISPLAY is not set)";
      return nullptr;
    }
    void* xlib = dlopen("libX11.so.6", RTLD_NOW | RTLD_GLOBAL);
    if (xlib == nullptr) {
      problem = "libX11.so.6 cannot be loaded";
      return nullptr;
    }
    using OpenDisplay = void* (*)(const char*);
    const auto open_display =
      reinterpret_cast<OpenDisplay>(dlsym(xlib, "XOpenDisplay"));
    if (open_display == nullptr) {
      problem = "libX11.so.6 has no XOpenDisplay";
      return nullptr;
    }
    void* connection = open_display(nullptr);
    if (connection == nullptr)
      problem = std::string("cannot open the X display '") + name + "'";
    return connection;
  }();
  why = problem;
  return display;
}

} // namespace visfeat_tools
