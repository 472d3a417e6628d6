// The picture options of the visfeat tool (-png, -png_radius, -png_size): reading and
// checking them before any work, their help lines, and the X display that VTK renders
// through. Not installed, not public API; rendering itself is in render_picture.h.
//
// Debian's VTK 9 is built for X only (no OSMesa, no EGL), so even offscreen it needs an
// X display: a headless machine runs the tool under `xvfb-run -a` (package xvfb).
#pragma once

#include "common/arguments.h"

#include <string>
#include <vector>

namespace visfeat_tools {

/** \brief Range of a picture's width and height, in pixels. */
constexpr int kMinPictureSize = 64;
constexpr int kMaxPictureSize = 8192;

/** \brief The tool's picture options: -png, -png_radius, -png_size. */
struct PictureRequests
{
  /** \brief -png: classes and graph; "" = none. */
  std::string classes;
  /** \brief -png_radius: the visibility map; "" = none. */
  std::string radius;
  int width = 1024;
  int height = 768;

  /** \brief The requested files (0, 1 or 2). */
  std::vector<std::string> paths() const;
};

/** \brief Print the help lines of the picture options. */
void printPictureHelp();

/** \brief Parse "WxH" (e.g. "800x600") into width and height, each in
 * [kMinPictureSize, kMaxPictureSize]; both untouched on failure. */
bool
parsePictureSize(const std::string& text, int& width, int& height, std::string& error);

/** \brief Read and check the picture options before any work: .png names, writable,
 * different from each other and from `other_outputs`, and rendering possible here
 * (checkPictureSupport). On failure `error` is one line. */
bool parsePictureRequests(const Arguments& args,
                          const std::vector<std::string>& other_outputs,
                          PictureRequests& requests,
                          std::string& error);

/** \brief True when this build of the tool can render pictures (PCL's visualization
 * module was found at configure time). */
bool picturesCompiledIn();

/** \brief Check, before any work, that pictures can be rendered here: compiled in and
 * an X display can be opened. On failure `error` is one line saying how to fix it. */
bool checkPictureSupport(std::string& error);

/** \brief The X connection (an Xlib `Display*`) every picture renders through, opened
 * once and kept open until the process exits; nullptr when none could be opened, and
 * then `why` says why.
 *
 * Xlib is loaded at run time (VTK loads it anyway), so the tool needs no X headers.
 * VTK 9.1 calls abort() when it cannot open a display, so this is checked before VTK
 * is touched. Sharing one connection matters under xvfb-run: an X server resets when
 * its last client disconnects, and a window opened during the reset finds no server
 * (VTK aborts on the second picture). */
void* xDisplay(std::string& why);

} // namespace visfeat_tools
