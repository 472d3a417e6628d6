// Steps 2 and 3 of FeatureSegmentation: the watershed, then each region judged by the
// faces it touches, the vertex test, and the specks merged into their neighbours.

#include "segmentation_steps.h"

#include <visfeat/core/segmentation/flat_cores.h>
#include <visfeat/core/segmentation/region_growing.h>

#include <algorithm>

namespace visfeat {
namespace segmentation {
namespace {

/** Two pieces of a small core's own edge lie on opposite sides of it when the
 * directions from its centroid to theirs make an angle above 120 degrees (cosine
 * below this). Set on the U prism (seed 1, 256), whose 60-cell notch edge broke into
 * five small cores that all passed the vertex test; pieces beside a true corner lie
 * on one side of it. Not swept. */
constexpr double kOppositeCosine = -0.5;

/** The face regions a region touches, as (shared boundary, face), most boundary
 * first. */
std::vector<std::pair<std::uint32_t, std::uint32_t>>
faceNeighbours(const std::vector<FeatureClass>& cls,
               const Contacts& contacts,
               std::uint32_t a)
{
  std::vector<std::pair<std::uint32_t, std::uint32_t>> faces;
  for (auto it = contacts.lower_bound({a, 0});
       it != contacts.end() && it->first.first == a; ++it)
    if (cls[it->first.second] == FeatureClass::kFace)
      faces.emplace_back(it->second, it->first.second);
  std::sort(faces.rbegin(), faces.rend());
  return faces;
}

/** A crease fading into its face: an edge core that bends like one
 * (fadingCreaseCore(): more than 5 min_radius cells, a turn of about 40 degrees or
 * more). Where a crease's valley fades (a fin that sinks into a
 * face, a crease that turns shallow towards one end) the face's core reaches around its
 * end, the watershed puts one face on both its sides, and the speck rule would merge it
 * into that face. */
bool
fadingCrease(const SegmentationState& state,
             std::uint32_t l,
             std::vector<std::uint32_t>& stamp,
             std::uint32_t& next_stamp)
{
  return state.cores[l - 1].feature_class == FeatureClass::kEdge &&
         fadingCreaseCore(state.band, state.core_cells[l],
                          state.parameters.components.min_radius, stamp, next_stamp);
}

/** The neighbour a region shares the most boundary with (the smallest label of
 * equals); 0 if it touches none. */
std::uint32_t
largestNeighbour(const Contacts& contacts, std::uint32_t a)
{
  std::uint32_t best = 0, best_contact = 0;
  for (auto it = contacts.lower_bound({a, 0});
       it != contacts.end() && it->first.first == a; ++it)
    if (it->second > best_contact) {
      best_contact = it->second;
      best = it->first.second;
    }
  return best;
}

/** Per label, the mean coordinate of its seed cells (zero if none). */
std::vector<Eigen::Vector3d>
coreCentroids(const SegmentationState& state)
{
  std::vector<Eigen::Vector3d> centroid(state.labelCount() + 1,
                                        Eigen::Vector3d::Zero());
  for (std::uint32_t l = 1; l <= state.labelCount(); ++l) {
    for (const CellId c : state.core_cells[l])
      centroid[l] += state.band.coord(c).cast<double>();
    if (!state.core_cells[l].empty())
      centroid[l] /= static_cast<double>(state.core_cells[l].size());
  }
  return centroid;
}

/** A short edge may break into small cores that all pass the vertex test (they reach
 * the edges of both its corners). A small core with pieces of its own edge (same face
 * pair) on opposite sides lies inside that edge, not at a corner. */
bool
insideAnEdge(const SegmentationState& state,
             const std::vector<Eigen::Vector3d>& centroid,
             std::uint32_t l)
{
  const auto own = state.signature.find(l);
  if (own == state.signature.end())
    return false;
  std::vector<Eigen::Vector3d> directions;
  for (const std::uint32_t m : valueOrEmpty(state.reached, l)) {
    const auto other = state.signature.find(m);
    if (other == state.signature.end() || other->second != own->second)
      continue;
    const Eigen::Vector3d d = centroid[m] - centroid[l];
    if (d.norm() > 0.0)
      directions.push_back(d.normalized());
  }
  for (std::size_t i = 0; i < directions.size(); ++i)
    for (std::size_t j = i + 1; j < directions.size(); ++j)
      if (directions[i].dot(directions[j]) < kOppositeCosine)
        return true;
  return false;
}

/** The paper's vertex test on a small core l (in `reached`): the edges it and the
 * cores it reaches separate two different face pairs, or it touches three faces, or
 * it reaches three face cores. */
bool
passesVertexTest(const SegmentationState& state, std::uint32_t l)
{
  std::set<FacePair> met;
  if (const auto own = state.signature.find(l); own != state.signature.end())
    met.insert(own->second);
  std::size_t faces_met = 0;
  for (const std::uint32_t m : state.reached.at(l)) {
    if (const auto other = state.signature.find(m); other != state.signature.end())
      met.insert(other->second);
    faces_met += state.cls[m] == FeatureClass::kFace;
  }
  return state.face_count[l] >= 3 || faces_met >= 3 || met.size() >= 2;
}

/** A corner often holds several small cores (the blob at the tip, ridge specks); the
 * test may pass for one a few cells off and fail for the tip itself, so an accepted
 * vertex takes every small core within its reach (not a face, not inside an edge). */
void
absorbSmallCores(SegmentationState& state, const std::vector<Eigen::Vector3d>& centroid)
{
  const auto vertex_max =
    static_cast<std::uint32_t>(state.parameters.components.vertex_max_cells);
  std::set<std::uint32_t> absorbed(state.vertices.begin(), state.vertices.end());
  for (const std::uint32_t l : std::vector<std::uint32_t>(state.vertices))
    for (const std::uint32_t m : state.reached.at(l))
      if (state.cls[m] != FeatureClass::kFace &&
          state.cores[m - 1].cells <= vertex_max && !insideAnEdge(state, centroid, m) &&
          absorbed.insert(m).second)
        state.vertices.push_back(m);
}

/** Sets left of specks only (specks that merged into specks) go to their classified
 * neighbour with the most shared boundary, until none touches one. */
void
mergeSpeckChains(SegmentationState& state)
{
  for (bool changed = true; changed;) {
    changed = false;
    const Contacts around = state.contacts.through(state.sets);
    std::map<std::uint32_t, std::pair<std::uint32_t, std::uint32_t>>
      best; // root -> (contact, to)
    for (const auto& [pair, count] : around) {
      if (state.cls[pair.first] != FeatureClass::kNone ||
          state.cls[pair.second] == FeatureClass::kNone)
        continue;
      const auto it = best.find(pair.first);
      if (it == best.end() || count > it->second.first)
        best[pair.first] = {count, pair.second};
    }
    for (const auto& [root, target] : best) {
      state.sets.attach(target.second, root);
      changed = true;
    }
  }
}

} // namespace

void
growCoresIntoRegions(SegmentationState& state)
{
  state.labels = growRegions(state.band, state.map, state.seeds);
  state.contacts = LabelContacts(state.band, state.labels);
  state.core_cells.assign(state.labelCount() + 1, {});
  for (std::size_t c = 0; c < state.seeds.size(); ++c)
    if (state.seeds[c] != 0)
      state.core_cells[state.seeds[c]].push_back(static_cast<CellId>(c));
}

void
classifyByFaces(SegmentationState& state)
{
  // Every label is still its own set: the label contacts are the sets'.
  const Contacts& contacts = state.contacts.byLabel();
  std::vector<std::uint32_t> stamp(state.band.size(), 0);
  std::uint32_t next_stamp = 0;
  for (std::uint32_t l = 1; l <= state.labelCount(); ++l) {
    if (state.cls[l] == FeatureClass::kFace)
      continue;
    const auto faces = faceNeighbours(state.cls, contacts, l);
    state.face_count[l] = static_cast<std::uint32_t>(faces.size());
    if (faces.size() == 1 && fadingCrease(state, l, stamp, next_stamp)) {
      state.cls[l] = FeatureClass::kEdge;
      state.signature[l] = {faces[0].second, faces[0].second};
      continue;
    }
    if (faces.size() <= 1) {
      state.cls[l] = FeatureClass::kNone; // a speck unless the vertex test claims it
      state.speck_into[l] = largestNeighbour(contacts, l);
      continue;
    }
    state.cls[l] = FeatureClass::kEdge;
    state.signature[l] = std::minmax(faces[0].second, faces[1].second);
  }
}

void
findVertices(SegmentationState& state)
{
  const auto reach = static_cast<std::uint32_t>(state.parameters.vertex_reach);
  const auto vertex_max =
    static_cast<std::uint32_t>(state.parameters.components.vertex_max_cells);
  std::vector<std::uint32_t> small;
  for (std::uint32_t l = 1; l <= state.labelCount(); ++l)
    if (state.cores[l - 1].feature_class != FeatureClass::kFace &&
        state.cores[l - 1].cells <= vertex_max && !state.core_cells[l].empty())
      small.push_back(l);
  // and the edges' joining reach (joinEdgeFragments()), on the same threads
  std::vector<std::uint32_t> labels = small, steps(small.size(), reach);
  for (const auto& [l, faces] : state.signature)
    if (state.cls[l] == FeatureClass::kEdge && !state.core_cells[l].empty()) {
      labels.push_back(l);
      steps.push_back(joinSteps(state.parameters));
    }
  std::vector<std::set<std::uint32_t>> reached = state.coresWithin(labels, steps);
  for (std::size_t i = 0; i < labels.size(); ++i)
    (i < small.size() ? state.reached : state.edge_reach)[labels[i]] =
      std::move(reached[i]);
  const std::vector<Eigen::Vector3d> centroid = coreCentroids(state);
  for (std::uint32_t l = 1; l <= state.labelCount(); ++l)
    if (state.reached.count(l) && !insideAnEdge(state, centroid, l) &&
        passesVertexTest(state, l))
      state.vertices.push_back(l);
  absorbSmallCores(state, centroid);
  for (const std::uint32_t l : state.vertices) {
    state.cls[l] = FeatureClass::kVertex;
    state.signature.erase(l);
    state.speck_into[l] = 0;
  }
  // Vertex candidates within reach of each other mark one corner.
  const std::set<std::uint32_t> vertex_set(state.vertices.begin(),
                                           state.vertices.end());
  for (const std::uint32_t l : state.vertices)
    for (const std::uint32_t m : state.reached.at(l))
      if (vertex_set.count(m))
        state.sets.join(l, m);
}

void
mergeSpecks(SegmentationState& state)
{
  // A speck joins its neighbour's set; chains of specks resolve through the union.
  for (std::uint32_t l = 1; l <= state.labelCount(); ++l)
    if (state.speck_into[l] != 0) {
      state.sets.attach(state.speck_into[l], l);
      state.speck[l] = 1;
    }
  mergeSpeckChains(state);
}

} // namespace segmentation
} // namespace visfeat
