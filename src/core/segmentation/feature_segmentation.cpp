#include <visfeat/core/band/band_dilation.h>
#include <visfeat/core/common/error.h>
#include <visfeat/core/segmentation/feature_segmentation.h>
#include <visfeat/core/segmentation/region_growing.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iterator>
#include <limits>
#include <map>
#include <numeric>
#include <queue>
#include <set>
#include <sstream>

namespace visfeat {
namespace {

/** Cells around a skeleton cell averaged into its centre: wider than the widest cores
 * (about 4 cells, on 138-degree edges), short against the curvature of a circle. */
constexpr int kSkeletonCentreRadius = 3;
/** An edge is straight when its core cells lie within this many cells of their line
 * (cores are up to about 4 cells wide). */
constexpr double kStraightTolerance = 3.0;
constexpr std::size_t kMinLineCells = 4;
/** Pieces of one straight edge join across any gap when they are parallel within
 * about 15 degrees, on one line, and each at least this long (cells). */
constexpr double kMinJoinLength = 8.0;
constexpr double kJoinCosine = 0.966;
/** A vertex ahead of a straight edge's end lies within this slope of its line. */
constexpr double kAheadSlope = 0.2;
/** A skeleton is locally a line where its spread along the main axis is this many
 * times the next. */
constexpr double kElongation = 4.0;
/** Smallest eigenvalue of sum(I - u u^T) over a corner's edge directions u: 0 when they
 * are parallel, 1 - cos(angle) for two edges at an angle (0.13 at 30 degrees). */
constexpr double kMinCornerConditioning = 0.1;
/** A drawn edge ends at its first core cell with this many more within this many
 * cells beyond it along the line. */
constexpr std::size_t kEdgeEndCells = 2;
constexpr double kEdgeEndRun = 3.0;
/** Cells of a drawn edge within this distance of the corner join the vertex. */
constexpr double kCornerCells = 1.5;

/** A core's least-squares line, in cell units. */
struct CoreLine
{
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d direction = Eigen::Vector3d::UnitX();
  double length = 0.0; // extent along the direction
  double width = 0.0;  // largest distance of a cell from the line
  /** Its cells lie within kStraightTolerance of the line, at any length. */
  bool narrow() const { return width <= kStraightTolerance; }
  /** Narrow and long enough to join other pieces on its line. */
  bool straight() const { return narrow() && length >= kMinJoinLength; }
  /** `other` (shorter) continues this straight line: it is straight, parallel, and its
   * middle lies on this line. */
  bool onLine(const CoreLine& other) const
  {
    if (!straight() || !other.straight())
      return false;
    const Eigen::Vector3d d = other.point - point;
    return std::abs(other.direction.dot(direction)) >= kJoinCosine &&
           (d - d.dot(direction) * direction).norm() <= kStraightTolerance;
  }
};

CoreLine
fitCoreLine(const VoxelBand& band, const std::vector<CellId>& cells)
{
  CoreLine line;
  if (cells.empty())
    return line;
  for (const CellId c : cells)
    line.point += band.coord(c).cast<double>();
  line.point /= static_cast<double>(cells.size());
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const CellId c : cells) {
    const Eigen::Vector3d d = band.coord(c).cast<double>() - line.point;
    scatter += d * d.transpose();
  }
  line.direction = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(scatter)
                     .eigenvectors()
                     .col(2)
                     .normalized();
  double low = 0.0, high = 0.0;
  for (const CellId c : cells) {
    const Eigen::Vector3d d = band.coord(c).cast<double>() - line.point;
    const double along = d.dot(line.direction);
    low = std::min(low, along);
    high = std::max(high, along);
    line.width = std::max(line.width, (d - along * line.direction).norm());
  }
  line.length = high - low;
  return line;
}

/** Union-find over labels 1..n (0 unused). */
class LabelUnion
{
public:
  explicit LabelUnion(std::size_t labels)
      : parent_(labels + 1)
  {
    std::iota(parent_.begin(), parent_.end(), std::uint32_t{0});
  }

  std::uint32_t find(std::uint32_t a)
  {
    while (parent_[a] != a)
      a = parent_[a] = parent_[parent_[a]];
    return a;
  }

  /** Joins b's set into a's; the smaller root survives, so results do not depend on
   * the order of calls. */
  void join(std::uint32_t a, std::uint32_t b)
  {
    a = find(a);
    b = find(b);
    if (a != b)
      parent_[std::max(a, b)] = std::min(a, b);
  }

