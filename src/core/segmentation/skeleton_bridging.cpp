// Step 5 of FeatureSegmentation (complete regions): gaps in an edge's skeleton. Noise
// thins the ridge, most on curved and shallow edges (the cylinder's recall at sigma
// 0.32 went from 0.84-0.92 to 0.98 with the bridges).

#include "segmentation_steps.h"

#include <algorithm>
#include <cmath>

namespace visfeat {
namespace segmentation {
namespace {

/** The 26-connected pieces of an edge's skeleton cells (`cells`, in id order), each
 * in breadth-first order from its smallest cell; piece_of[c] = its piece's number
 * (1-based) for every cell of a piece. */
std::vector<std::vector<CellId>>
skeletonPieces(const ThinningState& state,
               std::uint32_t edge,
               const std::vector<CellId>& cells,
               std::vector<std::uint32_t>& piece_of)
{
  std::vector<std::vector<CellId>> pieces;
  for (const CellId seed : cells) {
    if (piece_of[static_cast<std::size_t>(seed)] != 0)
      continue;
    pieces.emplace_back(1, seed);
    const auto id = static_cast<std::uint32_t>(pieces.size());
    piece_of[static_cast<std::size_t>(seed)] = id;
    std::vector<CellId>& piece = pieces.back();
    for (std::size_t head = 0; head < piece.size(); ++head) {
      const CellCoord at = state.band.coord(piece[head]);
      for (int dz = -1; dz <= 1; ++dz)
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const CellId m = state.band.find(at + CellCoord(dx, dy, dz));
            if (m != kNoCell && state.skeleton[static_cast<std::size_t>(m)] &&
                state.labels[static_cast<std::size_t>(m)] == edge &&
                piece_of[static_cast<std::size_t>(m)] == 0) {
              piece_of[static_cast<std::size_t>(m)] = id;
              piece.push_back(m);
            }
          }
    }
  }
  return pieces;
}

/** For each end of each piece (its farthest pair of cells), the nearest cell of
 * another piece within join_distance cells (the last of equals): (end, that cell). */
std::vector<std::pair<CellId, CellId>>
bridgesOf(const ThinningState& state,
          const std::vector<std::vector<CellId>>& pieces,
          const std::vector<CellId>& cells,
          const std::vector<std::uint32_t>& piece_of)
{
  std::vector<std::pair<CellId, CellId>> bridges;
  for (const auto& piece : pieces) {
    const CellId first = state.farthestFrom(piece.front(), piece);
    for (const CellId end : {first, state.farthestFrom(first, piece)}) {
      CellId best = kNoCell;
      double best_distance = static_cast<double>(state.parameters.join_distance);
      for (const CellId c : cells)
        if (piece_of[static_cast<std::size_t>(c)] !=
              piece_of[static_cast<std::size_t>(end)] &&
            state.distance(end, c) <= best_distance) {
          best_distance = state.distance(end, c);
          best = c;
        }
      if (best != kNoCell)
        bridges.emplace_back(end, best);
    }
  }
  return bridges;
}

/** The cells strictly between the two ends on the straight segment join the edge's
 * skeleton, centred on the segment; skeleton cells and other features' cells stay as
 * they are. */
void
drawBridge(ThinningState& state, std::uint32_t edge, CellId from, CellId to)
{
  const Eigen::Vector3d a = state.band.coord(from).cast<double>();
  const Eigen::Vector3d b = state.band.coord(to).cast<double>();
  const double length = (b - a).norm();
  const int samples =
    std::max(1, static_cast<int>(std::ceil(length * kSamplesPerCell)));
  for (int k = 1; k < samples; ++k) {
    const Eigen::Vector3d x = a + (b - a) * (double(k) / samples);
    const CellId c = state.nearestCell(x);
    if (c == kNoCell || state.skeleton[static_cast<std::size_t>(c)])
      continue;
    const std::uint32_t l = state.labels[static_cast<std::size_t>(c)];
    if (l != edge && state.isFeature(l))
      continue; // another feature's cell stays its own
    state.skeleton[static_cast<std::size_t>(c)] = 1;
    state.labels[static_cast<std::size_t>(c)] = edge;
    state.setCentre(c, x, (b - a) / length);
  }
}

} // namespace

void
bridgeSkeletonGaps(ThinningState& state)
{
  std::map<std::uint32_t, std::vector<CellId>> edge_skeleton;
  for (std::size_t c = 0; c < state.band.size(); ++c)
    if (state.skeleton[c] && state.cls[state.labels[c]] == FeatureClass::kEdge)
      edge_skeleton[state.labels[c]].push_back(static_cast<CellId>(c));
  std::vector<std::uint32_t> piece_of(state.band.size(), 0);
  for (const auto& [edge, cells] : edge_skeleton) {
    const auto pieces = skeletonPieces(state, edge, cells, piece_of);
    const auto bridges = bridgesOf(state, pieces, cells, piece_of);
    for (const CellId c : cells)
      piece_of[static_cast<std::size_t>(c)] = 0;
    for (const auto& [from, to] : bridges)
      drawBridge(state, edge, from, to);
  }
}

} // namespace segmentation
} // namespace visfeat
