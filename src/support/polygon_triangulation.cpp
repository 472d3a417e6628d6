#include <support/polygon_triangulation.h>
#include <visfeat/core/common/error.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numeric>
#include <string>

namespace visfeat {
namespace synthetic {

namespace {

/** A boundary as indices into the points; after bridging a point may appear twice
 * (the two sides of a bridge). Counter-clockwise: the region lies on the left. */
using Ring = std::vector<std::uint32_t>;

/** Twice the signed area of (a, b, c): positive when counter-clockwise. */
double
orient(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c)
{
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

/** Whether r lies in the closed triangle (a, b, c) of either orientation. */
bool
inTriangle(const Eigen::Vector2d& a,
           const Eigen::Vector2d& b,
           const Eigen::Vector2d& c,
           const Eigen::Vector2d& r)
{
  const double d0 = orient(a, b, r), d1 = orient(b, c, r), d2 = orient(c, a, r);
  return (d0 >= 0.0 && d1 >= 0.0 && d2 >= 0.0) || (d0 <= 0.0 && d1 <= 0.0 && d2 <= 0.0);
}

/** Whether the direction from ring[i] to q enters the region at ring[i] (between its
 * two boundary edges, on the region's side). */
bool
locallyInside(const Polygon2& points,
              const Ring& ring,
              std::size_t i,
              const Eigen::Vector2d& q)
{
  const std::size_t n = ring.size();
  const Eigen::Vector2d& a = points[ring[(i + n - 1) % n]];
  const Eigen::Vector2d& p = points[ring[i]];
  const Eigen::Vector2d& b = points[ring[(i + 1) % n]];
  const bool left_of_in = orient(a, p, q) > 0.0;
  const bool left_of_out = orient(p, b, q) > 0.0;
  return orient(a, p, b) >= 0.0 ? left_of_in && left_of_out : left_of_in || left_of_out;
}

/** The ring position of a vertex of `ring` that sees m (a point of a hole inside the
 * ring, the hole's largest x): the nearest edge crossed by the ray from m along +x,
 * then the vertex of the smallest angle to the ray in the triangle it spans. */
std::size_t
visibleVertex(const Polygon2& points, const Ring& ring, const Eigen::Vector2d& m)
{
  const std::size_t n = ring.size();
  const std::size_t none = std::numeric_limits<std::size_t>::max();
  double hit_x = std::numeric_limits<double>::infinity();
  std::size_t hit = none;
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d& a = points[ring[i]];
    const Eigen::Vector2d& b = points[ring[(i + 1) % n]];
    // Edges going up have the region on their -x side: the ray meets them from inside.
    if (!(a.y() <= m.y() && m.y() <= b.y() && a.y() < b.y()))
      continue;
    const double x = a.x() + (m.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
    if (x < m.x() || x >= hit_x)
      continue;
    hit_x = x;
    if (a.y() == m.y() && a.x() == x)
      hit = i;
    else if (b.y() == m.y() && b.x() == x)
      hit = (i + 1) % n;
    else
      hit = a.x() > b.x() ? i : (i + 1) % n; // the end with the larger x
  }
  if (hit == none)
    throw Error("triangulatePolygon: a hole is not inside the outer boundary");
  const Eigen::Vector2d p = points[ring[hit]];
  if (p.y() == m.y())
    return hit; // the ray meets a vertex
  // A vertex inside the triangle (m, ray hit, p) may hide p: take the one of the
  // smallest angle to the ray (then the nearest) that opens onto m.
  const Eigen::Vector2d hit_point(hit_x, m.y());
  std::size_t best = hit;
  double best_tan = std::abs(p.y() - m.y()) / (p.x() - m.x());
  double best_distance = (p - m).squaredNorm();
  for (std::size_t j = 0; j < n; ++j) {
    const Eigen::Vector2d& r = points[ring[j]];
    if (j == hit || !(r.x() > m.x()) || !inTriangle(m, hit_point, p, r) ||
        !locallyInside(points, ring, j, m))
      continue;
    const double tan = std::abs(r.y() - m.y()) / (r.x() - m.x());
    const double distance = (r - m).squaredNorm();
    if (tan < best_tan || (tan == best_tan && distance < best_distance)) {
      best = j;
      best_tan = tan;
      best_distance = distance;
    }
  }
  return best;
}

/** Splice the clockwise hole into the ring through a bridge from its point of the
 * largest x to a ring vertex that sees it. */
void
bridgeHole(const Polygon2& points, Ring& ring, const Ring& hole)
{
  std::size_t m = 0;
  for (std::size_t i = 1; i < hole.size(); ++i)
    if (points[hole[i]].x() > points[hole[m]].x())
      m = i;
  const std::size_t p = visibleVertex(points, ring, points[hole[m]]);
  Ring spliced(ring.begin(), ring.begin() + static_cast<std::ptrdiff_t>(p) + 1);
  for (std::size_t k = 0; k <= hole.size(); ++k)
    spliced.push_back(hole[(m + k) % hole.size()]); // m ... m again
  spliced.push_back(ring[p]);
  spliced.insert(spliced.end(), ring.begin() + static_cast<std::ptrdiff_t>(p) + 1,
                 ring.end());
  ring.swap(spliced);
}

/** Ear clipping of a bridged counter-clockwise ring. */
std::vector<std::array<std::uint32_t, 3>>
clipEars(const Polygon2& points, const Ring& ring)
{
  const std::size_t n = ring.size();
  std::vector<std::size_t> prev(n), next(n);
  for (std::size_t i = 0; i < n; ++i) {
    prev[i] = (i + n - 1) % n;
    next[i] = (i + 1) % n;
  }
  auto isEar = [&](std::size_t i) {
    const Eigen::Vector2d& a = points[ring[prev[i]]];
    const Eigen::Vector2d& b = points[ring[i]];
    const Eigen::Vector2d& c = points[ring[next[i]]];
    if (!(orient(a, b, c) > 0.0))
      return false;
    for (std::size_t j = next[next[i]]; j != prev[i]; j = next[j]) {
      const Eigen::Vector2d& r = points[ring[j]];
      if (r != a && r != b && r != c && inTriangle(a, b, c, r))
        return false;
    }
    return true;
  };
  std::vector<std::array<std::uint32_t, 3>> triangles;
  triangles.reserve(n - 2);
  std::size_t remaining = n, i = 0, tried = 0;
  while (remaining > 3) {
    if (isEar(i)) {
      triangles.push_back({{ring[prev[i]], ring[i], ring[next[i]]}});
      next[prev[i]] = next[i];
      prev[next[i]] = prev[i];
      --remaining;
      i = next[next[i]]; // skipping a vertex makes fewer slivers
      tried = 0;
    } else {
      i = next[i];
      if (++tried > remaining)
        throw Error("triangulatePolygon: no ear found among " +
                    std::to_string(remaining) +
                    " vertices (the polygon is not simple)");
    }
  }
  triangles.push_back({{ring[prev[i]], ring[i], ring[next[i]]}});
  return triangles;
}

} // namespace

double
twiceSignedArea(const Polygon2& polygon)
{
  double twice = 0.0;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++)
    twice += polygon[j].x() * polygon[i].y() - polygon[i].x() * polygon[j].y();
  return twice;
}

std::vector<std::array<std::uint32_t, 3>>
triangulatePolygon(const Polygon2& outer, const std::vector<Polygon2>& holes)
{
  if (outer.size() < 3 || !(twiceSignedArea(outer) > 0.0))
    throw Error("triangulatePolygon: the outer boundary needs 3 or more points, "
                "counter-clockwise");
  Polygon2 points(outer);
  Ring ring(outer.size());
  std::iota(ring.begin(), ring.end(), 0u);
  std::vector<Ring> hole_rings;
  for (const Polygon2& hole : holes) {
    if (hole.size() < 3)
      throw Error("triangulatePolygon: a hole has fewer than 3 points");
    Ring h(hole.size());
    std::iota(h.begin(), h.end(), static_cast<std::uint32_t>(points.size()));
    if (twiceSignedArea(hole) > 0.0)
      std::reverse(h.begin(), h.end()); // holes run clockwise
    points.insert(points.end(), hole.begin(), hole.end());
    hole_rings.push_back(h);
  }
  auto max_x = [&](const Ring& r) {
    double x = -std::numeric_limits<double>::infinity();
    for (std::uint32_t i : r)
      x = std::max(x, points[i].x());
    return x;
  };
  std::sort(hole_rings.begin(), hole_rings.end(),
            [&](const Ring& a, const Ring& b) { return max_x(a) > max_x(b); });
  for (const Ring& h : hole_rings)
    bridgeHole(points, ring, h);
  return clipEars(points, ring);
}

} // namespace synthetic
} // namespace visfeat
