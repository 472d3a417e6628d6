#include "core_line.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace visfeat {
namespace segmentation {

bool
CoreLine::onLine(const CoreLine& other) const
{
  if (!straight() || !other.straight())
    return false;
  const Eigen::Vector3d d = other.point - point;
  return std::abs(other.direction.dot(direction)) >= kJoinCosine &&
         (d - d.dot(direction) * direction).norm() <= kStraightTolerance;
}

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

} // namespace segmentation
} // namespace visfeat
