// The automatic resolution of the visfeat tool; see automatic_resolution.h.

#include "common/automatic_resolution.h"

#include <visfeat/core/grid/grid_spec.h>

#include <pcl/common/point_tests.h>
#include <pcl/console/print.h>
#include <pcl/console/time.h>
#include <pcl/kdtree/kdtree_flann.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>
#include <vector>

namespace visfeat_tools {

CloudShape
cloudShape(const pcl::PointCloud<pcl::PointXYZ>& cloud)
{
  CloudShape shape;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::max());
  Eigen::Vector3d hi = -lo;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const auto& p : cloud) {
    if (!pcl::isXYZFinite(p))
      continue;
    const Eigen::Vector3d v = p.getVector3fMap().cast<double>();
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
    sum += v;
    ++shape.finite;
  }
  if (shape.finite < 2)
    return shape;
  shape.extent = (hi - lo).maxCoeff();
  const Eigen::Vector3d mean = sum / static_cast<double>(shape.finite);
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const auto& p : cloud)
    if (pcl::isXYZFinite(p)) {
      const Eigen::Vector3d d = p.getVector3fMap().cast<double>() - mean;
      covariance += d * d.transpose();
    }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
  // Eigenvalues ascending: axis 2 is the main one.
  Eigen::Vector3d pmin = Eigen::Vector3d::Constant(std::numeric_limits<double>::max());
  Eigen::Vector3d pmax = -pmin;
  for (const auto& p : cloud)
    if (pcl::isXYZFinite(p)) {
      const Eigen::Vector3d q =
        solver.eigenvectors().transpose() * (p.getVector3fMap().cast<double>() - mean);
      pmin = pmin.cwiseMin(q);
      pmax = pmax.cwiseMax(q);
    }
  const Eigen::Vector3d w = pmax - pmin;
  shape.widths = Eigen::Vector3d(w[2], w[1], w[0]);
  return shape;
}

bool
estimateSpacing(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                std::size_t max_queries,
                SpacingEstimate& estimate,
                std::string& error)
{
  auto finite = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  finite->reserve(cloud.size());
  for (const auto& p : cloud)
    if (pcl::isXYZFinite(p))
      finite->push_back(p);
  const std::size_t n = finite->size();
  if (n < 2) {
    error = "too few finite points to estimate the point spacing";
    return false;
  }
  estimate.k = static_cast<int>(std::min<std::size_t>(8, n - 1));
  pcl::KdTreeFLANN<pcl::PointXYZ> tree;
  tree.setInputCloud(finite);
  const std::size_t stride = std::max<std::size_t>(1, n / max_queries);
  std::vector<double> radii;
  pcl::Indices indices;
  std::vector<float> sqr_distances;
  for (std::size_t i = 0; i < n && radii.size() < max_queries; i += stride) {
    // k + 1: the query point itself comes back too.
    if (tree.nearestKSearch((*finite)[i], estimate.k + 1, indices, sqr_distances) <= 0)
      continue;
    radii.push_back(std::sqrt(static_cast<double>(sqr_distances.back())));
  }
  estimate.queries = radii.size();
  if (radii.empty()) {
    error = "the nearest-neighbour search found no neighbours";
    return false;
  }
  auto middle = radii.begin() + static_cast<std::ptrdiff_t>(radii.size() / 2);
  std::nth_element(radii.begin(), middle, radii.end());
  const double r = *middle;
  if (!(r > 0.0)) {
    error = "cannot estimate the point spacing: most points have " +
            std::to_string(estimate.k) + " or more duplicates";
    return false;
  }
  // For uniform random samples pi r^2 / spacing^2 is Gamma(k, 1) distributed, whose
  // median is about k - 1/3.
  estimate.spacing = r * std::sqrt(3.14159265358979323846 / (estimate.k - 1.0 / 3.0));
  return true;
}

int
resolutionForSpacing(double extent, double spacing)
{
  const double r = std::round(extent / (kSpacingsPerCell * spacing));
  if (!(r >= visfeat::GridSpec::kMinResolution))
    return visfeat::GridSpec::kMinResolution;
  if (r > visfeat::GridSpec::kMaxResolution)
    return visfeat::GridSpec::kMaxResolution;
  return static_cast<int>(r);
}

bool
checkShapeAndResolution(const std::string& input,
                        const pcl::PointCloud<pcl::PointXYZ>& xyz,
                        bool user_resolution,
                        int& resolution,
                        std::string& error)
{
  using namespace pcl::console;
  const CloudShape shape = cloudShape(xyz);
  if (shape.finite < 2 || !(shape.extent > 0.0)) {
    if (!user_resolution)
      resolution = visfeat::GridSpec::kMinResolution; // the estimator refuses it
    return true;
  }
  const double relative = 1e-5;
  if (shape.widths[1] <= relative * shape.widths[0]) {
    error = "'" + input + "': all " + std::to_string(shape.finite) +
            " finite points lie on a line (collinear): there is no surface to label";
    return false;
  }
  if (!user_resolution) {
    TicToc tt;
    tt.tic();
    print_highlight("Estimating the point spacing ");
    SpacingEstimate estimate;
    if (!estimateSpacing(xyz, kSpacingQueries, estimate, error)) {
      print_info("\n");
      error = "'" + input + "': " + error + "; give -resolution";
      return false;
    }
    resolution = resolutionForSpacing(shape.extent, estimate.spacing);
    print_info("[done, ");
    print_value("%g", tt.toc());
    print_info(" ms]\n");
    print_info("Resolution ");
    print_value("%d", resolution);
    print_info(" chosen: point spacing ");
    print_value("%.6g", estimate.spacing);
    print_info(" (median distance to the %d%s nearest neighbour over ", estimate.k,
               estimate.k == 1   ? "st"
               : estimate.k == 2 ? "nd"
               : estimate.k == 3 ? "rd"
                                 : "th");
    print_value("%zu", estimate.queries);
    print_info(" points), %g spacings per cell, extent ", kSpacingsPerCell);
    print_value("%.6g", shape.extent);
    const double wanted =
      std::round(shape.extent / (kSpacingsPerCell * estimate.spacing));
    if (wanted < visfeat::GridSpec::kMinResolution ||
        wanted > visfeat::GridSpec::kMaxResolution)
      print_info(" (clamped from %.0f)", wanted);
    print_info("; -resolution overrides\n");
  }
  const double cell = shape.extent / resolution;
  if (shape.widths[1] < 2.0 * cell) {
    std::ostringstream s;
    s << "'" << input << "': the points lie within " << shape.widths[1] / cell
      << " cells of a line at resolution " << resolution
      << ": a surface needs at least 2 cells across; raise -resolution";
    error = s.str();
    return false;
  }
  if (shape.widths[2] <= relative * shape.widths[0])
    print_info("Note: all points lie in a plane: expect one face and no edges or "
               "vertices (the outline of a flat patch is a boundary, not a crease)\n");
  return true;
}

} // namespace visfeat_tools
