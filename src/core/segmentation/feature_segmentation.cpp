// FeatureSegmentation: the driver of the steps (segmentation_steps.h), parameter
// checks and the final numbering.

#include "segmentation_steps.h"

#include <visfeat/core/common/error.h>
#include <visfeat/core/segmentation/feature_segmentation.h>

#include <limits>
#include <string>

namespace visfeat {
namespace segmentation {

void
applyUnion(SegmentationState& state)
{
  for (std::size_t c = 0; c < state.labels.size(); ++c) {
    if (state.labels[c] == 0)
      continue;
    state.labels[c] = state.sets.find(state.labels[c]);
    if (!state.parameters.complete_regions && state.core_of[c] == 0)
      state.labels[c] = 0;
  }
}

} // namespace segmentation

namespace {

/** Renumbers the labels 1.. in the order of each region's smallest cell id and
 * counts the regions' cells and core cells. classes: per label, its class. */
std::vector<Region>
numberRegions(std::vector<std::uint32_t>& labels,
              const std::vector<FeatureClass>& classes,
              const std::vector<std::uint32_t>& core_of)
{
  std::vector<Region> regions;
  std::vector<std::uint32_t> renumber(classes.size(), 0);
  for (std::size_t c = 0; c < labels.size(); ++c) {
    std::uint32_t& label = labels[c];
    if (label == 0)
      continue;
    if (renumber[label] == 0) {
      regions.push_back(Region{classes[label], 0, 0});
      renumber[label] = static_cast<std::uint32_t>(regions.size());
    }
    label = renumber[label];
    Region& region = regions[label - 1];
    ++region.cells;
    if (core_of[c] != 0)
      ++region.core_cells;
  }
  return regions;
}

/** numberRegions() on labels, and per label before (index < classes.size()) its label
 * after; 0 for a label no cell holds. */
std::vector<std::uint32_t>
renumberRegions(std::vector<std::uint32_t>& labels,
                const std::vector<FeatureClass>& classes,
                const std::vector<std::uint32_t>& core_of,
                std::vector<Region>& regions)
{
  const std::vector<std::uint32_t> before = labels;
  regions = numberRegions(labels, classes, core_of);
  std::vector<std::uint32_t> after(classes.size(), 0);
  for (std::size_t c = 0; c < labels.size(); ++c)
    after[before[c]] = labels[c];
  return after;
}

} // namespace

void
FeatureSegmentation::validate(const SegmentationParameters& p, int max_radius)
{
  p.validate(max_radius);
}

std::array<std::size_t, 4>
FeatureSegmentation::classCounts() const
{
  std::array<std::size_t, 4> counts{};
  for (const Region& r : regions_)
    ++counts[static_cast<std::size_t>(r.feature_class)];
  return counts;
}

FeatureSegmentation
FeatureSegmentation::compute(const VoxelBand& band,
                             const VisibilityMap& map,
                             const SegmentationParameters& parameters)
{
  using namespace segmentation;
  validate(parameters, map.parameters().max_radius);
  FeatureSegmentation result;
  // 1. Cores; those in outlier pieces seed nothing.
  result.cores_ =
    ComponentSet::extract(band, map, parameters.components, parameters.raw);
  SegmentationState state(band, map, parameters, result.cores_);
  if (parameters.raw) {
    state.labels = state.seeds;
  } else {
    growCoresIntoRegions(state); // 2. watershed
    classifyByFaces(state);      // 3. edges, specks and vertices
    findVertices(state);
    mergeSpecks(state);
    joinEdgeFragments(state); // 4. one region per edge and per corner
    joinCornersSharingEdges(state);
    applyUnion(state);
    if (parameters.complete_regions) { // 5. thin edges and vertices to skeletons
      ThinningState thinning(state);
      findVertexEdgePairs(thinning);
      if (splitMergedCorners(thinning))
        findVertexEdgePairs(thinning);
      cornersAtFreeEnds(thinning);
      centreStraightEdges(thinning);
      drawCorners(thinning);
      traceRidgePaths(thinning);
      bridgeSkeletonGaps(thinning);
      cutToSkeletonWidth(thinning);
      rejoinCutPairs(thinning);
      middleOfSkeleton(thinning);
      result.skeleton_ = std::move(thinning.skeleton);
      result.skeleton_centres_ = std::move(thinning.centres);
      result.skeleton_tangents_ = std::move(thinning.tangents);
    }
  }
  result.regions_ = numberRegions(state.labels, state.cls, state.core_of);
  result.labels_ = std::move(state.labels);
  return result;
}

std::vector<std::uint32_t>
FeatureSegmentation::mergeRegions(const std::vector<std::uint32_t>& into)
{
  const std::size_t n = regions_.size();
  if (into.size() != n + 1)
    throw Error("mergeRegions: " + std::to_string(into.size()) + " entries for " +
                std::to_string(n) + " regions (one per label and index 0)");
  std::vector<FeatureClass> classes(n + 1, FeatureClass::kNone);
  for (std::size_t l = 1; l <= n; ++l) {
    if (into[l] == 0 || into[l] > n || into[into[l]] != into[l])
      throw Error("mergeRegions: region " + std::to_string(l) + " joins " +
                  std::to_string(into[l]) + ", not a kept region");
    classes[l] = regions_[into[l] - 1].feature_class;
  }
  for (std::size_t c = 0; c < labels_.size(); ++c) {
    std::uint32_t& label = labels_[c];
    if (label == 0)
      continue;
    label = into[label];
    if (classes[label] == FeatureClass::kFace && !skeleton_.empty() && skeleton_[c]) {
      skeleton_[c] = 0;
      skeleton_centres_[c] =
        Eigen::Vector3f::Constant(std::numeric_limits<float>::quiet_NaN());
      skeleton_tangents_[c] = Eigen::Vector3f::Zero();
    }
  }
  const std::vector<std::uint32_t> after =
    renumberRegions(labels_, classes, cores_.cellLabels(), regions_);
  std::vector<std::uint32_t> renumbered(n + 1, 0);
  for (std::size_t l = 1; l <= n; ++l)
    renumbered[l] = after[into[l]];
  return renumbered;
}

std::vector<std::uint32_t>
FeatureSegmentation::addEdgeRegions(const std::vector<std::vector<CellId>>& cells)
{
  return addRegions(cells,
                    std::vector<FeatureClass>(cells.size(), FeatureClass::kEdge));
}

std::vector<std::uint32_t>
FeatureSegmentation::addRegions(const std::vector<std::vector<CellId>>& cells,
                                const std::vector<FeatureClass>& list_classes)
{
  if (list_classes.size() != cells.size())
    throw Error("addRegions: " + std::to_string(cells.size()) + " lists of cells but " +
                std::to_string(list_classes.size()) + " classes");
  // a list takes the cells of lower rank: faces for an edge, faces and edges for a
  // vertex
  const auto rank = [](FeatureClass c) {
    return c == FeatureClass::kFace     ? 1
           : c == FeatureClass::kEdge   ? 2
           : c == FeatureClass::kVertex ? 3
                                        : 0;
  };
  const std::size_t n = regions_.size();
  std::vector<FeatureClass> classes(n + cells.size() + 1, FeatureClass::kNone);
  for (std::size_t l = 1; l <= n; ++l)
    classes[l] = regions_[l - 1].feature_class;
  for (std::size_t r = 0; r < cells.size(); ++r) {
    if (list_classes[r] != FeatureClass::kEdge &&
        list_classes[r] != FeatureClass::kVertex)
      throw Error("addRegions: a new region must be an edge or a vertex");
    classes[n + 1 + r] = list_classes[r];
  }
  for (std::size_t r = 0; r < cells.size(); ++r) {
    const auto label_of_list = static_cast<std::uint32_t>(n + 1 + r);
    for (const CellId c : cells[r]) {
      if (c < 0 || static_cast<std::size_t>(c) >= labels_.size())
        throw Error("addRegions: cell " + std::to_string(c) + " is not one of the " +
                    std::to_string(labels_.size()) + " band cells");
      std::uint32_t& label = labels_[static_cast<std::size_t>(c)];
      // old regions keep their edges and vertices; new lists take from earlier ones
      const bool old_feature =
        label != 0 && label <= n && classes[label] != FeatureClass::kFace;
      if (label != 0 && !old_feature && rank(classes[label]) < rank(list_classes[r]))
        label = label_of_list;
    }
  }
  // an old region whose cells all moved holds no cell any more: 0
  std::vector<std::uint32_t> renumbered =
    renumberRegions(labels_, classes, cores_.cellLabels(), regions_);
  renumbered.resize(n + 1);
  return renumbered;
}

std::vector<std::uint32_t>
FeatureSegmentation::moveFaceCells(const std::vector<std::vector<CellId>>& cells,
                                   const std::vector<std::uint32_t>& faces)
{
  if (faces.size() != cells.size())
    throw Error("moveFaceCells: " + std::to_string(cells.size()) +
                " lists of cells but " + std::to_string(faces.size()) + " faces");
  const std::size_t n = regions_.size();
  std::vector<FeatureClass> classes(n + 1, FeatureClass::kNone);
  for (std::size_t l = 1; l <= n; ++l)
    classes[l] = regions_[l - 1].feature_class;
  for (std::size_t r = 0; r < cells.size(); ++r) {
    if (faces[r] == 0 || faces[r] > n || classes[faces[r]] != FeatureClass::kFace)
      throw Error("moveFaceCells: region " + std::to_string(faces[r]) +
                  " is not a face region");
    for (const CellId c : cells[r]) {
      if (c < 0 || static_cast<std::size_t>(c) >= labels_.size())
        throw Error("moveFaceCells: cell " + std::to_string(c) + " is not one of the " +
                    std::to_string(labels_.size()) + " band cells");
      std::uint32_t& label = labels_[static_cast<std::size_t>(c)];
      if (label != 0 && classes[label] == FeatureClass::kFace)
        label = faces[r];
    }
  }
  std::vector<std::uint32_t> renumbered =
    renumberRegions(labels_, classes, cores_.cellLabels(), regions_);
  renumbered.resize(n + 1);
  return renumbered;
}

std::vector<std::uint32_t>
FeatureSegmentation::splitFaces(const std::vector<std::vector<CellId>>& cells)
{
  const std::size_t n = regions_.size();
  std::vector<FeatureClass> classes(n + cells.size() + 1, FeatureClass::kFace);
  classes[0] = FeatureClass::kNone;
  for (std::size_t l = 1; l <= n; ++l)
    classes[l] = regions_[l - 1].feature_class;
  for (std::size_t r = 0; r < cells.size(); ++r)
    for (const CellId c : cells[r]) {
      if (c < 0 || static_cast<std::size_t>(c) >= labels_.size())
        throw Error("splitFaces: cell " + std::to_string(c) + " is not one of the " +
                    std::to_string(labels_.size()) + " band cells");
      std::uint32_t& label = labels_[static_cast<std::size_t>(c)];
      if (label != 0 && label <= n && classes[label] == FeatureClass::kFace)
        label = static_cast<std::uint32_t>(n + 1 + r);
    }
  std::vector<std::uint32_t> renumbered =
    renumberRegions(labels_, classes, cores_.cellLabels(), regions_);
  renumbered.resize(n + 1);
  return renumbered;
}

} // namespace visfeat
