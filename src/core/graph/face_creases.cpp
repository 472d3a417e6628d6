#include <visfeat/core/common/error.h>
#include <visfeat/core/common/threads.h>
#include <visfeat/core/graph/face_creases.h>

#include "../common/plane_sums.h"
#include "region_boundaries.h"

#include <algorithm>
#include <array>
#include <map>
#include <numeric>
#include <utility>

namespace visfeat {

using detail::classOfLabel;
using detail::PlaneSums;

namespace {

/** A face's bricks: (label, brick) keys in ascending order, with the sums of the
 * face's points in each brick (relative to the brick's corner, cell units). */
struct BrickSums
{
  std::vector<std::pair<std::uint32_t, std::uint64_t>> keys;
  std::vector<PlaneSums> sums;

  std::int64_t find(std::uint32_t label, std::uint64_t brick) const
  {
    const auto key = std::make_pair(label, brick);
    const auto it = std::lower_bound(keys.begin(), keys.end(), key);
    return it != keys.end() && *it == key ? it - keys.begin() : -1;
  }
};

constexpr int kBrickBits = 21;
constexpr std::int64_t kBrickBias = std::int64_t(1) << (kBrickBits - 1);

std::uint64_t
brickKey(const Eigen::Vector3i& b)
{
  const auto part = [](int v) { return static_cast<std::uint64_t>(v + kBrickBias); };
  return (part(b.z()) << (2 * kBrickBits)) | (part(b.y()) << kBrickBits) | part(b.x());
}

Eigen::Vector3i
brickOf(const Eigen::Vector3d& q)
{
  return (q / FaceCreaseParameters::kBrickCells).array().floor().cast<int>();
}

/** Sums of one cell's points relative to its corner (floats: the coordinates are
 * below 1). */
struct CellSums
{
  std::uint32_t count = 0;
  std::array<float, 9> sums{}; // x, y, z, xx, xy, xz, yy, yz, zz
};

/** The face points summed per face and brick (each point takes its cell's label), and
 * per band cell its entry in the result (-1: none: not a face cell, or no point). */
BrickSums
sumBricks(const VoxelBand& band,
          const std::vector<std::uint32_t>& cell_labels,
          const std::vector<Eigen::Vector3d>& points,
          const std::vector<CellId>& point_cells,
          const std::vector<FeatureClass>& classes,
          std::vector<std::int32_t>& entry_of)
{
  const Eigen::Vector3d origin = band.grid().origin;
  const double scale = 1.0 / band.grid().cell_size;
  std::vector<CellSums> cells(band.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const CellId c = point_cells[i];
    if (c == kNoCell || !points[i].allFinite() ||
        classOfLabel(classes, cell_labels[static_cast<std::size_t>(c)]) !=
          FeatureClass::kFace)
      continue;
    // relative to the cell's corner; moved to the brick's below
    const Eigen::Vector3f q =
      ((points[i] - origin) * scale - band.coord(c).cast<double>()).cast<float>();
    CellSums& sum = cells[static_cast<std::size_t>(c)];
    ++sum.count;
    const std::array<float, 9> terms{q.x(),         q.y(),         q.z(),
                                     q.x() * q.x(), q.x() * q.y(), q.x() * q.z(),
                                     q.y() * q.y(), q.y() * q.z(), q.z() * q.z()};
    for (std::size_t k = 0; k < terms.size(); ++k)
      sum.sums[k] += terms[k];
  }
  // the cells grouped by face and brick
  std::vector<std::pair<std::pair<std::uint32_t, std::uint64_t>, CellId>> at;
  for (std::size_t c = 0; c < cells.size(); ++c)
    if (cells[c].count != 0) {
      const auto id = static_cast<CellId>(c);
      at.push_back(
        {{cell_labels[c], brickKey(brickOf(band.coord(id).cast<double>()))}, id});
    }
  std::sort(at.begin(), at.end());
  BrickSums bricks;
  entry_of.assign(band.size(), -1);
  for (const auto& [key, c] : at) {
    if (bricks.keys.empty() || bricks.keys.back() != key) {
      bricks.keys.push_back(key);
      bricks.sums.emplace_back();
    }
    const CellSums& cell = cells[static_cast<std::size_t>(c)];
    const std::array<float, 9>& t = cell.sums;
    const Eigen::Vector3d m(t[0], t[1], t[2]);
    Eigen::Matrix3d outer;
    outer << t[3], t[4], t[5], t[4], t[6], t[7], t[5], t[7], t[8];
    // from the cell's corner to its brick's (0 or 1 cell on each axis)
    const Eigen::Vector3i& coord = band.coord(c);
    const Eigen::Vector3d shift =
      (coord - brickOf(coord.cast<double>()) * FaceCreaseParameters::kBrickCells)
        .cast<double>();
    const double n = cell.count;
    PlaneSums& sum = bricks.sums.back();
    sum.count += cell.count;
    sum.sum += m + n * shift;
    sum.outer += outer + m * shift.transpose() + shift * m.transpose() +
                 n * shift * shift.transpose();
    entry_of[static_cast<std::size_t>(c)] =
      static_cast<std::int32_t>(bricks.keys.size() - 1);
  }
  return bricks;
}

/** Per entry of `bricks`, 1 when the 3 x 3 x 3 bricks of its face around it read a
 * crease. */
std::vector<char>
ridgeBricks(const BrickSums& bricks, const FaceCreaseParameters& parameters)
{
  const auto n = static_cast<std::int64_t>(bricks.keys.size());
  std::vector<char> ridge(bricks.keys.size(), 0);
#pragma omp parallel for schedule(static)                                              \
  num_threads(resolveThreads(parameters.threads))
  for (std::int64_t e = 0; e < n; ++e) {
    const auto [label, key] = bricks.keys[static_cast<std::size_t>(e)];
    const auto coordinate = [](std::uint64_t k, int axis) {
      return static_cast<int>((k >> (axis * kBrickBits)) &
                              ((std::uint64_t(1) << kBrickBits) - 1)) -
             static_cast<int>(kBrickBias);
    };
    const Eigen::Vector3i b(coordinate(key, 0), coordinate(key, 1), coordinate(key, 2));
    PlaneSums block;
    // keys order a face's bricks by z, y, x: each row of three (dx = -1..1) is one run
    // of the sorted keys, found with one search
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy) {
        const auto first =
          std::make_pair(label, brickKey(b + Eigen::Vector3i(-1, dy, dz)));
        const auto last =
          std::make_pair(label, brickKey(b + Eigen::Vector3i(1, dy, dz)));
        for (auto it = std::lower_bound(bricks.keys.begin(), bricks.keys.end(), first);
             it != bricks.keys.end() && *it <= last; ++it) {
          const Eigen::Vector3i d(coordinate(it->second, 0) - b.x(), dy, dz);
          // the other brick's sums moved to this brick's corner
          const PlaneSums& s =
            bricks.sums[static_cast<std::size_t>(it - bricks.keys.begin())];
          const Eigen::Vector3d shift =
            (d * FaceCreaseParameters::kBrickCells).cast<double>();
          block.count += s.count;
          block.sum += s.sum + double(s.count) * shift;
          block.outer += s.outer + s.sum * shift.transpose() +
                         shift * s.sum.transpose() +
                         double(s.count) * shift * shift.transpose();
        }
      }
    if (block.count >= parameters.min_points &&
        block.surfaceVariation() >= parameters.min_surface_variation)
      ridge[static_cast<std::size_t>(e)] = 1;
  }
  return ridge;
}

/** Scratch per band cell for the breadth-first passes over one face at a time
 * (kUnset outside the face being split, reset after it). */
constexpr int kUnset = -3;
constexpr int kRidge = -1;
constexpr int kNotReached = -2;

/** The parts of face `face` (cells ascending) without its ridge cells: each cell's
 * part in part_of (kRidge for a ridge cell), and the parts' sizes. */
std::vector<std::size_t>
faceParts(const VoxelBand& band,
          const std::vector<CellId>& cells,
          const std::vector<char>& is_ridge,
          std::vector<int>& part_of)
{
  std::vector<std::size_t> sizes;
  for (std::size_t k = 0; k < cells.size(); ++k)
    part_of[static_cast<std::size_t>(cells[k])] = is_ridge[k] ? kRidge : kNotReached;
  std::vector<CellId> queue;
  for (const CellId seed : cells) {
    if (part_of[static_cast<std::size_t>(seed)] != kNotReached)
      continue;
    const int part = static_cast<int>(sizes.size());
    queue.assign(1, seed);
    part_of[static_cast<std::size_t>(seed)] = part;
    for (std::size_t i = 0; i < queue.size(); ++i)
      for (const CellId m : band.neighbours(queue[i])) {
        if (m == kNoCell)
          continue;
        int& p = part_of[static_cast<std::size_t>(m)];
        if (p == kNotReached) { // a cell of the face, not a ridge cell
          p = part;
          queue.push_back(m);
        }
      }
    sizes.push_back(queue.size());
  }
  return sizes;
}

/** Splits face `face` where its ridge cells cut it into large parts (see
 * creasedFacePieces()); appends the pieces but the largest to `pieces`. part_of and
 * piece_of: scratch, kUnset on every cell, left so. */
void
splitFace(const VoxelBand& band,
          std::uint32_t face,
          const std::vector<CellId>& cells,
          const std::vector<char>& is_ridge,
          std::size_t min_piece_cells,
          std::vector<int>& part_of,
          std::vector<int>& piece_of,
          std::vector<CreasedFacePiece>& pieces)
{
  const std::vector<std::size_t> sizes = faceParts(band, cells, is_ridge, part_of);
  std::vector<int> large(sizes.size(), -1); // part -> index among the large parts
  int large_count = 0;
  for (std::size_t p = 0; p < sizes.size(); ++p)
    if (sizes[p] >= min_piece_cells)
      large[p] = large_count++;
  // every cell of the face joins the nearest large part, breadth-first from all of
  // them at once (seeds in order of cell id)
  std::vector<CellId> queue;
  if (large_count >= 2) {
    for (const CellId c : cells) {
      piece_of[static_cast<std::size_t>(c)] = kNotReached;
      const int p = part_of[static_cast<std::size_t>(c)];
      if (p >= 0 && large[static_cast<std::size_t>(p)] >= 0) {
        piece_of[static_cast<std::size_t>(c)] = large[static_cast<std::size_t>(p)];
        queue.push_back(c);
      }
    }
    for (std::size_t i = 0; i < queue.size(); ++i) {
      const int piece = piece_of[static_cast<std::size_t>(queue[i])];
      for (const CellId m : band.neighbours(queue[i]))
        if (m != kNoCell && piece_of[static_cast<std::size_t>(m)] == kNotReached) {
          piece_of[static_cast<std::size_t>(m)] = piece;
          queue.push_back(m);
        }
    }
    std::vector<std::vector<CellId>> grown(static_cast<std::size_t>(large_count));
    for (const CellId c : cells) {
      const int piece = piece_of[static_cast<std::size_t>(c)];
      if (piece >= 0)
        grown[static_cast<std::size_t>(piece)].push_back(c);
    }
    std::size_t largest = 0;
    for (std::size_t p = 1; p < grown.size(); ++p)
      if (grown[p].size() > grown[largest].size())
        largest = p;
    for (std::size_t p = 0; p < grown.size(); ++p)
      if (p != largest)
        pieces.push_back({face, std::move(grown[p])});
  }
  for (const CellId c : cells)
    part_of[static_cast<std::size_t>(c)] = piece_of[static_cast<std::size_t>(c)] =
      kUnset;
}

} // namespace

