#include <visfeat/core/graph/contact_creases.h>

#include <visfeat/core/common/error.h>
#include <visfeat/core/common/threads.h>

#include "../common/angles.h"
#include "face_point_index.h"
#include "plane_sums.h"
#include "region_boundaries.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <utility>

namespace visfeat {

using detail::classOfLabel;
using detail::FacePointIndex;
using detail::PlaneSums;

namespace {

/** Calls f(m) for each band cell m in the cube of cells within `reach` of cell `at`,
 * in z, y, x order (the order the results depend on). */
template <typename F>
void
forEachCellAround(const VoxelBand& band, const CellCoord& at, int reach, F&& f)
{
  for (int dz = -reach; dz <= reach; ++dz)
    for (int dy = -reach; dy <= reach; ++dy)
      for (int dx = -reach; dx <= reach; ++dx) {
        const CellId m = band.find(at + CellCoord(dx, dy, dz));
        if (m != kNoCell)
          f(m);
      }
}

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

/** The sum of squared distances of a set's points to its least-squares plane. */
double
residual(const PlaneSums& sums)
{
  if (sums.count < 3)
    return 0.0;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
  solver.computeDirect(sums.covariance(), Eigen::EigenvaluesOnly);
  return static_cast<double>(sums.count) * std::max(0.0, solver.eigenvalues()(0));
}

/** A split found walking across a contact holds a crease when its two planes leave at
 * most this share of the scatter that one plane through both halves leaves (sums of
 * squared distances): two surfaces meet at the split, not two layers side by side.
 * Measured on splits of at least the minimum crease angle: the public icosahedron's
 * crease that the watershed spilled across (500,000 points, 912 cells) 0.00-0.55, half
 * of them below 0.10; two sheets 10 degrees apart meeting at a wedge (the unit test
 * ContactCreases.AShallowTurnPlacesNoCrease), whose halves each hold both, 0.6-1.0. */
constexpr double kWalkedSplitResidualRatio = 0.25;

/** Where the planes fitted by label at a contact hardly turn, the watershed's boundary
 * lies beside the crease (a face holds a strip of the other's surface up to the
 * contact, and both fit one plane there). Walking across the contact,
 * kContactScanWindows windows to both sides in steps of half a window, the points of
 * both faces within the window at each position split by the plane across the walk
 * there: the sharpest split of at least min_crease_angle (and min_sine) whose planes
 * leave at most kWalkedSplitResidualRatio of one plane's scatter gives the crease's
 * line (relative to `at`), and `offset` its position's distance from `at` (world
 * units). As detail::contactTurn() walks for the crease-angle rule, so a contact the
 * rule keeps has its line here. False when no position turns enough. */
bool
walkedCreaseLine(const FacePointIndex& index,
                 const std::vector<Eigen::Vector3d>& points,
                 const std::vector<std::uint32_t>& labels,
                 const std::array<std::uint32_t, 2>& pair,
                 const Eigen::Vector3d& at,
                 const Eigen::Vector3d& across,
                 double radius,
                 double min_sine,
                 double min_crease_angle,
                 CreaseLine& line,
                 double& offset)
{
  const int steps = static_cast<int>(2.0 * CreaseAngleParameters::kContactScanWindows);
  double sharpest = 0.0;
  for (const double way : {1.0, -1.0})
    for (int k = 1; k <= steps; ++k) {
      const Eigen::Vector3d shift = (way * 0.5 * radius * k) * across;
      PlaneSums before, after;
      index.forEachWithin(at + shift, radius, [&](std::uint32_t i) {
        if (labels[i] != pair[0] && labels[i] != pair[1])
          return;
        const Eigen::Vector3d d = points[i] - at - shift; // from the position
        (d.dot(across) > 0.0 ? after : before).add(d);
      });
      CreaseLine found;
      if (!creaseLine(before, after, min_sine, found) ||
          !(found.turn >= min_crease_angle) || found.turn <= sharpest ||
          found.distance(Eigen::Vector3d::Zero()) > radius)
        continue;
      PlaneSums both = before;
      both.add(after);
      const double ratio = (residual(before) + residual(after)) / residual(both);
      if (!(ratio <= kWalkedSplitResidualRatio))
        continue;
      sharpest = found.turn;
      found.point += shift; // relative to at
      line = found;
      offset = 0.5 * radius * k;
    }
  return sharpest > 0.0;
}

/** The crease line at a contact (relative to `at`): where the planes fitted to the two
 * faces' points within the window (side_a, side_b, by label) cross, when they turn by
 * at least min_crease_angle (offset 0); otherwise the line walkedCreaseLine() finds
 * across the contact (offset: how far from `at`, world units). False when neither. */
bool
contactLine(const FacePointIndex& index,
            const std::vector<Eigen::Vector3d>& points,
            const std::vector<std::uint32_t>& labels,
            const std::array<std::uint32_t, 2>& pair,
            const Eigen::Vector3d& at,
            const PlaneSums& side_a,
            const PlaneSums& side_b,
            double radius,
            double min_sine,
            double min_crease_angle,
            CreaseLine& line,
            double& offset)
{
  offset = 0.0;
  if (creaseLine(side_a, side_b, min_sine, line) && line.turn >= min_crease_angle)
    return true;
  if (side_a.count < 3 || side_b.count < 3)
    return false;
  const Eigen::Vector3d across = acrossDirection(side_a, side_b);
  return !across.isZero() &&
         walkedCreaseLine(index, points, labels, pair, at, across, radius, min_sine,
                          min_crease_angle, line, offset);
}

/** One end of a crease: its outermost sample's centre and line, and the way out. */
struct CreaseEnd
{
  Eigen::Vector3d at;
  CreaseLine line;
  Eigen::Vector3d outward;
};

/** The two ends of a crease: the samples outermost along the main axis of the
 * samples' centres, each with its line's direction turned away from the other end. */
template <typename SamplePtr>
std::vector<CreaseEnd>
creaseEnds(const std::vector<SamplePtr>& samples)
{
  std::vector<CreaseEnd> ends;
  if (samples.size() < 2)
    return ends;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& s : samples)
    mean += s->at;
  mean /= static_cast<double>(samples.size());
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const auto& s : samples)
    scatter += (s->at - mean) * (s->at - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(scatter);
  const Eigen::Vector3d axis = solver.eigenvectors().col(2);
  std::size_t lo = 0, hi = 0;
  for (std::size_t i = 1; i < samples.size(); ++i) {
    const double t = (samples[i]->at - mean).dot(axis);
    if (t < (samples[lo]->at - mean).dot(axis))
      lo = i;
    if (t > (samples[hi]->at - mean).dot(axis))
      hi = i;
  }
  for (const auto& [i, sign] : {std::make_pair(lo, -1.0), std::make_pair(hi, 1.0)}) {
    CreaseEnd end{samples[i]->at, samples[i]->line, sign * axis};
    if (end.line.direction.dot(end.outward) < 0.0)
      end.line.direction = -end.line.direction;
    end.outward = end.line.direction;
    ends.push_back(end);
  }
  return ends;
}

/** Where a crease's line, followed beyond its end, went. */
struct Extension
{
  enum Outcome
  {
    kMetVertex, // it touches a vertex region: the graph's arc
    kMetEdge,   // it touches an edge region: a corner is missing there
    kLeftFaces, // it left its two faces (into a third face, or off the band past a
                // convex corner): a corner if other creases end there
    kRanOut     // still on its faces after `length`: nothing to meet
  };
  Outcome outcome = kRanOut;
  std::vector<CellId> cells; // of the two faces, along the line
  Eigen::Vector3d at;        // the last point followed (world units)
};

/** Cells of the two faces of `pair` along a crease's line beyond its end, up to
 * `length` (world units) or until the line meets an edge or vertex region or leaves
 * the two faces. */
Extension
extendToFeature(const VoxelBand& band,
                const std::vector<std::uint32_t>& cell_labels,
                const std::vector<FeatureClass>& classes,
                const std::array<std::uint32_t, 2>& pair,
                const Eigen::Vector3d& at,
                const CreaseLine& line,
                const Eigen::Vector3d& outward,
                double half_width,
                double length)
{
  const GridSpec& grid = band.grid();
  const double step = 0.5 * grid.cell_size;
  const Eigen::Vector3d origin = at + line.point;
  const double start = (at - origin).dot(outward);
  Extension extension;
  for (double t = step; t <= length; t += step) {
    const Eigen::Vector3d x = origin + (start + t) * outward;
    extension.at = x;
    const CellCoord home = grid.cellOf(x);
    bool on_faces = false;
    FeatureClass met = FeatureClass::kNone;
    forEachCellAround(band, home, 1, [&](CellId m) {
      if (line.distance(grid.cellCenter(band.coord(m)) - at) > half_width)
        return;
      const std::uint32_t l = cell_labels[static_cast<std::size_t>(m)];
      const FeatureClass c = classOfLabel(classes, l);
      if (l == pair[0] || l == pair[1]) {
        on_faces = true;
        extension.cells.push_back(m);
      } else if (c == FeatureClass::kVertex ||
                 (c == FeatureClass::kEdge && met != FeatureClass::kVertex)) {
        met = c;
      }
    });
    if (met != FeatureClass::kNone) {
      extension.outcome =
        met == FeatureClass::kVertex ? Extension::kMetVertex : Extension::kMetEdge;
      return extension;
    }
    if (!on_faces) {
      extension.outcome = Extension::kLeftFaces;
      return extension;
    }
  }
  extension.cells.clear();
  return extension;
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
    return classOfLabel(classes, l) == FeatureClass::kFace;
  };
  // the face pair {min, max} of face label a and neighbour n when they are a contact
  // outside `excluded`; {0, 0} otherwise (labels of faces are >= 1)
  const auto contactPair = [&](std::uint32_t a, CellId n) {
    const std::uint32_t b = n == kNoCell ? 0 : cell_labels[static_cast<std::size_t>(n)];
    const std::array<std::uint32_t, 2> pair{{std::min(a, b), std::max(a, b)}};
    return b == a || !isFace(b) || excluded.count(pair) != 0
             ? std::array<std::uint32_t, 2>{}
             : pair;
  };
  // Most parts have no two faces touching outside the excluded pairs: then there is
  // nothing to sample, and the two point indexes below are not built.
  bool any_contact = false;
  for (std::size_t c = 0; c < band.size() && !any_contact; ++c) {
    const std::uint32_t a = cell_labels[c];
    if (isFace(a))
      for (const CellId n : band.neighbours(static_cast<CellId>(c)))
        any_contact = any_contact || contactPair(a, n)[0] != 0;
  }
  if (!any_contact)
    return creases;
  const FacePointIndex index(points, labels, classes, radius);
  // samples only away from edges and vertices: near them the watershed spills across
  // a crease that has its edge (sparse icosahedra: a second edge along one)
  const double clearance = CreaseAngleParameters::kContactClearanceCells * cell;
  const FacePointIndex features(points, labels, classes, clearance, false);
  const double min_sine =
    std::sin(std::clamp(min_crease_angle, 0.0, 90.0) * detail::kPi / 180.0);
  const double half_width = half_width_cells * cell;
  const int reach = static_cast<int>(std::ceil(window_cells));
  // the samples stop kContactClearanceCells from features, their cells `reach` beyond
  const double extension_length =
    (CreaseAngleParameters::kContactClearanceCells + 2.0) * cell;
  // One sample per contact cell (the planes of the two faces around it), on threads
  // over chunks of cells; the chunks' samples are then gathered in cell order.
  struct Sample
  {
    std::array<std::uint32_t, 2> pair{};
    double turn = 0.0;
    Eigen::Vector3d at = Eigen::Vector3d::Zero(); // the contact cell's centre
    CreaseLine line;                              // relative to at
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
          const std::array<std::uint32_t, 2> pair = contactPair(a, n);
          if (pair[0] == 0)
            continue;
          const std::uint32_t b = pair[0] == a ? pair[1] : pair[0];
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
          double offset = 0.0; // of a crease found walking across, world units
          if (!contactLine(index, points, labels, pair, at, side_a, side_b, radius,
                           min_sine, min_crease_angle, line, offset))
            break;
          Sample sample;
          sample.pair = pair;
          sample.turn = line.turn;
          sample.at = at;
          sample.line = line;
          const int cells_reach = reach + static_cast<int>(std::ceil(offset / cell));
          forEachCellAround(band, at_cell, cells_reach, [&](CellId m) {
            const std::uint32_t l = cell_labels[static_cast<std::size_t>(m)];
            if ((l == a || l == b) &&
                line.distance(grid.cellCenter(band.coord(m)) - at) <= half_width)
              sample.cells.push_back(m);
          });
          out.push_back(std::move(sample));
          break;
        }
      }
    });
  // per pair of faces, its samples in cell order
  std::map<std::array<std::uint32_t, 2>, std::vector<const Sample*>> placed;
  for (const std::vector<Sample>& samples : chunk_samples)
    for (const Sample& sample : samples)
      placed[sample.pair].push_back(&sample);
  for (const auto& [pair, samples] : placed) {
    if (samples.size() < kMinContactCreaseSamples)
      continue; // a few cells near a corner are no crease
    ContactCrease result;
    result.faces = pair;
    std::vector<double> turns;
    std::vector<CellId> cells;
    for (const Sample* sample : samples) {
      turns.push_back(sample->turn);
      cells.insert(cells.end(), sample->cells.begin(), sample->cells.end());
    }
    std::nth_element(turns.begin(),
                     turns.begin() + static_cast<std::ptrdiff_t>(turns.size() / 2),
                     turns.end());
    result.degrees = turns[turns.size() / 2];
    result.samples = static_cast<std::uint32_t>(turns.size());
    for (const CreaseEnd& end : creaseEnds(samples)) {
      const Extension more =
        extendToFeature(band, cell_labels, classes, pair, end.at, end.line, end.outward,
                        half_width, extension_length);
      cells.insert(cells.end(), more.cells.begin(), more.cells.end());
      if (more.outcome == Extension::kMetEdge || more.outcome == Extension::kLeftFaces)
        result.open_ends.push_back(
          {more.at, end.outward, more.outcome == Extension::kMetEdge});
    }
    std::sort(cells.begin(), cells.end());
    cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
    result.cells = std::move(cells);
    creases.push_back(std::move(result));
  }
  return creases;
}

