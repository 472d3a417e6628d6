#pragma once

// Queries on a CAD model: areas, lengths, exact distances to its curves and faces, the
// incidences derived from the truth, the Euler characteristic, the truth as JSON.

#include <support/cad_model.h>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace visfeat {
namespace synthetic {

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

} // namespace synthetic
} // namespace visfeat
