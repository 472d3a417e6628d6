#pragma once

// Internal to the segmentation (not installed): what its steps share. The steps
// themselves are declared in segmentation_steps.h.

#include "core_line.h"
#include "label_union.h"

#include <visfeat/core/band/band_dilation.h>
#include <visfeat/core/band/voxel_band.h>
#include <visfeat/core/segmentation/components.h>
#include <visfeat/core/segmentation/feature_segmentation.h>
#include <visfeat/core/visibility/visibility_map.h>

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <set>
#include <utility>
#include <vector>

namespace visfeat {
namespace segmentation {

/** \brief The two faces an edge separates (smaller label first). */
using FacePair = std::pair<std::uint32_t, std::uint32_t>;

/** \brief A vertex and an edge (labels), in that order. */
using VertexEdge = std::pair<std::uint32_t, std::uint32_t>;

/** \brief Per label, the mapped value, or an empty one where the label has none (a
 * read that inserts nothing, unlike std::map::operator[]). */
template <typename Map>
const typename Map::mapped_type&
valueOrEmpty(const Map& map, const typename Map::key_type& key)
{
  static const typename Map::mapped_type empty{};
  const auto it = map.find(key);
  return it == map.end() ? empty : it->second;
}

/** \brief The labels of the default mode from the cores to the final regions, shared
 * by the steps of FeatureSegmentation (segmentation_steps.h).
 *
 * Labels are the cores' (1..n, ComponentSet numbering); merging puts them into sets of
 * `sets`, and from the specks' merge on a set's class is read at its root. Cell
 * labels (`labels`) stay the watershed's until applyUnion() writes the roots.
 *
 * The state keeps references to the band, the map, the parameters and the cores:
 * they must outlive it.
 */
struct SegmentationState
{
  /** \brief Seeds = the cores without those in band pieces smaller than
   * parameters.min_piece_cells; classes = the cores'; every label its own set. */
  SegmentationState(const VoxelBand& band,
                    const VisibilityMap& map,
                    const SegmentationParameters& parameters,
                    const ComponentSet& cores);

  const VoxelBand& band;
  const VisibilityMap& map;
  const SegmentationParameters& parameters;
  /** \brief The cores: components()[label - 1]. */
  const std::vector<Component>& cores;
  /** \brief Per cell, its core label (ComponentSet::cellLabels(), outliers included),
   * 0 below min_radius. */
  const std::vector<std::uint32_t>& core_of;

  /** \brief Per cell, its core label, 0 below min_radius and in outlier pieces. */
  std::vector<std::uint32_t> seeds;
  /** \brief Per label (index 0 unused), its seed cells in increasing id order. */
  std::vector<std::vector<CellId>> core_cells;
  /** \brief Per cell, its region label (0 = none). */
  std::vector<std::uint32_t> labels;
  /** \brief Per label (index 0 unused), its class; kNone for a speck. */
  std::vector<FeatureClass> cls;
  LabelUnion sets;
  /** \brief Contacts of the watershed's labels (growCoresIntoRegions). */
  LabelContacts contacts;
  /** \brief Per edge label, the two faces it separates. */
  std::map<std::uint32_t, FacePair> signature;
  /** \brief Per label, the face regions its region touches (classifyByFaces). */
  std::vector<std::uint32_t> face_count;
  /** \brief Per speck label, the neighbour it shares the most boundary with; 0 for
   * non-specks. */
  std::vector<std::uint32_t> speck_into;
  /** \brief Per label, 1 when it merged into a neighbour as a speck. */
  std::vector<char> speck;
  /** \brief Vertex candidates: labels that passed the vertex test or were absorbed. */
  std::vector<std::uint32_t> vertices;
  /** \brief Per small core (<= vertex_max_cells, not a face), the other cores its
   * geodesic dilation reaches within vertex_reach. */
  std::map<std::uint32_t, std::set<std::uint32_t>> reached;
  /** \brief Per edge core after classifyByFaces() (class kEdge, with a signature), the
   * other cores within joinSteps() 6-steps of it: the joining's reach, found with the
   * vertex test's in findVertices() so that both share one team of threads. */
  std::map<std::uint32_t, std::set<std::uint32_t>> edge_reach;
  /** \brief Scratch of the geodesic dilations, one per thread at work (reused between
   * runs). */
  std::vector<std::unique_ptr<BandDilation>> dilations;

  /** \brief The number of core labels. */
  std::uint32_t labelCount() const { return static_cast<std::uint32_t>(cores.size()); }

