#pragma once

#include <support/synthetic_shapes.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <cstddef>
#include <cstdint>
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

/** \brief Names accepted by cadModelByName(): "cube", "tetrahedron", "icosahedron",
 * "triangular_prism", "u_prism", "box_with_hole", "cylinder". */
std::vector<std::string> cadModelNames();

/** \brief The model of a name of cadModelNames(), centred at the origin, axis-aligned.
 *
 * Truth counts (vertices / curves / faces): cube 8/12/6, tetrahedron 4/6/4,
 * icosahedron 12/30/20 (the Platonic solids of platonicSolid(), circumradius 1);
 * triangular_prism 6/9/5 (equilateral triangle of side 2, length 2); u_prism 16/24/10
 * (a U of 3 x 3 with arms and base 1 thick and a 1-wide notch, extruded by 1.5);
 * box_with_hole 8/14/7 (a 2 x 2 x 1.5 box, a through-hole of radius 0.5 along its short
 * side: 12 segments + 2 circles, 6 planar faces of which two have a hole + the hole's
 * wall); cylinder 0/2/3 (radius 1, height 2: 2 discs + the lateral face).
 * \throws visfeat::Error for an unknown name, listing the known ones. */
CadModel cadModelByName(const std::string& name);

/** \brief A polyhedral model from a closed polygon mesh (faces may be non-convex).
 *
 * Inputs:
 *   name  the model's name
 *   mesh  closed, consistently oriented (counter-clockwise seen from outside), planar
 *         faces; every edge shared by exactly two faces that are not coplanar
 * Outputs:
 *   the model: the mesh's vertices, one kSegment curve per mesh edge (in the order of
 *   first appearance along the faces), one kPlanar face per mesh face (same ids).
 * \throws visfeat::Error when the mesh breaks one of these conditions. */
CadModel polyhedralModel(const std::string& name, const PolygonMesh& mesh);

/** \brief Check the model's consistency (ids, incidences both ways, planarity, circles
 * in their faces' planes, cylinders between two coaxial circles of one radius).
 * \throws visfeat::Error naming the first problem found. */
void checkCadModel(const CadModel& model);

/** \brief The model with its geometry and truth rotated about the origin. */
CadModel rotated(const CadModel& model, const Eigen::Matrix3d& rotation);

/** \brief The area of one face. */
double faceArea(const CadModel& model, int face);

/** \brief The length of one curve. */
double curveLength(const CadModel& model, int curve);

/** \brief The exact distance from p to one curve (segment or full circle). */
double curveDistance(const CadModel& model, int curve, const Eigen::Vector3d& p);

/** \brief The exact distance from p to the nearest true sharp curve of the model
 * (+infinity when the model has no curve). */
double curveDistance(const CadModel& model, const Eigen::Vector3d& p);

/** \brief The exact distance from p to one face (the bounded region, not its plane or
 * cylinder). */
double faceDistance(const CadModel& model, int face, const Eigen::Vector3d& p);

/** \brief Per vertex, the ids of the curves ending at it (sorted). */
std::vector<std::vector<int>> vertexCurves(const CadModel& model);

/** \brief Per vertex, the ids of the faces touching it (sorted), derived from the
 * curves' faces. */
std::vector<std::vector<int>> vertexFaces(const CadModel& model);

/** \brief Per face, the ids of the curves bounding it (sorted), derived from the
 * curves' faces. */
std::vector<std::vector<int>> faceCurves(const CadModel& model);

/** \brief The Euler characteristic of the surface from the truth: V - S + sum over
 * faces of (1 - holes) for planar faces and 0 for cylindrical ones, where S is the
 * number of segments; circles count 0 (a vertex-free closed curve). It is 2 - 2 genus:
 * 2 for every polyhedron and the cylinder, 0 for box_with_hole (genus 1). */
int eulerCharacteristic(const CadModel& model);

/** \brief The truth as JSON, where the sharp curves are called edges: "name",
 * "counts" (vertices, edges, straight_edges, circular_edges, faces),
 * "euler_characteristic", "vertices" (id, xyz, edges, faces), "edges" (id, kind
 * "straight"/"circle", vertices, faces, length, and centre/axis/radius for circles),
 * "faces" (id, kind "planar"/"cylindrical", area, edges, polygon, circles, and normal
 * for planar faces or hole for cylindrical ones). Coordinates with 17 digits. */
std::string cadModelJson(const CadModel& model);

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
};

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
 * A face is picked with probability proportional to its area, then a point uniformly
 * on it: planar faces by rejection in the bounding rectangle of the face, cylinders by
 * (angle, height).
 * \throws visfeat::Error for a negative or non-finite noise, no count and no positive
 * spacing, or a model of zero area. */
CadSamples sampleCadModel(const CadModel& model, const SamplingOptions& options);

} // namespace synthetic
} // namespace visfeat
