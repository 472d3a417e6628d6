// Step 5 of FeatureSegmentation (complete regions): the middle line of the skeleton
// where no edge line or drawn segment gave one (curved edges, corner blobs).

#include "segmentation_steps.h"

#include <Eigen/Eigenvalues>

#include <cmath>

namespace visfeat {
namespace segmentation {
namespace {

/** Cells around a skeleton cell averaged into its centre (a ball of this radius,
 * cells): wider than the widest cores (about 4 cells, the icosahedron's 138-degree
 * edges at 256), short against the curvature of the cylinder's circles. Set with the
 * per-point middle lines (145ed0d, which took the icosahedron's precision from 0.870
 * to 0.998); not swept. */
constexpr int kSkeletonCentreRadius = 3;

/** The skeleton around a cell is locally a line (it gets a tangent) where its spread
 * along the main axis (largest eigenvalue of the scatter) is more than this many
 * times the next; blobs at corners get none. Set with the per-point line pieces under
 * noise (d39ae0a, 7 models at sigma 0.22 and 0.32); not swept. */
constexpr double kElongation = 4.0;

/** Fewest skeleton cells around a cell for a main axis. */
constexpr std::size_t kMinAxisCells = 3;

/** The region's skeleton cells within kSkeletonCentreRadius of cell c (c included), as
 * coordinates. */
void
skeletonAround(const ThinningState& state,
               std::size_t c,
               std::vector<Eigen::Vector3d>& around)
{
  const int radius = kSkeletonCentreRadius;
  const int r2 = radius * radius;
  const CellCoord at = state.band.coord(static_cast<CellId>(c));
  around.clear();
  for (int dz = -radius; dz <= radius; ++dz)
    for (int dy = -radius; dy <= radius; ++dy)
      for (int dx = -radius; dx <= radius; ++dx) {
        if (dx * dx + dy * dy + dz * dz > r2)
          continue;
        const CellCoord q = at + CellCoord(dx, dy, dz);
        const CellId m = state.band.find(q);
        if (m != kNoCell && state.skeleton[static_cast<std::size_t>(m)] &&
            state.labels[static_cast<std::size_t>(m)] == state.labels[c])
          around.push_back(q.cast<double>());
      }
}

} // namespace

void
middleOfSkeleton(ThinningState& state)
{
  std::vector<Eigen::Vector3d> around;
  for (std::size_t c = 0; c < state.band.size(); ++c) {
    if (!state.skeleton[c] || !std::isnan(state.centres[c].x()))
      continue;
    skeletonAround(state, c, around);
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (const auto& q : around)
      mean += q;
    mean /= static_cast<double>(around.size());
    state.centres[c] = mean.cast<float>() + Eigen::Vector3f::Constant(0.5f);
    // The local direction where the skeleton is elongated (an edge; not a blob).
    Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
    for (const auto& q : around)
      scatter += (q - mean) * (q - mean).transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(scatter);
    if (around.size() >= kMinAxisCells &&
        solver.eigenvalues()(2) > kElongation * solver.eigenvalues()(1))
      state.tangents[c] = solver.eigenvectors().col(2).normalized().cast<float>();
  }
}

} // namespace segmentation
} // namespace visfeat