  /** Puts b's set under a's root (a merge into a, which keeps its class). */
  void attach(std::uint32_t a, std::uint32_t b)
  {
    a = find(a);
    b = find(b);
    if (a != b)
      parent_[b] = a;
  }

private:
  std::vector<std::uint32_t> parent_;
};

using Contacts = std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t>;

/** Shared boundary (6-adjacent cell pairs) between the sets of the union, both ways. */
Contacts
contactsOf(const VoxelBand& band,
           const std::vector<std::uint32_t>& labels,
           LabelUnion& sets)
{
  Contacts contacts;
  for (std::size_t c = 0; c < labels.size(); ++c) {
    if (labels[c] == 0)
      continue;
    const std::uint32_t a = sets.find(labels[c]);
    for (const CellId nb : band.neighbours(static_cast<CellId>(c))) {
      if (nb == kNoCell || labels[static_cast<std::size_t>(nb)] == 0)
        continue;
      const std::uint32_t b = sets.find(labels[static_cast<std::size_t>(nb)]);
      if (a != b)
        ++contacts[{a, b}];
    }
  }
  return contacts;
}

/** Edge and vertex regions end where the watershed met the faces, in the valleys 3-4
 * cells out. Keep only their skeleton (core cells, plus a ridge-following path from
 * each vertex core to the cores of its edges, so edges reach their vertices) widened by
 * `width` cells; the rest goes to the nearest face region.
 *
 * A vertex and an edge are joined when their regions touch, or when an end of the
 * edge's cores lies within `reach` cells of the vertex's cores: near a corner the
 * radius drops below min_radius, and on obtuse corners (the icosahedron's) the faces
 * take the cells between the last edge core and the vertex. */
std::vector<char>
thinFeatureRegions(const VoxelBand& band,
                   const VisibilityMap& map,
                   const std::vector<std::uint32_t>& core_labels,
                   const std::vector<char>& speck,
                   std::vector<FeatureClass>& cls,
                   int width,
                   int reach,
                   int bridge,
                   std::vector<std::uint32_t>& labels,
                   std::vector<Eigen::Vector3f>& centres,
                   std::vector<Eigen::Vector3f>& tangents)
{
  const float nan = std::numeric_limits<float>::quiet_NaN();
  centres.assign(band.size(), Eigen::Vector3f::Constant(nan));
  tangents.assign(band.size(), Eigen::Vector3f::Zero());
  // x in cell index units; direction: the line's, unit.
  auto setCentre = [&](CellId c, const Eigen::Vector3d& x,
                       const Eigen::Vector3d& direction) {
    centres[static_cast<std::size_t>(c)] =
      (x + Eigen::Vector3d::Constant(0.5)).cast<float>();
    tangents[static_cast<std::size_t>(c)] = direction.cast<float>();
  };
  const std::size_t n = band.size();
  auto isFeature = [&](std::uint32_t label) {
    return label != 0 &&
           (cls[label] == FeatureClass::kEdge || cls[label] == FeatureClass::kVertex);
  };
  std::vector<char> skeleton(n, 0);
  std::map<std::uint32_t, std::vector<CellId>> vertex_cores, edge_cores;
  for (std::size_t c = 0; c < n; ++c) {
    skeleton[c] = isFeature(labels[c]) && core_labels[c] != 0 && !speck[core_labels[c]];
    if (skeleton[c])
      (cls[labels[c]] == FeatureClass::kVertex ? vertex_cores : edge_cores)[labels[c]]
        .push_back(static_cast<CellId>(c));
  }
  std::map<std::uint32_t, CoreLine> core_line; // per edge, fitted once
  for (const auto& [edge, cells] : edge_cores)
    core_line[edge] = fitCoreLine(band, cells);

  // Vertex-edge pairs: regions that touch, and each end of an edge (the farthest pair
  // of its core cells) with the vertex nearest to it, within reach.
  auto distance = [&](CellId a, CellId b) {
    return (band.coord(a) - band.coord(b)).cast<double>().norm();
  };
  auto farthestFrom = [&](CellId from, const std::vector<CellId>& cells) {
    CellId best = from;
    double best_distance = -1.0;
    for (const CellId c : cells)
      if (const double d = distance(from, c); d > best_distance) {
        best_distance = d;
        best = c;
      }
    return best;
  };
  struct EdgeEnds
  {
    std::array<CellId, 2> cell{{kNoCell, kNoCell}};
    std::array<std::uint32_t, 2> vertex{{0, 0}};
  };
  // A straight edge whose core stops more than `reach` short of its corner (a shallow
  // crease under noise): the vertex nearest ahead of that end on its line, within
  // twice the reach.
  auto vertexAhead = [&](std::uint32_t edge, CellId end) -> std::uint32_t {
    const CoreLine& line = core_line[edge];
    if (!line.straight())
      return 0;
    const Eigen::Vector3d from = band.coord(end).cast<double>();
    const Eigen::Vector3d out =
      (from - line.point).dot(line.direction) >= 0.0 ? line.direction : -line.direction;
    std::uint32_t best = 0;
    double best_along = 2.0 * static_cast<double>(reach);
    for (const auto& [vertex, vertex_cells] : vertex_cores)
      for (const CellId c : vertex_cells) {
        const Eigen::Vector3d d = band.coord(c).cast<double>() - from;
        const double along = d.dot(out);
        if (along > 0.0 && along <= best_along &&
            (d - along * out).norm() <=
              std::max(kStraightTolerance, kAheadSlope * along)) {
          best_along = along;
          best = vertex;
        }
      }
    return best;
  };
  std::set<std::pair<std::uint32_t, std::uint32_t>> pairs;
  std::map<std::uint32_t, EdgeEnds> ends;
  auto findPairs = [&]() {
    pairs.clear();
    ends.clear();
    for (std::size_t c = 0; c < n; ++c) {
      if (labels[c] == 0 || cls[labels[c]] != FeatureClass::kVertex)
        continue;
      for (const CellId nb : band.neighbours(static_cast<CellId>(c)))
        if (nb != kNoCell && labels[static_cast<std::size_t>(nb)] != 0 &&
            cls[labels[static_cast<std::size_t>(nb)]] == FeatureClass::kEdge)
          pairs.emplace(labels[c], labels[static_cast<std::size_t>(nb)]);
    }
    for (const auto& [edge, cells] : edge_cores) {
      EdgeEnds& e = ends[edge];
      e.cell[0] = farthestFrom(cells.front(), cells);
      e.cell[1] = farthestFrom(e.cell[0], cells);
      for (int k = 0; k < 2; ++k) {
        double nearest_distance = static_cast<double>(reach);
        for (const auto& [vertex, vertex_cells] : vertex_cores)
          for (const CellId c : vertex_cells)
            if (const double d = distance(e.cell[k], c); d <= nearest_distance) {
              nearest_distance = d;
              e.vertex[k] = vertex;
            }
        if (e.vertex[k] == 0)
          e.vertex[k] = vertexAhead(edge, e.cell[k]);
        if (e.vertex[k] != 0)
          pairs.emplace(e.vertex[k], edge);
      }
    }
  };
  findPairs();
  // Two corners merged into one vertex (noise can join the candidates at both ends of a
  // short edge): a straight run whose two ends, more than half the reach apart, both
  // link to the same vertex.
  // The vertex is split across the middle of that edge; the half on the far side takes
  // the id of one of its own cores.
  bool split = false;
  for (const auto& [edge, e] : ends) {
    const std::uint32_t vertex = e.vertex[0];
    if (vertex == 0 || e.vertex[1] != vertex ||
        distance(e.cell[0], e.cell[1]) <= 0.5 * reach)
      continue;
    const Eigen::Vector3d a = band.coord(e.cell[0]).cast<double>();
    const Eigen::Vector3d b = band.coord(e.cell[1]).cast<double>();
    auto farSide = [&](std::size_t c) {
      const Eigen::Vector3d x = band.coord(static_cast<CellId>(c)).cast<double>();
      return (x - b).squaredNorm() < (x - a).squaredNorm();
    };
    std::uint32_t other = 0;
    for (const CellId c : vertex_cores[vertex]) {
      const std::uint32_t core = core_labels[static_cast<std::size_t>(c)];
      if (farSide(static_cast<std::size_t>(c)) && core != vertex &&
          (other == 0 || core < other))
        other = core;
    }
    bool near_side = false;
    for (const CellId c : vertex_cores[vertex])
      near_side = near_side || !farSide(static_cast<std::size_t>(c));
    if (other == 0 || !near_side)
      continue;
    for (std::size_t c = 0; c < n; ++c)
      if (labels[c] == vertex && farSide(c))
        labels[c] = other;
    cls[other] = FeatureClass::kVertex;
    std::vector<CellId>& cells = vertex_cores[vertex];
    std::vector<CellId> stay;
    for (const CellId c : cells)
      (farSide(static_cast<std::size_t>(c)) ? vertex_cores[other] : stay).push_back(c);
    cells = stay;
    split = true;
  }
  if (split)
    findPairs();

  // Straight edges and corners. Near a corner the radius drops below min_radius, so an
  // edge's core stops short of it and the vertex's cores are specks at the ends of its
  // edges rather than at the tip. Where a vertex has two or more straight edges, its
  // corner is the point nearest to their lines (least squares), and each edge is drawn
  // from its core's end to that corner.
  // Straight here: narrow at any length, unlike joining.
  auto isStraightEdge = [&](std::uint32_t edge) {
    return edge_cores[edge].size() >= kMinLineCells && core_line[edge].narrow();
  };
  // On a straight edge, the middle of the skeleton is its line.
  for (const auto& [edge, line] : core_line)
    if (isStraightEdge(edge))
      for (const CellId c : edge_cores[edge]) {
        const Eigen::Vector3d d = band.coord(c).cast<double>() - line.point;
        setCentre(c, line.point + d.dot(line.direction) * line.direction,
                  line.direction);
      }
  std::map<std::uint32_t, std::vector<std::uint32_t>> straight_edges_of;
  for (const auto& [vertex, edge] : pairs)
    if (core_line.count(edge) && isStraightEdge(edge))
      straight_edges_of[vertex].push_back(edge);
  auto nearestCell = [&](const Eigen::Vector3d& x) {
    const CellCoord at = x.array().round().cast<int>().matrix();
    CellId best = kNoCell;
    double best_distance = std::numeric_limits<double>::infinity();
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const CellId c = band.find(at + CellCoord(dx, dy, dz));
          if (c == kNoCell)
            continue;
          const double d = (band.coord(c).cast<double>() - x).norm();
          if (d < best_distance) {
            best_distance = d;
            best = c;
          }
        }
    return best;
  };
  std::set<std::pair<std::uint32_t, std::uint32_t>> drawn;
  for (const auto& [vertex, edges] : straight_edges_of) {
    if (edges.size() < 2)
      continue;
    Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
    Eigen::Vector3d b = Eigen::Vector3d::Zero();
    for (const std::uint32_t e : edges) {
      const CoreLine& line = core_line[e];
      const Eigen::Matrix3d across =
        Eigen::Matrix3d::Identity() - line.direction * line.direction.transpose();
      a += across;
      b += across * line.point;
    }
    // Nearly parallel lines (a straight run through a speck) have no corner.
    if (Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(a).eigenvalues()(0) <
        kMinCornerConditioning)
      continue;
    const Eigen::Vector3d corner = a.ldlt().solve(b);
    double to_vertex = std::numeric_limits<double>::infinity();
    for (const CellId c : vertex_cores[vertex])
      to_vertex = std::min(to_vertex, (band.coord(c).cast<double>() - corner).norm());
    if (!(to_vertex <= reach) || nearestCell(corner) == kNoCell)
      continue;
    for (const std::uint32_t e : edges) {
      const CoreLine& line = core_line[e];
      // The end of the edge's cores on the corner's side: the nearest core cell with
      // more of its edge just beyond it. Noise leaves stray core cells between the
      // corner and the edge's body; drawn to one of those, the segment would stop
      // short of the body and leave the edge apart from its vertex.
      const double t_corner = (corner - line.point).dot(line.direction);
      std::vector<std::pair<double, double>> along; // (from the corner, t)
      for (const CellId c : edge_cores[e]) {
        const double t =
          (band.coord(c).cast<double>() - line.point).dot(line.direction);
        along.emplace_back(std::abs(t - t_corner), t);
      }
      std::sort(along.begin(), along.end());
      double t_end = along.front().second;
      for (std::size_t i = 0; i < along.size(); ++i) {
        std::size_t beyond = 0;
        for (std::size_t j = i + 1;
             j < along.size() && along[j].first <= along[i].first + kEdgeEndRun; ++j)
          ++beyond;
        if (beyond >= kEdgeEndCells) {
          t_end = along[i].second;
          break;
        }
      }
      const Eigen::Vector3d end = line.point + t_end * line.direction;
      const double length = (end - corner).norm();
      const int steps = std::max(1, static_cast<int>(std::ceil(length * 4.0)));
      for (int k = 0; k <= steps; ++k) {
        const Eigen::Vector3d x = corner + (end - corner) * (double(k) / steps);
        const CellId c = nearestCell(x);
        if (c == kNoCell)
          continue;
        const std::uint32_t l = labels[static_cast<std::size_t>(c)];
        const bool sibling =
          std::find(edges.begin(), edges.end(), l) != edges.end() && l != e;
        if (l != vertex && l != e && isFeature(l) && !sibling)
          continue; // another feature's cell stays its own
        // Edges of one corner converge: a cell on another edge's skeleton is where
        // they meet, and joins the vertex; the rest of its region yields.
        const bool meeting = sibling && skeleton[static_cast<std::size_t>(c)];
        const bool first = !skeleton[static_cast<std::size_t>(c)] ||
                           std::isnan(centres[static_cast<std::size_t>(c)].x());
        skeleton[static_cast<std::size_t>(c)] = 1;
        labels[static_cast<std::size_t>(c)] =
          meeting || (x - corner).norm() <= kCornerCells ? vertex : e;
        const Eigen::Vector3d at = band.coord(c).cast<double>();
        if (first ||
            (x - at).norm() < (centres[static_cast<std::size_t>(c)].cast<double>() -
                               Eigen::Vector3d::Constant(0.5) - at)
                                .norm())
          setCentre(c, x, (end - corner) / std::max(length, 1e-9));
      }
      drawn.emplace(vertex, e);
    }
    // The vertex is now its corner: its own cores (specks at the ends of its edges,
    // pieces of faces) leave the skeleton.
    for (const CellId c : vertex_cores[vertex])
      if (std::isnan(centres[static_cast<std::size_t>(c)].x()))
        skeleton[static_cast<std::size_t>(c)] = 0;
  }

