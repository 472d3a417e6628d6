// The outputs of the visfeat tool (not installed, not public API): the labelled cloud,
// the -voxels cloud, the -graph file and the pictures, each written under its
// temporary name (common/output_files.h) and moved into place only when all are
// complete, so a failure leaves none.
#pragma once

#include "visfeat_options.h"

#include <visfeat/point_types.h>
#include <visfeat/visibility_feature_estimation.h>

#include <pcl/PCLPointCloud2.h>
#include <pcl/point_cloud.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <string>

namespace visfeat_tools {

/** \brief The estimator the visfeat tool runs. */
using Estimator =
  visfeat::VisibilityFeatureEstimation<pcl::PointXYZ, visfeat::PointVisibility>;

/** \brief The output cloud: the input's fields (those named like ours removed) + the
 * three new fields of `result`, which has one point per input point. */
bool mergeFields(const pcl::PCLPointCloud2& cloud,
                 const pcl::PointCloud<visfeat::PointVisibility>& result,
                 pcl::PCLPointCloud2& merged,
                 std::string& error);

/** \brief Write the output cloud `merged` (with the input's viewpoint) and the
 * -voxels cloud, if requested, as binary compressed PCD under their temporary names,
 * printing a "Saving" line for each. `offset` is what was subtracted from the input's
 * coordinates (recentringOffset()): when it is not zero the cell centres are written
 * as double x y z with it added back, in the input's frame. */
bool writeClouds(const Options& opt,
                 const pcl::PCLPointCloud2& merged,
                 const Eigen::Vector4f& origin,
                 const Eigen::Quaternionf& orientation,
                 const Estimator& estimator,
                 const Eigen::Vector3d& offset,
                 std::string& error);

/** \brief Write the -graph file under its temporary name (DOT, or JSON with the grid,
 * every parameter and the `offset`, coordinates in the input's frame); on failure the
 * clouds' temporary files are removed too. */
bool writeGraph(const Options& opt,
                const Estimator& estimator,
                const Eigen::Vector3d& offset,
                std::string& error);

/** \brief Render the pictures, then move every output into place; on any failure no
 * output (finished or temporary) is left. */
bool writePicturesAndCommit(const Options& opt,
                            const Estimator& estimator,
                            const pcl::PointCloud<visfeat::PointVisibility>& result,
                            std::string& error);

} // namespace visfeat_tools