  /** \brief Per label of `labels`, the other cores (core_of, outliers included) within
   * steps[i] 6-steps through the band of its core cells (core_cells). The labels are
   * independent: they run on parameters.threads threads, the result the same for any
   * count. */
  std::vector<std::set<std::uint32_t>>
  coresWithin(const std::vector<std::uint32_t>& labels,
              const std::vector<std::uint32_t>& steps);
};

/** \brief The ends of an edge's cores and the vertex each links to. */
struct EdgeEnds
{
  /** \brief The farthest pair of its core cells. */
  std::array<CellId, 2> cell{{kNoCell, kNoCell}};
  /** \brief Per end, the linked vertex label (0 = none). */
  std::array<std::uint32_t, 2> vertex{{0, 0}};
};

/** \brief The skeleton of the edge and vertex regions while they are thinned
 * (complete regions), over the labels and classes of a SegmentationState after
 * applyUnion() (labels are set roots). */
struct ThinningState
{
  /** \brief Centres NaN, tangents zero; the skeleton, vertex_cores and edge_cores =
   * the non-speck core cells of the vertex and edge regions; their lines fitted. */
  explicit ThinningState(SegmentationState& state);

  const VoxelBand& band;
  const VisibilityMap& map;
  const SegmentationParameters& parameters;
  const std::vector<std::uint32_t>& core_of;
  const std::vector<char>& speck;
  /** \brief Per cell, its region label (the SegmentationState's, changed in place). */
  std::vector<std::uint32_t>& labels;
  /** \brief Per label, its class (the SegmentationState's, changed in place). */
  std::vector<FeatureClass>& cls;

  /** \brief Per cell, 1 on the skeleton of an edge or vertex region. */
  std::vector<char> skeleton;
  /** \brief Per cell, the middle of the skeleton through it, in cell units (cell
   * (i, j, k) spans [i, i+1) x ...); NaN until set. */
  std::vector<Eigen::Vector3f> centres;
  /** \brief Per cell, the unit direction of the middle line; zero if none. */
  std::vector<Eigen::Vector3f> tangents;
  /** \brief Per vertex / edge region, its skeleton core cells. */
  std::map<std::uint32_t, std::vector<CellId>> vertex_cores, edge_cores;
  /** \brief Per edge in edge_cores, its cores' line, fitted once. */
  std::map<std::uint32_t, CoreLine> core_line;
  /** \brief Vertex-edge pairs (findVertexEdgePairs). */
  std::set<VertexEdge> pairs;
  /** \brief Per edge in edge_cores, its ends (findVertexEdgePairs). */
  std::map<std::uint32_t, EdgeEnds> ends;
  /** \brief Pairs whose edge was drawn to the vertex's corner (drawCorners). */
  std::set<VertexEdge> drawn;

  /** \brief An edge or vertex label. */
  bool isFeature(std::uint32_t label) const
  {
    return label != 0 &&
           (cls[label] == FeatureClass::kEdge || cls[label] == FeatureClass::kVertex);
  }

  /** \brief Sets the centre of cell c to x (cell index units: the centre is stored
   * 0.5 further, in cell units) and its tangent to the unit `direction`. */
  void setCentre(CellId c, const Eigen::Vector3d& x, const Eigen::Vector3d& direction);

  /** \brief Distance between the cells' coordinates (cells). */
  double distance(CellId a, CellId b) const;

  /** \brief The cell of `cells` farthest from `from` (the first of equals; `from` if
   * cells is empty). */
  CellId farthestFrom(CellId from, const std::vector<CellId>& cells) const;

  /** \brief The band cell among the 27 around round(x) (cell index units) nearest to
   * x; kNoCell if none is in the band. */
  CellId nearestCell(const Eigen::Vector3d& x) const;

  /** \brief The band cell within `radius` cells of x (a cube of cells around round(x))
   * nearest to x, the first in z, y, x order among equals; kNoCell if none. */
  CellId nearestCellWithin(const Eigen::Vector3d& x, int radius) const;
};

/** \brief A segment drawn through cells takes this many samples per cell of its
 * length, each marking its nearest band cell: samples 0.25 cells apart, so a cell the
 * segment crosses is missed only where the segment clips its corner. Used by corner
 * drawing and gap bridging; chosen with the corner drawing (145ed0d), not swept. */
constexpr double kSamplesPerCell = 4.0;

} // namespace segmentation
} // namespace visfeat