  // Ridge paths: Dijkstra from the vertex's core cells to the first core cell of the
  // edge, through the two regions and the faces (not through other features); low
  // radii cost more, so the path follows the ridge. Its cells join the edge.
  const int cap = map.parameters().max_radius;
  std::vector<double> cost(n, std::numeric_limits<double>::infinity());
  std::vector<CellId> from(n, kNoCell), touched;
  for (const auto& [vertex, edge] : pairs) {
    if (drawn.count({vertex, edge}))
      continue;
    for (const CellId c : touched) {
      cost[static_cast<std::size_t>(c)] = std::numeric_limits<double>::infinity();
      from[static_cast<std::size_t>(c)] = kNoCell;
    }
    touched.clear();
    using Entry = std::pair<double, CellId>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
    for (const CellId c : vertex_cores[vertex]) {
      cost[static_cast<std::size_t>(c)] = 0.0;
      touched.push_back(c);
      queue.emplace(0.0, c);
    }
    CellId reached = kNoCell;
    while (!queue.empty()) {
      const auto [d, c] = queue.top();
      queue.pop();
      if (d > cost[static_cast<std::size_t>(c)])
        continue;
      if (labels[static_cast<std::size_t>(c)] == edge &&
          skeleton[static_cast<std::size_t>(c)]) {
        reached = c;
        break;
      }
      for (const CellId nb : band.neighbours(c)) {
        if (nb == kNoCell)
          continue;
        const std::uint32_t l = labels[static_cast<std::size_t>(nb)];
        if (l == 0 || (l != vertex && l != edge && isFeature(l)))
          continue;
        const double next = d + 1.0 + std::max(0, cap - map.radius(nb));
        if (next < cost[static_cast<std::size_t>(nb)]) {
          cost[static_cast<std::size_t>(nb)] = next;
          from[static_cast<std::size_t>(nb)] = c;
          touched.push_back(nb);
          queue.emplace(next, nb);
        }
      }
    }
    for (CellId c = reached; c != kNoCell; c = from[static_cast<std::size_t>(c)]) {
      skeleton[static_cast<std::size_t>(c)] = 1;
      if (labels[static_cast<std::size_t>(c)] != vertex)
        labels[static_cast<std::size_t>(c)] = edge;
    }
  }

