#include <support/evaluation.h>
#include <visfeat/core/common/error.h>
#include <visfeat/core/common/feature_class.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <sstream>

namespace visfeat {
namespace evaluation {

namespace {

double
ratio(std::size_t a, std::size_t b)
{
  return b == 0 ? 0.0 : static_cast<double>(a) / static_cast<double>(b);
}

void
checkSizes(std::size_t a, std::size_t b, const char* what)
{
  if (a != b) {
    std::ostringstream s;
    s << what << ": " << a << " values for " << b << " curve distances";
    throw Error(s.str());
  }
}

/** The key with the most votes (the smallest key on ties: maps iterate in order). */
template <typename Map>
typename Map::key_type
majority(const Map& votes)
{
  auto best = votes.begin();
  for (auto it = votes.begin(); it != votes.end(); ++it)
    if (it->second > best->second)
      best = it;
  return best->first;
}

} // namespace

double
PointScores::precision() const
{
  return ratio(labeled_near, labeled);
}

double
PointScores::recall() const
{
  return ratio(near_labeled, near);
}

double
PointScores::f1() const
{
  const double p = precision(), r = recall();
  return p + r > 0.0 ? 2.0 * p * r / (p + r) : 0.0;
}

PointScores
scoreFeaturePoints(const std::vector<std::uint8_t>& is_feature,
                   const std::vector<double>& curve_distance_cells,
                   const Tolerances& tolerances)
{
  checkSizes(is_feature.size(), curve_distance_cells.size(), "scoreFeaturePoints");
  PointScores s;
  for (std::size_t i = 0; i < is_feature.size(); ++i) {
    const bool feature = is_feature[i] != 0;
    const double d = curve_distance_cells[i]; // NaN compares false: never near
    const bool near_recall = d <= tolerances.recall_cells;
    const bool near_precision = d <= tolerances.precision_cells;
    s.labeled += feature;
    s.labeled_near += feature && near_precision;
    s.near += near_recall;
    s.near_labeled += feature && near_recall;
  }
  return s;
}

ThresholdSweep
sweepThreshold(const std::vector<float>& score,
               const std::vector<double>& curve_distance_cells,
               std::size_t quantiles,
               const Tolerances& tolerances)
{
  checkSizes(score.size(), curve_distance_cells.size(), "sweepThreshold");
  ThresholdSweep best;
  best.threshold = std::numeric_limits<double>::quiet_NaN();

  // Finite scores in ascending order. Feature = score >= t, so for t = sorted[j] with j
  // the first index of its value, the features are exactly sorted[j..n).
  std::vector<std::size_t> order;
  order.reserve(score.size());
  std::size_t near_total = 0;
  for (std::size_t i = 0; i < score.size(); ++i) {
    near_total += curve_distance_cells[i] <= tolerances.recall_cells;
    if (std::isfinite(score[i]))
      order.push_back(i);
  }
  best.scores.near = near_total;
  const std::size_t n = order.size();
  if (n == 0)
    return best;
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return score[a] < score[b]; });

  // Suffix counts: how many of sorted[j..n) are near for recall / for precision.
  std::vector<std::size_t> suffix_recall(n + 1, 0), suffix_precision(n + 1, 0);
  for (std::size_t j = n; j-- > 0;) {
    const double d = curve_distance_cells[order[j]];
    suffix_recall[j] = suffix_recall[j + 1] + (d <= tolerances.recall_cells);
    suffix_precision[j] = suffix_precision[j + 1] + (d <= tolerances.precision_cells);
  }

  // Candidate starts: the first index of each distinct value, or of the value at
  // each quantile.
  std::vector<std::size_t> starts;
  if (quantiles == 0) {
    for (std::size_t j = 0; j < n; ++j)
      if (j == 0 || score[order[j]] != score[order[j - 1]])
        starts.push_back(j);
  } else {
    for (std::size_t q = 0; q < quantiles; ++q) {
      const std::size_t k = std::min(n - 1, q * n / quantiles);
      const float value = score[order[k]];
      const auto first =
        std::lower_bound(order.begin(), order.end(), value,
                         [&](std::size_t index, float v) { return score[index] < v; });
      starts.push_back(static_cast<std::size_t>(first - order.begin()));
    }
    starts.erase(std::unique(starts.begin(), starts.end()), starts.end());
  }

