#include <visfeat/core/graph/corner_meets.h>

#include <visfeat/core/common/error.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

namespace visfeat {
namespace {

/** A coarse lattice over the points (cells of `size`), each cell listing the entries
 * whose ball reaches it: a point finds the entries near it in its own cell only. */
class CoarseLattice
{
public:
  CoarseLattice(const std::vector<Eigen::Vector3d>& points, double size)
      : size_(size)
  {
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::max());
    Eigen::Vector3d hi = -lo;
    for (const Eigen::Vector3d& p : points)
      if (p.allFinite()) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
      }
    if (!(lo.array() <= hi.array()).all())
      lo = hi = Eigen::Vector3d::Zero();
    origin_ = lo;
    for (int a = 0; a < 3; ++a)
      dims_[static_cast<std::size_t>(a)] =
        static_cast<int>(std::floor((hi[a] - lo[a]) / size_)) + 1;
    lists_.resize(static_cast<std::size_t>(dims_[0]) * dims_[1] * dims_[2]);
  }

  /** Lists `id` in every cell that the ball (centre, radius) overlaps. */
  void add(std::uint32_t id, const Eigen::Vector3d& centre, double radius)
  {
    std::array<int, 3> a{}, b{};
    for (std::size_t k = 0; k < 3; ++k) {
      const double o = origin_[static_cast<int>(k)];
      const double c = centre[static_cast<int>(k)];
      a[k] = std::max(0, static_cast<int>(std::floor((c - radius - o) / size_)));
      b[k] =
        std::min(dims_[k] - 1, static_cast<int>(std::floor((c + radius - o) / size_)));
      if (a[k] > b[k])
        return;
    }
    for (int z = a[2]; z <= b[2]; ++z)
      for (int y = a[1]; y <= b[1]; ++y)
        for (int x = a[0]; x <= b[0]; ++x)
          lists_[index(x, y, z)].push_back(id);
  }

  /** Empties every cell's list; the lattice's geometry stays. */
  void clear()
  {
    for (std::vector<std::uint32_t>& list : lists_)
      list.clear();
  }

  /** The entries listed in the cell of p (none when p lies outside). */
  const std::vector<std::uint32_t>& near(const Eigen::Vector3d& p) const
  {
    std::array<int, 3> c{};
    for (std::size_t k = 0; k < 3; ++k) {
      const double v =
        std::floor((p[static_cast<int>(k)] - origin_[static_cast<int>(k)]) / size_);
      if (!(v >= 0.0 && v < dims_[k]))
        return empty_;
      c[k] = static_cast<int>(v);
    }
    return lists_[index(c[0], c[1], c[2])];
  }

private:
  std::size_t index(int x, int y, int z) const
  {
    return (static_cast<std::size_t>(z) * static_cast<std::size_t>(dims_[1]) +
            static_cast<std::size_t>(y)) *
             static_cast<std::size_t>(dims_[0]) +
           static_cast<std::size_t>(x);
  }

  double size_;
  Eigen::Vector3d origin_;
  std::array<int, 3> dims_{1, 1, 1};
  std::vector<std::vector<std::uint32_t>> lists_;
  std::vector<std::uint32_t> empty_;
};

/** Sums of an edge's points near one vertex: count, sum, sum of outer products. */
struct LineSums
{
  std::uint32_t edge = 0;
  std::size_t count = 0;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  Eigen::Matrix3d outer = Eigen::Matrix3d::Zero();
};

/** The meet of the lines of `sums` (those with enough points) when well posed. */
bool
meetOfLines(const std::vector<LineSums>& sums, Eigen::Vector3d& meet)
{
  Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  int lines = 0;
  for (const LineSums& s : sums) {
    if (s.count < CornerMeetParameters::kMinLinePoints)
      continue;
    const Eigen::Vector3d mean = s.sum / static_cast<double>(s.count);
    const Eigen::Matrix3d covariance =
      s.outer / static_cast<double>(s.count) - mean * mean.transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
    const Eigen::Vector3d direction = solver.eigenvectors().col(2); // largest
    const Eigen::Matrix3d across =
      Eigen::Matrix3d::Identity() - direction * direction.transpose();
    a += across;
    b += across * mean;
    ++lines;
  }
  if (lines < 2)
    return false;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(a);
  if (!(solver.eigenvalues()[0] >= CornerMeetParameters::kMinConditioning))
    return false;
  meet = a.ldlt().solve(b);
  return meet.allFinite();
}

} // namespace

