#include <visfeat/core/band/band_roughness.h>
#include <visfeat/core/band/voxel_band.h>
#include <visfeat/core/common/error.h>
#include <visfeat/core/common/threads.h>

#include <algorithm>
#include <cstdlib>
#include <numeric>
#include <sstream>
#include <utility>

namespace visfeat {
namespace {

const std::array<CellCoord, 6> kFaceSteps = {CellCoord(-1, 0, 0), CellCoord(1, 0, 0),
                                             CellCoord(0, -1, 0), CellCoord(0, 1, 0),
                                             CellCoord(0, 0, -1), CellCoord(0, 0, 1)};

/** Chunks of the parallel loops (small enough to balance, large enough to be cheap). */
constexpr std::size_t kPointsPerChunk = 16384;
constexpr std::size_t kCellsPerChunk = 8192;

/** Indices 0..n-1 ordered by the linear key of coord(i) (keys computed once; the keys
 * are distinct, so the order is the one std::sort gave). A radix sort, 11 bits a pass
 * (3 passes up to 2^33 cells): on the generated icosahedron at 256 (216,000 cells, 1
 * thread, 2 cores, 2026-12-07) the band's two sorts took 12 + 7 ms with std::sort,
 * 6 + 5 ms so. */
template <typename Coord>
std::vector<std::size_t>
sortedByKey(const GridSpec& grid, std::size_t n, Coord&& coord)
{
  std::vector<std::pair<std::uint64_t, std::size_t>> keyed(n), swap(n);
  std::uint64_t highest = 0;
  for (std::size_t i = 0; i < n; ++i) {
    keyed[i] = {grid.linearKey(coord(i)), i};
    highest = std::max(highest, keyed[i].first);
  }
  constexpr int kDigitBits = 11;
  constexpr std::size_t kDigits = std::size_t{1} << kDigitBits;
  std::vector<std::size_t> start(kDigits);
  for (int shift = 0; shift < 64 && (highest >> shift) != 0; shift += kDigitBits) {
    std::fill(start.begin(), start.end(), 0);
    for (const auto& entry : keyed)
      ++start[(entry.first >> shift) & (kDigits - 1)];
    std::size_t sum = 0;
    for (std::size_t& s : start)
      sum += std::exchange(s, sum);
    for (const auto& entry : keyed)
      swap[start[(entry.first >> shift) & (kDigits - 1)]++] = entry;
    keyed.swap(swap);
  }
  std::vector<std::size_t> order(n);
  for (std::size_t i = 0; i < n; ++i)
    order[i] = keyed[i].second;
  return order;
}

/** The 26-neighbour offsets that are not face steps: 12 edge and 8 corner steps. */
std::vector<CellCoord>
diagonalSteps()
{
  std::vector<CellCoord> steps;
  for (int z = -1; z <= 1; ++z)
    for (int y = -1; y <= 1; ++y)
      for (int x = -1; x <= 1; ++x)
        if (std::abs(x) + std::abs(y) + std::abs(z) >= 2)
          steps.emplace_back(x, y, z);
  return steps;
}

/** Repairs the 6-connectivity of a growing set of cells. */
class BandRepair
{
public:
  BandRepair(const GridSpec& grid,
             std::vector<CellCoord>& coords,
             std::vector<std::uint32_t>& counts,
             std::vector<Eigen::Vector3d>& sums)
      : coords_(coords)
      , counts_(counts)
      , sums_(sums)
      , index_(grid.dims)
  {
    index_.allocateBricks(coords_);
    for (std::size_t i = 0; i < coords_.size(); ++i)
      index_.insert(coords_[i], static_cast<CellId>(i));
  }

