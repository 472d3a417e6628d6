#include <visfeat/core/common/error.h>
#include <visfeat/core/segmentation/attached_ridges.h>
#include <visfeat/core/segmentation/components.h>
#include <visfeat/core/segmentation/flat_cores.h>
#include <visfeat/core/segmentation/narrow_faces.h>

#include <algorithm>
#include <limits>
#include <sstream>

namespace visfeat {
namespace {

/** Cells left out of every core between a face core and a ridge split off it
 * (attachedRidges()) while the components are extracted; 0 afterwards. */
constexpr std::uint32_t kGapLabel = std::numeric_limits<std::uint32_t>::max();

/** The cells of a face core split by attachedRidges() until their piece is labelled. */
constexpr std::uint32_t kUnassignedLabel = kGapLabel - 1;

} // namespace

void
ComponentParameters::validate(int max_radius) const
{
  if (!kMinRadiusRange.contains(min_radius) || min_radius > max_radius) {
    std::ostringstream msg;
    msg << "min_radius " << min_radius << " is out of range [" << kMinRadiusRange.min
        << ", max_radius = " << max_radius
        << "] (rings; raise max_radius to at least min_radius)";
    throw Error(msg.str());
  }
  checkRange("vertex_max_cells", vertex_max_cells, kVertexMaxCellsRange, "cells");
  checkRange("dimensionality", dimensionality, kDimensionalityRange,
             "mean same-component 6-neighbours");
  checkRange("face_min_depth", face_min_depth, kFaceMinDepthRange, "cells");
  checkRange("narrow_face_persistence", narrow_face_persistence,
             kNarrowFacePersistenceRange, "rings");
}

void
ComponentSet::validate(const ComponentParameters& p, int max_radius)
{
  p.validate(max_radius);
}

Component
ComponentSet::measure(const VoxelBand& band,
                      const std::vector<CellId>& members,
                      std::vector<std::uint32_t>& depth) const
{
  const std::uint32_t label = labels_[static_cast<std::size_t>(members.front())];
  Component component;
  component.cells = static_cast<std::uint32_t>(members.size());
  // Dimensionality (paper) and depth: BFS inwards from the border cells.
  std::uint64_t same = 0;
  std::vector<CellId> frontier;
  for (const CellId c : members) {
    bool border = false;
    for (const CellId nb : band.neighbours(c)) {
      if (nb == kNoCell)
        continue; // off the band (the band is a surface: most cells have such sides)
      if (labels_[static_cast<std::size_t>(nb)] == label)
        ++same;
      else
        border = true; // a band neighbour outside the component
    }
    depth[static_cast<std::size_t>(c)] = border ? 0 : std::uint32_t(-1);
    if (border)
      frontier.push_back(c);
  }
  for (std::size_t head = 0; head < frontier.size(); ++head) {
    const std::uint32_t d = depth[static_cast<std::size_t>(frontier[head])] + 1;
    for (const CellId nb : band.neighbours(frontier[head]))
      if (nb != kNoCell && labels_[static_cast<std::size_t>(nb)] == label &&
          depth[static_cast<std::size_t>(nb)] > d) {
        depth[static_cast<std::size_t>(nb)] = d;
        frontier.push_back(nb);
        component.depth = std::max(component.depth, d);
      }
  }
  if (frontier.empty()) // the component is a whole closed piece of the band
    component.depth = component.cells;
  component.mean_neighbours = static_cast<float>(double(same) / double(members.size()));
  return component;
}

ComponentSet
ComponentSet::extract(const VoxelBand& band,
                      const VisibilityMap& map,
                      const ComponentParameters& parameters,
                      bool raw)
{
  validate(parameters, map.parameters().max_radius);
  const std::size_t n = band.size();
  ComponentSet set;
  set.labels_.assign(n, 0);
  std::vector<CellId> members;
  std::vector<std::uint32_t> depth(n, 0);
  std::vector<std::uint32_t> stamp(n, 0);
  std::uint32_t next_stamp = 0;
  // thin cores that may be the middle of a face (flat_core_faces): label, a cell
  std::vector<std::pair<std::uint32_t, CellId>> thin;
  const std::size_t thin_min_cells = static_cast<std::size_t>(parameters.min_radius) *
                                     static_cast<std::size_t>(parameters.min_radius);
  // Measures and classifies the component of `cells` (labelled with the next label).
  const auto add = [&](const std::vector<CellId>& cells, const Component* measured) {
    const auto label = static_cast<std::uint32_t>(set.components_.size() + 1);
    Component component = measured ? *measured : set.measure(band, cells, depth);
    if (cells.size() <= static_cast<std::size_t>(parameters.vertex_max_cells))
      component.feature_class = FeatureClass::kVertex;
    else if (raw)
      component.feature_class = component.mean_neighbours < parameters.dimensionality
                                  ? FeatureClass::kEdge
                                  : FeatureClass::kFace;
    else if (component.depth >= static_cast<std::uint32_t>(parameters.face_min_depth))
      component.feature_class = FeatureClass::kFace;
    else {
      component.feature_class = FeatureClass::kEdge;
      if (parameters.flat_core_faces && cells.size() >= thin_min_cells)
        thin.emplace_back(label, cells.front());
    }
    set.components_.push_back(component);
  };
  for (std::size_t seed = 0; seed < n; ++seed) {
    if (set.labels_[seed] != 0 || map.radii()[seed] < parameters.min_radius)
      continue;
    const auto label = static_cast<std::uint32_t>(set.components_.size() + 1);
    members.assign(1, static_cast<CellId>(seed));
    set.labels_[seed] = label;
    for (std::size_t head = 0; head < members.size(); ++head)
      for (const CellId nb : band.neighbours(members[head]))
        if (nb != kNoCell && set.labels_[static_cast<std::size_t>(nb)] == 0 &&
            map.radius(nb) >= parameters.min_radius) {
          set.labels_[static_cast<std::size_t>(nb)] = label;
          members.push_back(nb);
        }
    const Component whole = set.measure(band, members, depth);
    RidgeSplit split;
    if (!raw &&
        members.size() > static_cast<std::size_t>(parameters.vertex_max_cells) &&
        whole.depth >= static_cast<std::uint32_t>(parameters.face_min_depth))
      split =
        attachedRidges(band, members, depth, parameters.min_radius, stamp, next_stamp);
    if (split.ridges.empty()) {
      add(members, &whole);
      continue;
    }
    // Each piece of the face core left is a component of its own, then each ridge;
    // until its turn, a list's cells belong to none (measure() reads the labels).
    for (const CellId c : members)
      set.labels_[static_cast<std::size_t>(c)] = kUnassignedLabel;
    for (const CellId c : split.gap)
      set.labels_[static_cast<std::size_t>(c)] = kGapLabel;
    for (const auto* list : {&split.face_pieces, &split.ridges})
      for (const std::vector<CellId>& cells : *list) {
        const auto cells_label = static_cast<std::uint32_t>(set.components_.size() + 1);
        for (const CellId c : cells)
          set.labels_[static_cast<std::size_t>(c)] = cells_label;
        add(cells, nullptr);
      }
  }
  if (!thin.empty())
    set.findFlatCores(band, thin);
  if (!raw && parameters.narrow_face_persistence > 0)
    set.addNarrowFaceCores(band, map, parameters, depth);
  for (std::uint32_t& label : set.labels_)
    if (label == kGapLabel)
      label = 0;
  return set;
}

void
ComponentSet::findFlatCores(const VoxelBand& band,
                            const std::vector<std::pair<std::uint32_t, CellId>>& thin)
{
  std::vector<std::uint32_t> stamp(band.size(), 0);
  std::uint32_t next_stamp = 0;
  std::vector<CellId> members;
  for (const auto& [label, seed] : thin) {
    members.assign(1, seed);
    stamp[static_cast<std::size_t>(seed)] = ++next_stamp;
    for (std::size_t head = 0; head < members.size(); ++head)
      for (const CellId nb : band.neighbours(members[head]))
        if (nb != kNoCell && labels_[static_cast<std::size_t>(nb)] == label &&
            stamp[static_cast<std::size_t>(nb)] != next_stamp) {
          stamp[static_cast<std::size_t>(nb)] = next_stamp;
          members.push_back(nb);
        }
    if (flatCore(band, members, stamp, next_stamp))
      components_[label - 1].feature_class = FeatureClass::kFace;
  }
}

void
ComponentSet::addNarrowFaceCores(const VoxelBand& band,
                                 const VisibilityMap& map,
                                 const ComponentParameters& parameters,
                                 std::vector<std::uint32_t>& depth)
{
  const int min_radius = parameters.min_radius;
  std::vector<NarrowFace> faces = narrowFaces(
    band, map, min_radius, parameters.narrow_face_persistence,
    static_cast<std::size_t>(min_radius) * static_cast<std::size_t>(min_radius));
  // Each core is the upper half of its peak; the highest cut first, so that a peak
  // nested in a wider one keeps its own core.
  const auto cut = [](const NarrowFace& f) {
    return f.saddle + (f.peak - f.saddle + 1) / 2;
  };
  std::stable_sort(
    faces.begin(), faces.end(),
    [&](const NarrowFace& a, const NarrowFace& b) { return cut(a) > cut(b); });
  std::vector<CellId> members;
  for (const NarrowFace& face : faces) {
    const auto label = static_cast<std::uint32_t>(components_.size() + 1);
    // a cell next to another core stays out: cores never touch
    const auto free = [&](CellId c) {
      if (labels_[static_cast<std::size_t>(c)] != 0)
        return false;
      for (const CellId nb : band.neighbours(c))
        if (nb != kNoCell && labels_[static_cast<std::size_t>(nb)] != 0 &&
            labels_[static_cast<std::size_t>(nb)] != label)
          return false;
      return true;
    };
    if (!free(face.peak_cell))
      continue;
    const int level = cut(face);
    members.assign(1, face.peak_cell);
    labels_[static_cast<std::size_t>(face.peak_cell)] = label;
    for (std::size_t head = 0; head < members.size(); ++head)
      for (const CellId nb : band.neighbours(members[head]))
        if (nb != kNoCell && map.radius(nb) >= level && free(nb)) {
          labels_[static_cast<std::size_t>(nb)] = label;
          members.push_back(nb);
        }
    Component component = measure(band, members, depth);
    component.feature_class = FeatureClass::kFace; // a face by what it is, any depth
    components_.push_back(component);
  }
}

} // namespace visfeat
