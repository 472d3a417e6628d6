#include "../common/angles.h"
#include <visfeat/core/band/crease_strips.h>
#include <visfeat/core/common/error.h>
#include <visfeat/core/common/threads.h>

#include <Eigen/Geometry>
#include <Eigen/LU>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

namespace visfeat {

namespace {

/** Below this cosine between the line to the other point and a point's plane, the other
 * point lies too close to that plane to tell the sides of the crease apart. */
constexpr double kMinSideCosine = 0.05;

/** Points per chunk of the parallel loop. */
constexpr std::size_t kPerChunk = 512;

/** Neighbours of a point that may pair with it across a crease (nearest first). */
constexpr int kStripNeighbours = 8;

/** A point's plane is confirmed by a neighbour whose plane is within this angle
 * (degrees) and which lies within kConfirmSine of its distance off it. */
constexpr double kConfirmDegrees = 5.0;
constexpr double kConfirmSine = 0.05;

/** Neighbours of a point that may make a corner with it (nearest first): a corner's
 * nearest points on its three faces can be two spacings apart where a face's corner is
 * acute (the triangular prism's 60 degrees). */
constexpr int kCornerNeighbours = 16;

/** A foot on the crease line farther from its point than this many times the distance
 * between the two points means the planes meet elsewhere (another crease, a wrong
 * plane). In the triangle of the two points and the crease, the ratio is at most
 * 1 / sin(dihedral angle): 2 admits creases down to 30 degrees. */
constexpr double kMaxFootShare = 2.0;

/** The crease strip of neighbours p and q on planes (p, np) and (q, nq) that differ by
 * more than the crease angle: the feet lp, lq of p and q on the planes' intersection,
 * when that line lies between them (each plane's side of the other point is clear, and
 * each foot within kMaxFootShare times their distance of its point).
 * \return false when p and q do not straddle one crease. */
bool
creaseFeet(const Eigen::Vector3d& p,
           Eigen::Vector3d np,
           const Eigen::Vector3d& q,
           Eigen::Vector3d nq,
           Eigen::Vector3d& lp,
           Eigen::Vector3d& lq)
{
  const Eigen::Vector3d pq = q - p;
  const double length = pq.norm();
  const double side_p = np.dot(pq), side_q = -nq.dot(pq);
  if (std::abs(side_p) < kMinSideCosine * length ||
      std::abs(side_q) < kMinSideCosine * length)
    return false;
  np *= side_p < 0.0 ? 1.0 : -1.0; // q below p's plane
  nq *= side_q < 0.0 ? 1.0 : -1.0; // p below q's plane
  const Eigen::Vector3d direction = np.cross(nq);
  if (direction.norm() < 1e-9)
    return false;
  Eigen::Matrix3d m;
  m.row(0) = np.transpose();
  m.row(1) = nq.transpose();
  m.row(2) = direction.transpose();
  const Eigen::Vector3d on_line = m.fullPivLu().solve(
    Eigen::Vector3d(np.dot(p), nq.dot(q), direction.dot(0.5 * (p + q))));
  const Eigen::Vector3d d = direction.normalized();
  lp = on_line + d * d.dot(p - on_line);
  lq = on_line + d * d.dot(q - on_line);
  const double reach = kMaxFootShare * length;
  return lp.allFinite() && lq.allFinite() && (lp - p).norm() <= reach &&
         (lq - q).norm() <= reach && (lp - p).dot(pq) > 0.0 && (lq - q).dot(pq) < 0.0;
}

/** The corner of three neighbours p, q, r on three planes that differ pairwise: the
 * point v where the planes meet and, per point, its feet on the two crease lines
 * through v that bound its face (`feet[i]` = {on the line with the next point's plane,
 * on the line with the previous one's}). Accepted when v is within kMaxFootShare times
 * the points' largest distance of each, and each crease line's two feet lie on the
 * same ray from v: then every point lies in the convex corner of its face between the
 * two rays (at a face's reflex corner, one foot falls on the line's far side).
 * \return false when the three do not share one such corner. */
bool
cornerFeet(const std::array<Eigen::Vector3d, 3>& x,
           const std::array<Eigen::Vector3d, 3>& n,
           Eigen::Vector3d& v,
           std::array<std::array<Eigen::Vector3d, 2>, 3>& feet)
{
  Eigen::Matrix3d m;
  for (int i = 0; i < 3; ++i)
    m.row(i) = n[std::size_t(i)].transpose();
  const Eigen::FullPivLU<Eigen::Matrix3d> lu(m);
  if (!lu.isInvertible())
    return false;
  v = lu.solve(Eigen::Vector3d(n[0].dot(x[0]), n[1].dot(x[1]), n[2].dot(x[2])));
  double size = 0.0;
  for (int i = 0; i < 3; ++i)
    size = std::max(size, (x[std::size_t(i)] - x[std::size_t((i + 1) % 3)]).norm());
  for (int i = 0; i < 3; ++i)
    if (!v.allFinite() || (x[std::size_t(i)] - v).norm() > kMaxFootShare * size)
      return false;
  for (int i = 0; i < 3; ++i) {
    const std::size_t a = std::size_t(i), b = std::size_t((i + 1) % 3);
    const Eigen::Vector3d d = n[a].cross(n[b]).normalized(); // line of planes a, b
    const double ta = d.dot(x[a] - v), tb = d.dot(x[b] - v);
    if (ta * tb <= 0.0)
      return false;
    feet[a][0] = v + ta * d;
    feet[b][1] = v + tb * d;
  }
  return true;
}

} // namespace

std::vector<CellCoord>
creaseStripCells(const GridSpec& grid,
                 const std::vector<Eigen::Vector3d>& points,
                 const std::vector<TangentPlane>& planes,
                 const std::vector<std::uint32_t>& neighbours,
                 int k,
                 double crease_degrees,
                 int threads)
{
  if (k < 0 || neighbours.size() != points.size() * static_cast<std::size_t>(k) ||
      planes.size() != points.size())
    throw Error("creaseStripCells: the neighbours or planes do not match the points");
  if (crease_degrees >= 180.0)
    return {};
  const double agree = detail::cosineOfDegrees(crease_degrees);
  // per chunk of points: the feet (appended after the points) and the strip triangles
  const std::size_t chunks = (points.size() + kPerChunk - 1) / kPerChunk;
  std::vector<std::vector<Eigen::Vector3d>> feet(chunks);
  std::vector<std::vector<std::array<std::uint32_t, 4>>> strips(chunks);
  // a corner is made only of points whose plane another point shares (a point beside a
  // crease can take a plane between the faces' that no neighbour confirms)
  std::vector<std::uint8_t> confirmed(points.size(), 0);
  const double same = detail::cosineOfDegrees(kConfirmDegrees);
  parallelFor(
    points.size(), threads, kPerChunk, [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) {
        const TangentPlane& plane = planes[i];
        if (plane.normal.squaredNorm() == 0.0)
          continue;
        for (int j = 0; j < std::min(k, kStripNeighbours + 1) && !confirmed[i]; ++j) {
          const std::uint32_t q = neighbours[i * static_cast<std::size_t>(k) + j];
          if (q >= points.size() || q == i)
            continue;
          const Eigen::Vector3d d = planes[q].point - plane.point;
          confirmed[i] = std::abs(plane.normal.dot(planes[q].normal)) >= same &&
                         std::abs(plane.normal.dot(d)) <= kConfirmSine * d.norm();
        }
      }
    });
  // Two faces' planes also meet where the faces do not (two faces of an icosahedron
  // that share only a corner): a point of a third face nearer to the middle of the
  // feet than the pair itself shows that the line is not their crease.
  auto thirdFaceBetween = [&](std::size_t p, std::uint32_t q,
                              const Eigen::Vector3d& m) {
    const double reach = std::min((points[p] - m).norm(), (points[q] - m).norm());
    for (int j = 0; j < std::min(k, kCornerNeighbours + 1); ++j) {
      const std::uint32_t r = neighbours[p * static_cast<std::size_t>(k) + j];
      if (r >= points.size() || r == p || r == q ||
          planes[r].normal.squaredNorm() == 0.0)
        continue;
      if (std::abs(planes[r].normal.dot(planes[p].normal)) < agree &&
          std::abs(planes[r].normal.dot(planes[q].normal)) < agree &&
          (points[r] - m).norm() < reach)
        return true;
    }
    return false;
  };
  // corner fans: (point or foot index, foot index, foot index); a point index is below
  // points.size(), a foot's is its index in the chunk's feet
  std::vector<std::vector<std::array<std::uint32_t, 3>>> fans(chunks);
  parallelFor(chunks, threads, 1, [&](std::size_t first, std::size_t last) {
    std::vector<std::uint32_t> across;
    for (std::size_t c = first; c < last; ++c) {
      const std::size_t end = std::min(points.size(), (c + 1) * kPerChunk);
      for (std::size_t i = c * kPerChunk; i < end; ++i) {
        const Eigen::Vector3d& np = planes[i].normal;
        if (np.squaredNorm() == 0.0 || !points[i].allFinite())
          continue;
        across.clear();
        for (int j = 0; j < std::min(k, kCornerNeighbours + 1); ++j) {
          const std::uint32_t q = neighbours[i * static_cast<std::size_t>(k) + j];
          if (q >= points.size() || q == i || planes[q].normal.squaredNorm() == 0.0 ||
              !points[q].allFinite() || std::abs(np.dot(planes[q].normal)) >= agree)
            continue;
          across.push_back(q);
          if (j > kStripNeighbours)
            continue;
          Eigen::Vector3d lp, lq;
          if (!creaseFeet(planes[i].point, np, planes[q].point, planes[q].normal, lp,
                          lq) ||
              thirdFaceBetween(i, q, 0.5 * (lp + lq)))
            continue;
          const auto base = static_cast<std::uint32_t>(feet[c].size());
          feet[c].push_back(lp);
          feet[c].push_back(lq);
          strips[c].push_back({static_cast<std::uint32_t>(i), q, base, base + 1});
        }
        // corners: two neighbours on two other planes
        for (std::size_t a = 0; a < across.size() && confirmed[i]; ++a)
          for (std::size_t b = a + 1; b < across.size(); ++b) {
            const std::uint32_t q = across[a], r = across[b];
            if (!confirmed[q] || !confirmed[r] ||
                std::abs(planes[q].normal.dot(planes[r].normal)) >= agree)
              continue;
            const std::array<std::uint32_t, 3> corner{static_cast<std::uint32_t>(i), q,
                                                      r};
            Eigen::Vector3d v;
            std::array<std::array<Eigen::Vector3d, 2>, 3> corner_feet;
            if (!cornerFeet({planes[i].point, planes[q].point, planes[r].point},
                            {np, planes[q].normal, planes[r].normal}, v, corner_feet))
              continue;
            const auto base = static_cast<std::uint32_t>(feet[c].size());
            feet[c].push_back(v);
            for (std::size_t f = 0; f < 3; ++f) {
              feet[c].push_back(corner_feet[f][0]);
              feet[c].push_back(corner_feet[f][1]);
              // (point, its foot on one line, v) and (point, v, its foot on the other)
              const auto foot = base + 1 + 2 * static_cast<std::uint32_t>(f);
              fans[c].push_back({corner[f], foot, base});
              fans[c].push_back({corner[f], base, foot + 1});
            }
          }
      }
    }
  });
  // the points moved onto their planes, then the feet
  std::vector<Eigen::Vector3d> vertices(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    vertices[i] = planes[i].point;
  std::vector<TriangleIndices> triangles;
  for (std::size_t c = 0; c < chunks; ++c) {
    const auto offset = static_cast<std::uint32_t>(vertices.size());
    vertices.insert(vertices.end(), feet[c].begin(), feet[c].end());
    for (const auto& s : strips[c]) {
      // (p, lp, lq) on p's plane, (q, lq, lp) on q's plane
      triangles.push_back({s[0], offset + s[2], offset + s[3]});
      triangles.push_back({s[1], offset + s[3], offset + s[2]});
    }
    for (const auto& f : fans[c])
      triangles.push_back({f[0], offset + f[1], offset + f[2]});
  }
  // rasterizeTriangles() refuses non-finite vertices; no triangle uses them
  for (Eigen::Vector3d& v : vertices)
    if (!v.allFinite())
      v = Eigen::Vector3d::Zero();
  return rasterizeTriangles(grid, vertices, triangles, threads);
}

} // namespace visfeat