  std::size_t run()
  {
    const std::vector<CellCoord> steps = diagonalSteps();
    std::size_t added = 0;
    // Cells added on the way are appended and visited too, so they get repaired as
    // well; every pair is seen from both ends, the first visit decides. A pair stays
    // connected once connected (cells are only added) and the test is symmetric, so
    // the second visit adds nothing: a pair of two input cells is visited from its
    // lower id only. Every cell a visit looks at lies in the 3x3x3 block around the
    // visiting cell, read once per cell (near_) and kept up to date as cells are
    // added. Generated icosahedron at 256, 1 thread, 2 cores, 2026-12-07: the repair's
    // visits took 50 ms with a find per step and per test, 41 ms so.
    const std::size_t inputs = coords_.size();
    for (std::size_t i = 0; i < coords_.size(); ++i) {
      index_.neighbourhood(coords_[i], near_);
      for (const CellCoord& step : steps) {
        const CellId j = near_[slot(step)];
        if (j != kNoCell && !(i < inputs && static_cast<std::size_t>(j) < i))
          added += connect(static_cast<CellId>(i), j);
      }
    }
    return added;
  }

private:
  /** Place of the offset d (each coordinate -1, 0 or 1) in near_. */
  static std::size_t slot(const CellCoord& d)
  {
    return static_cast<std::size_t>((d.z() + 1) * 9 + (d.y() + 1) * 3 + (d.x() + 1));
  }

  /** Whether the cell at offset d from the visiting cell is in the set. */
  bool mixed(const CellCoord& d) const { return near_[slot(d)] != kNoCell; }

  /** Adds the cell at offset d from the visiting cell a. */
  void add(CellId a, const CellCoord& d)
  {
    const CellCoord c = coords_[a] + d;
    near_[slot(d)] = static_cast<CellId>(coords_.size());
    index_.insert(c, static_cast<CellId>(coords_.size()));
    coords_.push_back(c);
    counts_.push_back(0);
    sums_.push_back(Eigen::Vector3d::Zero());
  }

  /** Centroid of the points of both cells (cell units), centres for cells without. */
  Eigen::Vector3d pairCentroid(CellId a, CellId b) const
  {
    const std::uint64_t n = std::uint64_t{counts_[a]} + counts_[b];
    if (n == 0)
      return 0.5 * (coords_[a].cast<double>() + coords_[b].cast<double>()) +
             Eigen::Vector3d::Constant(0.5);
    return (sums_[a] + sums_[b]) / static_cast<double>(n);
  }

  double distance(const CellCoord& c, const Eigen::Vector3d& p) const
  {
    return (c.cast<double>() + Eigen::Vector3d::Constant(0.5) - p).squaredNorm();
  }

  /** Adds the fewest cells of the 2x2x2 box of a and b so they are 6-connected in it
   * (a is the visiting cell; offsets below are from a). */
  std::size_t connect(CellId a, CellId b)
  {
    const CellCoord ca = coords_[a];
    const CellCoord step = coords_[b] - ca;
    std::array<CellCoord, 3> units;
    int axes = 0;
    for (int k = 0; k < 3; ++k)
      if (step[k] != 0)
        units[axes++] = CellCoord::Unit(k) * step[k];

    if (axes == 2) {
      const CellCoord p = units[0], q = units[1];
      if (mixed(p) || mixed(q))
        return 0;
      const Eigen::Vector3d centroid = pairCentroid(a, b);
      add(a, distance(ca + q, centroid) < distance(ca + p, centroid) ? q : p);
      return 1;
    }

    // Corner pair: monotone paths a -> a+u -> a+u+v -> b over the 6 axis orders (any
    // path inside the box implies a monotone one).
    static const int kOrders[6][2] = {{0, 1}, {0, 2}, {1, 0}, {1, 2}, {2, 0}, {2, 1}};
    std::array<bool, 3> first_mixed, second_mixed; // a + u_i, b - u_i
    for (int i = 0; i < 3; ++i) {
      first_mixed[i] = mixed(units[i]);
      second_mixed[i] = mixed(step - units[i]);
    }
    for (const auto& order :
         kOrders) // second cell of order (i, j) is b - u_k, k the third axis
      if (first_mixed[order[0]] && second_mixed[3 - order[0] - order[1]])
        return 0;

    const Eigen::Vector3d centroid = pairCentroid(a, b);
    int best_missing = 3;
    double best_cost = 0.0;
    std::array<CellCoord, 2> best_path;
    for (const auto& order : kOrders) {
      const CellCoord first = units[order[0]];
      const CellCoord second = first + units[order[1]];
      const bool has_first = first_mixed[order[0]];
      const bool has_second = second_mixed[3 - order[0] - order[1]];
      const int missing = int(!has_first) + int(!has_second);
      const double cost = (has_first ? 0.0 : distance(ca + first, centroid)) +
                          (has_second ? 0.0 : distance(ca + second, centroid));
      if (missing < best_missing || (missing == best_missing && cost < best_cost)) {
        best_missing = missing;
        best_cost = cost;
        best_path = {first, second};
      }
    }
    std::size_t added = 0;
    for (const CellCoord& d : best_path)
      if (!mixed(d)) {
        add(a, d);
        ++added;
      }
    return added;
  }

