#include <visfeat/core/band/tangent_planes.h>
#include <visfeat/core/common/error.h>
#include <visfeat/core/common/threads.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/QR>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

namespace visfeat {

namespace {

/** Neighbours a point's plane is fitted to (nearest first). */
constexpr std::size_t kPlaneNeighbours = 10;

/** The noise scale is set by planes that hold this many points besides the three that
 * define them: beside a box's corner a point's 10 nearest neighbours can hold only 3
 * of its own face. */
constexpr std::size_t kPlaneSupport = 1;

/** Inliers lie within this many times the noise scale of a plane. */
constexpr double kInlierBand = 4.0;

/** The inlier band is at least this many times the cloud's noise scale (the median
 * RMS distance of the points' neighbourhoods from their least squares planes: about
 * 0.85 sigma for Gaussian noise on 11 points). */
constexpr double kNoiseBand = 3.0;

/** The inlier band is at least this share of the mean neighbour distance wide, so that
 * on noise-free faces round-off does not drop neighbours. */
constexpr double kMinInlierShare = 1e-3;

/** Candidate planes whose defining points are closer to collinear than this (sine of
 * the angle at the first) are skipped: their normal is noise. */
constexpr double kMinTripleSine = 0.1;

/** The reported noise may fit a quadric height function (6 coefficients) over a
 * point's least squares plane, so that the curvature of a sparsely sampled curved face
 * does not read as noise; sets of fewer points keep the plane's residual. */
constexpr std::size_t kQuadricMinPoints = 8;

/** A set's residual is the quadric's rather than the plane's when the plane leaves
 * more than this many times the quadric's sum of squares: on a flat noisy face the
 * ratio is about (n - 3) / (n - 6) = 1.6 for 11 points and exceeds 10 for about 1% of
 * them (F(3, 5) > 15), which leaves the median of pure noise where the plane put it
 * (the quadric alone read 0.69 sigma at sigma 0.4 on the crease of the noise test; a
 * ratio of 4 moved the calmer resolution of a noisy 10,000-point cube enough to lose
 * a corner); on a curved face sampled sparsely the plane's residual is the curvature,
 * tens to hundreds of times the quadric's. */
constexpr double kCurvatureRatio = 10.0;

/** A set lies flat when its reported residual (plane or quadric) is at most this share
 * of its mean distance from the point: noise-free samples read about 1e-16 there, and
 * Gaussian noise of sigma per coordinate reads about 0.85 sigma, so a cloud whose
 * noise is at least 2% of its spacing has almost no flat set (a residual below 0.01 of
 * the spacing is below 0.6 of its median: chi with 8 degrees of freedom, about 1e-4 of
 * the sets at 2%). */
constexpr double kFlatResidualShare = 0.01;

/** Sum of squared distances of the set from the quadric height function fitted over
 * `plane` (along its normal). */
double
quadricSquares(const std::vector<Eigen::Vector3d>& set, const TangentPlane& plane)
{
  const Eigen::Vector3d n = plane.normal;
  const Eigen::Vector3d u = n.unitOrthogonal();
  const Eigen::Vector3d v = n.cross(u);
  const auto rows = static_cast<Eigen::Index>(set.size());
  Eigen::MatrixXd a(rows, 6);
  Eigen::VectorXd h(rows);
  for (Eigen::Index r = 0; r < rows; ++r) {
    const Eigen::Vector3d d = set[static_cast<std::size_t>(r)] - plane.point;
    const double x = u.dot(d), y = v.dot(d);
    a.row(r) << x * x, x * y, y * y, x, y, 1.0;
    h(r) = n.dot(d);
  }
  const Eigen::VectorXd coefficients = a.colPivHouseholderQr().solve(h);
  return (a * coefficients - h).squaredNorm();
}

/** Points per chunk of the parallel loop. */
constexpr std::size_t kPerChunk = 512;

/** Least squares plane of the points: the unit normal and the centroid. */
TangentPlane
leastSquaresPlane(const std::vector<Eigen::Vector3d>& points)
{
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& q : points)
    mean += q;
  mean /= static_cast<double>(points.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector3d& q : points)
    cov += (q - mean) * (q - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(cov);
  TangentPlane plane;
  plane.normal = solver.eigenvectors().col(0).normalized();
  plane.point = mean;
  return plane;
}

/** A plane through three points of a set. */
struct Candidate
{
  Eigen::Vector3d normal; ///< unit
  std::array<std::size_t, 3> through;
};

/** The candidate planes through three points of `set`, the nearly collinear triples
 * skipped. */
std::vector<Candidate>
candidatePlanes(const std::vector<Eigen::Vector3d>& set)
{
  std::vector<Candidate> planes;
  const std::size_t n = set.size();
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b)
      for (std::size_t c = b + 1; c < n; ++c) {
        const Eigen::Vector3d u = set[b] - set[a], v = set[c] - set[a];
        const Eigen::Vector3d cross = u.cross(v);
        if (cross.norm() >= kMinTripleSine * u.norm() * v.norm())
          planes.push_back({cross.normalized(), {a, b, c}});
      }
  return planes;
}

/** The robust plane of set[0] (the point) and the rest (its neighbours); `fitted` is
 * the set's least squares plane, `noise` the cloud's noise scale (world units). */
TangentPlane
robustPlane(const std::vector<Eigen::Vector3d>& set,
            const TangentPlane& fitted,
            double noise)
{
  const Eigen::Vector3d& p = set[0];
  const std::size_t n = set.size();
  double mean_distance = 0.0;
  for (std::size_t j = 1; j < n; ++j)
    mean_distance += (set[j] - p).norm();
  mean_distance /= static_cast<double>(n - 1);
  // Fast path: a neighbourhood on one plane within the noise (most of a face) has every
  // point an inlier of its least squares plane, which the search below would return.
  {
    TangentPlane plane = fitted;
    const double band = std::max(kNoiseBand * noise, kMinInlierShare * mean_distance);
    bool flat = true;
    for (const Eigen::Vector3d& q : set)
      flat = flat && std::abs(plane.normal.dot(q - plane.point)) <= band;
    if (flat) {
      plane.point = p - plane.normal * plane.normal.dot(p - plane.point);
      return plane;
    }
  }
  const auto candidates = candidatePlanes(set);
  if (candidates.empty()) // all nearly collinear
    return fitted;

  // the scale: the least, over the planes, of the worse of p's distance and the
  // kPlaneSupport-th smallest distance of a point besides the three that define it
  // (with p, at least kPlaneSupport + 3 points within it)
  double scale = std::numeric_limits<double>::infinity();
  for (const Candidate& plane : candidates) {
    const Eigen::Vector3d& origin = set[plane.through[0]];
    const double at_p = std::abs(plane.normal.dot(p - origin));
    if (at_p >= scale)
      continue; // max(at_p, ...) cannot lower the scale
    // the kPlaneSupport smallest residuals of the other points, ascending
    std::array<double, kPlaneSupport> least;
    least.fill(std::numeric_limits<double>::infinity());
    std::size_t others = 0;
    for (std::size_t j = 1; j < n; ++j) {
      if (j == plane.through[0] || j == plane.through[1] || j == plane.through[2])
        continue;
      ++others;
      double r = std::abs(plane.normal.dot(set[j] - origin));
      for (std::size_t i = 0; i < kPlaneSupport && r < least.back(); ++i)
        if (r < least[i])
          std::swap(r, least[i]);
    }
    if (others < kPlaneSupport)
      continue;
    scale = std::min(scale, std::max(at_p, least.back()));
  }
  if (!std::isfinite(scale))
    return fitted;
  const double band = std::max(
    {kInlierBand * scale, kNoiseBand * noise, kMinInlierShare * mean_distance});
  // the plane through p (within the band) with the most points within the band
  std::size_t best_count = 0;
  double best_sum = std::numeric_limits<double>::infinity();
  Eigen::Vector3d best_normal = candidates.front().normal;
  for (const Candidate& plane : candidates) {
    const Eigen::Vector3d& normal = plane.normal;
    const Eigen::Vector3d& origin = set[plane.through[0]];
    if (std::abs(normal.dot(p - origin)) > band)
      continue;
    std::size_t count = 0;
    double sum = 0.0;
    for (const Eigen::Vector3d& q : set) {
      const double r = std::abs(normal.dot(q - origin));
      if (r <= band) {
        ++count;
        sum += r;
      }
    }
    if (count > best_count || (count == best_count && sum < best_sum)) {
      best_count = count;
      best_sum = sum;
      best_normal = normal;
    }
  }
  // least squares through the inliers of the best plane (through p)
  std::vector<Eigen::Vector3d> inliers;
  for (const Eigen::Vector3d& q : set)
    if (std::abs(best_normal.dot(q - p)) <= 2.0 * band)
      inliers.push_back(q);
  TangentPlane plane;
  if (inliers.size() >= 3) {
    plane = leastSquaresPlane(inliers);
  } else {
    plane.normal = best_normal;
    plane.point = p;
  }
  plane.point = p - plane.normal * plane.normal.dot(p - plane.point);
  return plane;
}

} // namespace

