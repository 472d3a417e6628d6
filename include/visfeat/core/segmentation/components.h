#pragma once

#include <visfeat/core/band/voxel_band.h>
#include <visfeat/core/common/feature_class.h>
#include <visfeat/core/visibility/visibility_map.h>

#include <cstdint>
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
   * The paper uses 11. We default to 16: at 11, 14-19% of the valley cells 3-5 cells
   * from an icosahedron edge (dihedral 138 degrees) reach the threshold and faces
   * leak into edges; at 16 the valley stays below it, while edge ridges and face cores
   * (more than ~10 cells from an edge) stay above. Needs max_radius >= min_radius. */
  int min_radius = 16;
  /** \brief Components with at most this many cells are vertex candidates (paper: 25).
   * Vertex blobs hold the cells within 1-2 cells of a corner; keep it at 25. */
  int vertex_max_cells = 25;
  /** \brief Raw mode only: a component is an edge when the mean number of
   * same-component 6-neighbours of its cells is below this (paper: 3.5). */
  double dimensionality = 3.5;
  /** \brief Default mode: a component is a face when one of its cells lies at least
   * this many 6-steps inside it (from its border); thinner ones are edges or vertices.
   * Edge ridges are 2-4 cells wide (depth <= 2), face cores span tens of cells. */
  int face_min_depth = 4;
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
 * radius reaches min_radius, numbered 1.. in the order of their smallest cell id.
 *
 * Classification: vertex if cells <= vertex_max_cells; otherwise, raw mode: edge if
 * mean_neighbours < dimensionality, else face; default mode: face if depth >=
 * face_min_depth, else edge (depth does not care whether the edge is straight or
 * circular, unlike a principal-axis measure).
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

  /** \brief Throws visfeat::Error naming the first parameter out of range, with its
   * value, range and unit: min_radius in [1, max_radius] (rings), vertex_max_cells in
   * [0, 100000] (cells), dimensionality in [0, 6], face_min_depth in [1, 1000]
   * (cells). */
  static void validate(const ComponentParameters& parameters, int max_radius);

  /** \brief Per cell (size n), its component label (1-based), 0 for cells below
   * min_radius. */
  const std::vector<std::uint32_t>& cellLabels() const { return labels_; }

  /** \brief components()[label - 1]. */
  const std::vector<Component>& components() const { return components_; }

private:
  std::vector<std::uint32_t> labels_;
  std::vector<Component> components_;
};

} // namespace visfeat