  std::vector<CellCoord>& coords_;
  std::vector<std::uint32_t>& counts_;
  std::vector<Eigen::Vector3d>& sums_;
  CellIndex index_;
  std::array<CellId, 27> near_; // ids around the visiting cell
};

/** Appends the cells of fill that no entry of occupied holds, without points; returns
 * how many. */
std::size_t
addFillCells(const GridSpec& grid,
             const std::vector<CellCoord>& fill,
             std::vector<OccupiedCell>& occupied)
{
  if (fill.empty())
    return 0;
  std::vector<std::uint64_t> held(occupied.size());
  for (std::size_t i = 0; i < occupied.size(); ++i)
    held[i] = grid.linearKey(occupied[i].coord);
  std::sort(held.begin(), held.end());
  std::vector<std::pair<std::uint64_t, std::size_t>> keyed(fill.size());
  for (std::size_t i = 0; i < fill.size(); ++i)
    keyed[i] = {grid.linearKey(fill[i]), i};
  if (!std::is_sorted(keyed.begin(), keyed.end()))
    std::sort(keyed.begin(), keyed.end()); // rasterizeTriangles() gives them sorted
  const std::size_t before = occupied.size();
  occupied.reserve(occupied.size() + fill.size());
  for (std::size_t i = 0; i < keyed.size(); ++i) {
    if (i > 0 && keyed[i].first == keyed[i - 1].first)
      continue;
    if (std::binary_search(held.begin(), held.end(), keyed[i].first))
      continue;
    OccupiedCell cell;
    cell.coord = fill[keyed[i].second];
    occupied.push_back(cell);
  }
  return occupied.size() - before;
}

} // namespace

VoxelBand
VoxelBand::build(const GridSpec& grid,
                 std::vector<OccupiedCell> occupied,
                 const std::vector<std::int32_t>& point_occupied,
                 const Options& options,
                 const std::vector<CellCoord>& fill)
{
  if (occupied.empty() && fill.empty())
    throw Error("the band is empty: no cell holds a finite point");
  if ((grid.dims.array() <= 0).any())
    throw Error("the grid has no cells");
  auto check = [&grid](const CellCoord& c) {
    if (!grid.contains(c)) {
      std::ostringstream msg;
      msg << "cell (" << c.transpose() << ") lies outside the grid of "
          << grid.dims.transpose() << " cells";
      throw Error(msg.str());
    }
  };
  for (const OccupiedCell& cell : occupied)
    check(cell.coord);
  for (const CellCoord& c : fill)
    check(c);
  const std::size_t entries = occupied.size();
  const std::size_t fill_cells = addFillCells(grid, fill, occupied);

  // Number the occupied cells by linear key; remember where each input entry went.
  const std::vector<std::size_t> order = sortedByKey(
    grid, occupied.size(), [&](std::size_t i) { return occupied[i].coord; });
  std::vector<CellCoord> coords;
  std::vector<std::uint32_t> counts;
  std::vector<Eigen::Vector3d> sums; // sum of point positions, cell units
  coords.reserve(occupied.size());
  counts.reserve(occupied.size());
  sums.reserve(occupied.size());
  for (std::size_t r = 0; r < order.size(); ++r) {
    const OccupiedCell& cell = occupied[order[r]];
    if (r > 0 && coords.back() == cell.coord)
      throw Error("the occupied cells hold a duplicate");
    coords.push_back(cell.coord);
    counts.push_back(cell.point_count);
    sums.push_back(cell.offset_sum.cast<double>() / OccupiedCell::kOffsetScale +
                   static_cast<double>(cell.point_count) * cell.coord.cast<double>());
  }

  VoxelBand band;
  band.grid_ = grid;
  band.fill_cells_ = fill_cells;
  band.roughness_ = bandRoughness(grid, coords, counts, sums);
  if (options.repair)
    band.repair_cells_ = BandRepair(grid, coords, counts, sums).run();
  band.finalize(std::move(coords), std::move(counts), options.threads);

  for (const std::int32_t entry : point_occupied)
    if (entry >= 0 && static_cast<std::size_t>(entry) >= entries)
      throw Error("a point refers to an occupied cell that does not exist");
  // The final id of every occupied entry once, then of every point through its entry.
  std::vector<CellId> entry_cell(occupied.size());
  parallelFor(occupied.size(), options.threads, kCellsPerChunk,
              [&](std::size_t begin, std::size_t end) {
                for (std::size_t e = begin; e < end; ++e)
                  entry_cell[e] = band.find(occupied[e].coord);
              });
  band.point_cell_.assign(point_occupied.size(), kNoCell);
  parallelFor(point_occupied.size(), options.threads, kPointsPerChunk,
              [&](std::size_t begin, std::size_t end) {
                for (std::size_t p = begin; p < end; ++p) {
                  const std::int32_t entry = point_occupied[p];
                  if (entry >= 0)
                    band.point_cell_[p] = entry_cell[static_cast<std::size_t>(entry)];
                }
              });
  return band;
}

VoxelBand
VoxelBand::fromCells(const GridSpec& grid,
                     const std::vector<CellCoord>& cells,
                     const Options& options)
{
  std::vector<OccupiedCell> occupied(cells.size());
  const std::int64_t half = static_cast<std::int64_t>(OccupiedCell::kOffsetScale / 2);
  for (std::size_t i = 0; i < cells.size(); ++i) {
    occupied[i].coord = cells[i];
    occupied[i].point_count = 1;
    occupied[i].offset_sum.setConstant(half);
  }
  std::vector<std::int32_t> point_occupied(cells.size());
  std::iota(point_occupied.begin(), point_occupied.end(), 0);
  return build(grid, std::move(occupied), point_occupied, options);
}

void
VoxelBand::finalize(std::vector<CellCoord> coords,
                    std::vector<std::uint32_t> counts,
                    int threads)
{
  const std::vector<std::size_t> order =
    sortedByKey(grid_, coords.size(), [&](std::size_t i) { return coords[i]; });
  coords_.resize(coords.size());
  point_counts_.resize(coords.size());
  for (std::size_t r = 0; r < order.size(); ++r) {
    coords_[r] = coords[order[r]];
    point_counts_[r] = counts[order[r]];
  }
  index_ = CellIndex(grid_.dims);
  index_.allocateBricks(coords_);
  // every brick is allocated: inserts only write their own cell's entry
  parallelFor(coords_.size(), threads, kCellsPerChunk,
              [&](std::size_t begin, std::size_t end) {
                for (std::size_t r = begin; r < end; ++r)
                  index_.insert(coords_[r], static_cast<CellId>(r));
              });
  neighbours_.resize(coords_.size());
  parallelFor(coords_.size(), threads, kCellsPerChunk,
              [&](std::size_t begin, std::size_t end) {
                for (std::size_t i = begin; i < end; ++i)
                  for (std::size_t s = 0; s < kFaceSteps.size(); ++s)
                    neighbours_[i][s] = index_.find(coords_[i] + kFaceSteps[s]);
              });
}

std::uint64_t
VoxelBand::memoryBytes() const
{
  return coords_.capacity() * sizeof(CellCoord) +
         point_counts_.capacity() * sizeof(std::uint32_t) +
         neighbours_.capacity() * sizeof(Neighbours) +
         point_cell_.capacity() * sizeof(CellId) + index_.memoryBytes();
}

std::uint64_t
VoxelBand::estimateBytes(const GridSpec& grid, std::size_t cells, std::size_t points)
{
  // coords, counts, neighbours, repair sums; index bricks (~1 per 8 cells on a surface)
  const std::uint64_t per_cell = sizeof(CellCoord) + sizeof(std::uint32_t) +
                                 sizeof(Neighbours) + sizeof(Eigen::Vector3d) +
                                 512 * sizeof(CellId) / 8;
  return CellIndex::tableBytes(grid.dims) * 2 + per_cell * cells +
         sizeof(CellId) * points;
}

} // namespace visfeat
