// The visfeat tool's shape check and automatic resolution (not installed, not public
// API): the library's cloudShapeOf(), shapeProblem(), shapeNote() and
// estimateResolution() (visfeat/resolution_estimation.h), with the tool's messages.
#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <string>

namespace visfeat_tools {

/** \brief Refuse clouds without a surface before the load is converted further; the
 * resolution is left to the library (0) when the user gave none (VisibilityFeature-
 * Estimation chooses it from the spacing and the fill, and the tool prints why).
 *
 * - All points on a line, or within 2 cells of one at the resolution: refused, there
 *   is no surface to label (visfeat::shapeProblem).
 * - All points in a plane: processed (one face: the outline of a flat patch is a
 *   boundary, not a crease); the library's note is printed after the run.
 * - No finite point, a single one, or all coincident: left to the estimator, whose
 *   message says so.
 * \param[in] input the file name, for the messages
 * \param[in,out] resolution the user's, or 0 (automatic) when !user_resolution */
bool checkShapeAndResolution(const std::string& input,
                             const pcl::PointCloud<pcl::PointXYZ>& xyz,
                             bool user_resolution,
                             int& resolution,
                             std::string& error);

} // namespace visfeat_tools
