// The merge of the edges that turn less than the minimum crease angle
// (shallowCreaseMerge(), crease_angles.h): their two faces become one, and the
// vertices and edge pieces that no longer separate anything follow.

#include <visfeat/core/graph/crease_angles.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <vector>

namespace visfeat {

namespace {

/** Union-find whose root is chosen by the caller (attach b's set under a's root). */
struct Joined
{
  std::vector<std::uint32_t> parent;

  explicit Joined(std::size_t n)
      : parent(n + 1)
  {
    for (std::size_t l = 0; l <= n; ++l)
      parent[l] = static_cast<std::uint32_t>(l);
  }
  std::uint32_t find(std::uint32_t a)
  {
    while (parent[a] != a)
      a = parent[a] = parent[parent[a]];
    return a;
  }
  /** b's set joins a's; a's root stays the root. */
  void attach(std::uint32_t a, std::uint32_t b)
  {
    const std::uint32_t ra = find(a), rb = find(b);
    if (ra != rb)
      parent[rb] = ra;
  }
};

/** Each remaining edge of vertex v as the set of its faces' roots; the distinct sets.
 */
std::set<std::vector<std::uint32_t>>
facePairsAt(const TopologyGraph& graph,
            std::uint32_t v,
            const std::vector<char>& removed,
            Joined& joined,
            std::vector<std::uint32_t>& remaining)
{
  std::set<std::vector<std::uint32_t>> pairs;
  for (const std::uint32_t e : graph.neighbours(v, FeatureClass::kEdge)) {
    if (removed[e])
      continue;
    remaining.push_back(e);
    std::vector<std::uint32_t> faces;
    for (const std::uint32_t f : graph.facesOfEdge(e))
      faces.push_back(joined.find(f));
    std::sort(faces.begin(), faces.end());
    faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
    pairs.insert(faces);
  }
  return pairs;
}

/** For a vertex whose creases' face pairs (two faces each) do not close around it,
 * the face every pair holds; 0 otherwise.
 *
 * Around a corner the faces and creases alternate in a cycle, so each face bounds two
 * of its creases (or more). Where one face bounds only one, no crease separates it
 * from the next: the creases pass the vertex by rather than meet at it. Measured on
 * the generated filleted box (rotation 2, thin face cores on): a 3,460-cell vertex
 * region on a fillet bounded top-side, side-bottom, bottom-side' and side'-top; once
 * side and side' were one face, the pairs were top-side and side-bottom, the top and
 * bottom rims passing it by. */
std::uint32_t
sharedFaceOfOpenFan(const std::set<std::vector<std::uint32_t>>& pairs)
{
  std::map<std::uint32_t, std::size_t> bounds;
  for (const std::vector<std::uint32_t>& faces : pairs) {
    if (faces.size() != 2)
      return 0;
    for (const std::uint32_t f : faces)
      ++bounds[f];
  }
  const bool open = std::any_of(bounds.begin(), bounds.end(),
                                [](const auto& fc) { return fc.second == 1; });
  if (!open)
    return 0;
  for (const auto& [face, count] : bounds)
    if (count == pairs.size())
      return face;
  return 0;
}

} // namespace

std::vector<std::uint32_t>
shallowCreaseMerge(const TopologyGraph& graph,
                   const std::vector<CreaseAngle>& angles,
                   const std::vector<CreaseAngle>& contacts,
                   double min_crease_angle)
{
  const std::size_t n = graph.size();
  Joined joined(n);
  std::vector<char> removed(n + 1, 0);
  if (min_crease_angle > 0.0) {
    // 1. Shallow edges: their two faces become one (the smaller label the root).
    for (std::uint32_t e = 1; e <= n && e <= angles.size(); ++e) {
      const CreaseAngle& a = angles[e - 1];
      if (graph.node(e).feature_class != FeatureClass::kEdge ||
          !std::isfinite(a.degrees) || a.degrees >= min_crease_angle ||
          a.faces[0] == 0 || !graph.contains(a.faces[1]))
        continue;
      removed[e] = 1;
      const std::uint32_t fa = joined.find(a.faces[0]), fb = joined.find(a.faces[1]);
      joined.attach(std::min(fa, fb), std::max(fa, fb));
    }
    // 2. Faces touching without an edge between them, at a shallow turn, unless a
    // crease kept separates them elsewhere (then the contact is a spill of the
    // watershed across that crease, not a blend).
    const auto creaseBetween = [&](std::uint32_t fa, std::uint32_t fb) {
      for (std::uint32_t e = 1; e <= n && e <= angles.size(); ++e) {
        const CreaseAngle& a = angles[e - 1];
        if (graph.node(e).feature_class != FeatureClass::kEdge || removed[e] ||
            !std::isfinite(a.degrees) || a.faces[0] == 0)
          continue;
        const std::uint32_t x = joined.find(a.faces[0]), y = joined.find(a.faces[1]);
        if ((x == fa && y == fb) || (x == fb && y == fa))
          return true;
      }
      return false;
    };
    for (const CreaseAngle& c : contacts) {
      if (!std::isfinite(c.degrees) || c.degrees >= min_crease_angle ||
          c.faces[0] == 0 || !graph.contains(c.faces[1]))
        continue;
      const std::uint32_t fa = joined.find(c.faces[0]), fb = joined.find(c.faces[1]);
      if (!creaseBetween(fa, fb))
        joined.attach(std::min(fa, fb), std::max(fa, fb));
    }
    for (std::uint32_t e = 1; e <= n; ++e)
      if (removed[e])
        joined.attach(angles[e - 1].faces[0], e);
  }
  // Faces in a set with others: their edges' face pairs may have changed.
  std::vector<std::uint32_t> set_size(n + 1, 0);
  for (std::uint32_t f = 1; f <= n; ++f)
    if (graph.node(f).feature_class == FeatureClass::kFace)
      ++set_size[joined.find(f)];
  const auto mergedFace = [&](std::uint32_t f) { return set_size[joined.find(f)] > 1; };
  // Faces that all merged into one (a blend's pieces).
  const auto insideOneMergedFace = [&](const std::vector<std::uint32_t>& faces) {
    return !faces.empty() && std::all_of(faces.begin(), faces.end(), mergedFace) &&
           std::all_of(faces.begin(), faces.end(), [&](std::uint32_t f) {
             return joined.find(f) == joined.find(faces.front());
           });
  };
  // An edge that could not be measured (no two faces around it) whose faces all
  // merged into one lies inside a blend: it joins that face.
  for (std::uint32_t e = 1; e <= n && e <= angles.size(); ++e) {
    if (graph.node(e).feature_class != FeatureClass::kEdge || removed[e] ||
        std::isfinite(angles[e - 1].degrees))
      continue;
    const std::vector<std::uint32_t> faces = graph.facesOfEdge(e);
    if (!insideOneMergedFace(faces))
      continue;
    removed[e] = 1;
    joined.attach(faces.front(), e);
  }
  // 3. Vertices of removed edges or of merged faces' edges that no longer end two
  // different creases, and vertices without edges inside merged faces.
  for (std::uint32_t v = 1; v <= n; ++v) {
    if (graph.node(v).feature_class != FeatureClass::kVertex)
      continue;
    const std::vector<std::uint32_t> edges = graph.neighbours(v, FeatureClass::kEdge);
    if (edges.empty()) {
      // A vertex region touching no edge between faces that all merged into one lies
      // inside a blend (a speck where the watershed cut a cylinder's wall: the box
      // with hole at 10,000 points, seed 49, three of 5-20 cells): it joins that face.
      // One touching a single face (a cone's apex) stays.
      const std::vector<std::uint32_t> faces = graph.neighbours(v, FeatureClass::kFace);
      if (faces.size() >= 2 && insideOneMergedFace(faces))
        joined.attach(faces.front(), v);
      continue;
    }
    const auto changed = [&](std::uint32_t e) {
      const std::vector<std::uint32_t> faces = graph.facesOfEdge(e);
      return removed[e] != 0 || std::any_of(faces.begin(), faces.end(), mergedFace);
    };
    if (std::none_of(edges.begin(), edges.end(), changed))
      continue;
    std::vector<std::uint32_t> remaining;
    const std::set<std::vector<std::uint32_t>> pairs =
      facePairsAt(graph, v, removed, joined, remaining);
    if (pairs.size() >= 2) {
      // Creases passing by: the vertex joins the one face they all bound.
      const std::uint32_t shared = sharedFaceOfOpenFan(pairs);
      if (shared != 0)
        joined.attach(shared, v);
      continue;
    }
    if (!remaining.empty()) {
      for (const std::uint32_t e : remaining)
        joined.attach(remaining.front(), e);
      joined.attach(remaining.front(), v);
    } else {
      const std::vector<std::uint32_t> faces = graph.neighbours(v, FeatureClass::kFace);
      if (!faces.empty())
        joined.attach(faces.front(), v);
    }
  }
  // 4. Pieces of one crease: kept edges whose faces were merged and now separate the
  // same two faces (before, they separated different pairs, so the segmentation
  // never joined them; e.g. a rim cut where the fillets were) are one edge.
  std::map<std::vector<std::uint32_t>, std::uint32_t> edge_of_pair;
  for (std::uint32_t e = 1; e <= n; ++e) {
    if (graph.node(e).feature_class != FeatureClass::kEdge || removed[e])
      continue;
    const std::vector<std::uint32_t> faces = graph.facesOfEdge(e);
    if (std::none_of(faces.begin(), faces.end(), mergedFace))
      continue;
    std::vector<std::uint32_t> roots;
    for (const std::uint32_t f : faces)
      roots.push_back(joined.find(f));
    std::sort(roots.begin(), roots.end());
    roots.erase(std::unique(roots.begin(), roots.end()), roots.end());
    if (roots.size() != 2)
      continue;
    const auto [it, first] = edge_of_pair.emplace(roots, e);
    if (!first)
      joined.attach(it->second, e);
  }
  std::vector<std::uint32_t> into(n + 1, 0);
  for (std::uint32_t l = 1; l <= n; ++l)
    into[l] = joined.find(l);
  return into;
}

} // namespace visfeat
