// VisibilityFeatureEstimation (not for inclusion on its own): edges along the creases
// where two faces touch without an edge region between them, and the corners split in
// two that their corners leave.
#pragma once

#include <visfeat/core/graph/contact_creases.h>
#include <visfeat/core/graph/corner_meets.h>
#include <visfeat/core/graph/edge_bridges.h>
#include <visfeat/core/graph/face_creases.h>
#include <visfeat/core/graph/face_pieces.h>
#include <visfeat/core/graph/open_faces.h>
#include <visfeat/impl/visibility_feature_estimation.hpp>

#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <set>
#include <vector>

namespace visfeat {
namespace detail {

/** Each region's crease angle, per label (index 0 unused; NaN where not measured, and
 * for vertices and faces). */
inline std::vector<double>
creaseAnglesOf(const TopologyGraph& graph)
{
  std::vector<double> angle_of(graph.size() + 1,
                               std::numeric_limits<double>::quiet_NaN());
  for (std::uint32_t id = 1; id <= graph.size(); ++id)
    angle_of[id] = graph.node(id).crease_angle;
  return angle_of;
}

/** The angles of creaseAnglesOf() back onto a graph whose labels were renumbered
 * (`now`: per old label its new one, 0 for none; empty: nothing changed): each
 * region still an edge keeps its angle. */
inline void
restoreCreaseAngles(TopologyGraph& graph,
                    const std::vector<double>& angle_of,
                    const std::vector<std::uint32_t>& now)
{
  for (std::size_t old = 1; old < now.size() && old < angle_of.size(); ++old)
    if (now[old] != 0 && std::isfinite(angle_of[old]) &&
        graph.node(now[old]).feature_class == FeatureClass::kEdge)
      graph.setCreaseAngle(now[old], angle_of[old]);
}

/** After contact creases became edges (addRegions(), renumbered: per label before,
 * its label now): the pieces of their faces that the new edges cut off
 * (cutOffFacePieces()) go to the face on their side, and so do the face points of their
 * cells (cell_of(i): point i's band cell); the labels of all points and renumbered
 * follow the renumbering. */
template <typename Results, typename Cloud, typename CellOf>
void
moveCutOffPieces(Results& results,
                 Cloud& output,
                 const std::vector<ContactCrease>& creases,
                 std::vector<std::uint32_t>& renumbered,
                 const CellOf& cell_of)
{
  std::vector<std::array<std::uint32_t, 2>> pairs;
  for (const ContactCrease& crease : creases)
    pairs.push_back({{renumbered[crease.faces[0]], renumbered[crease.faces[1]]}});
  const std::vector<FacePiece> pieces =
    cutOffFacePieces(results.band, results.segmentation.cellLabels(),
                     results.segmentation.regionClasses(), pairs);
  if (pieces.empty())
    return;
  std::vector<std::vector<CellId>> cells;
  std::vector<std::uint32_t> faces;
  std::vector<std::uint32_t> moved_to(results.band.size(), 0); // per cell, 0: stays
  for (const FacePiece& piece : pieces) {
    cells.push_back(piece.cells);
    faces.push_back(piece.into);
    for (const CellId c : piece.cells)
      moved_to[static_cast<std::size_t>(c)] = piece.into;
  }
  const std::vector<std::uint32_t> moved =
    results.segmentation.moveFaceCells(cells, faces);
  const auto face = static_cast<std::uint8_t>(FeatureClass::kFace);
  for (std::size_t i = 0; i < output.size(); ++i) {
    auto& p = output[i];
    const CellId cell = cell_of(i);
    if (p.feature_class == face && cell != kNoCell &&
        moved_to[static_cast<std::size_t>(cell)] != 0)
      p.label = moved_to[static_cast<std::size_t>(cell)];
    p.label = moved[p.label];
  }
  for (std::uint32_t& label : renumbered)
    label = moved[label];
}

/** Faces that hold creases the map did not see: the pieces their ridges of
 * non-planar points cut apart (creasedFacePieces(), from the points of `surface`, the
 * cloud the band was built from, each taking its cell's label: the same whatever the
 * input points) become faces, the output's face points with them (cell_of(i): point i's
 * band cell); then each two pieces of one face that touch join again unless their
 * contact turns by at least min_angle (measureFaceContacts(); a contact too short to
 * measure joins too). Returns false when no face was split; else `into` is the join for
 * applyRegionMerge() (identity when every contact is a crease) and `renumbered` the
 * split's renumbering (per label before, its label after). */
template <typename Results, typename Surface, typename Cloud, typename CellOf>
bool
splitCreasedFaces(Results& results,
                  const Surface& surface,
                  Cloud& output,
                  const FaceCreaseParameters& parameters,
                  double window_cells,
                  double min_angle,
                  const CellOf& cell_of,
                  std::vector<std::uint32_t>& into,
                  std::vector<std::uint32_t>& renumbered)
{
  std::vector<Eigen::Vector3d> ground(surface.size());
  for (std::size_t j = 0; j < surface.size(); ++j)
    ground[j] = surface[j].getVector3fMap().template cast<double>();
  std::vector<CellId> point_cells = results.band.pointCell();
  point_cells.resize(ground.size(), kNoCell);
  const std::vector<CreasedFacePiece> pieces =
    creasedFacePieces(results.band, results.segmentation.cellLabels(), ground,
                      point_cells, results.segmentation.regionClasses(), parameters);
  if (pieces.empty())
    return false;
  std::vector<Eigen::Vector3d> points(output.size());
  std::vector<std::uint32_t> labels(output.size());
  for (std::size_t i = 0; i < output.size(); ++i)
    points[i] = output[i].getVector3fMap().template cast<double>();
  std::vector<std::vector<CellId>> cells;
  for (const CreasedFacePiece& piece : pieces)
    cells.push_back(piece.cells);
  renumbered = results.segmentation.splitFaces(cells);
  const std::vector<std::uint32_t>& cell_labels = results.segmentation.cellLabels();
  const std::vector<Region>& regions = results.segmentation.regions();
  // per label now, the face it was cut from (its own label for the others)
  std::vector<std::uint32_t> origin(regions.size() + 1);
  std::iota(origin.begin(), origin.end(), 0u);
  for (const CreasedFacePiece& piece : pieces)
    origin[cell_labels[static_cast<std::size_t>(piece.cells.front())]] =
      renumbered[piece.face];
  const auto face = static_cast<std::uint8_t>(FeatureClass::kFace);
  for (std::size_t i = 0; i < output.size(); ++i) {
    auto& p = output[i];
    std::uint32_t label = renumbered[p.label];
    const CellId cell = cell_of(i);
    if (p.feature_class == face && cell != kNoCell) {
      const std::uint32_t now = cell_labels[static_cast<std::size_t>(cell)];
      if (origin[now] == label)
        label = now;
    }
    p.label = label;
    p.feature_class = static_cast<std::uint8_t>(
      label == 0 ? FeatureClass::kNone : regions[label - 1].feature_class);
    labels[i] = label;
  }
  // the contacts that are creases keep their pieces apart
  std::set<std::array<std::uint32_t, 2>> creases;
  for (const CreaseAngle& contact : measureFaceContacts(
         results.band, cell_labels, points, labels,
         results.segmentation.regionClasses(), window_cells, parameters.threads))
    if (contact.degrees >= min_angle)
      creases.insert(contact.faces);
  into = rejoinCreasedFacePieces(results.band, cell_labels, origin, creases);
  return true;
}

} // namespace detail

template <typename PointInT, typename PointOutT>
void
VisibilityFeatureEstimation<PointInT, PointOutT>::relabelAddedPoints(
  const Results& results,
  PointCloudOut& output,
  const std::vector<std::uint32_t>& renumbered) const
{
  const std::vector<std::uint32_t>& cell_labels = results.segmentation.cellLabels();
  const std::vector<Region>& regions = results.segmentation.regions();
  // Points: a point of a cell now in a new region takes it when its class ranks
  // below the region's (face < edge < vertex), the others their region's new label
  // (a point keeps the label the skeleton gave it).
  std::vector<char> fresh(regions.size() + 1, 1); // labels of the new regions
  for (const std::uint32_t label : renumbered)
    fresh[label] = 0;
  for (std::size_t i = 0; i < output.size(); ++i) {
    PointOutT& p = output[i];
    const auto index = static_cast<std::size_t>((*indices_)[i]);
    const CellId cell = bandCellOf(results.band, index);
    std::uint32_t label = p.label == 0 ? 0 : renumbered[p.label];
    if (cell != kNoCell) {
      const std::uint32_t now = cell_labels[static_cast<std::size_t>(cell)];
      const auto point_class = static_cast<FeatureClass>(p.feature_class);
      if (fresh[now] && (point_class == FeatureClass::kFace ||
                         (point_class == FeatureClass::kEdge &&
                          regions[now - 1].feature_class == FeatureClass::kVertex)))
        label = now;
    }
    if (label == 0 && cell != kNoCell)
      label = cell_labels[static_cast<std::size_t>(cell)];
    p.label = label;
    p.feature_class = static_cast<std::uint8_t>(
      label == 0 ? FeatureClass::kNone : regions[label - 1].feature_class);
  }
}

template <typename PointInT, typename PointOutT>
void
VisibilityFeatureEstimation<PointInT, PointOutT>::cleanUpRegions(
  Results& results,
  const Run& run,
  const PointCloudIn& surface,
  PointCloudOut& output) const
{
  if (run.segmentation.raw || !run.segmentation.complete_regions)
    return;
  std::vector<CreaseAngle> angles = mergeShallowCreases(results, run, output);
  // Stray regions after the crease rule: a face speck that the rule joins to the face
  // it touches is not one (the faceted boss: a 500-cell facet piece at a corner).
  const std::vector<std::uint32_t> renumbered = applyRegionMerge(
    results, run, output,
    strayRegionMerge(results.graph,
                     detail::splitCornerDistance(results.band, run.segmentation)));
  // stray regions join edges, faces or vertices, and an edge joins only a corner (a
  // piece between a split corner's two parts): each edge that stays keeps its angle
  // under its new label
  for (std::size_t r = 0; r < angles.size(); ++r) {
    const auto label = static_cast<std::uint32_t>(r + 1);
    const std::uint32_t now = renumbered.empty() ? label : renumbered[label];
    if (std::isfinite(angles[r].degrees) && now != 0 &&
        results.graph.node(now).feature_class == FeatureClass::kEdge)
      results.graph.setCreaseAngle(now, angles[r].degrees);
  }
  // Faces whose own points hold a crease the map did not see are split; the pieces
  // whose contact is a crease stay apart for the contact creases below. Not on noisy
  // points: their scatter reads as ridges (the band's roughness), and noise mode's
  // smoothing rounds every crease, so that faces read ridges along all their edges.
  if (run.crease_angles.min_crease_angle > 0.0 && !(run.smoothing.radius > 0.0) &&
      results.band.roughness() < FaceCreaseParameters::kMaxRoughness) {
    FaceCreaseParameters face_creases;
    face_creases.min_piece_cells = static_cast<std::size_t>(
      run.segmentation.components.min_radius * run.segmentation.components.min_radius);
    face_creases.threads = run.visibility.threads;
    const std::vector<double> angle_of = detail::creaseAnglesOf(results.graph);
    std::vector<std::uint32_t> into, now;
    if (detail::splitCreasedFaces(
          results, surface, output, face_creases, run.crease_angles.window_cells,
          run.crease_angles.min_crease_angle,
          [&](std::size_t i) {
            return bandCellOf(results.band, static_cast<std::size_t>((*indices_)[i]));
          },
          into, now)) {
      const std::vector<std::uint32_t> joined =
        applyRegionMerge(results, run, output, into);
      if (joined.empty())
        buildGraph(results, run, output);
      else
        for (std::uint32_t& label : now)
          label = joined[label];
      detail::restoreCreaseAngles(results.graph, angle_of, now);
    }
  }
  addContactCreases(results, run, output);
}

template <typename PointInT, typename PointOutT>
void
VisibilityFeatureEstimation<PointInT, PointOutT>::addContactCreases(
  Results& results, const Run& run, PointCloudOut& output) const
{
  const double min_angle = run.crease_angles.min_crease_angle;
  if (!(min_angle > 0.0))
    return; // the rule is off: every region stays as the map made it
  std::vector<Eigen::Vector3d> points(output.size());
  std::vector<std::uint32_t> labels(output.size());
  for (std::size_t i = 0; i < output.size(); ++i) {
    points[i] = output[i].getVector3fMap().template cast<double>();
    labels[i] = output[i].label;
  }
  const std::vector<FeatureClass> classes = results.segmentation.regionClasses();
  // Two faces an edge separates somewhere touch elsewhere only where the watershed
  // spills across that edge's end (the filleted box's corners, the box with hole's
  // rim): no crease of their own.
  std::set<std::array<std::uint32_t, 2>> separated;
  for (std::uint32_t id = 1; id <= results.graph.size(); ++id) {
    if (results.graph.node(id).feature_class != FeatureClass::kEdge)
      continue;
    const std::vector<std::uint32_t> faces = results.graph.facesOfEdge(id);
    for (std::size_t i = 0; i < faces.size(); ++i)
      for (std::size_t j = i + 1; j < faces.size(); ++j)
        separated.insert(
          {{std::min(faces[i], faces[j]), std::max(faces[i], faces[j])}});
  }
  const std::vector<ContactCrease> creases =
    locateContactCreases(results.band, results.segmentation.cellLabels(), points,
                         labels, classes, separated, run.crease_angles.window_cells,
                         min_angle, kContactCreaseHalfWidth, run.visibility.threads);
  if (creases.empty())
    return;

  // the edges' measured turns, kept across the renumbering
  const std::vector<double> angle_of = detail::creaseAnglesOf(results.graph);
  // the creases as edges, then the corners where they end as vertices
  const std::vector<std::vector<CellId>> corners =
    contactCorners(results.band, results.segmentation.cellLabels(), classes, creases);
  std::vector<std::vector<CellId>> cells;
  std::vector<FeatureClass> new_classes;
  for (const ContactCrease& crease : creases) {
    cells.push_back(crease.cells);
    new_classes.push_back(FeatureClass::kEdge);
  }
  for (const std::vector<CellId>& corner : corners) {
    cells.push_back(corner);
    new_classes.push_back(FeatureClass::kVertex);
  }
  std::vector<std::uint32_t> renumbered =
    results.segmentation.addRegions(cells, new_classes);
  relabelAddedPoints(results, output, renumbered);
  detail::moveCutOffPieces(results, output, creases, renumbered, [&](std::size_t i) {
    return bandCellOf(results.band, static_cast<std::size_t>((*indices_)[i]));
  });
  const std::vector<std::uint32_t>& cell_labels = results.segmentation.cellLabels();
  const std::vector<Region>& regions = results.segmentation.regions();

  std::vector<char> fresh(regions.size() + 1, 1); // labels of the new regions
  for (const std::uint32_t label : renumbered)
    fresh[label] = 0;
  buildGraph(results, run, output);
  detail::restoreCreaseAngles(results.graph, angle_of, renumbered);
  // each new edge the turn of the crease that holds most of its cells
  const std::vector<double> turns = contactCreaseTurns(
    creases, cell_labels, results.segmentation.regionClasses(), fresh);
  for (std::uint32_t label = 1; label < turns.size(); ++label)
    if (std::isfinite(turns[label]))
      results.graph.setCreaseAngle(label, turns[label]);
}

template <typename PointInT, typename PointOutT>
void
VisibilityFeatureEstimation<PointInT, PointOutT>::joinSplitCorners(
  Results& results, const Run& run, PointCloudOut& output) const
{
  if (run.segmentation.raw || !run.segmentation.complete_regions)
    return;
  // A contact crease's corner beside the corner its crease runs to (the crease ends
  // short of it) is one corner split in two (splitCornerMerge). After the corners
  // claimed their points: the one nearer the true corner keeps its point in the
  // joined region.
  const auto mergeKeepingAngles = [&](const std::vector<std::uint32_t>& into) {
    const std::vector<double> angle_of = detail::creaseAnglesOf(results.graph);
    detail::restoreCreaseAngles(results.graph, angle_of,
                                applyRegionMerge(results, run, output, into));
  };
  mergeKeepingAngles(splitCornerMerge(
    results.graph, detail::splitCornerDistance(results.band, run.segmentation)));
  // Then a few cells of ridge at a corner, too few points to measure a turn, dead
  // ending there (cornerSpurMerge), join the corner.
  mergeKeepingAngles(
    cornerSpurMerge(results.graph, CreaseAngleParameters::kMinSidePoints));
  // And a corner at the end of one edge only, beside the corner of the edge's two
  // faces (deadEndCornerMerge), joins its edge: the bridges take the edge on.
  mergeKeepingAngles(deadEndCornerMerge(results.graph));
  // A face sliver bounded by one crease between two corners (openFaceMerge) joins the
  // face it was cut from; the vertex that then lies inside one crease
  // (creaseInnerVertexMerge) joins it.
  mergeKeepingAngles(
    openFaceMerge(results.graph, results.band, results.segmentation.cellLabels()));
  mergeKeepingAngles(creaseInnerVertexMerge(results.graph));
}

template <typename PointInT, typename PointOutT>
void
VisibilityFeatureEstimation<PointInT, PointOutT>::joinAddedRegions(
  Results& results,
  const Run& run,
  PointCloudOut& output,
  const std::vector<std::uint32_t>& into,
  const std::vector<std::uint32_t>& renumbered,
  const std::vector<double>& angle_of) const
{
  const std::vector<std::uint32_t> joined =
    applyRegionMerge(results, run, output, into);
  if (joined.empty())
    buildGraph(results, run, output);
  std::vector<std::uint32_t> now = renumbered; // through both renumberings
  if (!joined.empty())
    for (std::uint32_t& label : now)
      label = joined[label];
  detail::restoreCreaseAngles(results.graph, angle_of, now);
}

template <typename PointInT, typename PointOutT>
void
VisibilityFeatureEstimation<PointInT, PointOutT>::bridgeEdgesToCorners(
  Results& results, const Run& run, PointCloudOut& output) const
{
  // Meshes: the resolution search raises the resolution while such gaps are left
  // (kSearchOnGraphGaps), which separates the features instead of bridging them.
  if (run.segmentation.raw || !run.segmentation.complete_regions ||
      run.fill == SurfaceFill::kMesh)
    return;
  const std::vector<EdgeBridge> bridges =
    bridgesToCorners(results.band, results.segmentation.cellLabels(), results.graph,
                     2.0 * run.segmentation.vertex_reach, run.graph.dilation_radius);
  if (bridges.empty())
    return;
  const std::vector<double> angle_of = detail::creaseAnglesOf(results.graph);
  // each bridge a new edge region, which then joins its edge
  std::vector<std::vector<CellId>> cells;
  for (const EdgeBridge& bridge : bridges)
    cells.push_back(bridge.cells);
  const std::vector<std::uint32_t> renumbered = results.segmentation.addRegions(
    cells, std::vector<FeatureClass>(cells.size(), FeatureClass::kEdge));
  relabelAddedPoints(results, output, renumbered);
  std::vector<std::uint32_t> into(results.segmentation.regions().size() + 1);
  std::iota(into.begin(), into.end(), 0u);
  for (const EdgeBridge& bridge : bridges) {
    const std::uint32_t added =
      results.segmentation.cellLabels()[static_cast<std::size_t>(bridge.cells[0])];
    if (into[added] == added && added != renumbered[bridge.edge])
      into[added] = renumbered[bridge.edge]; // (a cell two bridges share: the first's)
  }
  joinAddedRegions(results, run, output, into, renumbered, angle_of);
}

template <typename PointInT, typename PointOutT>
void
VisibilityFeatureEstimation<PointInT, PointOutT>::placeCornersAtMeets(
  Results& results, const Run& run, PointCloudOut& output) const
{
  if (run.segmentation.raw || !run.segmentation.complete_regions)
    return;
  const VoxelBand& band = results.band;
  std::vector<Eigen::Vector3d> points(output.size());
  std::vector<std::uint32_t> labels(output.size());
  for (std::size_t i = 0; i < output.size(); ++i) {
    points[i] =
      band.grid().toCellUnits(output[i].getVector3fMap().template cast<double>());
    labels[i] = output[i].label;
  }
  CornerMeetParameters parameters;
  parameters.max_point_distance =
    kCornerClaimDistances * run.segmentation.point_feature_distance;
  std::vector<std::uint64_t> points_per_label(results.segmentation.regions().size() + 1,
                                              0);
  for (const std::uint32_t label : labels)
    if (label < points_per_label.size())
      ++points_per_label[label];
  // Each corner takes the point nearest its meet, and the face cells around it
  // (within point_feature_distance of the point's cell): a region joined to the
  // corner, so the graph joins the corner to the creases that end there.
  const auto vertex = static_cast<std::uint8_t>(FeatureClass::kVertex);
  const double ball = std::max(1.0, run.segmentation.point_feature_distance);
  const int reach = static_cast<int>(std::floor(ball));
  std::vector<std::vector<CellId>> blobs;
  std::vector<std::uint32_t> owners;
  bool moved = false;
  for (const CornerMeet& m : cornerMeets(results.graph, points, labels, parameters)) {
    if (m.point == CornerMeet::kNoPoint)
      continue;
    PointOutT& p = output[m.point];
    // the vertex's own point already, another vertex's, or a region's last point
    if (p.label == m.vertex || p.feature_class == vertex ||
        points_per_label[p.label] < 2)
      continue;
    --points_per_label[p.label];
    ++points_per_label[m.vertex];
    p.label = m.vertex;
    p.feature_class = vertex;
    moved = true;
    const CellId cell =
      bandCellOf(band, static_cast<std::size_t>((*indices_)[m.point]));
    if (cell == kNoCell)
      continue;
    std::vector<CellId> blob;
    for (int dz = -reach; dz <= reach; ++dz)
      for (int dy = -reach; dy <= reach; ++dy)
        for (int dx = -reach; dx <= reach; ++dx) {
          const CellId c = band.find(band.coord(cell) + CellCoord(dx, dy, dz));
          if (c != kNoCell && dx * dx + dy * dy + dz * dz <= ball * ball)
            blob.push_back(c);
        }
    blobs.push_back(std::move(blob));
    owners.push_back(m.vertex);
  }
  if (!moved)
    return;
  if (blobs.empty()) {
    detail::refreshPointGeometry(results.segmentation.regions().size(), output,
                                 results.graph);
    return;
  }
  const std::vector<double> angle_of = detail::creaseAnglesOf(results.graph);
  const std::vector<std::uint32_t> renumbered = results.segmentation.addRegions(
    blobs, std::vector<FeatureClass>(blobs.size(), FeatureClass::kVertex));
  relabelAddedPoints(results, output, renumbered);
  // the new regions (the labels no old one maps to) join their corners
  const std::vector<std::uint32_t>& cell_labels = results.segmentation.cellLabels();
  std::vector<std::uint32_t> into(results.segmentation.regions().size() + 1);
  std::iota(into.begin(), into.end(), 0u);
  std::vector<char> old(into.size(), 0);
  for (const std::uint32_t label : renumbered)
    old[label] = 1;
  for (std::size_t k = 0; k < blobs.size(); ++k)
    for (const CellId c : blobs[k]) {
      const std::uint32_t label = cell_labels[static_cast<std::size_t>(c)];
      if (label != 0 && !old[label])
        into[label] = renumbered[owners[k]];
    }
  joinAddedRegions(results, run, output, into, renumbered, angle_of);
}

} // namespace visfeat
