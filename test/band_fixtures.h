#pragma once

// Small bands and clouds the tests generate for themselves (no files are read).

#include <support/cad_models.h>
#include <visfeat/core/band/voxel_band.h>
#include <visfeat/core/common/feature_class.h>
#include <visfeat/core/grid/grid_spec.h>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <map>
#include <random>
#include <string>
#include <vector>

namespace visfeat_test {

using visfeat::CellCoord;
using visfeat::GridSpec;

/** \brief A set of cells in a grid with unit cells at the origin (cell c's centre is
 * c + 0.5). */
struct CellBand
{
  std::string name;
  GridSpec grid;
  std::vector<CellCoord> cells;
};

/** \brief Grid of n^3 unit cells with its origin at 0. */
GridSpec cubeGrid(int n);

/** \brief A uniformly random rotation (own implementation: normalised Gaussian
 * quaternion), reproducible from the generator. */
Eigen::Matrix3d randomRotationMatrix(std::mt19937_64& rng);

/** \brief Cells whose centre lies within `thickness` of the sphere surface of one of a
 * few random balls (overlapping shells: cavities and occlusion). */
CellBand ballShells(std::uint64_t seed);

/** \brief The cells visited by a few random walkers (tangled 6-connected tubes). */
CellBand randomWalkBlob(std::uint64_t seed);

/** \brief Digital plane under a random rotation: cells whose centre is within
 * |n|_1 / 2 of the plane (the cells the plane crosses), clipped to a disc. */
CellBand digitalPlane(std::uint64_t seed, double disc_radius = 7.0);

/** \brief Rotated 90-degree crease: two half-planes (strips) meeting along a rotated
 * line; cells within |n|_1 / 2 of either strip. */
CellBand creaseBand(std::uint64_t seed, double half_length = 6.0, double width = 6.0);

/** \brief The surface (walls one cell thick) of an axis-aligned box of cells
 * [2, 2 + sx] x [3, 3 + sy] x [2, 2 + sz]: segments run along subcell faces and edges,
 * walls sz apart hide each other with a blocked length of exactly sz - 2 cell edges. */
CellBand hollowBox(int sx = 10, int sy = 8, int sz = 5);

/** \brief The B-rep regions of a hollowBox() band: per cell, the label of the box's
 * face, edge or corner it lies on, by which of its coordinates lie on the box's
 * extremes lo / hi (one: a face, two: an edge, three: a corner), labels numbered in
 * the order of the cells. */
struct BoxRegions
{
  std::vector<std::uint32_t> labels;               // per band cell
  std::vector<visfeat::FeatureClass> classes;      // per label - 1
  std::map<std::array<int, 3>, std::uint32_t> ids; // -1 / 0 / 1 per axis -> label
};

/** \brief BoxRegions of a band made from hollowBox(sx, sy, sz)'s cells.
 * \throws std::runtime_error for a cell inside the box. */
BoxRegions
hollowBoxRegions(const visfeat::VoxelBand& band, int sx = 10, int sy = 8, int sz = 5);

/** \brief A closed thin plate (rectangular box surface, rotated). The two large faces
 * are `gap` cells apart, with gap = 2 (thickness + |w|_1) + 1.25 so that a slab of
 * the occluder at least 1.25 cells thick separates them (see the .cpp). */
struct ThinPlate
{
  CellBand band;
  double gap = 0.0;
  /** \brief Cells of the band near the top / bottom face whose projection lies at least
   * 3 cells inside the rim. */
  std::vector<CellCoord> top_inner;
  std::vector<CellCoord> bottom_inner;
};

ThinPlate thinPlate(std::uint64_t seed, double half_size = 6.0);

/** \brief All small cell bands used by the reference comparisons. */
std::vector<CellBand> smallCellBands();

/** \brief A cloud sampled (visfeat::synthetic::sampleSurface) on a rotated platonic
 * solid, about `spacing_cells` apart on a grid of `resolution` cells. */
pcl::PointCloud<pcl::PointXYZ> syntheticShapeCloud(const std::string& shape,
                                                   std::uint64_t seed,
                                                   int resolution,
                                                   double spacing_cells = 0.5);

/** \brief A generated CAD model sampled as the benchmarks and acceptance tests do. */
struct SampledCadModel
{
  visfeat::synthetic::CadSamples samples;
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud;
};

/** \brief `model` (already rotated) sampled as `options` say, and its points as a
 * cloud. */
SampledCadModel sampleCadCloud(const visfeat::synthetic::CadModel& model,
                               const visfeat::synthetic::SamplingOptions& options);

/** \brief `model` (already rotated) sampled 0.5 cells apart on a grid of `resolution`
 * cells, with seed `seed` and Gaussian noise of `noise_cells` nominal cells. */
SampledCadModel sampleCadCloud(const visfeat::synthetic::CadModel& model,
                               int resolution,
                               std::uint64_t seed,
                               double noise_cells = 0.0);

/** \brief Uniform random points on a unit square (side 1, centred at the origin) with
 * axes u, v; `count` points. */
pcl::PointCloud<pcl::PointXYZ> squareCloud(const Eigen::Vector3d& u,
                                           const Eigen::Vector3d& v,
                                           std::size_t count,
                                           std::mt19937_64& rng);

/** \brief Two unit squares meeting at a 90-degree crease along the line through the
 * origin with direction u: {s u + t v} and {s u + t w}, s in [-1/2, 1/2], t in [0, 1].
 * `count_per_face` uniform points on each. */
pcl::PointCloud<pcl::PointXYZ> creaseCloud(const Eigen::Matrix3d& frame,
                                           std::size_t count_per_face,
                                           std::mt19937_64& rng);

/** \brief A band under test, with a name for messages. */
struct NamedBand
{
  std::string name;
  visfeat::VoxelBand band;
};

/** \brief The band of a cloud through the PCL path (gridForCloud + buildVoxelBand). */
visfeat::VoxelBand bandFromCloud(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                                 int resolution,
                                 bool repair = true);

/** \brief The bands the reference comparisons run on, by index: smallCellBands() (the
 * thin plate without repair, the others with repair) and three rotated synthetic solids
 * sampled at small resolutions through the PCL path. A few hundred to ~1500 cells each.
 * Names are known without building anything (for test names). */
const std::vector<std::string>& referenceBandNames();

NamedBand referenceBand(std::size_t index);

/** \brief Key for sorting / comparing coordinates. */
bool coordLess(const CellCoord& a, const CellCoord& b);

std::string toString(const Eigen::Vector3i& c);

} // namespace visfeat_test
