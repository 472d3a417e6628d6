// Text point clouds for the visfeat tools (not installed, not public API): .xyz and
// .txt files, one point a line, read in double precision so that survey coordinates
// keep every digit.
#pragma once

#include <pcl/PCLPointCloud2.h>

#include <istream>
#include <string>

namespace visfeat_tools {

/** \brief Read a text point cloud: one point a line, numbers separated by spaces, tabs,
 * commas or semicolons.
 *
 * - Blank lines and lines starting with '#' or '//' are skipped, except that a first
 *   such line or a first line of words (not numbers) may name the columns: "x y z",
 *   "//X,Y,Z,R,G,B" (CloudCompare), "X Y Z Intensity". Names are lower-cased; they must
 *   include x, y and z and be unique.
 * - Without names the first three columns are x y z and further ones are kept as
 *   "column_4", "column_5", ...
 * - Every line must have the same number of columns (at least 3). Each column becomes
 *   a FLOAT64 field, so 512345.678 stays 512345.678. "nan", "inf" are accepted (the
 *   point is then not finite and is skipped by the estimator, as in a PCD file).
 *
 * The cloud is unorganized (height 1), little-endian, is_dense false when a value is
 * not finite.
 * \param[out] cloud the points, fields in column order
 * \param[out] problem on failure one line without the file name, e.g. "line 7: 'abc'
 *             is not a number", "line 4 has 2 columns, line 1 has 3", "no points".
 * \return false on failure (cloud is then unspecified). */
bool readTextCloud(std::istream& in, pcl::PCLPointCloud2& cloud, std::string& problem);

/** \brief readTextCloud() on a file; true for the extensions it reads (.xyz, .txt,
 * case-insensitive). */
bool isTextCloudFile(const std::string& path);

} // namespace visfeat_tools