std::vector<TangentPlane>
tangentPlanes(const std::vector<Eigen::Vector3d>& points,
              const std::vector<std::uint32_t>& neighbours,
              int k,
              int threads,
              double* noise_out,
              double* flat_share_out)
{
  if (k < 0 || neighbours.size() != points.size() * static_cast<std::size_t>(k))
    throw Error("tangentPlanes: the neighbour table does not match the points");
  // the set of each point: itself first, then its distinct finite neighbours
  auto setOf = [&](std::size_t i, std::vector<Eigen::Vector3d>& set) {
    const Eigen::Vector3d& p = points[i];
    set.clear();
    if (!p.allFinite())
      return;
    set.push_back(p);
    for (int j = 0; j < k && set.size() <= kPlaneNeighbours; ++j) {
      const std::uint32_t q = neighbours[i * static_cast<std::size_t>(k) + j];
      if (q < points.size() && q != i && points[q].allFinite() && points[q] != p)
        set.push_back(points[q]);
    }
  };
  // The cloud's noise: the median over the points of the RMS distance of a point's set
  // from its least squares plane. On faces (most points) that is the noise; creases,
  // where it is the shape, are a minority. Zero on noise-free clouds. Without it the
  // band of a noisy point is set by the luckiest of its candidate planes, and most
  // points end up on planes of 4-5 points, tens of degrees off.
  // (The least squares planes are kept for the robust fit below.)
  // The reported noise: the same, or over the quadric fitted on that plane where the
  // face is curved (the curvature of a sparse curved face is not noise; computed only
  // when asked for).
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const bool report = noise_out || flat_share_out;
  std::vector<double> rms(points.size(), nan), curved_rms;
  std::vector<std::uint8_t> flat;
  if (report) {
    curved_rms.assign(points.size(), nan);
    flat.assign(points.size(), 0);
  }
  std::vector<TangentPlane> fitted(points.size());
  parallelFor(points.size(), threads, kPerChunk,
              [&](std::size_t begin, std::size_t end) {
                std::vector<Eigen::Vector3d> set;
                for (std::size_t i = begin; i < end; ++i) {
                  setOf(i, set);
                  if (set.size() < 4)
                    continue;
                  const TangentPlane& plane = fitted[i] = leastSquaresPlane(set);
                  double sum = 0.0;
                  for (const Eigen::Vector3d& q : set)
                    sum += std::pow(plane.normal.dot(q - plane.point), 2);
                  const auto n = static_cast<double>(set.size());
                  rms[i] = std::sqrt(sum / n);
                  if (!report)
                    continue;
                  curved_rms[i] = rms[i];
                  if (set.size() >= kQuadricMinPoints) {
                    // scaled by sqrt((n - 3) / (n - 6)) to read as the plane's residual
                    // (the degrees of freedom of 3 and 6 coefficients)
                    const double quadric = quadricSquares(set, plane);
                    if (sum > kCurvatureRatio * quadric)
                      curved_rms[i] = std::sqrt(quadric / n * (n - 3.0) / (n - 6.0));
                  }
                  double spread = 0.0;
                  for (const Eigen::Vector3d& q : set)
                    spread += (q - set.front()).norm();
                  spread /= n - 1.0;
                  flat[i] = curved_rms[i] <= kFlatResidualShare * spread;
                }
              });
  const auto median = [](std::vector<double> values) {
    values.erase(std::remove_if(values.begin(), values.end(),
                                [](double r) { return std::isnan(r); }),
                 values.end());
    if (values.empty())
      return 0.0;
    const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    return *middle;
  };
  const double noise = median(std::move(rms));
  if (flat_share_out) {
    std::size_t fitted_sets = 0, flat_sets = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
      fitted_sets += !std::isnan(curved_rms[i]);
      flat_sets += flat[i];
    }
    *flat_share_out = fitted_sets == 0 ? 0.0 : double(flat_sets) / double(fitted_sets);
  }
  if (noise_out)
    *noise_out = median(std::move(curved_rms));

  std::vector<TangentPlane> planes(points.size());
  parallelFor(points.size(), threads, kPerChunk,
              [&](std::size_t begin, std::size_t end) {
                std::vector<Eigen::Vector3d> set;
                for (std::size_t i = begin; i < end; ++i) {
                  planes[i].point = points[i];
                  setOf(i, set);
                  if (set.size() >= 3)
                    planes[i] = robustPlane(
                      set, set.size() >= 4 ? fitted[i] : leastSquaresPlane(set), noise);
                }
              });
  return planes;
}

} // namespace visfeat