std::vector<CreasedFacePiece>
creasedFacePieces(const VoxelBand& band,
                  const std::vector<std::uint32_t>& cell_labels,
                  const std::vector<Eigen::Vector3d>& points,
                  const std::vector<CellId>& point_cells,
                  const std::vector<FeatureClass>& classes,
                  const FaceCreaseParameters& parameters)
{
  if (points.size() != point_cells.size())
    throw Error("creasedFacePieces: " + std::to_string(points.size()) + " points but " +
                std::to_string(point_cells.size()) + " point cells");
  if (cell_labels.size() != band.size())
    throw Error("creasedFacePieces: cell labels do not match the band");
  for (const CellId c : point_cells)
    if (c != kNoCell && (c < 0 || static_cast<std::size_t>(c) >= band.size()))
      throw Error("creasedFacePieces: point cell " + std::to_string(c) +
                  " is not one of the " + std::to_string(band.size()) + " band cells");
  std::vector<std::int32_t> entry_of;
  const BrickSums bricks =
    sumBricks(band, cell_labels, points, point_cells, classes, entry_of);
  const std::vector<char> ridge = ridgeBricks(bricks, parameters);
  // the faces holding a ridge brick, and their cells
  std::map<std::uint32_t, std::vector<CellId>> cells_of;
  for (std::size_t e = 0; e < ridge.size(); ++e)
    if (ridge[e])
      cells_of[bricks.keys[e].first];
  if (cells_of.empty())
    return {};
  detail::gatherCells(cell_labels, cells_of);
  std::vector<CreasedFacePiece> pieces;
  std::vector<int> part_of(band.size(), kUnset), piece_of(band.size(), kUnset);
  for (const auto& [face, cells] : cells_of) {
    std::vector<char> is_ridge(cells.size(), 0);
    for (std::size_t k = 0; k < cells.size(); ++k) {
      std::int64_t e = entry_of[static_cast<std::size_t>(cells[k])];
      if (e < 0) // a cell without points: its brick's entry, if any
        e = bricks.find(face, brickKey(brickOf(band.coord(cells[k]).cast<double>())));
      is_ridge[k] = e >= 0 && ridge[static_cast<std::size_t>(e)];
    }
    splitFace(band, face, cells, is_ridge, parameters.min_piece_cells, part_of,
              piece_of, pieces);
  }
  return pieces;
}

