#include <support/cad_frames.h>
#include <support/cad_queries.h>

#include <core/common/json_document.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace visfeat {
namespace synthetic {

using detail::CylinderFrame;
using detail::cylinderFrame;
using detail::kPi;
using detail::PlanarFrame;
using detail::planarFrame;
using detail::polygonEdges;
using detail::segmentDistance;

double
faceArea(const CadModel& model, int face)
{
  const CadFace& f = model.faces.at(static_cast<std::size_t>(face));
  if (f.kind == CadFace::Kind::kCylindrical) {
    const CylinderFrame frame = cylinderFrame(model, f);
    return 2.0 * kPi * frame.radius * frame.height;
  }
  const PlanarFrame frame = planarFrame(model, f);
  double area = std::abs(frame.outerArea());
  for (std::size_t c = frame.polygon.empty() ? 1 : 0; c < frame.radii.size(); ++c)
    area -= kPi * frame.radii[c] * frame.radii[c];
  return area;
}

double
curveLength(const CadModel& model, int curve)
{
  const CadCurve& c = model.curves.at(static_cast<std::size_t>(curve));
  if (c.kind == CadCurve::Kind::kCircle)
    return 2.0 * kPi * c.radius;
  return (model.vertices[static_cast<std::size_t>(c.vertices[1])] -
          model.vertices[static_cast<std::size_t>(c.vertices[0])])
    .norm();
}

double
curveDistance(const CadModel& model, int curve, const Eigen::Vector3d& p)
{
  const CadCurve& c = model.curves.at(static_cast<std::size_t>(curve));
  if (c.kind == CadCurve::Kind::kCircle)
    return detail::circleDistance(c.centre, c.axis, c.radius, p);
  return segmentDistance(model.vertices[static_cast<std::size_t>(c.vertices[0])],
                         model.vertices[static_cast<std::size_t>(c.vertices[1])], p);
}

double
curveDistance(const CadModel& model, const Eigen::Vector3d& p)
{
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t c = 0; c < model.curves.size(); ++c)
    best = std::min(best, curveDistance(model, static_cast<int>(c), p));
  return best;
}

double
faceDistance(const CadModel& model, int face, const Eigen::Vector3d& p)
{
  const CadFace& f = model.faces.at(static_cast<std::size_t>(face));
  double best = std::numeric_limits<double>::infinity();
  for (int c : f.circles)
    best = std::min(best, curveDistance(model, c, p));
  if (f.kind == CadFace::Kind::kCylindrical) {
    const CylinderFrame frame = cylinderFrame(model, f);
    const Eigen::Vector3d q = p - frame.base;
    const double t = q.dot(frame.axis);
    if (t >= 0.0 && t <= frame.height)
      return std::abs((q - t * frame.axis).norm() - frame.radius);
    return best; // beyond an end: the nearest point is on an end circle
  }
  const PlanarFrame frame = planarFrame(model, f);
  if (frame.contains(frame.project(p)))
    return std::abs(frame.normal.dot(p - frame.origin));
  for (const auto& edge : polygonEdges(f))
    best = std::min(
      best, segmentDistance(model.vertices[static_cast<std::size_t>(edge.first)],
                            model.vertices[static_cast<std::size_t>(edge.second)], p));
  return best;
}

std::vector<std::vector<int>>
vertexCurves(const CadModel& model)
{
  std::vector<std::vector<int>> out(model.vertices.size());
  for (const CadCurve& c : model.curves)
    if (c.kind == CadCurve::Kind::kSegment)
      for (int v : c.vertices)
        out[static_cast<std::size_t>(v)].push_back(c.id);
  for (auto& list : out)
    std::sort(list.begin(), list.end());
  return out;
}

