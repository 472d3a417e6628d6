#include <visfeat/core/band/point_smoothing.h>
#include <visfeat/core/common/error.h>
#include <visfeat/core/grid/cell_index.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <sstream>

#include <visfeat/core/common/threads.h>

#include <omp.h>

namespace visfeat {

void
SmoothingParameters::validate() const
{
  checkRange("smoothing radius", radius, kRadiusRange, "cells; 0 = off");
  checkRange("smoothing min_neighbours", min_neighbours, kMinNeighboursRange, "points");
  checkRange("smoothing threads", threads, kThreadsRange, "0 = all available");
}

std::vector<Eigen::Vector3f>
smoothPoints(const std::vector<Eigen::Vector3f>& points,
             const GridSpec& grid,
             const SmoothingParameters& parameters)
{
  if (!(parameters.radius > 0.0 &&
        parameters.radius <= SmoothingParameters::kRadiusRange.max)) {
    std::ostringstream msg;
    msg << "smoothing radius " << parameters.radius << " is out of range (0, "
        << SmoothingParameters::kRadiusRange.max << "] (cells)";
    throw Error(msg.str());
  }
  parameters.validate();
  const std::size_t n = points.size();
  // Bucket the points by cell: cell ids in order of first appearance, points sorted by
  // (cell, index), so each cell's points are one range and the order is fixed.
  CellIndex index(grid.dims);
  std::vector<CellId> cell_of(n, kNoCell);
  std::vector<std::uint32_t> cell_count;
  for (std::size_t i = 0; i < n; ++i) {
    if (!points[i].allFinite())
      continue;
    const CellCoord c = grid.cellOf(points[i].cast<double>());
    if (!grid.contains(c))
      throw Error("smoothing: a point lies outside the grid");
    CellId id = index.find(c);
    if (id == kNoCell) {
      id = static_cast<CellId>(cell_count.size());
      index.insert(c, id);
      cell_count.push_back(0);
    }
    cell_of[i] = id;
    ++cell_count[static_cast<std::size_t>(id)];
  }
  std::vector<std::size_t> start(cell_count.size() + 1, 0);
  for (std::size_t c = 0; c < cell_count.size(); ++c)
    start[c + 1] = start[c] + cell_count[c];
  std::vector<std::uint32_t> members(start.back());
  {
    std::vector<std::size_t> fill(start.begin(), start.end() - 1);
    for (std::size_t i = 0; i < n; ++i)
      if (cell_of[i] != kNoCell)
        members[fill[static_cast<std::size_t>(cell_of[i])]++] =
          static_cast<std::uint32_t>(i);
  }

  const double radius = parameters.radius * grid.cell_size;
  const double radius2 = radius * radius;
  const int reach = static_cast<int>(std::ceil(parameters.radius));
  const int threads = resolveThreads(parameters.threads);
  std::vector<Eigen::Vector3f> result(points);

  // Cell by cell: the points of one cell share the cells within reach, looked up once
  // (the lookups were most of the time when each point made its own: 125 a point at 2
  // cells). Each point sums its neighbours in the same fixed order as before.
  const auto cells = static_cast<std::int64_t>(cell_count.size());
#pragma omp parallel num_threads(threads)
  {
    std::vector<CellId> near;
#pragma omp for schedule(dynamic, 256)
    for (std::int64_t cell = 0; cell < cells; ++cell) {
      const auto first = static_cast<std::size_t>(cell);
      const CellCoord at = grid.cellOf(points[members[start[first]]].cast<double>());
      near.clear();
      for (int dz = -reach; dz <= reach; ++dz)
        for (int dy = -reach; dy <= reach; ++dy)
          for (int dx = -reach; dx <= reach; ++dx) {
            const CellId c = index.find(at + CellCoord(dx, dy, dz));
            if (c != kNoCell)
              near.push_back(c);
          }
      for (std::size_t own = start[first]; own < start[first + 1]; ++own) {
        const std::size_t i = members[own];
        const Eigen::Vector3d p = points[i].cast<double>();
        // Mean and scatter about p (shifted, for precision), in a fixed order.
        Eigen::Vector3d sum = Eigen::Vector3d::Zero();
        Eigen::Matrix3d outer = Eigen::Matrix3d::Zero();
        int count = 0;
        for (const CellId c : near)
          for (std::size_t m = start[static_cast<std::size_t>(c)];
               m < start[static_cast<std::size_t>(c) + 1]; ++m) {
            const Eigen::Vector3d d = points[members[m]].cast<double>() - p;
            if (d.squaredNorm() > radius2)
              continue;
            sum += d;
            outer += d * d.transpose();
            ++count;
          }
        if (count < parameters.min_neighbours)
          continue;
        const Eigen::Vector3d mean = sum / count;
        const Eigen::Matrix3d covariance = outer / count - mean * mean.transpose();
        const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
        const Eigen::Vector3d normal = solver.eigenvectors().col(0);
        // p is the origin of the shifted frame: move it onto the plane through the
        // mean.
        result[i] = (p + normal * normal.dot(mean)).cast<float>();
      }
    }
  }
  return result;
}

} // namespace visfeat