  // Gaps in an edge's skeleton (noise thins the ridge, most on curved and shallow
  // edges): each end of a piece is bridged by a straight segment to the nearest cell
  // of another piece of the same edge within `bridge` cells.
  {
    std::map<std::uint32_t, std::vector<CellId>> edge_skeleton;
    for (std::size_t c = 0; c < n; ++c)
      if (skeleton[c] && cls[labels[c]] == FeatureClass::kEdge)
        edge_skeleton[labels[c]].push_back(static_cast<CellId>(c));
    std::vector<std::uint32_t> piece_of(n, 0);
    for (const auto& [edge, cells] : edge_skeleton) {
      std::vector<std::vector<CellId>> pieces;
      for (const CellId seed : cells) {
        if (piece_of[static_cast<std::size_t>(seed)] != 0)
          continue;
        pieces.emplace_back(1, seed);
        const auto id = static_cast<std::uint32_t>(pieces.size());
        piece_of[static_cast<std::size_t>(seed)] = id;
        for (std::size_t head = 0; head < pieces.back().size(); ++head) {
          const CellCoord at = band.coord(pieces.back()[head]);
          for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
              for (int dx = -1; dx <= 1; ++dx) {
                const CellId m = band.find(at + CellCoord(dx, dy, dz));
                if (m != kNoCell && skeleton[static_cast<std::size_t>(m)] &&
                    labels[static_cast<std::size_t>(m)] == edge &&
                    piece_of[static_cast<std::size_t>(m)] == 0) {
                  piece_of[static_cast<std::size_t>(m)] = id;
                  pieces.back().push_back(m);
                }
              }
        }
      }
      std::vector<std::pair<CellId, CellId>> bridges;
      for (const auto& piece : pieces) {
        const CellId first = farthestFrom(piece.front(), piece);
        for (const CellId end : {first, farthestFrom(first, piece)}) {
          CellId best = kNoCell;
          double best_distance = static_cast<double>(bridge);
          for (const CellId c : cells)
            if (piece_of[static_cast<std::size_t>(c)] !=
                  piece_of[static_cast<std::size_t>(end)] &&
                distance(end, c) <= best_distance) {
              best_distance = distance(end, c);
              best = c;
            }
          if (best != kNoCell)
            bridges.emplace_back(end, best);
        }
      }
      for (const CellId c : cells)
        piece_of[static_cast<std::size_t>(c)] = 0;
      for (const auto& [from_cell, to_cell] : bridges) {
        const Eigen::Vector3d a = band.coord(from_cell).cast<double>();
        const Eigen::Vector3d b = band.coord(to_cell).cast<double>();
        const double length = (b - a).norm();
        const int samples = std::max(1, static_cast<int>(std::ceil(length * 4.0)));
        for (int k = 1; k < samples; ++k) {
          const Eigen::Vector3d x = a + (b - a) * (double(k) / samples);
          const CellId c = nearestCell(x);
          if (c == kNoCell || skeleton[static_cast<std::size_t>(c)])
            continue;
          const std::uint32_t l = labels[static_cast<std::size_t>(c)];
          if (l != edge && isFeature(l))
            continue; // another feature's cell stays its own
          skeleton[static_cast<std::size_t>(c)] = 1;
          labels[static_cast<std::size_t>(c)] = edge;
          setCentre(c, x, (b - a) / length);
        }
      }
    }
  }

