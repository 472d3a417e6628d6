#pragma once

#include <visfeat/core/band/voxel_band.h>
#include <visfeat/core/common/feature_class.h>
#include <visfeat/core/common/parameters.h>
#include <visfeat/core/visibility/visibility_map.h>

#include <cstdint>
#include <utility>
#include <vector>

namespace visfeat {

/** \brief Parameters of component extraction and classification (paper, section 5).
 *
 * Radii count rings of cells, so thresholds in cells do not change with resolution
 * as long as features stay many cells apart: at resolution N a feature of size s
 * (fraction of the longest side) spans s*N cells. Below about 128 cells the valleys
 * between features become too narrow for any threshold.
 */
struct ComponentParameters
{
  /** \brief Cells with visibility radius >= min_radius form components (rings).
   * The paper uses 11. Default kDefaultMinRadius (16): at 11, 14-19% of the valley
   * cells 3-5 cells from an icosahedron edge (dihedral 138 degrees) reach the threshold
   * and faces leak into edges; at 16 the valley stays below it, while edge ridges and
   * face cores (more than ~10 cells from an edge) stay above. In cells, so it does not
   * scale with resolution: features closer than about 2 min_radius cells merge.
   * Range kMinRadiusRange and at most the visibility map's max_radius. */
  int min_radius = kDefaultMinRadius;
  /** \brief Components with at most this many cells are vertex candidates (paper: 25).
   * Vertex blobs hold the cells within 1-2 cells of a corner (1-10 cells at any
   * resolution); keep it at 25. Range kVertexMaxCellsRange (cells). */
  int vertex_max_cells = kDefaultVertexMaxCells;
  /** \brief Raw mode only: a component is an edge when the mean number of
   * same-component 6-neighbours of its cells is below this (paper: 3.5). Range
   * kDimensionalityRange. */
  double dimensionality = kDefaultDimensionality;
  /** \brief Default mode: a component is a face when one of its cells lies at least
   * this many 6-steps inside it (from its border); thinner ones are edges or vertices.
   * Edge ridges are 2-4 cells wide (depth <= 2), face cores span tens of cells.
   * Range kFaceMinDepthRange (cells). */
  int face_min_depth = kDefaultFaceMinDepth;
  /** \brief Default mode: a face too narrow for a core (narrower than about
   * 2 min_radius cells, so its middle peaks below min_radius between the valleys of
   * its creases) gets one when its peak stands at least this many rings above the
   * valley that separates it from every higher part of the map (its persistence,
   * visfeat::narrowFaces()) over at least min_radius^2 cells. Its core is the upper
   * half of the peak (cells at or above saddle + ceil((peak - saddle) / 2)), kept one
   * cell away from every other core, and is a face whatever its depth. 0 = off (the
   * paper's single threshold). Default kDefaultNarrowFacePersistence; range
   * kNarrowFacePersistenceRange (rings). Lower values also split curved surfaces
   * whose radius ripples (tessellated cylinders); higher ones lose narrow faces. */
  int narrow_face_persistence = kDefaultNarrowFacePersistence;
  /** \brief Default mode: a core thinner than face_min_depth with at least
   * min_radius^2 cells is a face when the band around it is flat (flatCore(): no bend
   * across it, so it is the middle of a face between two creases about 2 min_radius
   * cells apart, not the ridge of a crease). Off: by depth alone. On (the default),
   * the public fandisk mesh at 512 keeps a 30-cell-wide face between two creases and
   * both creases (per-point F1 0.82 -> 0.88; fandisk and pinion at 256 +0.10), but a
   * tessellated cylinder's map ripples become faces (CGAL joint: 0.82 -> 0.79): README,
   * "Thin face cores". */
  bool flat_core_faces = true;

  static constexpr int kDefaultVertexMaxCells = 25;
  static constexpr double kDefaultDimensionality = 3.5;
  static constexpr int kDefaultFaceMinDepth = 4;
  /** \brief 3 rings, as the resolution search's kNarrowFacePersistence: the 7
   * generated models (10,000 points to dense, 256 cells) have no peak of persistence 3
   * over min_radius^2 cells, so their results do not change; the risers of the stepped
   * block (21 cells, dense cloud) peak at 13-14 rings, 5-6 above their creases'
   * valleys; 4 and 5 found fewer of the public pinion's and fandisk's faces (README,
   * Method). */
  static constexpr int kDefaultNarrowFacePersistence = 3;