std::vector<std::vector<CellId>>
contactCorners(const VoxelBand& band,
               const std::vector<std::uint32_t>& cell_labels,
               const std::vector<FeatureClass>& classes,
               const std::vector<ContactCrease>& creases)
{
  const GridSpec& grid = band.grid();
  const double cell = grid.cell_size;
  const double gather = kContactCornerGatherCells * cell;
  struct End
  {
    std::size_t crease;
    const ContactCrease::End* end;
  };
  std::vector<End> ends;
  for (std::size_t k = 0; k < creases.size(); ++k)
    for (const ContactCrease::End& e : creases[k].open_ends)
      ends.push_back({k, &e});
  std::vector<char> used(ends.size(), 0);
  std::vector<std::vector<CellId>> corners;
  for (std::size_t i = 0; i < ends.size(); ++i) {
    if (used[i])
      continue;
    // the ends that meet here: one that runs into an edge alone; ends that left
    // their faces with those of other creases near them
    std::vector<std::size_t> group{i};
    if (!ends[i].end->meets_edge)
      for (std::size_t j = i + 1; j < ends.size(); ++j) {
        if (used[j] || ends[j].end->meets_edge)
          continue;
        bool fresh = true, near = false;
        for (const std::size_t g : group) {
          fresh = fresh && ends[g].crease != ends[j].crease;
          near = near || (ends[g].end->at - ends[j].end->at).norm() <= gather;
        }
        if (fresh && near)
          group.push_back(j);
      }
    if (!ends[i].end->meets_edge && group.size() < 2)
      continue;
    for (const std::size_t g : group)
      used[g] = 1;
    // the corner: the point nearest every end's line (least squares), or the ends'
    // mean where the lines are near parallel or the point lies far from the ends
    Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
    Eigen::Vector3d b = Eigen::Vector3d::Zero(), mean = Eigen::Vector3d::Zero();
    for (const std::size_t g : group) {
      const ContactCrease::End& e = *ends[g].end;
      const Eigen::Matrix3d off =
        Eigen::Matrix3d::Identity() - e.direction * e.direction.transpose();
      a += off;
      b += off * e.at;
      mean += e.at;
    }
    mean /= static_cast<double>(group.size());
    Eigen::Vector3d corner = mean;
    if (group.size() >= 2) {
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(a);
      if (solver.eigenvalues()(0) > 0.05 * solver.eigenvalues()(2)) {
        const Eigen::Vector3d x = a.ldlt().solve(b);
        bool close = true;
        for (const std::size_t g : group)
          close = close && (x - ends[g].end->at).norm() <= gather;
        if (close)
          corner = x;
      }
    }
    double reach = 0.0;
    for (const std::size_t g : group)
      reach = std::max(reach, (corner - ends[g].end->at).norm());
    const double radius =
      std::clamp(reach + 0.5 * cell, kContactCornerRadiusCells * cell,
                 kContactCornerMaxRadiusCells * cell);
    // the face cells within the radius
    std::vector<CellId> cells;
    const CellCoord home = grid.cellOf(corner);
    const int r = static_cast<int>(std::ceil(radius / cell));
    forEachCellAround(band, home, r, [&](CellId m) {
      if (classOfLabel(classes, cell_labels[static_cast<std::size_t>(m)]) ==
            FeatureClass::kFace &&
          (grid.cellCenter(band.coord(m)) - corner).norm() <= radius)
        cells.push_back(m);
    });
    if (!cells.empty()) {
      std::sort(cells.begin(), cells.end());
      corners.push_back(std::move(cells));
    }
  }
  return corners;
}