  // Ascending starts = ascending thresholds: the first best is the lowest threshold.
  double best_f1 = -1.0;
  for (std::size_t j : starts) {
    PointScores s;
    s.labeled = n - j;
    s.labeled_near = suffix_precision[j];
    s.near = near_total;
    s.near_labeled = suffix_recall[j];
    const double f1 = s.f1();
    if (f1 > best_f1) {
      best_f1 = f1;
      best.threshold = score[order[j]];
      best.scores = s;
    }
  }
  best.candidates = starts.size();
  return best;
}

bool
TopologyComparison::arcsCorrect() const
{
  return curves_matched == truth[1] && vertices_matched == truth[0] &&
         faces_matched == truth[2] && curves_linked == truth[1] &&
         vertices_linked == truth[0];
}

namespace {

constexpr std::uint32_t kNone = 0;

/** One problem line: the parts streamed one after the other. */
template <typename... Parts>
void
addProblem(std::vector<std::string>& problems, const Parts&... parts)
{
  std::ostringstream s;
  (s << ... << parts);
  problems.push_back(s.str());
}

/** Ids as "{a,b,c}". */
std::string
idList(const std::vector<std::uint32_t>& ids)
{
  std::ostringstream s;
  s << "{";
  for (std::size_t i = 0; i < ids.size(); ++i)
    s << (i ? "," : "") << ids[i];
  s << "}";
  return s.str();
}

/** Per region or true element, the votes of the labeled points. */
struct Votes
{
  /** Edge region -> true curve -> its points nearest to that curve. */
  std::map<std::uint32_t, std::map<int, std::size_t>> curve;
  /** True vertex -> vertex region -> its points within 3 cells of the vertex. */
  std::vector<std::map<std::uint32_t, std::size_t>> vertex;
  /** True face -> face region -> its points sampled from the face. */
  std::vector<std::map<std::uint32_t, std::size_t>> face;
};

/** The index of the true curve nearest to p (the first on ties). */
int
nearestCurve(const synthetic::CadModel& model, const Eigen::Vector3d& p)
{
  int nearest = 0;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < model.curves.size(); ++k) {
    const double d = synthetic::curveDistance(model, static_cast<int>(k), p);
    if (d < best) {
      best = d;
      nearest = static_cast<int>(k);
    }
  }
  return nearest;
}

/** Votes: edge region -> nearest true curve of its points; true vertex -> vertex
 * regions within 3 cells; true face -> face regions of the points sampled from it. */
Votes
collectVotes(const synthetic::CadModel& model,
             const std::vector<Eigen::Vector3f>& points,
             const std::vector<int>& point_face,
             const std::vector<std::uint32_t>& labels,
             const std::vector<std::uint8_t>& feature_class,
             double cell)
{
  const auto edge = static_cast<std::uint8_t>(FeatureClass::kEdge);
  const auto vertex = static_cast<std::uint8_t>(FeatureClass::kVertex);
  const auto face = static_cast<std::uint8_t>(FeatureClass::kFace);
  Votes votes;
  votes.vertex.resize(model.vertices.size());
  votes.face.resize(model.faces.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (labels[i] == 0)
      continue;
    const Eigen::Vector3d p = points[i].cast<double>();
    if (feature_class[i] == edge && !model.curves.empty()) {
      ++votes.curve[labels[i]][nearestCurve(model, p)];
    } else if (feature_class[i] == vertex) {
      for (std::size_t v = 0; v < model.vertices.size(); ++v)
        if ((p - model.vertices[v]).norm() <= 3.0 * cell)
          ++votes.vertex[v][labels[i]];
    } else if (feature_class[i] == face && point_face[i] >= 0 &&
               static_cast<std::size_t>(point_face[i]) < model.faces.size()) {
      ++votes.face[static_cast<std::size_t>(point_face[i])][labels[i]];
    }
  }
  return votes;
}