  /** \brief [1, VisibilityMap::kMaxRadius] rings; also at most max_radius. */
  static constexpr ParameterRange<int> kMinRadiusRange{1, VisibilityMap::kMaxRadius};
  /** \brief [0, 100000] cells. */
  static constexpr ParameterRange<int> kVertexMaxCellsRange{0, 100000};
  /** \brief [0, 6] mean same-component 6-neighbours. */
  static constexpr ParameterRange<double> kDimensionalityRange{0.0, 6.0};
  /** \brief [1, 1000] cells. */
  static constexpr ParameterRange<int> kFaceMinDepthRange{1, 1000};
  /** \brief [0, VisibilityMap::kMaxRadius] rings; 0 = off. */
  static constexpr ParameterRange<int> kNarrowFacePersistenceRange{
    0, VisibilityMap::kMaxRadius};

  /** \brief Throws visfeat::Error naming the first parameter out of range, with its
   * value, range and unit; min_radius must also be at most max_radius (the cap of the
   * visibility map the components are taken from). */
  void validate(int max_radius) const;
};

/** \brief One component (a "core": cells at or above min_radius, 6-connected). */
struct Component
{
  FeatureClass feature_class = FeatureClass::kNone;
  std::uint32_t cells = 0;
  /** \brief Mean same-component 6-neighbours per cell (the paper's dimensionality). */
  float mean_neighbours = 0.f;
  /** \brief Largest 6-step distance of a cell from the component's border. */
  std::uint32_t depth = 0;
};

/** \brief Components of the visibility map: 6-connected floods of the cells whose
 * radius reaches min_radius, numbered 1.. in the order of their smallest cell id; in
 * default mode then the cores of narrow faces (narrow_face_persistence), numbered on
 * from the highest cut.
 *
 * Classification: vertex if cells <= vertex_max_cells; otherwise, raw mode: edge if
 * mean_neighbours < dimensionality, else face; default mode: face if depth >=
 * face_min_depth (depth does not care whether the edge is straight or circular,
 * unlike a principal-axis measure), or (flat_core_faces) if it has at least
 * min_radius^2 cells and lies on a flat part of the band (flatCore(): the middle of a
 * face about 2 min_radius cells wide between two creases, where the map reaches
 * min_radius only along a strip a few cells wide), else edge. Smaller thin cores on
 * flat parts (specks of a rough band) stay edges, and the segmentation merges them into
 * their face as before. In default mode a face core is first cleared of the edge ridges
 * joined to it where their valleys fade (attachedRidges()): each ridge becomes an edge
 * component numbered right after the face core's pieces (the face core keeps its label
 * for its first piece, in `members` order, if the ridges cut it apart), and the cells
 * between them belong to no component.
 */
class ComponentSet
{
public:
  /** \brief The components of a band (n cells) from its map (one radius per cell).
   * raw: classify by mean_neighbours (the paper's rule) instead of depth.
   * \throws visfeat::Error for parameters out of range (validate(), against the
   * map's max_radius). */
  static ComponentSet extract(const VoxelBand& band,
                              const VisibilityMap& map,
                              const ComponentParameters& parameters,
                              bool raw);

  /** \brief Same as parameters.validate(max_radius). */
  static void validate(const ComponentParameters& parameters, int max_radius);

  /** \brief Per cell (size n), its component label (1-based), 0 for cells below
   * min_radius. */
  const std::vector<std::uint32_t>& cellLabels() const { return labels_; }

  /** \brief components()[label - 1]. */
  const std::vector<Component>& components() const { return components_; }

private:
  /** The thin cores (label, one of their cells) that are faces (see the class). */
  void findFlatCores(const VoxelBand& band,
                     const std::vector<std::pair<std::uint32_t, CellId>>& thin);

  /** Cells, depth and mean neighbours of the component of `members` (labelled);
   * depth: per cell scratch of the band's size. */
  Component measure(const VoxelBand& band,
                    const std::vector<CellId>& members,
                    std::vector<std::uint32_t>& depth) const;
  /** Appends the cores of narrow faces (ComponentParameters::narrow_face_persistence).
   */
  void addNarrowFaceCores(const VoxelBand& band,
                          const VisibilityMap& map,
                          const ComponentParameters& parameters,
                          std::vector<std::uint32_t>& depth);

  std::vector<std::uint32_t> labels_;
  std::vector<Component> components_;
};

} // namespace visfeat
