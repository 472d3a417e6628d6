#include <visfeat/core/graph/contact_creases.h>

#include <visfeat/core/common/threads.h>

#include "../common/angles.h"
#include "face_point_index.h"
#include "plane_sums.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace visfeat {

using detail::FacePointIndex;
using detail::PlaneSums;

namespace {

/** The line where two fitted planes cross, relative to the sample point, and the turn
 * between them. */
struct CreaseLine
{
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d direction = Eigen::Vector3d::Zero();
  double turn = 0.0; // degrees, detail::turnOfSides()

  double distance(const Eigen::Vector3d& q) const
  {
    const Eigen::Vector3d r = q - point;
    return (r - r.dot(direction) * direction).norm();
  }
};

/** The crease line of two sides (sums relative to the sample point), or false where a
 * side has too few points or the planes turn by less than min_sine (sine of the
 * smallest turn). */
bool
creaseLine(const PlaneSums& a, const PlaneSums& b, double min_sine, CreaseLine& line)
{
  if (a.count < CreaseAngleParameters::kMinSidePoints ||
      b.count < CreaseAngleParameters::kMinSidePoints)
    return false;
  const Eigen::Vector3d na = a.normal(), nb = b.normal();
  Eigen::Vector3d direction = na.cross(nb);
  const double sine = direction.norm();
  if (!(sine >= min_sine) || sine <= 0.0)
    return false;
  line.direction = direction / sine;
  // the point of the line nearest the sample: x = alpha na + beta nb on both planes
  const double cosine = na.dot(nb), ca = na.dot(a.mean()), cb = nb.dot(b.mean());
  const double det = sine * sine; // 1 - cosine^2
  line.point = ((ca - cosine * cb) / det) * na + ((cb - cosine * ca) / det) * nb;
  line.turn = detail::turnOfSides(a, b, na, nb);
  return true;
}

} // namespace

std::vector<ContactCrease>
locateContactCreases(const VoxelBand& band,
                     const std::vector<std::uint32_t>& cell_labels,
                     const std::vector<Eigen::Vector3d>& points,
                     const std::vector<std::uint32_t>& labels,
                     const std::vector<FeatureClass>& classes,
                     const std::set<std::array<std::uint32_t, 2>>& excluded,
                     double window_cells,
                     double min_crease_angle,
                     double half_width_cells,
                     int threads)
{
  std::vector<ContactCrease> creases;
  const GridSpec& grid = band.grid();
  const double cell = grid.cell_size, radius = window_cells * cell;
  if (!(radius > 0.0) || !(min_crease_angle > 0.0) || points.size() != labels.size() ||
      cell_labels.size() != band.size())
    return creases;
  const auto isFace = [&](std::uint32_t l) {
    return l != 0 && l <= classes.size() && classes[l - 1] == FeatureClass::kFace;
  };
  const FacePointIndex index(points, labels, classes, radius);
  // samples only away from edges and vertices: near them the watershed spills across
  // a crease that has its edge (sparse icosahedra: a second edge along one)
  const double clearance = CreaseAngleParameters::kContactClearanceCells * cell;
  const FacePointIndex features(points, labels, classes, clearance, false);
  const double min_sine =
    std::sin(std::clamp(min_crease_angle, 0.0, 90.0) * detail::kPi / 180.0);
  const double half_width = half_width_cells * cell;
  const int reach = static_cast<int>(std::ceil(window_cells));
  // One sample per contact cell (the planes of the two faces around it), on threads
  // over chunks of cells; the chunks' samples are then gathered in cell order.
  struct Sample
  {
    std::array<std::uint32_t, 2> pair{};
    double turn = 0.0;
    std::vector<CellId> cells;
  };
  constexpr std::size_t kCellsPerChunk = 4096;
  std::vector<std::vector<Sample>> chunk_samples((band.size() + kCellsPerChunk - 1) /
                                                 kCellsPerChunk);
  parallelFor(
    band.size(), threads, kCellsPerChunk, [&](std::size_t begin, std::size_t end) {
      std::vector<Sample>& out = chunk_samples[begin / kCellsPerChunk];
      for (std::size_t c = begin; c < end; ++c) {
        const std::uint32_t a = cell_labels[c];
        if (!isFace(a))
          continue;
        for (const CellId n : band.neighbours(static_cast<CellId>(c))) {
          const std::uint32_t b =
            n == kNoCell ? 0 : cell_labels[static_cast<std::size_t>(n)];
          if (b == a || !isFace(b))
            continue;
          const std::array<std::uint32_t, 2> pair{{std::min(a, b), std::max(a, b)}};
          if (excluded.count(pair) != 0)
            continue;
          const CellCoord at_cell = band.coord(static_cast<CellId>(c));
          const Eigen::Vector3d at = grid.cellCenter(at_cell);
          if (features.anyWithin(at, clearance))
            break;
          PlaneSums side_a, side_b;
          index.forEachWithin(at, radius, [&](std::uint32_t i) {
            if (labels[i] == a)
              side_a.add(points[i] - at);
            else if (labels[i] == b)
              side_b.add(points[i] - at);
          });
          CreaseLine line;
          if (!creaseLine(side_a, side_b, min_sine, line))
            break;
          if (!(line.turn >= min_crease_angle))
            break;
          Sample sample;
          sample.pair = pair;
          sample.turn = line.turn;
          for (int dz = -reach; dz <= reach; ++dz)
            for (int dy = -reach; dy <= reach; ++dy)
              for (int dx = -reach; dx <= reach; ++dx) {
                const CellId m = band.find(at_cell + CellCoord(dx, dy, dz));
                if (m == kNoCell)
                  continue;
                const std::uint32_t l = cell_labels[static_cast<std::size_t>(m)];
                if ((l == a || l == b) &&
                    line.distance(grid.cellCenter(band.coord(m)) - at) <= half_width)
                  sample.cells.push_back(m);
              }
          out.push_back(std::move(sample));
          break;
        }
      }
    });
  struct Placed
  {
    std::vector<double> turns;
    std::vector<CellId> cells;
  };
  std::map<std::array<std::uint32_t, 2>, Placed> placed;
  for (std::vector<Sample>& samples : chunk_samples)
    for (Sample& sample : samples) {
      Placed& crease = placed[sample.pair];
      crease.turns.push_back(sample.turn);
      crease.cells.insert(crease.cells.end(), sample.cells.begin(), sample.cells.end());
    }
  for (auto& [pair, crease] : placed) {
    if (crease.turns.size() < kMinContactCreaseSamples)
      continue; // a few cells near a corner are no crease
    ContactCrease result;
    result.faces = pair;
    std::nth_element(crease.turns.begin(),
                     crease.turns.begin() +
                       static_cast<std::ptrdiff_t>(crease.turns.size() / 2),
                     crease.turns.end());
    result.degrees = crease.turns[crease.turns.size() / 2];
    result.samples = static_cast<std::uint32_t>(crease.turns.size());
    std::sort(crease.cells.begin(), crease.cells.end());
    crease.cells.erase(std::unique(crease.cells.begin(), crease.cells.end()),
                       crease.cells.end());
    result.cells = std::move(crease.cells);
    creases.push_back(std::move(result));
  }
  return creases;
}

} // namespace visfeat