/** The true curves' regions: each edge region claims the curve of its majority; a
 * curve claimed by one region only is matched to it. */
struct CurveMatch
{
  std::vector<std::uint32_t> region;
  std::vector<std::size_t> claims;
};

CurveMatch
matchCurves(const std::map<std::uint32_t, std::map<int, std::size_t>>& curve_votes,
            std::size_t curve_count,
            TopologyComparison& c)
{
  CurveMatch match{std::vector<std::uint32_t>(curve_count, kNone),
                   std::vector<std::size_t>(curve_count, 0)};
  for (const auto& [region, votes] : curve_votes) {
    const int curve = majority(votes);
    if (++match.claims[static_cast<std::size_t>(curve)] == 1)
      match.region[static_cast<std::size_t>(curve)] = region;
  }
  for (std::size_t k = 0; k < curve_count; ++k) {
    if (match.claims[k] == 0)
      addProblem(c.problems, "true curve ", k, ": no edge region");
    else if (match.claims[k] > 1)
      addProblem(c.problems, "true curve ", k, ": claimed by ", match.claims[k],
                 " edge regions");
    else
      ++c.curves_matched;
  }
  return match;
}

/** How the problems of matchByMajority() name a kind of true element. */
struct ElementWords
{
  const char* element;  // "true vertex"
  const char* no_votes; // ": no vertex region within 3 cells"
  const char* others;   // " other true vertices"
};

/** Per true element, the region with most votes (kNone without votes); a region that
 * several elements would share matches none of them. Counts the matched ones. */
std::vector<std::uint32_t>
matchByMajority(const std::vector<std::map<std::uint32_t, std::size_t>>& votes,
                const ElementWords& words,
                std::size_t& matched,
                std::vector<std::string>& problems)
{
  std::vector<std::uint32_t> region_of(votes.size(), kNone);
  for (std::size_t e = 0; e < votes.size(); ++e) {
    if (votes[e].empty()) {
      addProblem(problems, words.element, " ", e, words.no_votes);
      continue;
    }
    region_of[e] = majority(votes[e]);
  }
  std::map<std::uint32_t, std::size_t> claims;
  for (std::uint32_t region : region_of)
    if (region != kNone)
      ++claims[region];
  for (std::size_t e = 0; e < votes.size(); ++e) {
    const std::uint32_t region = region_of[e];
    if (region == kNone)
      continue;
    if (claims[region] > 1)
      addProblem(problems, words.element, " ", e, ": its region ", region,
                 " also holds ", claims[region] - 1, words.others);
    else
      ++matched;
  }
  return region_of;
}

/** Every matched curve links exactly the regions of its two faces and of its end
 * vertices. */
void
checkCurveLinks(const synthetic::CadModel& model,
                const TopologyGraph& graph,
                const CurveMatch& curves,
                const std::vector<std::uint32_t>& region_of_vertex,
                const std::vector<std::uint32_t>& region_of_face,
                TopologyComparison& c)
{
  for (std::size_t k = 0; k < model.curves.size(); ++k) {
    if (curves.claims[k] != 1)
      continue;
    const synthetic::CadCurve& curve = model.curves[k];
    const std::uint32_t region = curves.region[k];
    if (!graph.contains(region) ||
        graph.node(region).feature_class != FeatureClass::kEdge) {
      addProblem(c.problems, "true curve ", k, ": region ", region,
                 " is not an edge of the graph");
      continue;
    }
    std::vector<std::uint32_t> faces{
      region_of_face[static_cast<std::size_t>(curve.faces[0])],
      region_of_face[static_cast<std::size_t>(curve.faces[1])]};
    std::vector<std::uint32_t> vertices;
    if (curve.kind == synthetic::CadCurve::Kind::kSegment)
      vertices = {region_of_vertex[static_cast<std::size_t>(curve.vertices[0])],
                  region_of_vertex[static_cast<std::size_t>(curve.vertices[1])]};
    std::sort(faces.begin(), faces.end());
    std::sort(vertices.begin(), vertices.end());
    const std::vector<std::uint32_t> linked_faces = graph.facesOfEdge(region);
    const std::vector<std::uint32_t> linked_vertices = graph.verticesOfEdge(region);
    bool ok = true;
    if (linked_faces != faces) {
      addProblem(c.problems, "true curve ", k, " (region ", region, "): faces ",
                 idList(linked_faces), ", expected ", idList(faces));
      ok = false;
    }
    if (linked_vertices != vertices) {
      addProblem(c.problems, "true curve ", k, " (region ", region, "): vertices ",
                 idList(linked_vertices), ", expected ", idList(vertices));
      ok = false;
    }
    c.curves_linked += ok;
  }
}

