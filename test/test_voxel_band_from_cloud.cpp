// VoxelBand through PCL (gridForCloud + buildVoxelBand): the grid and the point cells
// follow their definitions, the band does not depend on the points' order or the
// threads, the repair makes sparse bands face-connected, bad input throws.

#include "band_fixtures.h"
#include "shuffled_cloud.h"
#include "voxel_band_checks.h"
#include <support/cad_catalogue.h>
#include <support/cad_sampling.h>
#include <support/portable_random.h>
#include <support/synthetic_shapes.h>

#include <visfeat/core/band/voxel_band.h>
#include <visfeat/core/common/error.h>
#include <visfeat/voxel_band_from_cloud.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace {

using namespace visfeat_test::band_checks;

// ---------------------------------------------------------------- PCL path

pcl::PointCloud<pcl::PointXYZ>
cloudWithNaNs(std::uint64_t seed)
{
  pcl::PointCloud<pcl::PointXYZ> cloud =
    visfeat_test::syntheticShapeCloud("octahedron", seed, 20);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  cloud.points.insert(cloud.points.begin() + 3, pcl::PointXYZ(nan, 0.f, 0.f));
  cloud.points.insert(cloud.points.begin() + 10, pcl::PointXYZ(0.f, 0.f, inf));
  cloud.push_back(pcl::PointXYZ(nan, nan, nan));
  cloud.width = static_cast<std::uint32_t>(cloud.points.size());
  cloud.height = 1;
  cloud.is_dense = false;
  return cloud;
}

TEST(BandFromCloud, GridFollowsTheDefinition)
{
  const pcl::PointCloud<pcl::PointXYZ> cloud = cloudWithNaNs(41);
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e30), hi = -lo;
  for (const pcl::PointXYZ& p : cloud.points) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      continue;
    const Eigen::Vector3d q(p.x, p.y, p.z);
    lo = lo.cwiseMin(q);
    hi = hi.cwiseMax(q);
  }
  const int resolution = 20;
  const GridSpec grid = visfeat::gridForCloud(cloud, resolution);
  const double extent = (hi - lo).maxCoeff();
  EXPECT_NEAR(grid.cell_size, extent / resolution, 1e-9 * extent);
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(grid.origin[i], lo[i] - 2.0 * grid.cell_size, 1e-6 * grid.cell_size);
  // Every finite point lies at least 2 cells inside the grid.
  for (const pcl::PointXYZ& p : cloud.points) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      continue;
    const Eigen::Vector3d f =
      ((Eigen::Vector3d(p.x, p.y, p.z) - grid.origin) / grid.cell_size).array().floor();
    EXPECT_TRUE((f.array() >= 2).all() &&
                (f.array() <= (grid.dims.cast<double>().array() - 3)).all())
      << "point cell " << f.transpose() << " dims " << grid.dims.transpose();
  }
}

TEST(BandFromCloud, PointCellsFollowTheFloorFormula)
{
  const pcl::PointCloud<pcl::PointXYZ> cloud = cloudWithNaNs(42);
  for (bool repair : {false, true}) {
    const VoxelBand band = visfeat_test::bandFromCloud(cloud, 20, repair);
    checkBandStructure(band, repair ? "cloud, repair" : "cloud, no repair");
    const GridSpec& grid = band.grid();
    ASSERT_EQ(band.pointCell().size(), cloud.size());
    std::vector<std::uint32_t> counts(band.size(), 0);
    CoordSet occupied;
    for (std::size_t i = 0; i < cloud.size(); ++i) {
      const pcl::PointXYZ& p = cloud.points[i];
      const CellId id = band.pointCell()[i];
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
        EXPECT_EQ(id, kNoCell) << "point " << i;
        continue;
      }
      ASSERT_NE(id, kNoCell) << "point " << i;
      ASSERT_LT(static_cast<std::size_t>(id), band.size());
      ++counts[static_cast<std::size_t>(id)];
      const CellCoord& c = band.coord(id);
      occupied.insert(key(c));
      // Position inside the cell, in cell units: within [0, 1) up to rounding.
      const Eigen::Vector3d local =
        (Eigen::Vector3d(p.x, p.y, p.z) - grid.origin) / grid.cell_size -
        c.cast<double>();
      EXPECT_TRUE((local.array() >= -1e-6).all() && (local.array() < 1.0 + 1e-6).all())
        << "point " << i << " at " << local.transpose() << " inside cell "
        << toString(c);
    }
    for (std::size_t i = 0; i < band.size(); ++i)
      EXPECT_EQ(band.pointCount(static_cast<CellId>(i)), counts[i]);
    if (!repair) {
      EXPECT_EQ(toSet(band.coords()), occupied);
    } else {
      EXPECT_EQ(band.size(), occupied.size() + band.repairCellCount());
    }
  }
}