  // Keep feature cells within `width` steps of their region's skeleton.
  std::vector<int> steps(n, -1);
  std::vector<CellId> queue;
  for (std::size_t c = 0; c < n; ++c)
    if (skeleton[c]) {
      steps[c] = 0;
      queue.push_back(static_cast<CellId>(c));
    }
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const CellId c = queue[head];
    if (steps[static_cast<std::size_t>(c)] >= width)
      continue;
    for (const CellId nb : band.neighbours(c))
      if (nb != kNoCell && steps[static_cast<std::size_t>(nb)] < 0 &&
          labels[static_cast<std::size_t>(nb)] == labels[static_cast<std::size_t>(c)]) {
        steps[static_cast<std::size_t>(nb)] = steps[static_cast<std::size_t>(c)] + 1;
        queue.push_back(nb);
      }
  }
  // The rest of the feature cells go to the nearest face region (BFS from the faces).
  std::vector<std::uint32_t> original = labels;
  queue.clear();
  for (std::size_t c = 0; c < n; ++c) {
    if (isFeature(labels[c]) && steps[c] < 0)
      labels[c] = 0;
    else if (labels[c] != 0 && cls[labels[c]] == FeatureClass::kFace)
      queue.push_back(static_cast<CellId>(c));
  }
  for (std::size_t head = 0; head < queue.size(); ++head)
    for (const CellId nb : band.neighbours(queue[head]))
      if (nb != kNoCell && labels[static_cast<std::size_t>(nb)] == 0 &&
          original[static_cast<std::size_t>(nb)] != 0) {
        labels[static_cast<std::size_t>(nb)] =
          labels[static_cast<std::size_t>(queue[head])];
        queue.push_back(nb);
      }
  for (std::size_t c = 0; c < n; ++c) // enclosed cells no face reaches keep their label
    if (labels[c] == 0)
      labels[c] = original[c];
  return skeleton;
}

/** Per skeleton cell, the mean of the skeleton cells of its region within `radius`
 * cells (in cell units, cell (i,j,k) spanning [i, i+1) x ...): where a core is several
 * cells wide (obtuse edges), the mean lies on its middle line, near the true curve. */
void
middleOfSkeleton(const VoxelBand& band,
                 const std::vector<std::uint32_t>& labels,
                 const std::vector<char>& skeleton,
                 int radius,
                 std::vector<Eigen::Vector3f>& centres,
                 std::vector<Eigen::Vector3f>& tangents)
{
  const int r2 = radius * radius;
  std::vector<Eigen::Vector3d> around;
  for (std::size_t c = 0; c < band.size(); ++c) {
    if (!skeleton[c] || !std::isnan(centres[c].x()))
      continue;
    const CellCoord at = band.coord(static_cast<CellId>(c));
    around.clear();
    for (int dz = -radius; dz <= radius; ++dz)
      for (int dy = -radius; dy <= radius; ++dy)
        for (int dx = -radius; dx <= radius; ++dx) {
          if (dx * dx + dy * dy + dz * dz > r2)
            continue;
          const CellCoord q = at + CellCoord(dx, dy, dz);
          const CellId m = band.find(q);
          if (m != kNoCell && skeleton[static_cast<std::size_t>(m)] &&
              labels[static_cast<std::size_t>(m)] == labels[c])
            around.push_back(q.cast<double>());
        }
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (const auto& q : around)
      mean += q;
    mean /= static_cast<double>(around.size());
    centres[c] = mean.cast<float>() + Eigen::Vector3f::Constant(0.5f);
    // The local direction where the skeleton is elongated (an edge; not a blob).
    Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
    for (const auto& q : around)
      scatter += (q - mean) * (q - mean).transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(scatter);
    if (around.size() >= 3 &&
        solver.eigenvalues()(2) > kElongation * solver.eigenvalues()(1))
      tangents[c] = solver.eigenvectors().col(2).normalized().cast<float>();
  }
}

} // namespace

