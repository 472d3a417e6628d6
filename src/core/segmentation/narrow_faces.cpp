#include <visfeat/core/segmentation/narrow_faces.h>

#include <algorithm>
#include <cstdint>
#include <numeric>

namespace visfeat {
namespace {

/** Union-find over cells, each root knowing its part's peak, peak cell and size. */
struct MergeTree
{
  explicit MergeTree(std::size_t n)
      : parent(n)
      , peak(n, 0)
      , peak_cell(n)
      , cells(n, 0)
  {
    std::iota(parent.begin(), parent.end(), std::size_t{0});
    std::iota(peak_cell.begin(), peak_cell.end(), std::size_t{0});
  }

  std::size_t root(std::size_t c)
  {
    while (parent[c] != c) {
      parent[c] = parent[parent[c]];
      c = parent[c];
    }
    return c;
  }

  /** True when the root a's part is the elder of the two (higher peak, then lower id).
   */
  bool elder(std::size_t a, std::size_t b) const
  {
    return peak[a] != peak[b] ? peak[a] > peak[b] : peak_cell[a] < peak_cell[b];
  }

  std::vector<std::size_t> parent;
  std::vector<int> peak;
  std::vector<std::size_t> peak_cell;
  std::vector<std::size_t> cells;
};

} // namespace

std::vector<NarrowFace>
narrowFaces(const VoxelBand& band,
            const VisibilityMap& map,
            int min_radius,
            int min_persistence,
            std::size_t min_cells)
{
  const std::size_t n = band.size();
  // cells by radius, highest first (radii are small integers)
  int top = 0;
  for (std::size_t c = 0; c < n; ++c)
    top = std::max<int>(top, map.radius(static_cast<CellId>(c)));
  std::vector<std::size_t> first(static_cast<std::size_t>(top) + 2, 0);
  for (std::size_t c = 0; c < n; ++c)
    ++first[static_cast<std::size_t>(top - map.radius(static_cast<CellId>(c))) + 1];
  std::partial_sum(first.begin(), first.end(), first.begin());
  std::vector<CellId> order(n);
  {
    std::vector<std::size_t> next(first.begin(), first.end() - 1);
    for (std::size_t c = 0; c < n; ++c)
      order[next[static_cast<std::size_t>(
        top - map.radius(static_cast<CellId>(c)))]++] = static_cast<CellId>(c);
  }

  MergeTree tree(n);
  std::vector<std::uint8_t> active(n, 0);
  std::vector<NarrowFace> faces;
  const auto ends = [&](std::size_t r, int level) {
    // the part of root r ends at level (its saddle)
    if (tree.peak[r] < min_radius && tree.peak[r] - level >= min_persistence &&
        tree.cells[r] >= min_cells)
      faces.push_back(NarrowFace{tree.peak[r], level, tree.cells[r],
                                 static_cast<CellId>(tree.peak_cell[r])});
  };
  for (const CellId id : order) {
    const auto c = static_cast<std::size_t>(id);
    const int level = map.radius(id);
    active[c] = 1;
    tree.peak[c] = level;
    tree.cells[c] = 1;
    for (const CellId nb : band.neighbours(id)) {
      if (nb == kNoCell || !active[static_cast<std::size_t>(nb)])
        continue;
      std::size_t a = tree.root(c);
      std::size_t b = tree.root(static_cast<std::size_t>(nb));
      if (a == b)
        continue;
      if (!tree.elder(a, b))
        std::swap(a, b);
      ends(b, level);
      tree.parent[b] = a;
      tree.cells[a] += tree.cells[b];
    }
  }
  // parts that never met a higher one: a band piece whose highest peak is below the
  // core
  for (std::size_t c = 0; c < n; ++c)
    if (tree.parent[c] == c)
      ends(c, 0);
  std::sort(faces.begin(), faces.end(), [](const NarrowFace& a, const NarrowFace& b) {
    return a.cells != b.cells ? a.cells > b.cells : a.peak > b.peak;
  });
  return faces;
}

} // namespace visfeat