std::vector<CornerMeet>
cornerMeets(const TopologyGraph& graph,
            const std::vector<Eigen::Vector3d>& points,
            const std::vector<std::uint32_t>& labels,
            const CornerMeetParameters& parameters)
{
  if (points.size() != labels.size())
    throw Error("cornerMeets: " + std::to_string(points.size()) + " points but " +
                std::to_string(labels.size()) + " labels");
  if (!(parameters.line_radius > 0.0) || !(parameters.max_point_distance > 0.0))
    throw Error("cornerMeets: line_radius and max_point_distance must be positive");
  const std::size_t n = graph.size();
  const auto known = [&](std::uint32_t l) { return l != 0 && l <= n; };
  // the vertices' point centroids
  std::vector<Eigen::Vector3d> centroid(n + 1, Eigen::Vector3d::Zero());
  std::vector<std::size_t> count(n + 1, 0);
  for (std::size_t i = 0; i < points.size(); ++i)
    if (known(labels[i]) && points[i].allFinite() &&
        graph.node(labels[i]).feature_class == FeatureClass::kVertex) {
      centroid[labels[i]] += points[i];
      ++count[labels[i]];
    }
  const double radius = parameters.line_radius;
  CoarseLattice lattice(points, radius);
  std::vector<std::vector<LineSums>> sums(n + 1); // per vertex, one per edge
  for (std::uint32_t v = 1; v <= n; ++v) {
    if (graph.node(v).feature_class != FeatureClass::kVertex || count[v] == 0)
      continue;
    centroid[v] /= static_cast<double>(count[v]);
    for (const std::uint32_t e : graph.neighbours(v, FeatureClass::kEdge))
      sums[v].push_back(LineSums{e});
    if (sums[v].size() >= 2)
      lattice.add(v, centroid[v], radius);
  }
  // each edge point near a vertex of its edge adds to that line
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::uint32_t l = labels[i];
    if (!known(l) || !points[i].allFinite() ||
        graph.node(l).feature_class != FeatureClass::kEdge)
      continue;
    for (const std::uint32_t v : lattice.near(points[i])) {
      if ((points[i] - centroid[v]).squaredNorm() >= radius * radius)
        continue;
      for (LineSums& s : sums[v])
        if (s.edge == l) {
          ++s.count;
          s.sum += points[i];
          s.outer += points[i] * points[i].transpose();
        }
    }
  }
  std::vector<CornerMeet> meets;
  std::vector<std::size_t> meet_of(n + 1, 0); // index into meets + 1
  CoarseLattice& meet_lattice = lattice; // same points and cell size: now the meets
  meet_lattice.clear();
  for (std::uint32_t v = 1; v <= n; ++v) {
    CornerMeet m;
    m.vertex = v;
    if (sums[v].size() < 2 || !meetOfLines(sums[v], m.meet) ||
        (m.meet - centroid[v]).norm() > radius)
      continue;
    meets.push_back(m);
    meet_of[v] = meets.size();
    meet_lattice.add(v, m.meet, parameters.max_point_distance);
  }
  // the nearest point of the vertex or its neighbours to each meet
  const double limit2 = parameters.max_point_distance * parameters.max_point_distance;
  std::vector<double> best(meets.size(), limit2);
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!known(labels[i]) || !points[i].allFinite())
      continue;
    for (const std::uint32_t v : meet_lattice.near(points[i])) {
      CornerMeet& m = meets[meet_of[v] - 1];
      const double d2 = (points[i] - m.meet).squaredNorm();
      if (d2 > best[meet_of[v] - 1] ||
          (d2 == best[meet_of[v] - 1] && m.point != CornerMeet::kNoPoint))
        continue;
      if (labels[i] != v && !graph.adjacent(v, labels[i]))
        continue;
      best[meet_of[v] - 1] = d2;
      m.point = i;
    }
  }
  return meets;
}

} // namespace visfeat
