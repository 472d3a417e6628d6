// Pictures of a classified cloud for the visfeat tool (-png, -png_radius): the points
// coloured by class (vertex / edge / face) with the topology graph drawn over them, or
// by visibility radius on a blue-to-red ramp (the paper's Figure 3). Not installed, not
// public API; the only part of visfeat that needs PCL's visualization module (VTK).
//
// Rendering is offscreen through pcl::visualization::PCLVisualizer, on the X display
// of xDisplay() (picture_requests.h); the camera comes from picture_camera.h.
#pragma once

#include "picture/picture_requests.h"

#include <visfeat/core/graph/topology_graph.h>
#include <visfeat/point_types.h>

#include <pcl/point_cloud.h>

#include <cstddef>
#include <string>

namespace visfeat_tools {

/** \brief What a picture shows. */
enum class PictureMode
{
  /** \brief Vertices red, edges blue, faces in pastel colours (one per face region),
   * and the topology graph: spheres at the region centroids, arcs between them. */
  kClasses,
  /** \brief visibility_radius on a blue (0) to red (max_radius) ramp, with a scalar
   * bar. */
  kRadius
};

/** \brief Parameters of renderPicture(). */
struct PictureOptions
{
  PictureMode mode = PictureMode::kClasses;
  /** \brief Image size in pixels. Range [kMinPictureSize, kMaxPictureSize]. */
  int width = 1024;
  int height = 768;
  /** \brief Upper end of the radius ramp, in rings (the tool's max_radius). */
  int max_radius = 16;
  /** \brief Cell size of the band's grid (world units) and number of band cells, for
   * the point spacing estimate that sizes the points on screen. */
  double cell_size = 0.0;
  std::size_t band_cells = 0;
  /** \brief One line of text in the top left corner (e.g. the input file name). */
  std::string title;
};

/** \brief Render `cloud` (the estimator's output) with `graph` as a PNG written to
 * `file` (any name; the tool passes its temporary name). Returns false with a one-line
 * `error` when rendering or writing fails; a partial file is removed. */
bool renderPicture(const pcl::PointCloud<visfeat::PointVisibility>& cloud,
                   const visfeat::TopologyGraph& graph,
                   const PictureOptions& options,
                   const std::string& file,
                   std::string& error);

/** \brief Render the requested pictures to their temporary names
 * (temporaryPath(path)), printing a "Rendering ..." line; commitOutput() moves them
 * into place. On failure no temporary file is left and `error` is one line. */
bool writePictures(const PictureRequests& requests,
                   const pcl::PointCloud<visfeat::PointVisibility>& cloud,
                   const visfeat::TopologyGraph& graph,
                   PictureOptions options,
                   std::string& error);

} // namespace visfeat_tools