std::vector<double>
contactCreaseTurns(const std::vector<ContactCrease>& creases,
                   const std::vector<std::uint32_t>& cell_labels,
                   const std::vector<FeatureClass>& classes,
                   const std::vector<char>& is_new)
{
  const std::size_t labels = classes.size() + 1;
  if (is_new.size() < labels)
    throw Error("contactCreaseTurns: is_new holds " + std::to_string(is_new.size()) +
                " labels, the regions " + std::to_string(labels));
  std::vector<double> turns(labels, std::numeric_limits<double>::quiet_NaN());
  std::vector<std::size_t> most(labels, 0); // per label, the cells of its crease
  std::vector<std::size_t> held(labels, 0); // per label, the current crease's cells
  const auto labelOf = [&](CellId c) {
    if (static_cast<std::size_t>(c) >= cell_labels.size() ||
        cell_labels[static_cast<std::size_t>(c)] >= labels)
      throw Error("contactCreaseTurns: a crease cell beyond the band or the regions");
    return cell_labels[static_cast<std::size_t>(c)];
  };
  for (const ContactCrease& crease : creases) {
    for (const CellId c : crease.cells)
      ++held[labelOf(c)];
    for (const CellId c : crease.cells) {
      const std::uint32_t label = labelOf(c);
      if (label != 0 && is_new[label] && classes[label - 1] == FeatureClass::kEdge &&
          held[label] > most[label]) {
        most[label] = held[label];
        turns[label] = crease.degrees;
      }
      held[label] = 0; // each label once per crease
    }
  }
  return turns;
}

} // namespace visfeat
