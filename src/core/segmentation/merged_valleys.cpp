#include <visfeat/core/band/band_dilation.h>
#include <visfeat/core/segmentation/merged_valleys.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace visfeat {

namespace {

/** The spread of a group of cells: length and width (cells) of the uniform segment and
 * strip with the same second moments, sqrt(12 lambda) along the first two principal
 * axes of its cell centres. */
struct GroupSpread
{
  std::size_t cells = 0;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  Eigen::Matrix3d squares = Eigen::Matrix3d::Zero();

  void add(const CellCoord& c)
  {
    const Eigen::Vector3d p = c.cast<double>();
    ++cells;
    sum += p;
    squares += p * p.transpose();
  }

  /** (length, width), cells. */
  std::pair<double, double> extent() const
  {
    const double n = static_cast<double>(cells);
    const Eigen::Vector3d mean = sum / n;
    const Eigen::Matrix3d covariance = squares / n - mean * mean.transpose();
    const Eigen::Vector3d lambda =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(covariance, Eigen::EigenvaluesOnly)
        .eigenvalues(); // increasing
    return {std::sqrt(12.0 * std::max(lambda(2), 0.0)),
            std::sqrt(12.0 * std::max(lambda(1), 0.0))};
  }
};

/** The longest valley line among the 26-connected groups of the cells marked 1 in
 * `line` (marks them 2): see MergedValleys::longest_line. */
void
findValleyLines(const VoxelBand& band,
                const std::vector<CellId>& cells,
                std::vector<std::uint8_t>& line,
                MergedValleys& found)
{
  std::vector<CellId> stack;
  for (const CellId seed : cells) {
    if (line[static_cast<std::size_t>(seed)] != 1)
      continue;
    line[static_cast<std::size_t>(seed)] = 2;
    stack.assign(1, seed);
    GroupSpread group;
    while (!stack.empty()) {
      const CellId c = stack.back();
      stack.pop_back();
      const CellCoord& at = band.coord(c);
      group.add(at);
      for (int z = -1; z <= 1; ++z)
        for (int y = -1; y <= 1; ++y)
          for (int x = -1; x <= 1; ++x) {
            const CellId m = band.find(at + CellCoord(x, y, z));
            if (m == kNoCell || line[static_cast<std::size_t>(m)] != 1)
              continue;
            line[static_cast<std::size_t>(m)] = 2;
            stack.push_back(m);
          }
    }
    const auto [length, width] = group.extent();
    if (length >= kValleyLineElongation * width && width >= kValleyLineMinWidth &&
        length > found.longest_line) {
      found.longest_line = length;
      found.line_width = width;
      found.line_cells = group.cells;
    }
  }
}

} // namespace

MergedValleys
mergedValleys(const VoxelBand& band,
              const VisibilityMap& map,
              const FeatureSegmentation& segmentation,
              int valley_radius,
              int reach,
              int line_radius)
{
  const std::size_t n = band.size();
  // the cells within reach of an edge or vertex cell (one dilation from all of them)
  std::vector<CellId> features;
  for (std::size_t c = 0; c < n; ++c) {
    const FeatureClass k = segmentation.cellClass(static_cast<CellId>(c));
    if (k == FeatureClass::kEdge || k == FeatureClass::kVertex)
      features.push_back(static_cast<CellId>(c));
  }
  std::vector<std::uint8_t> near(n, 0);
  BandDilation(band).run(features, static_cast<std::uint32_t>(std::max(reach, 0)),
                         [&](CellId c) { near[static_cast<std::size_t>(c)] = 1; });
  MergedValleys found;
  std::vector<std::uint8_t> line(n, 0); // 1: a far face cell up to the line radius
  std::vector<CellId> lines;
  for (std::size_t c = 0; c < n; ++c) {
    const auto id = static_cast<CellId>(c);
    const int radius = map.radius(id);
    if (near[c] || segmentation.cellClass(id) != FeatureClass::kFace)
      continue;
    if (radius <= line_radius) {
      line[c] = 1;
      lines.push_back(id);
    }
    if (radius > valley_radius)
      continue;
    found.deepest = found.cells == 0 ? radius : std::min(found.deepest, radius);
    ++found.cells;
  }
  findValleyLines(band, lines, line, found);
  return found;
}

} // namespace visfeat