/** Every matched corner links exactly the regions of the faces it lies on. */
void
checkVertexLinks(const synthetic::CadModel& model,
                 const TopologyGraph& graph,
                 const std::vector<std::uint32_t>& region_of_vertex,
                 const std::vector<std::uint32_t>& region_of_face,
                 TopologyComparison& c)
{
  const std::vector<std::vector<int>> faces_of_vertex = synthetic::vertexFaces(model);
  for (std::size_t v = 0; v < model.vertices.size(); ++v) {
    const std::uint32_t region = region_of_vertex[v];
    if (region == kNone || !graph.contains(region) ||
        graph.node(region).feature_class != FeatureClass::kVertex)
      continue;
    std::vector<std::uint32_t> faces;
    for (const int f : faces_of_vertex[v])
      faces.push_back(region_of_face[static_cast<std::size_t>(f)]);
    std::sort(faces.begin(), faces.end());
    const std::vector<std::uint32_t> linked =
      graph.neighbours(region, FeatureClass::kFace);
    if (linked == faces)
      ++c.vertices_linked;
    else
      addProblem(c.problems, "true vertex ", v, " (region ", region, "): faces ",
                 idList(linked), ", expected ", idList(faces));
  }
}

} // namespace

TopologyComparison
compareTopology(const synthetic::CadModel& model,
                const std::vector<Eigen::Vector3f>& points,
                const std::vector<int>& point_face,
                const std::vector<std::uint32_t>& labels,
                const std::vector<std::uint8_t>& feature_class,
                const TopologyGraph& graph,
                double cell)
{
  const std::size_t n = points.size();
  if (point_face.size() != n || labels.size() != n || feature_class.size() != n)
    throw Error("compareTopology: per-point inputs of different sizes");

  TopologyComparison c;
  c.found = {graph.classCount(FeatureClass::kVertex),
             graph.classCount(FeatureClass::kEdge),
             graph.classCount(FeatureClass::kFace)};
  c.truth = {model.vertices.size(), model.curves.size(), model.faces.size()};
  if (!c.countsExact())
    addProblem(c.problems, "regions V/E/F ", c.found[0], "/", c.found[1], "/",
               c.found[2], ", true ", c.truth[0], "/", c.truth[1], "/", c.truth[2]);

  const Votes votes =
    collectVotes(model, points, point_face, labels, feature_class, cell);
  const CurveMatch curves = matchCurves(votes.curve, model.curves.size(), c);
  const std::vector<std::uint32_t> region_of_vertex = matchByMajority(
    votes.vertex,
    {"true vertex", ": no vertex region within 3 cells", " other true vertices"},
    c.vertices_matched, c.problems);
  const std::vector<std::uint32_t> region_of_face =
    matchByMajority(votes.face, {"true face", ": no face region", " other true faces"},
                    c.faces_matched, c.problems);

  checkCurveLinks(model, graph, curves, region_of_vertex, region_of_face, c);
  checkVertexLinks(model, graph, region_of_vertex, region_of_face, c);
  return c;
}

} // namespace evaluation
} // namespace visfeat
