#pragma once

// Internal to visfeat_support (included by the cad_*.cpp files only): the elementary
// geometry of a CadModel's curves and faces, and the 2D frame of a planar face and the
// parametric frame of a cylindrical one, shared by the checks, the queries and the
// sampling.

#include <support/cad_model.h>

#include <Eigen/Core>

#include <cstddef>
#include <utility>
#include <vector>

namespace visfeat {
namespace synthetic {
namespace detail {

inline constexpr double kPi = 3.14159265358979323846;

/** A point of a face's plane in the face's 2D frame (no Eigen alignment concerns). */
struct Point2
{
  double x = 0.0;
  double y = 0.0;
};

/** The distance from p to the segment a-b. */
double segmentDistance(const Eigen::Vector3d& a,
                       const Eigen::Vector3d& b,
                       const Eigen::Vector3d& p);

/** The distance from p to the full circle (centre, unit axis, radius). */
double circleDistance(const Eigen::Vector3d& centre,
                      const Eigen::Vector3d& axis,
                      double radius,
                      const Eigen::Vector3d& p);

/** Even-odd rule; points on the boundary may go either way (measure zero). */
bool insidePolygon(const std::vector<Point2>& polygon, const Point2& q);

/** A planar face in its own orthonormal frame (u, v, normal), u x v = normal. */
struct PlanarFrame
{
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d u = Eigen::Vector3d::UnitX();
  Eigen::Vector3d v = Eigen::Vector3d::UnitY();
  std::vector<Point2> polygon; // empty for a disc
  std::vector<Point2> centres; // the face's circles, in CadFace::circles order
  std::vector<double> radii;
  Point2 lo, hi; // bounding rectangle of the outer boundary

  Point2 project(const Eigen::Vector3d& p) const
  {
    const Eigen::Vector3d q = p - origin;
    return {q.dot(u), q.dot(v)};
  }

  Eigen::Vector3d lift(const Point2& q) const { return origin + q.x * u + q.y * v; }

  bool contains(const Point2& q) const;

  /** Signed area of the outer boundary (positive: counter-clockwise about normal). */
  double outerArea() const;
};

PlanarFrame planarFrame(const CadModel& model, const CadFace& face);

/** The lateral patch of a finite cylinder: base + t axis + radius (cos a e1 + sin a
 * e2), t in [0, height]. */
struct CylinderFrame
{
  Eigen::Vector3d base = Eigen::Vector3d::Zero();
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d e1 = Eigen::Vector3d::UnitX();
  Eigen::Vector3d e2 = Eigen::Vector3d::UnitY();
  double radius = 0.0;
  double height = 0.0;
};

CylinderFrame cylinderFrame(const CadModel& model, const CadFace& face);

/** The consecutive vertex pairs of a face's polygon. */
std::vector<std::pair<int, int>> polygonEdges(const CadFace& face);

/** {min(a, b), max(a, b)}: the key of an undirected edge. */
std::pair<int, int> sortedPair(int a, int b);

} // namespace detail
} // namespace synthetic
} // namespace visfeat
