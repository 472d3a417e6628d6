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
  auto problem = [&c](const auto&... parts) {
    std::ostringstream s;
    (s << ... << parts);
    c.problems.push_back(s.str());
  };
  if (!c.countsExact())
    problem("regions V/E/F ", c.found[0], "/", c.found[1], "/", c.found[2], ", true ",
            c.truth[0], "/", c.truth[1], "/", c.truth[2]);

  const auto edge = static_cast<std::uint8_t>(FeatureClass::kEdge);
  const auto vertex = static_cast<std::uint8_t>(FeatureClass::kVertex);
  const auto face = static_cast<std::uint8_t>(FeatureClass::kFace);

  // Votes: edge region -> nearest true curve of its points; true vertex -> vertex
  // regions within 3 cells; true face -> face regions of the points sampled from it.
  std::map<std::uint32_t, std::map<int, std::size_t>> curve_votes;
  std::vector<std::map<std::uint32_t, std::size_t>> vertex_votes(model.vertices.size());
  std::vector<std::map<std::uint32_t, std::size_t>> face_votes(model.faces.size());
  for (std::size_t i = 0; i < n; ++i) {
    if (labels[i] == 0)
      continue;
    const Eigen::Vector3d p = points[i].cast<double>();
    if (feature_class[i] == edge && !model.curves.empty()) {
      int nearest = 0;
      double best = std::numeric_limits<double>::infinity();
      for (std::size_t k = 0; k < model.curves.size(); ++k) {
        const double d = synthetic::curveDistance(model, static_cast<int>(k), p);
        if (d < best) {
          best = d;
          nearest = static_cast<int>(k);
        }
      }
      ++curve_votes[labels[i]][nearest];
    } else if (feature_class[i] == vertex) {
      for (std::size_t v = 0; v < model.vertices.size(); ++v)
        if ((p - model.vertices[v]).norm() <= 3.0 * cell)
          ++vertex_votes[v][labels[i]];
    } else if (feature_class[i] == face && point_face[i] >= 0 &&
               static_cast<std::size_t>(point_face[i]) < model.faces.size()) {
      ++face_votes[static_cast<std::size_t>(point_face[i])][labels[i]];
    }
  }

  constexpr std::uint32_t kNone = 0;
  std::vector<std::uint32_t> region_of_curve(model.curves.size(), kNone);
  std::vector<std::size_t> claims(model.curves.size(), 0);
  for (const auto& [region, votes] : curve_votes) {
    const int curve = majority(votes);
    if (++claims[static_cast<std::size_t>(curve)] == 1)
      region_of_curve[static_cast<std::size_t>(curve)] = region;
  }
  for (std::size_t k = 0; k < model.curves.size(); ++k) {
    if (claims[k] == 0)
      problem("true curve ", k, ": no edge region");
    else if (claims[k] > 1)
      problem("true curve ", k, ": claimed by ", claims[k], " edge regions");
    else
      ++c.curves_matched;
  }
  std::vector<std::uint32_t> region_of_vertex(model.vertices.size(), kNone);
  for (std::size_t v = 0; v < model.vertices.size(); ++v) {
    if (vertex_votes[v].empty()) {
      problem("true vertex ", v, ": no vertex region within 3 cells");
      continue;
    }
    region_of_vertex[v] = majority(vertex_votes[v]);
  }
  std::map<std::uint32_t, std::size_t> vertex_claims;
  for (std::uint32_t region : region_of_vertex)
    if (region != kNone)
      ++vertex_claims[region];
  for (std::size_t v = 0; v < model.vertices.size(); ++v) {
    const std::uint32_t region = region_of_vertex[v];
    if (region == kNone)
      continue;
    if (vertex_claims[region] > 1)
      problem("true vertex ", v, ": its region ", region, " also holds ",
              vertex_claims[region] - 1, " other true vertices");
    else
      ++c.vertices_matched;
  }
  std::vector<std::uint32_t> region_of_face(model.faces.size(), kNone);
  for (std::size_t f = 0; f < model.faces.size(); ++f) {
    if (face_votes[f].empty()) {
      problem("true face ", f, ": no face region");
      continue;
    }
    region_of_face[f] = majority(face_votes[f]);
  }
  std::map<std::uint32_t, std::size_t> face_claims;
  for (std::uint32_t region : region_of_face)
    if (region != kNone)
      ++face_claims[region];
  for (std::size_t f = 0; f < model.faces.size(); ++f) {
    const std::uint32_t region = region_of_face[f];
    if (region == kNone)
      continue;
    if (face_claims[region] > 1)
      problem("true face ", f, ": its region ", region, " also holds ",
              face_claims[region] - 1, " other true faces");
    else
      ++c.faces_matched;
  }

  auto list = [](const std::vector<std::uint32_t>& ids) {
    std::ostringstream s;
    s << "{";
    for (std::size_t i = 0; i < ids.size(); ++i)
      s << (i ? "," : "") << ids[i];
    s << "}";
    return s.str();
  };
  for (std::size_t k = 0; k < model.curves.size(); ++k) {
    if (claims[k] != 1)
      continue;
    const synthetic::CadCurve& curve = model.curves[k];
    const std::uint32_t region = region_of_curve[k];
    if (!graph.contains(region) ||
        graph.node(region).feature_class != FeatureClass::kEdge) {
      problem("true curve ", k, ": region ", region, " is not an edge of the graph");
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
      problem("true curve ", k, " (region ", region, "): faces ", list(linked_faces),
              ", expected ", list(faces));
      ok = false;
    }
    if (linked_vertices != vertices) {
      problem("true curve ", k, " (region ", region, "): vertices ",
              list(linked_vertices), ", expected ", list(vertices));
      ok = false;
    }
    c.curves_linked += ok;
  }
  // Every matched corner links exactly the regions of the faces it lies on.
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
      problem("true vertex ", v, " (region ", region, "): faces ", list(linked),
              ", expected ", list(faces));
  }
  return c;
}

} // namespace evaluation
} // namespace visfeat
