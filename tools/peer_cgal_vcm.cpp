// visfeat_eval's CGAL peer: the Voronoi Covariance Measure (Merigot, Ovsjanikov and
// Guibas), compiled only when CMake finds CGAL (VISFEAT_HAVE_CGAL). CGAL's Point Set
// Processing package is GPL-3 (or commercial): a visfeat_eval built with it is bound
// by that licence; the visfeat library never includes CGAL.

#include "peers.h"

// First: CGAL/config.h decides CGAL_EIGEN3_ENABLED, which Default_diagonalize_traits.h
// tests before including anything itself.
#include <CGAL/config.h>

#include <CGAL/Default_diagonalize_traits.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/vcm_estimate_edges.h>
#include <CGAL/vcm_estimate_normals.h>

#include <array>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <vector>

namespace visfeat_tools {

PeerScore
cgalVcm(const pcl::PointCloud<pcl::PointXYZ>& cloud,
        double offset_radius,
        double convolution_radius)
{
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Point = Kernel::Point_3;
  using Covariance = std::array<double, 6>;

  PeerScore result;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  result.score.assign(cloud.size(), nan);
  // Finite points only; `index` maps them back.
  std::vector<Point> points;
  std::vector<std::size_t> index;
  points.reserve(cloud.size());
  index.reserve(cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const pcl::PointXYZ& p = cloud[i];
    if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) {
      points.emplace_back(p.x, p.y, p.z);
      index.push_back(i);
    }
  }
  std::vector<Covariance> covariances;
  try {
    const auto t0 = std::chrono::steady_clock::now();
    CGAL::compute_vcm(points, covariances, offset_radius, convolution_radius,
                      CGAL::parameters::geom_traits(Kernel()));
    result.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  } catch (const std::exception& e) {
    result.error = std::string("CGAL::compute_vcm failed: ") + e.what();
    return result;
  }
  if (covariances.size() != points.size()) {
    result.error = "CGAL::compute_vcm returned a wrong number of covariances";
    return result;
  }
  // The ratio of CGAL::vcm_is_on_feature_edge, with the same diagonalization.
  for (std::size_t j = 0; j < covariances.size(); ++j) {
    std::array<double, 3> eigenvalues{};
    if (!CGAL::Default_diagonalize_traits<
          double, 3>::diagonalize_selfadjoint_covariance_matrix(covariances[j],
                                                                eigenvalues))
      continue;
    const double sum = eigenvalues[0] + eigenvalues[1] + eigenvalues[2];
    if (sum > 0.0)
      result.score[index[j]] = static_cast<float>(eigenvalues[1] / sum);
  }
  return result;
}

} // namespace visfeat_tools