TEST(BandFromCloud, ShuffledPointsGiveTheSameBand)
{
  pcl::PointCloud<pcl::PointXYZ> cloud = cloudWithNaNs(43);
  const auto [shuffled, perm] = visfeat_test::shuffledCloud(cloud, 17);

  const GridSpec g1 = visfeat::gridForCloud(cloud, 20),
                 g2 = visfeat::gridForCloud(shuffled, 20);
  EXPECT_EQ(g1.origin, g2.origin);
  EXPECT_EQ(g1.cell_size, g2.cell_size);
  EXPECT_EQ(g1.dims, g2.dims);
  for (bool repair : {false, true}) {
    const VoxelBand a = visfeat::buildVoxelBand(cloud, g1, withRepair(repair));
    const VoxelBand b = visfeat::buildVoxelBand(shuffled, g2, withRepair(repair));
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
      ASSERT_EQ(a.coord(static_cast<CellId>(i)), b.coord(static_cast<CellId>(i)));
      ASSERT_EQ(a.pointCount(static_cast<CellId>(i)),
                b.pointCount(static_cast<CellId>(i)));
    }
    for (std::size_t j = 0; j < perm.size(); ++j)
      ASSERT_EQ(b.pointCell()[j], a.pointCell()[perm[j]]);
  }
}

// Large clouds are split into slabs of bricks, one pcl::octree each, built on several
// threads: the band (cells, ids, counts, adjacency, repair, point cells) is the same
// for any thread count. 360,000 points make 3 slabs of more than 100,000.
TEST(BandFromCloud, SlabOctreesOnThreadsGiveTheSameBand)
{
  const visfeat::synthetic::CadModel model =
    visfeat::synthetic::rotated(visfeat::synthetic::cadModelByName("box_with_hole"),
                                visfeat::synthetic::randomRotation(5));
  visfeat::synthetic::SamplingOptions sampling;
  sampling.count = 360000;
  sampling.seed = 5;
  const std::vector<Eigen::Vector3f> samples =
    visfeat::synthetic::sampleCadModel(model, sampling).points;
  pcl::PointCloud<pcl::PointXYZ> cloud;
  for (const Eigen::Vector3f& p : samples)
    cloud.push_back(pcl::PointXYZ(p.x(), p.y(), p.z()));
  cloud[7].x = std::numeric_limits<float>::quiet_NaN(); // skipped on every thread count
  cloud.is_dense = false;
  const GridSpec grid = visfeat::gridForCloud(cloud, 200);
  VoxelBand::Options one;
  one.threads = 1;
  const VoxelBand a = visfeat::buildVoxelBand(cloud, grid, one);
  EXPECT_GT(a.repairCellCount(), 0u);
  for (int threads : {2, 3, 5}) {
    VoxelBand::Options many;
    many.threads = threads;
    const VoxelBand b = visfeat::buildVoxelBand(cloud, grid, many);
    ASSERT_EQ(a.size(), b.size()) << threads << " threads";
    EXPECT_EQ(a.repairCellCount(), b.repairCellCount());
    for (std::size_t i = 0; i < a.size(); ++i) {
      const auto id = static_cast<CellId>(i);
      ASSERT_EQ(a.coord(id), b.coord(id)) << threads << " threads, cell " << i;
      ASSERT_EQ(a.pointCount(id), b.pointCount(id));
      ASSERT_EQ(a.neighbours(id), b.neighbours(id));
    }
    EXPECT_EQ(a.pointCell(), b.pointCell());
  }
  EXPECT_EQ(a.pointCell()[7], visfeat::kNoCell);
}

TEST(BandFromCloud, RepairMakesSparseCloudBandsFaceConnected)
{
  // A sparsely sampled rotated cube: its band is 26- but not 6-connected in places.
  const pcl::PointCloud<pcl::PointXYZ> cloud =
    visfeat_test::syntheticShapeCloud("cube", 44, 24, 1.2);
  const VoxelBand off = visfeat_test::bandFromCloud(cloud, 24, false);
  std::vector<CellCoord> cells = off.coords();
  checkRepair(off.grid(), cells, "sparse cube cloud");
  const VoxelBand on = visfeat_test::bandFromCloud(cloud, 24, true);
  CoordSet with = toSet(on.coords());
  for (const CellCoord& c : cells)
    EXPECT_TRUE(with.count(key(c)));
  EXPECT_EQ(on.repairCellCount(), on.size() - cells.size());
}

TEST(BandFromCloud, BadInputThrows)
{
  pcl::PointCloud<pcl::PointXYZ> empty;
  EXPECT_THROW(visfeat::gridForCloud(empty, 32), visfeat::Error);
  pcl::PointCloud<pcl::PointXYZ> nans;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  nans.push_back(pcl::PointXYZ(nan, nan, nan));
  nans.push_back(pcl::PointXYZ(1.f, nan, 0.f));
  EXPECT_THROW(visfeat::gridForCloud(nans, 32), visfeat::Error);
  pcl::PointCloud<pcl::PointXYZ> same;
  same.push_back(pcl::PointXYZ(1.f, 2.f, 3.f));
  same.push_back(pcl::PointXYZ(1.f, 2.f, 3.f));
  EXPECT_THROW(visfeat::gridForCloud(same, 32), visfeat::Error);
  const pcl::PointCloud<pcl::PointXYZ> ok =
    visfeat_test::syntheticShapeCloud("cube", 45, 8);
  EXPECT_THROW(visfeat::gridForCloud(ok, 0), visfeat::Error);
  EXPECT_THROW(visfeat::gridForCloud(ok, GridSpec::kMinResolution - 1), visfeat::Error);
  EXPECT_THROW(visfeat::gridForCloud(ok, GridSpec::kMaxResolution + 1), visfeat::Error);
  EXPECT_NO_THROW(visfeat::gridForCloud(ok, GridSpec::kMinResolution));
}

} // namespace
