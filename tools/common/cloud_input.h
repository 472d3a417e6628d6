// Cloud input of the visfeat tools (not installed, not public API): .pcd and .ply files
// loaded safely into pcl::PCLPointCloud2 with every field kept, x y z of any numeric
// type, and fields removed before new ones of the same names are added.
#pragma once

#include "common/pcd_check.h"

#include <pcl/PCLPointCloud2.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstdint>
#include <set>
#include <string>

namespace visfeat_tools {

/** \brief Check that `path` is a regular file that can be opened and is not empty;
 * false + `error` (one line naming the file) when not. `size` is its size in bytes. */
bool checkInputFile(const std::string& path, std::uintmax_t& size, std::string& error);

/** \brief Load a .pcd, .ply, .xyz or .txt file (extension checked case-insensitively)
 * into a PCLPointCloud2, keeping every field in its own type (double x y z stay
 * double; text clouds are read as double, see readTextCloud()). On failure `error` is
 * one line naming the file and the problem. origin / orientation are the PCD viewpoint
 * (identity for the other formats). */
bool loadCloud(const std::string& path,
               pcl::PCLPointCloud2& cloud,
               Eigen::Vector4f& origin,
               Eigen::Quaternionf& orientation,
               std::string& error);

/** \brief The names of a cloud's fields separated by spaces, "none" without fields.
 * pcl::getFieldsList (PCL 1.13) reads before its vector's start when there are none,
 * as a PLY file without a vertex element gives (found by fuzzing). */
std::string fieldsList(const pcl::PCLPointCloud2& cloud);

/** \brief What is inconsistent in a cloud's layout, empty when nothing is: data shorter
 * than width x height points, a field of unknown type or outside point_step. */
std::string layoutProblem(const pcl::PCLPointCloud2& cloud);

/** \brief Check that a cloud's layout holds together (layoutProblem) and that it has
 * scalar numeric x, y, z fields; `problem` names the first one missing or not a
 * scalar. */
bool hasXYZ(const pcl::PCLPointCloud2& cloud, std::string& problem);

/** \brief Read one field value at `p` as a double, whatever its numeric type
 * (pcl::PCLPointField::INT8 ... FLOAT64, INT64 and UINT64 too); NaN for an unknown
 * datatype. */
double readScalar(const std::uint8_t* p, std::uint8_t datatype);

/** \brief Coordinates farther from the origin than this many extents (the longest
 * side of the bounding box) are recentred before they are cast to float: a float
 * there resolves 2^-19 extents (1/60 of a cell at 8192 cells). */
constexpr double kRecentreExtents = 16.0;

/** \brief What to subtract from x, y, z (world units) before they are cast to float:
 * zero for a cloud within kRecentreExtents extents of the origin (nothing changes);
 * otherwise the centre of the bounding box of the finite points, computed in double
 * and rounded to a multiple of the power of ten at least the extent (a part 10 m
 * across near (512345, 4312345, 120) gets (512350, 4312350, 120)), so the recentred
 * coordinates lie within about 6 extents of the origin. Zero when no point is finite.
 * Call hasXYZ() first. */
Eigen::Vector3d recentringOffset(const pcl::PCLPointCloud2& in);

/** \brief The same rule for a bounding box [lo, hi] (world units, double): zero when it
 * is empty (lo > hi on an axis) or within kRecentreExtents extents of the origin. */
Eigen::Vector3d recentringOffset(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi);

/** \brief x, y, z of a PCLPointCloud2 minus `offset`, as PointXYZ: the subtraction in
 * double precision, then the cast to float. fromPCLPointCloud2 when they are float and
 * the offset is zero (the usual case), else converted from whatever numeric type they
 * have (PLY files and text clouds often store double). Call hasXYZ() first. */
void toXYZ(const pcl::PCLPointCloud2& in,
           pcl::PointCloud<pcl::PointXYZ>& out,
           const Eigen::Vector3d& offset = Eigen::Vector3d::Zero());

/** \brief A copy of `in` without the named fields, the others packed in offset order
 * (padding fields "_" dropped too). Returns `in` unchanged when none is present. */
pcl::PCLPointCloud2 withoutFields(const pcl::PCLPointCloud2& in,
                                  const std::set<std::string>& names);

} // namespace visfeat_tools