std::vector<std::vector<int>>
vertexFaces(const CadModel& model)
{
  std::vector<std::vector<int>> out(model.vertices.size());
  for (const CadCurve& c : model.curves)
    if (c.kind == CadCurve::Kind::kSegment)
      for (int v : c.vertices)
        for (int f : c.faces)
          out[static_cast<std::size_t>(v)].push_back(f);
  for (auto& list : out) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  return out;
}

std::vector<std::vector<int>>
faceCurves(const CadModel& model)
{
  std::vector<std::vector<int>> out(model.faces.size());
  for (const CadCurve& c : model.curves)
    for (int f : c.faces)
      out[static_cast<std::size_t>(f)].push_back(c.id);
  for (auto& list : out) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  return out;
}

int
eulerCharacteristic(const CadModel& model)
{
  int chi = static_cast<int>(model.vertices.size());
  for (const CadCurve& c : model.curves)
    if (c.kind == CadCurve::Kind::kSegment)
      --chi; // an open segment; a circle (closed, no vertex) counts 0
  for (const CadFace& f : model.faces)
    if (f.kind == CadFace::Kind::kPlanar) {
      const int holes =
        static_cast<int>(f.circles.size()) - (f.polygon.empty() ? 1 : 0);
      chi += 1 - holes; // an open disc minus closed discs; an open cylinder counts 0
    }
  return chi;
}

std::string
cadModelJson(const CadModel& model)
{
  using visfeat::json_document::Json;
  using visfeat::json_document::vector3;
  std::size_t circles = 0;
  for (const CadCurve& c : model.curves)
    circles += c.kind == CadCurve::Kind::kCircle ? 1 : 0;
  const auto vertex_curves = vertexCurves(model);
  const auto vertex_faces = vertexFaces(model);
  const auto face_curves = faceCurves(model);

  Json vertices = Json::array();
  for (std::size_t v = 0; v < model.vertices.size(); ++v)
    vertices.push_back({{"id", v},
                        {"xyz", vector3(model.vertices[v])},
                        {"edges", vertex_curves[v]},
                        {"faces", vertex_faces[v]}});
  Json edges = Json::array();
  for (std::size_t i = 0; i < model.curves.size(); ++i) {
    const CadCurve& c = model.curves[i];
    const bool circle = c.kind == CadCurve::Kind::kCircle;
    Json edge = {{"id", i},
                 {"kind", circle ? "circle" : "straight"},
                 {"vertices", circle ? std::vector<int>()
                                     : std::vector<int>{c.vertices[0], c.vertices[1]}},
                 {"faces", {c.faces[0], c.faces[1]}},
                 {"length", curveLength(model, static_cast<int>(i))}};
    if (circle) {
      edge["centre"] = vector3(c.centre);
      edge["axis"] = vector3(c.axis);
      edge["radius"] = c.radius;
    }
    edges.push_back(edge);
  }
  Json faces = Json::array();
  for (std::size_t i = 0; i < model.faces.size(); ++i) {
    const CadFace& f = model.faces[i];
    const bool planar = f.kind == CadFace::Kind::kPlanar;
    Json face = {{"id", i},
                 {"kind", planar ? "planar" : "cylindrical"},
                 {"area", faceArea(model, static_cast<int>(i))},
                 {"edges", face_curves[i]},
                 {"polygon", f.polygon},
                 {"circles", f.circles}};
    if (planar)
      face["normal"] = vector3(f.normal);
    else
      face["hole"] = f.hole;
    faces.push_back(face);
  }
  Json document;
  document["name"] = model.name;
  document["counts"] = {{"vertices", model.vertices.size()},
                        {"edges", model.curves.size()},
                        {"straight_edges", model.curves.size() - circles},
                        {"circular_edges", circles},
                        {"faces", model.faces.size()}};
  document["euler_characteristic"] = eulerCharacteristic(model);
  document["vertices"] = vertices;
  document["edges"] = edges;
  document["faces"] = faces;
  std::ostringstream out;
  visfeat::json_document::write(out, document);
  return out.str();
}

} // namespace synthetic
} // namespace visfeat
