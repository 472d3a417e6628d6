#pragma once

#include <visfeat/core/band/voxel_band.h>
#include <visfeat/core/common/feature_class.h>
#include <visfeat/core/common/parameters.h>

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace visfeat {

/** \brief Parameters of flatFeaturePoints(): which edge and vertex points lie on flat
 * ground.
 *
 * A point within point_feature_distance of a crease has points of both sides within
 * point_feature_distance + kMargin cells of it, so the points around it do not lie on
 * one plane. An edge or vertex point whose points within `radius` cells do lie on one
 * plane is on a face: its skeleton strayed from the crease (a skeleton drawn across a
 * flat face, a corner placed in the middle of one). Measured on the public meshes
 * sampled by scripts/eval_meshes.py (6 points a cell squared, no noise; 2026-12-07):
 * per-point precision of the fandisk at 1024 0.918 -> 0.964, recall 0.947 both, F1
 * 0.932 -> 0.956; ABC 00000050 at 1024 F1 0.725 -> 0.776. Noise of 0.05 cell or more
 * reads above the default bound, unless smoothed away first (the estimator reads the
 * points as the band saw them: in noise mode, smoothed).
 */
struct FlatPointParameters
{
  /** \brief Cells between point_feature_distance and the neighbourhood's radius: the
   * ball of a point within point_feature_distance of a crease reaches a cell past it
   * (of the points within 1 cell of 30-45-degree creases of random samples of 1.5-2
   * points a cell squared, half a cell moved 7-16%, a cell 0.5-3%; at 6 points a cell
   * squared, 1-2% and none). */
  static constexpr double kMargin = 1.0;
  /** \brief Radius of a point's neighbourhood, cells (> 0): the estimator sets
   * point_feature_distance + kMargin (2 by default, 2.25 in noise mode). */
  double radius = 2.0;
  /** \brief A neighbourhood is flat when its surface variation (PCL's curvature:
   * lambda_0 / (lambda_0 + lambda_1 + lambda_2) of the covariance of its points, 0 on
   * a plane, 1/3 for isotropic scatter) is at most this. About (rms distance to the
   * plane / radius)^2 x 2: 1e-3 is a scatter of about 0.045 cell over a 2-cell ball.
   * Points 1 cell from a crease read 1.4e-3 at 20 degrees (the default minimum crease
   * angle), 3.2e-3 at 30, 1.8e-2 at 60 (a lattice of points 0.3 cells apart); 1.15
   * cells from a 20-degree crease, 1e-3. 0 = off. Default
   * kDefaultMaxSurfaceVariation, range kMaxSurfaceVariationRange. */
  double max_surface_variation = kDefaultMaxSurfaceVariation;
  /** \brief Fewest points in the ball for a judgement (a sparser neighbourhood keeps
   * its label). Default kDefaultMinPoints, range kMinPointsRange. */
  int min_points = kDefaultMinPoints;
  /** \brief OpenMP threads (0 = all available); the result does not depend on it. */
  int threads = 0;

  /** \brief 1e-3: measured with a 1.5-cell ball, the fandisk's F1 was 0.958 at 1e-4
   * and 0.961 at 1e-3 (the ABC's 0.80 at 1e-3), recall unchanged at both. */
  static constexpr double kDefaultMaxSurfaceVariation = 1e-3;
  /** \brief 24 points: the 2-cell ball of a cloud of 2 points a cell squared holds
   * about 25. Random samples of 1 point a cell squared (12-13 in the ball) moved 3-5%
   * of the points within 1 cell of 30-45-degree creases; from 2 points, at most 1.3%;
   * from 3, none. So sparse clouds, and clouds whose point_feature_distance is widened
   * to their spacing, keep their labels. */
  static constexpr int kDefaultMinPoints = 24;
  /** \brief [0, 0.1]: at 0.1 points 1 cell from a 90-degree crease (about 0.06)
   * already read flat; values above the default trade real creases. */
  static constexpr ParameterRange<double> kMaxSurfaceVariationRange{0.0, 0.1};
  /** \brief [3, 1000] points. */
  static constexpr ParameterRange<int> kMinPointsRange{3, 1000};
  /** \brief (0, 20] cells, checked as [1e-6, 20] (point_feature_distance is at most
   * 10). */
  static constexpr ParameterRange<double> kRadiusRange{1e-6, 20.0};

  /** \brief Throws visfeat::Error naming the first parameter out of range. */
  void validate() const;
};

/** \brief What flatFeaturePoints() looked at: the edge and vertex points (finite),
 * those it could judge (a ball of at least min_points points and a face cell within
 * reach), and those it moved. */
struct FlatPointStats
{
  std::size_t feature_points = 0;
  std::size_t judged = 0;
  std::size_t moved = 0;
};

/** \brief One point moved off a feature: it takes the label of face `label`. */
struct FlatPointMove
{
  std::size_t point = 0;
  std::uint32_t label = 0;
};

/** \brief The edge and vertex points on flat ground (see FlatPointParameters), each
 * with the face it goes to: the face region of the band cell nearest to it (cell
 * centres) among the cells its ball reaches (ties: the lower label); a point with no
 * face cell there stays.
 *
 * The ball holds the points of the surface the band was built from (the search
 * surface, as PCL's features), gathered through the band's cells: the points of one
 * cell share the band cells within ceil(radius) of it, and each reads those its ball
 * reaches. A region never loses all its labelled points:
 * where every one would move, its least flat one stays (the first on ties), so the
 * graph keeps a point for each of its nodes, as the corner claim does for vertices
 * no point fell in. The result does not depend on the thread count.
 * \param[in] band the band the points were labelled on
 * \param[in] surface the band's points, in cell units of the band's grid
 * \param[in] surface_cells per surface point, its band cell, or kNoCell (left out)
 * \param[in] points the labelled points, in cell units (non-finite ones stay)
 * \param[in] labels per labelled point, its region label (1-based), 0 = none
 * \param[in] classes per labelled point, its class
 * \param[in] cell_labels per band cell, its region label, 0 = none
 * \param[in] region_classes region_classes[label - 1] is the class of a region
 * \param[in] parameters see FlatPointParameters
 * \param[out] stats if not null, what was looked at (zeros when max_surface_variation
 *             is 0)
 * \return the moves, in increasing point order (empty when max_surface_variation is 0)
 * \throws visfeat::Error for parameters out of range, arrays of mismatched sizes, a
 *         cell id outside the band or a label outside region_classes. */
std::vector<FlatPointMove>
flatFeaturePoints(const VoxelBand& band,
                  const std::vector<Eigen::Vector3f>& surface,
                  const std::vector<CellId>& surface_cells,
                  const std::vector<Eigen::Vector3f>& points,
                  const std::vector<std::uint32_t>& labels,
                  const std::vector<FeatureClass>& classes,
                  const std::vector<std::uint32_t>& cell_labels,
                  const std::vector<FeatureClass>& region_classes,
                  const FlatPointParameters& parameters,
                  FlatPointStats* stats = nullptr);

/** \brief Surface variation of the points (PCL's curvature: lambda_0 / (lambda_0 +
 * lambda_1 + lambda_2) of their covariance), in [0, 1/3]; NaN for fewer than 3 points
 * or points that all coincide. */
double surfaceVariation(const std::vector<Eigen::Vector3d>& points);

} // namespace visfeat
