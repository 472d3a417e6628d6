#include <visfeat/core/band/band_enclosure.h>

#include <algorithm>
#include <vector>

namespace visfeat {

BandEnclosure
bandEnclosure(const VoxelBand& band)
{
  BandEnclosure result;
  if (band.empty())
    return result;
  const Eigen::Vector3i& dims = band.grid().dims;
  const int b = std::max(1, (dims.maxCoeff() + kEnclosureBlocksPerSide - 1) /
                              kEnclosureBlocksPerSide);
  result.block = b;
  // The grid's blocks inside two layers: an empty one, where the flood of the outside
  // starts (so the outside is one piece whatever touches the grid's border), and a
  // closed one that stops it (so the flood needs no bounds checks).
  const Eigen::Vector3i blocks = (dims.array() + b - 1) / b + 4;
  const std::size_t nx = static_cast<std::size_t>(blocks.x());
  const std::size_t nxy = nx * static_cast<std::size_t>(blocks.y());
  const std::size_t total = nxy * static_cast<std::size_t>(blocks.z());
  enum : std::uint8_t
  {
    kEmpty = 0,
    kClosed = 1,
    kOutside = 2
  };
  std::vector<std::uint8_t> state(total, kEmpty);
  const auto at = [&](int x, int y, int z) {
    return static_cast<std::size_t>(x) + nx * static_cast<std::size_t>(y) +
           nxy * static_cast<std::size_t>(z);
  };
  for (int z = 0; z < blocks.z(); ++z)
    for (int y = 0; y < blocks.y(); ++y)
      for (int x = 0; x < blocks.x(); ++x)
        if (x == 0 || y == 0 || z == 0 || x == blocks.x() - 1 || y == blocks.y() - 1 ||
            z == blocks.z() - 1)
          state[at(x, y, z)] = kClosed;
  // Each band cell closes its block and those of its 26 neighbours: the band of a cloud
  // sampled about 0.5 cells apart misses cells the surface only clips, and the outside
  // would leak in through them (face to face). The free space is dilated likewise.
  // Cell c lies in block c / b + 2; the grid's padding keeps its neighbours inside the
  // grid, and a neighbour one past the grid lies in the empty layer at worst.
  const auto first = [b](int c) { return (c - 1 + b) / b + 1; };
  const auto last = [b](int c) { return (c + 1 + b) / b + 1; };
  for (const CellCoord& c : band.coords())
    for (int z = first(c.z()); z <= last(c.z()); ++z)
      for (int y = first(c.y()); y <= last(c.y()); ++y)
        for (int x = first(c.x()); x <= last(c.x()); ++x)
          state[at(x, y, z)] = kClosed;
  // flood the outside from a corner of the empty layer
  std::vector<std::size_t> stack{at(1, 1, 1)};
  state[stack.back()] = kOutside;
  std::size_t outside = 1;
  const std::size_t steps[6] = {
    1, nx, nxy, std::size_t(0) - 1, std::size_t(0) - nx, std::size_t(0) - nxy};
  while (!stack.empty()) {
    const std::size_t block = stack.back();
    stack.pop_back();
    for (const std::size_t step : steps) {
      const std::size_t next = block + step; // wraps for the negative steps
      if (state[next] == kEmpty) {
        state[next] = kOutside;
        stack.push_back(next);
        ++outside;
      }
    }
  }
  const auto closed =
    static_cast<std::size_t>(std::count(state.begin(), state.end(), kClosed));
  const std::uint64_t block_cells = static_cast<std::uint64_t>(b) *
                                    static_cast<std::uint64_t>(b) *
                                    static_cast<std::uint64_t>(b);
  result.enclosed_cells =
    static_cast<std::uint64_t>(total - outside - closed) * block_cells;
  return result;
}

} // namespace visfeat
