#pragma once

// Sampling a CAD model: the cell size and sample count of a grid resolution, and
// uniform (area-weighted) point samples with their per-point truth.

#include <support/cad_model.h>

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace visfeat {
namespace synthetic {

/** \brief The cell of a grid of `resolution` cells along the model's longest
 * bounding-box side (the side of the box of the model as it is: rotate it first). */
double cellSize(const CadModel& model, int resolution);

/** \brief How many uniform samples give a mean spacing of about spacing_cells cells
 * (count = area / spacing^2) on a grid of `resolution` cells along the model's longest
 * bounding-box side. */
std::size_t
samplesForSpacing(const CadModel& model, int resolution, double spacing_cells);

/** \brief How to sample a CadModel. */
struct SamplingOptions
{
  /** Number of points; 0: derived from `spacing`. */
  std::size_t count = 0;
  /** Mean spacing in world units, used when count is 0: count = ceil(area /
   * spacing^2). */
  double spacing = 0.0;
  /** Seed of the sampling and (in a separate stream) of the noise: the same seed with
   * and without noise gives the same noise-free points. */
  std::uint64_t seed = 1;
  /** Standard deviation of the isotropic Gaussian noise per coordinate (world units).
   */
  double noise_sigma = 0.0;
  /** Applied to the sampled points (noise added after). The truth is not rotated: use
   * rotated(model, rotation) for it; distances and face ids do not change. */
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  /** Per-face density multipliers, indexed by face id: empty for a uniform density;
   * otherwise one finite value >= 0 per face, not all zero. A face with multiplier m
   * receives m times as many points per unit area as a face with multiplier 1 (a face
   * is picked with probability proportional to m times its area); the total count is
   * unchanged (from `count`, or from `spacing` over the true area). All ones give the
   * same points as empty. */
  std::vector<double> face_density;
};

/** \brief Per-face density multipliers: 1 on every face of the model but `dense_face`,
 * which gets `ratio` (> 0, finite).
 * \throws visfeat::Error for a face id out of range or a bad ratio. */
std::vector<double> denseFace(const CadModel& model, int dense_face, double ratio);

/** \brief A sampled cloud with its per-point truth. */
struct CadSamples
{
  std::vector<Eigen::Vector3f> points;
  /** The id of the face each point was sampled from. */
  std::vector<int> face;
  /** Distance from each point's noise-free position to the nearest true sharp curve
   * (world units). */
  std::vector<double> curve_distance;
};

/** \brief Points uniformly distributed over the model's surface (by area), reproducible
 * from the seed.
 *
 * Inputs:
 *   model    the CAD model (checkCadModel() holds)
 *   options  count or spacing, seed, noise sigma, rotation
 * Outputs:
 *   the points (rotated, then noise added), their face ids and curve distances.
 * A face is picked with probability proportional to its area (times its
 * options.face_density multiplier, when given), then a point uniformly on it: planar
 * faces by rejection in the bounding rectangle of the face, cylinders by (angle,
 * height).
 * \throws visfeat::Error for a negative or non-finite noise, no count and no positive
 * spacing, a model of zero area, or face_density of the wrong size, with a negative or
 * non-finite value, or zero on every face. */
CadSamples sampleCadModel(const CadModel& model, const SamplingOptions& options);

} // namespace synthetic
} // namespace visfeat
