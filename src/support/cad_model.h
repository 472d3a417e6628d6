#pragma once

// The CAD model's data: its vertices, sharp curves and faces with their incidences,
// the consistency check, the rotation. The named models are in cad_catalogue.h, the
// queries on a model in cad_queries.h, the sampling in cad_sampling.h (cad_models.h
// includes them all).

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <string>
#include <vector>

namespace visfeat {
namespace synthetic {

/** \brief A true sharp curve of a CadModel: a straight segment between two vertices, or
 * a full circle (no vertices).
 *
 * The curve separates exactly two faces (`faces`). */
struct CadCurve
{
  enum class Kind
  {
    kSegment,
    kCircle,
  };

  Kind kind = Kind::kSegment;
  /** Index of the curve in CadModel::curves. */
  int id = -1;
  /** kSegment: the ids of its two end vertices; kCircle: {-1, -1}. */
  std::array<int, 2> vertices{{-1, -1}};
  /** kCircle: centre, unit normal of the circle's plane, radius (world units). */
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
  double radius = 0.0;
  /** The ids of the two faces the curve separates. */
  std::array<int, 2> faces{{-1, -1}};
};

/** \brief A true face of a CadModel: a planar region bounded by a polygon or a circle,
 * possibly with circular holes, or the lateral patch of a finite circular cylinder.
 *
 * - kPlanar: `polygon` lists the outer boundary's vertex ids counter-clockwise seen
 *   from outside (along `normal`, the outward unit normal); a face whose outer boundary
 *   is a circle (a disc) has an empty polygon and `circles[0]` is that circle. The
 * other entries of `circles` are circular holes, all curves of kind kCircle lying in
 * the face's plane.
 * - kCylindrical: the full (360 degree) lateral surface between the two circles of
 *   `circles` (same radius, same axis); `hole` says whether the solid lies outside the
 *   cylinder (the wall of a through-hole: the outward normal points to the axis) or
 *   inside it (a solid cylinder). `normal` and `polygon` are unused. */
struct CadFace
{
  enum class Kind
  {
    kPlanar,
    kCylindrical,
  };

  Kind kind = Kind::kPlanar;
  /** Index of the face in CadModel::faces. */
  int id = -1;
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  std::vector<int> polygon;
  std::vector<int> circles;
  bool hole = false;
};

/** \brief An exact CAD solid and its ground truth: the vertices (corners), the sharp
 * curves (creases) and the faces, with their incidences.
 *
 * Incidences: curve -> its end vertices (CadCurve::vertices, none for a circle);
 * curve -> the two faces it separates (CadCurve::faces); face -> its boundary
 * (CadFace::polygon, CadFace::circles); vertex -> curves and faces are derived by
 * vertexCurves() and vertexFaces(). Ids are indices into the vectors. World units are
 * those of the model (every named model fits in a box of a few units, centred at the
 * origin). */
struct CadModel
{
  std::string name;
  std::vector<Eigen::Vector3d> vertices;
  std::vector<CadCurve> curves;
  std::vector<CadFace> faces;

  /** \brief The exact bounding box of the surface (vertices and circles). */
  Eigen::AlignedBox3d bounds() const;

  /** \brief The total surface area. */
  double area() const;
};

/** \brief Check the model's consistency (ids, incidences both ways, planarity, circles
 * in their faces' planes, cylinders between two coaxial circles of one radius).
 * \throws visfeat::Error naming the first problem found. */
void checkCadModel(const CadModel& model);

/** \brief The model with its geometry and truth rotated about the origin. */
CadModel rotated(const CadModel& model, const Eigen::Matrix3d& rotation);

} // namespace synthetic
} // namespace visfeat