std::vector<std::uint32_t>
rejoinCreasedFacePieces(const VoxelBand& band,
                        const std::vector<std::uint32_t>& cell_labels,
                        const std::vector<std::uint32_t>& origin,
                        const std::set<std::array<std::uint32_t, 2>>& creases)
{
  std::vector<std::uint32_t> into(origin.size());
  std::iota(into.begin(), into.end(), 0u);
  const auto root = [&](std::uint32_t l) {
    while (into[l] != l)
      l = into[l];
    return l;
  };
  std::map<std::uint32_t, std::vector<CellId>> cells_of;
  for (std::uint32_t l = 1; l < origin.size(); ++l)
    if (origin[l] != l)
      cells_of[l];
  if (cells_of.empty())
    return into;
  detail::gatherCells(cell_labels, cells_of);
  for (const auto& [piece, cells] : cells_of)
    for (const auto& [other, shared] :
         detail::sharedBoundary(band, cell_labels, cells, piece)) {
      if (other >= origin.size() || origin[other] != origin[piece] ||
          creases.count({{std::min(piece, other), std::max(piece, other)}}) != 0)
        continue;
      const std::uint32_t a = root(piece), b = root(other);
      into[std::max(a, b)] = std::min(a, b);
    }
  for (std::uint32_t l = 1; l < into.size(); ++l)
    into[l] = root(l);
  return into;
}

} // namespace visfeat
