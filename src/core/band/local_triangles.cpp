#include "../common/angles.h"
#include <visfeat/core/band/local_triangles.h>
#include <visfeat/core/common/error.h>
#include <visfeat/core/common/threads.h>

#include <Eigen/Geometry>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

namespace visfeat {

namespace {

/** Points per chunk of the parallel fan building. */
constexpr std::size_t kPointsPerChunk = 1024;

/** Neighbours the tangent plane is fitted to (nearest first). */
constexpr std::size_t kPlaneNeighbours = 8;

/** The fan of point i, appended to out. */
void
appendUmbrella(const std::vector<Eigen::Vector3d>& points,
               const std::uint32_t* row,
               int k,
               std::uint32_t i,
               const LocalTriangleParameters& parameters,
               std::vector<TriangleIndices>& out)
{
  const Eigen::Vector3d& p = points[i];
  if (!p.allFinite())
    return;
  // distinct, finite neighbours, nearest first
  std::vector<std::pair<double, std::uint32_t>> near;
  near.reserve(static_cast<std::size_t>(k));
  for (int j = 0; j < k; ++j) {
    const std::uint32_t q = row[j];
    if (q >= points.size() || q == i || !points[q].allFinite())
      continue;
    const double d = (points[q] - p).norm();
    if (d > 0.0)
      near.emplace_back(d, q);
  }
  if (near.size() < 2)
    return;
  std::sort(near.begin(), near.end());
  const std::size_t s =
    std::min<std::size_t>(near.size(), LocalTriangleParameters::kSpacingNeighbour) - 1;
  const double max_edge = parameters.max_edge_spacings * near[s].first;
  while (!near.empty() && near.back().first > max_edge)
    near.pop_back();
  if (near.size() < 2)
    return;

  // tangent plane: least squares through p and its nearest kept neighbours
  const std::size_t fit = std::min<std::size_t>(near.size(), kPlaneNeighbours);
  Eigen::Vector3d mean = p;
  for (std::size_t j = 0; j < fit; ++j)
    mean += points[near[j].second];
  mean /= static_cast<double>(fit + 1);
  Eigen::Matrix3d cov = (p - mean) * (p - mean).transpose();
  for (std::size_t j = 0; j < fit; ++j) {
    const Eigen::Vector3d d = points[near[j].second] - mean;
    cov += d * d.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(cov);
  const Eigen::Vector3d normal = solver.eigenvectors().col(0);
  const Eigen::Vector3d u = solver.eigenvectors().col(2);
  const Eigen::Vector3d v = normal.cross(u);
  // Delaunay triangles of p on its tangent plane: (p, a, b) whose circumcircle holds
  // no other neighbour (brute force over the few neighbours).
  const std::size_t m = near.size();
  std::vector<Eigen::Vector2d> flat(m);
  for (std::size_t j = 0; j < m; ++j) {
    const Eigen::Vector3d d = points[near[j].second] - p;
    flat[j] = Eigen::Vector2d(d.dot(u), d.dot(v));
  }
  const double max_angle = detail::cosineOfDegrees(parameters.max_gap_degrees);
  for (std::size_t a = 0; a < m; ++a)
    for (std::size_t b = a + 1; b < m; ++b) {
      const Eigen::Vector2d& qa = flat[a];
      const Eigen::Vector2d& qb = flat[b];
      const double cross = qa.x() * qb.y() - qa.y() * qb.x();
      const double scale = qa.squaredNorm() * qb.squaredNorm();
      if (cross * cross <= 1e-12 * scale)
        continue; // collinear with p
      if (qa.dot(qb) < max_angle * std::sqrt(scale))
        continue; // too wide an angle at p: the scan's border
      if ((points[near[a].second] - points[near[b].second]).norm() > max_edge)
        continue;
      // circumcircle of (0, qa, qb)
      const double d = 2.0 * cross;
      const Eigen::Vector2d centre(
        (qb.y() * qa.squaredNorm() - qa.y() * qb.squaredNorm()) / d,
        (qa.x() * qb.squaredNorm() - qb.x() * qa.squaredNorm()) / d);
      const double r2 = centre.squaredNorm() * (1.0 - 1e-9);
      bool empty = true;
      for (std::size_t c = 0; c < m && empty; ++c)
        if (c != a && c != b && (flat[c] - centre).squaredNorm() < r2)
          empty = false;
      if (empty)
        out.push_back({i, near[a].second, near[b].second});
    }
}

} // namespace

void
LocalTriangleParameters::validate() const
{
  checkRange("neighbours", neighbours, kNeighboursRange, "points");
  checkRange("max_gap_degrees", max_gap_degrees, kMaxGapRange, "degrees");
  checkRange("max_edge_spacings", max_edge_spacings, kMaxEdgeRange, "local spacings");
  checkRange("crease_degrees", crease_degrees, kCreaseDegreesRange, "degrees");
}

std::vector<TriangleIndices>
umbrellaTriangles(const std::vector<Eigen::Vector3d>& points,
                  const std::vector<std::uint32_t>& neighbours,
                  int k,
                  const LocalTriangleParameters& parameters,
                  int threads)
{
  parameters.validate();
  if (k < 0 || neighbours.size() != points.size() * static_cast<std::size_t>(k)) {
    std::ostringstream msg;
    msg << "the neighbour table holds " << neighbours.size() << " entries, not "
        << points.size() << " points x " << k;
    throw Error(msg.str());
  }
  const std::size_t chunks = (points.size() + kPointsPerChunk - 1) / kPointsPerChunk;
  std::vector<std::vector<TriangleIndices>> fans(chunks);
  parallelFor(chunks, threads, 1, [&](std::size_t first, std::size_t last) {
    for (std::size_t c = first; c < last; ++c) {
      const std::size_t end = std::min(points.size(), (c + 1) * kPointsPerChunk);
      for (std::size_t i = c * kPointsPerChunk; i < end; ++i)
        appendUmbrella(points, neighbours.data() + i * static_cast<std::size_t>(k), k,
                       static_cast<std::uint32_t>(i), parameters, fans[c]);
    }
  });
  std::vector<TriangleIndices> triangles;
  for (std::vector<TriangleIndices>& fan : fans) {
    for (TriangleIndices t : fan) {
      std::sort(t.begin(), t.end());
      triangles.push_back(t);
    }
    fan = {};
  }
  // keep the triangles that enough of their corners chose
  std::sort(triangles.begin(), triangles.end());
  std::size_t kept = 0;
  for (std::size_t i = 0; i < triangles.size();) {
    std::size_t j = i + 1;
    while (j < triangles.size() && triangles[j] == triangles[i])
      ++j;
    if (static_cast<int>(j - i) >= parameters.min_votes)
      triangles[kept++] = triangles[i];
    i = j;
  }
  triangles.resize(kept);
  return triangles;
}

} // namespace visfeat
