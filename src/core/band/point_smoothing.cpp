#include <visfeat/core/band/point_smoothing.h>
#include <visfeat/core/common/error.h>
#include <visfeat/core/grid/cell_index.h>

#include "../common/plane_sums.h"
#include "../grid/cell_members.h"

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
  std::size_t cell_count = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!points[i].allFinite())
      continue;
    const CellCoord c = grid.cellOf(points[i].cast<double>());
    if (!grid.contains(c))
      throw Error("smoothing: a point lies outside the grid");
    CellId id = index.find(c);
    if (id == kNoCell) {
      id = static_cast<CellId>(cell_count++);
      index.insert(c, id);
    }
    cell_of[i] = id;
  }
  const detail::CellMembers buckets(cell_count, cell_of);
  const std::vector<std::size_t>& start = buckets.start;
  const std::vector<std::uint32_t>& members = buckets.members;

  const double radius = parameters.radius * grid.cell_size;
  const double radius2 = radius * radius;
  const int reach = static_cast<int>(std::ceil(parameters.radius));
  const int threads = resolveThreads(parameters.threads);
  std::vector<Eigen::Vector3f> result(points);

  // Cell by cell: the points of one cell share the cells within reach, looked up once
  // (the lookups were most of the time when each point made its own: 125 a point at 2
  // cells). Each point sums its neighbours in the same fixed order as before.
  const auto cells = static_cast<std::int64_t>(cell_count);
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
        detail::PlaneSums sums;
        for (const CellId c : near)
          for (std::size_t m = start[static_cast<std::size_t>(c)];
               m < start[static_cast<std::size_t>(c) + 1]; ++m) {
            const Eigen::Vector3d d = points[members[m]].cast<double>() - p;
            if (d.squaredNorm() <= radius2)
              sums.add(d);
          }
        if (sums.count < static_cast<std::size_t>(parameters.min_neighbours))
          continue;
        const Eigen::Vector3d normal = sums.normal();
        // p is the origin of the shifted frame: move it onto the plane through the
        // mean.
        result[i] = (p + normal * normal.dot(sums.mean())).cast<float>();
      }
    }
  }
  return result;
}

} // namespace visfeat