void
FeatureSegmentation::validate(const SegmentationParameters& p, int max_radius)
{
  ComponentSet::validate(p.components, max_radius);
  if (!(p.point_feature_distance >= 0.0 && p.point_feature_distance <= 10.0)) {
    std::ostringstream msg;
    msg << "point_feature_distance " << p.point_feature_distance
        << " is out of range [0, 10] (cells)";
    throw Error(msg.str());
  }
  if (p.vertex_reach < 1 || p.vertex_reach > 1000) {
    std::ostringstream msg;
    msg << "vertex_reach " << p.vertex_reach << " is out of range [1, 1000] (cells)";
    throw Error(msg.str());
  }
  if (p.join_distance < 0 || p.join_distance > 1000) {
    std::ostringstream msg;
    msg << "join_distance " << p.join_distance << " is out of range [0, 1000] (cells)";
    throw Error(msg.str());
  }
  if (p.feature_width < 0 || p.feature_width > 1000) {
    std::ostringstream msg;
    msg << "feature_width " << p.feature_width << " is out of range [0, 1000] (cells)";
    throw Error(msg.str());
  }
  if (p.min_piece_cells < 0 || p.min_piece_cells > 1000000) {
    std::ostringstream msg;
    msg << "min_piece_cells " << p.min_piece_cells
        << " is out of range [0, 1000000] (cells)";
    throw Error(msg.str());
  }
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
  validate(parameters, map.parameters().max_radius);
  FeatureSegmentation result;
  result.cores_ =
    ComponentSet::extract(band, map, parameters.components, parameters.raw);
  const std::vector<Component>& cores = result.cores_.components();
  const std::size_t n = band.size();

  // Outlier clusters: small band pieces get no label at all.
  std::vector<std::uint32_t> seeds = result.cores_.cellLabels();
  const std::vector<std::uint32_t> piece = bandPieceSizes(band);
  for (std::size_t c = 0; c < n; ++c)
    if (piece[c] < static_cast<std::uint32_t>(parameters.min_piece_cells))
      seeds[c] = 0;

  std::vector<FeatureClass> cls(cores.size() + 1, FeatureClass::kNone);
  for (std::size_t l = 0; l < cores.size(); ++l)
    cls[l + 1] = cores[l].feature_class;
  LabelUnion sets(cores.size());
  std::vector<std::uint32_t> labels;

  if (parameters.raw) {
    labels = seeds;
  } else {
    // Judge every core by the regions it grows into, then keep the cores' own cells
    // only if regions are not wanted.
    labels = growRegions(band, map, seeds);
    auto faceNeighbours = [&](const Contacts& contacts, std::uint32_t a) {
      std::vector<std::pair<std::uint32_t, std::uint32_t>> faces; // (contact, face)
      for (auto it = contacts.lower_bound({a, 0});
           it != contacts.end() && it->first.first == a; ++it)
        if (cls[it->first.second] == FeatureClass::kFace)
          faces.emplace_back(it->second, it->first.second);
      std::sort(faces.rbegin(), faces.rend());
      return faces;
    };

    // 3. Specks (touching at most one face) merge into their largest neighbour. The
    // rest are edges between their two main faces, except small ones that meet edges
    // of two different face pairs, or three faces: those are vertices (corner blobs).
    std::map<std::uint32_t, std::pair<std::uint32_t, std::uint32_t>> signature;
    Contacts contacts = contactsOf(band, labels, sets);
    std::vector<std::pair<std::uint32_t, std::uint32_t>> speck_merges;
    std::vector<std::uint32_t> face_count(cores.size() + 1, 0);
    std::vector<std::uint32_t> speck_into(cores.size() + 1, 0);
    for (std::uint32_t l = 1; l <= cores.size(); ++l) {
      if (cls[l] == FeatureClass::kFace)
        continue;
      const auto faces = faceNeighbours(contacts, l);
      face_count[l] = static_cast<std::uint32_t>(faces.size());
      if (faces.size() <= 1) {
        cls[l] = FeatureClass::kNone; // a speck unless the vertex test below claims it
        std::uint32_t best_contact = 0;
        for (auto it = contacts.lower_bound({l, 0});
             it != contacts.end() && it->first.first == l; ++it)
          if (it->second > best_contact) {
            best_contact = it->second;
            speck_into[l] = it->first.second;
          }
        continue;
      }
      cls[l] = FeatureClass::kEdge;
      signature[l] = std::minmax(faces[0].second, faces[1].second);
    }
    // Geodesic dilation of a small core through the band (the paper's vertex test):
    // the cores it reaches within vertex_reach cells.
    const std::uint32_t reach = static_cast<std::uint32_t>(parameters.vertex_reach);
    const std::uint32_t join = static_cast<std::uint32_t>(parameters.join_distance);
    const std::vector<std::uint32_t>& core_of = result.cores_.cellLabels();
    BandDilation dilation(band);
    auto dilate = [&](std::uint32_t l, const std::vector<CellId>& cells,
                      std::uint32_t distance) {
      std::set<std::uint32_t> met;
      dilation.run(cells, distance, [&](CellId c) {
        const std::uint32_t other = core_of[static_cast<std::size_t>(c)];
        if (other != 0 && other != l)
          met.insert(other);
      });
      return met;
    };
    std::vector<std::vector<CellId>> core_cells(cores.size() + 1);
    for (std::size_t c = 0; c < n; ++c)
      if (seeds[c] != 0)
        core_cells[seeds[c]].push_back(static_cast<CellId>(c));
    const auto vertex_max =
      static_cast<std::uint32_t>(parameters.components.vertex_max_cells);
    std::vector<std::uint32_t> vertices;
    std::map<std::uint32_t, std::set<std::uint32_t>> reached;
    for (std::uint32_t l = 1; l <= cores.size(); ++l)
      if (cores[l - 1].feature_class != FeatureClass::kFace &&
          cores[l - 1].cells <= vertex_max && !core_cells[l].empty())
        reached[l] = dilate(l, core_cells[l], reach);
    // A short edge may break into small cores that all pass the vertex test (they
    // reach the edges of both its corners). A small core with pieces of its own edge
    // on opposite sides lies inside that edge, not at a corner: it is never a vertex.
    std::vector<Eigen::Vector3d> centroid(cores.size() + 1, Eigen::Vector3d::Zero());
    for (std::uint32_t l = 1; l <= cores.size(); ++l) {
      for (const CellId c : core_cells[l])
        centroid[l] += band.coord(c).cast<double>();
      if (!core_cells[l].empty())
        centroid[l] /= static_cast<double>(core_cells[l].size());
    }
    auto insideAnEdge = [&](std::uint32_t l) {
      const auto own = signature.find(l);
      if (own == signature.end())
        return false;
      std::vector<Eigen::Vector3d> directions;
      for (const std::uint32_t m : reached[l]) {
        const auto other = signature.find(m);
        if (other == signature.end() || other->second != own->second)
          continue;
        const Eigen::Vector3d d = centroid[m] - centroid[l];
        if (d.norm() > 0.0)
          directions.push_back(d.normalized());
      }
      for (std::size_t i = 0; i < directions.size(); ++i)
        for (std::size_t j = i + 1; j < directions.size(); ++j)
          if (directions[i].dot(directions[j]) < -0.5)
            return true;
      return false;
    };
    for (std::uint32_t l = 1; l <= cores.size(); ++l) {
      if (!reached.count(l) || insideAnEdge(l))
        continue;
      std::set<std::pair<std::uint32_t, std::uint32_t>> met;
      if (signature.count(l))
        met.insert(signature[l]);
      std::size_t faces_met = 0;
      for (const std::uint32_t m : reached[l]) {
        if (signature.count(m))
          met.insert(signature[m]);
        faces_met += cls[m] == FeatureClass::kFace;
      }
      if (face_count[l] >= 3 || faces_met >= 3 || met.size() >= 2)
        vertices.push_back(l);
    }
    // A corner often holds several small cores (the blob at the tip, ridge specks);
    // the test may pass for one a few cells off and fail for the tip itself, so an
    // accepted vertex takes every small core within its reach.
    {
      std::set<std::uint32_t> absorbed(vertices.begin(), vertices.end());
      for (const std::uint32_t l : std::vector<std::uint32_t>(vertices))
        for (const std::uint32_t m : reached[l])
          if (cls[m] != FeatureClass::kFace && cores[m - 1].cells <= vertex_max &&
              !insideAnEdge(m) && absorbed.insert(m).second)
            vertices.push_back(m);
    }
    for (const std::uint32_t l : vertices) {
      cls[l] = FeatureClass::kVertex;
      signature.erase(l);
      speck_into[l] = 0;
    }
    for (std::uint32_t l = 1; l <= cores.size(); ++l)
      if (speck_into[l] != 0)
        speck_merges.emplace_back(speck_into[l], l);
    // Vertex candidates within reach of each other mark one corner.
    const std::set<std::uint32_t> vertex_set(vertices.begin(), vertices.end());
    for (const std::uint32_t l : vertices)
      for (const std::uint32_t m : reached[l])
        if (vertex_set.count(m))
          sets.join(l, m);
    // A speck joins its neighbour's set; chains of specks resolve through the union.
    std::vector<char> speck(cores.size() + 1, 0);
    for (const auto& [into, l] : speck_merges) {
      sets.attach(into, l);
      speck[l] = 1;
    }
    // Specks that merged into specks: such a set goes to its largest classified
    // neighbour, until none is left that touches one.
    for (bool changed = true; changed;) {
      changed = false;
      const Contacts around = contactsOf(band, labels, sets);
      std::map<std::uint32_t, std::pair<std::uint32_t, std::uint32_t>>
        best; // contact, to
      for (const auto& [pair, count] : around)
        if (cls[pair.first] == FeatureClass::kNone &&
            cls[pair.second] != FeatureClass::kNone && count > best[pair.first].first)
          best[pair.first] = {count, pair.second};
      for (const auto& [root, target] : best) {
        sets.attach(target.second, root);
        changed = true;
      }
    }
    // From here on classes are read at set roots only: a merged label takes its
    // root's class.

    // 4. Fragments: touching edges with the same pair of faces, touching vertices.
    // A path of 6-steps is up to sqrt(3) times longer than the straight gap it spans,
    // so an edge at an angle to the grid would join shorter gaps than one along it:
    // the band is searched sqrt(3) * join_distance steps wide, and pieces join when
    // their closest core cells are also within join_distance cells of each other.
    std::map<std::uint32_t, std::set<std::uint32_t>> edge_reach;
    const auto join_steps =
      static_cast<std::uint32_t>(std::ceil(std::sqrt(3.0) * static_cast<double>(join)));
    auto gapWithin = [&](std::uint32_t a, std::uint32_t b) {
      const auto limit = static_cast<int>(join) * static_cast<int>(join);
      for (const CellId x : core_cells[a])
        for (const CellId y : core_cells[b])
          if ((band.coord(x) - band.coord(y)).squaredNorm() <= limit)
            return true;
      return false;
    };
    for (const auto& [l, own] : signature)
      if (cls[l] == FeatureClass::kEdge && !core_cells[l].empty()) {
        std::set<std::uint32_t> near;
        for (const std::uint32_t m : dilate(l, core_cells[l], join_steps))
          if (signature.count(m) && signature[m] == own && gapWithin(l, m))
            near.insert(m);
        edge_reach[l] = std::move(near);
      }
    for (bool changed = true; changed;) {
      changed = false;
      contacts = contactsOf(band, labels, sets);
      for (const auto& [pair, count] : contacts) {
        const auto [a, b] = pair;
        if (a > b || cls[a] != cls[b])
          continue;
        const bool same_edge = cls[a] == FeatureClass::kEdge && signature.count(a) &&
                               signature.count(b) && signature[a] == signature[b];
        if (same_edge || cls[a] == FeatureClass::kVertex) {
          sets.join(a, b);
          changed = true;
        }
      }
      // Pieces of one edge with something else between them (a speck merged into a
      // face, a vertex, a gap that noise opened): same pair of faces, within
      // join_distance cells of each other.
      for (const auto& [a0, near] : edge_reach)
        for (const std::uint32_t b0 : near) {
          const std::uint32_t a = sets.find(a0), b = sets.find(b0);
          if (a != b && cls[a] == FeatureClass::kEdge &&
              cls[b] == FeatureClass::kEdge && signature.count(a) &&
              signature.count(b) && signature[a] == signature[b]) {
            sets.join(a, b);
            changed = true;
          }
        }
      // Pieces of one edge that a vertex region sits between: same pair of faces,
      // both touching the same vertex. (Two faces may meet along several edges, e.g. a
      // half-cylinder on a plane, but those do not share a vertex.)
      std::map<std::uint32_t, std::vector<std::uint32_t>> edges_at;
      for (const auto& [pair, count] : contacts)
        if (cls[pair.first] == FeatureClass::kVertex &&
            cls[pair.second] == FeatureClass::kEdge)
          edges_at[pair.first].push_back(pair.second);
      for (const auto& [vertex, edges] : edges_at)
        for (std::size_t i = 0; i < edges.size(); ++i)
          for (std::size_t j = i + 1; j < edges.size(); ++j) {
            const std::uint32_t a = sets.find(edges[i]), b = sets.find(edges[j]);
            if (a != b && signature.count(a) && signature.count(b) &&
                signature[a] == signature[b]) {
              sets.join(a, b);
              changed = true;
            }
          }
      // Pieces of one straight edge with a longer gap than join_distance (a shallow
      // crease under noise loses its ridge for tens of cells): same pair of faces, and
      // the smaller piece on the line of the larger. Two edges of the same two faces
      // are never on one line. join_distance 0 turns joining off, this too.
      if (!changed && join > 0) {
        std::map<std::uint32_t, std::vector<CellId>> cells_of;
        for (const auto& [l, own] : signature)
          if (cls[sets.find(l)] == FeatureClass::kEdge)
            cells_of[sets.find(l)].insert(cells_of[sets.find(l)].end(),
                                          core_cells[l].begin(), core_cells[l].end());
        std::map<std::uint32_t, CoreLine> line_of;
        for (const auto& [root, cells] : cells_of)
          line_of[root] = fitCoreLine(band, cells);
        for (auto a = line_of.begin(); a != line_of.end() && !changed; ++a)
          for (auto b = std::next(a); b != line_of.end() && !changed; ++b) {
            if (!signature.count(a->first) || !signature.count(b->first) ||
                signature[a->first] != signature[b->first])
              continue;
            const bool a_longer = a->second.length >= b->second.length;
            const CoreLine& longer = a_longer ? a->second : b->second;
            const CoreLine& shorter = a_longer ? b->second : a->second;
            if (longer.onLine(shorter)) {
              sets.join(a->first, b->first);
              changed = true;
            }
          }
      }
    }
    // 5. Two corners share at most one edge: vertex candidates whose reached edges
    // share two or more mark the same corner.
    for (bool changed = true; changed;) {
      changed = false;
      std::map<std::uint32_t, std::set<std::uint32_t>> edges_of;
      for (const std::uint32_t l : vertices)
        for (const std::uint32_t m : reached[l])
          if (cls[sets.find(m)] == FeatureClass::kEdge)
            edges_of[sets.find(l)].insert(sets.find(m));
      for (auto a = edges_of.begin(); a != edges_of.end() && !changed; ++a)
        for (auto b = std::next(a); b != edges_of.end() && !changed; ++b) {
          std::size_t shared = 0;
          for (const std::uint32_t e : a->second)
            shared += b->second.count(e);
          if (shared >= 2) {
            sets.join(a->first, b->first);
            changed = true;
          }
        }
    }
    for (std::size_t c = 0; c < n; ++c) {
      if (labels[c] == 0)
        continue;
      labels[c] = sets.find(labels[c]);
      if (!parameters.complete_regions && result.cores_.cellLabels()[c] == 0)
        labels[c] = 0;
    }
    if (parameters.complete_regions)
      result.skeleton_ = thinFeatureRegions(
        band, map, result.cores_.cellLabels(), speck, cls, parameters.feature_width,
        parameters.vertex_reach, parameters.join_distance, labels,
        result.skeleton_centres_, result.skeleton_tangents_);
    if (parameters.complete_regions)
      middleOfSkeleton(band, labels, result.skeleton_, kSkeletonCentreRadius,
                       result.skeleton_centres_, result.skeleton_tangents_);
  }

  // Renumber 1.. by smallest cell id.
  std::vector<std::uint32_t> renumber(cores.size() + 1, 0);
  for (std::size_t c = 0; c < n; ++c) {
    std::uint32_t& label = labels[c];
    if (label == 0)
      continue;
    if (renumber[label] == 0) {
      result.regions_.push_back(Region{cls[label], 0, 0});
      renumber[label] = static_cast<std::uint32_t>(result.regions_.size());
    }
    label = renumber[label];
    Region& region = result.regions_[label - 1];
    ++region.cells;
    if (result.cores_.cellLabels()[c] != 0)
      ++region.core_cells;
  }
  result.labels_ = std::move(labels);
  return result;
}

} // namespace visfeat
