#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace visfeat {

/** \brief A point's tangent plane: its unit normal (any sign; zero when it could not be
 * fitted) and the point moved onto the plane. */
struct TangentPlane
{
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  /** \brief The point projected onto the plane (world units): on a face the point
   * itself; beside a crease, where the plane is fitted to the point's face without it,
   * its foot on that plane. */
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
};

/** \brief The points' noise (tangentPlanes()' noise, getPointNoise()) reads the shape,
 * not noise, when at least this share of the points' neighbourhoods lie flat
 * (tangentPlanes()' flat_share): a noisy cloud has almost none (Gaussian noise of at
 * least 2% of the spacing leaves about 1e-4), while on a clean cloud too sparse for its
 * part, the neighbourhoods of most points span a crease and those of the rest are exact
 * (the U prism at 1,000 points reads 0.28 cells at resolution 95). The warnings then
 * name sparsity as the cause; the resolution is lowered all the same, since the band
 * filled across those neighbourhoods is as rough. */
constexpr double kShapeNotNoiseShare = 0.1;

/** \brief Below this many points, the points' noise reads the shape whatever the flat
 * share: a neighbourhood (a point and its 10 nearest) is too large a part of each face
 * for any to lie flat, so noise cannot be told from the shape, and the warnings name
 * sparsity (sample denser), not noise (smooth). Measured 2026-12-07, clean clouds of
 * the 7 generated models, seed 5: the flat share was below kShapeNotNoiseShare
 * (read as noise, advised to smooth) at 100 points on all but the cylinder, at 150 on
 * the icosahedron, U prism and box with hole, at 200 on the icosahedron and U prism
 * (10 points a face of the icosahedron); at 300 and 500 on none. */
constexpr std::size_t kNoiseReadablePoints = 300;

/** \brief Per point, the plane of its own face, fitted so that a point beside a crease
 * or a corner is not pulled towards the faces across it.
 *
 * Robust fit over the point p and its kPlaneNeighbours nearest distinct neighbours
 * (rows of `neighbours`, k per point, nearest first, as umbrellaTriangles() reads
 * them): among the planes through three of these points, the one whose worse of (p's
 * distance, the kPlaneSupport-th smallest distance of the other points) is least, so
 * that it holds p and a few more points exactly on noise-free faces; then least
 * squares through its inliers (within kInlierBand times that score, at least a
 * thousandth of the mean neighbour distance). Least median of squares would need half
 * the neighbours on p's face; beside an acute crease or at a corner most of the nearest
 * ones lie on the other faces.
 *
 * \param[in] points positions (world units); a non-finite point gets a zero normal
 * \param[in] neighbours k indices per point, row i = neighbours[i * k, (i + 1) * k),
 *            nearest first; an index >= points.size() (or the point itself) is skipped
 * \param[in] k neighbours per point in `neighbours`
 * \param[in] threads 0 = all available; the result does not depend on it
 * \param[out] noise if not null, the cloud's noise (world units): the median over the
 *             points of the RMS distance of a point and its kPlaneNeighbours nearest
 *             neighbours from their least-squares plane, or from the quadric height
 *             function fitted over it where the plane leaves 10 times its squares (a
 *             curved face; scaled by sqrt((n - 3) / (n - 6)) to read as a plane's
 *             residual; 8 points or more). 0 on
 * noise-free faces, flat or curved (creases, where it measures the shape, are a
 * minority; a plane read the curvature of a 15,000-point sample of a public rocker arm
 * as 0.14 cells of noise); about 0.85 sigma for Gaussian noise of sigma per coordinate;
 * 0 when no point has 3 neighbours. The planes' inlier band still scales with the
 * planes' residual.
 * \param[out] flat_share if not null, the share of the points whose set's residual
 *             (the one `noise` takes the median of) is at most 1% of the set's mean
 *             distance from the point (kFlatResidualShare): about 0 on a noisy cloud,
 *             the share of points away from creases on a noise-free one. When `noise`
 *             is high and this share is not small, the spread is the shape (a sparse
 *             cloud whose neighbourhoods span creases), not noise. \return one plane
 * per point; a zero normal for a point with fewer than 2 usable neighbours. \throws
 * visfeat::Error for a neighbour table of the wrong size. */
std::vector<TangentPlane> tangentPlanes(const std::vector<Eigen::Vector3d>& points,
                                        const std::vector<std::uint32_t>& neighbours,
                                        int k,
                                        int threads,
                                        double* noise = nullptr,
                                        double* flat_share = nullptr);

} // namespace visfeat
