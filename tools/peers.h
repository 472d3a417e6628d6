// The methods visfeat_eval compares visfeat with ("peers"), each in its own source
// file: PCL's surface variation (peer_pcl_surface_variation.cpp, always built) and
// CGAL's Voronoi Covariance Measure (peer_cgal_vcm.cpp, built only when CMake finds
// CGAL, which then defines VISFEAT_HAVE_CGAL). Each gives a per-point feature score
// (higher = more likely on a sharp edge) and the seconds its computation took; the
// threshold is chosen by visfeat::evaluation::sweepThreshold().
#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <string>
#include <vector>

namespace visfeat_tools {

struct PeerScore
{
  /** Per input point; NaN where the method gives no value. */
  std::vector<float> score;
  /** Wall time of the method's computation (not of the threshold sweep). */
  double seconds = 0.0;
  /** Empty on success. */
  std::string error;
};

/** \brief PCL's surface variation: pcl::NormalEstimationOMP with k nearest neighbours
 * (kd-tree build included in the time); score = its curvature field, lambda0 /
 * (lambda0 + lambda1 + lambda2) with lambda0 the smallest eigenvalue of the
 * neighbourhood's covariance. threads 0 = all. */
PeerScore pclSurfaceVariation(const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& cloud,
                              int k,
                              unsigned int threads);

/** \brief CGAL's Voronoi Covariance Measure: CGAL::compute_vcm (single-threaded) with
 * the offset and convolution radii in world units; score = the sharpness ratio that
 * CGAL::vcm_is_on_feature_edge thresholds, lambda1 / (lambda0 + lambda1 + lambda2) of
 * the convolved covariance with eigenvalues in ascending order (the middle one). Only
 * compute_vcm is timed. Defined only when VISFEAT_HAVE_CGAL is. */
PeerScore cgalVcm(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                  double offset_radius,
                  double convolution_radius);

} // namespace visfeat_tools
