// Unit tests of flatCore() and of the classification it adds to ComponentSet: cores
// thinner than a face by depth are faces on a flat part of the band, edges where the
// band bends across them. Bands are voxelized here from exact surfaces under random
// rotations; the maps are painted on them.

#include "band_fixtures.h"

#include <visfeat/core/segmentation/components.h>
#include <visfeat/core/segmentation/flat_cores.h>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
#include <set>
#include <vector>

namespace {

using visfeat::CellCoord;
using visfeat::CellId;
using visfeat::FeatureClass;
using visfeat::VoxelBand;

constexpr int kGrid = 128;
constexpr double kHalf = 45.0; // half the side of the square of surface, cells

/** A square of surface folded by `turn` degrees along the line y = 0 (the fold), under
 * `rotation`, about the grid's centre: each half tilts by turn / 2. */
struct Fold
{
  double turn = 0.0;
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();

  Eigen::Vector3d at(double x, double y) const
  {
    const double half = 0.5 * turn * M_PI / 180.0;
    const Eigen::Vector3d p(x, std::abs(y) * std::cos(half),
                            std::abs(y) * std::sin(half));
    const Eigen::Vector3d q(p.x(), y < 0.0 ? -p.y() : p.y(), p.z());
    return rotation * q + Eigen::Vector3d::Constant(kGrid / 2.0);
  }
};

/** The band of a fold (the cells its dense samples fall into, repaired) and, as core
 * candidates, the cells whose samples lie within `core_half_width` of the line
 * y = `core_y` for |x| <= core_half_length. */
struct FoldBand
{
  VoxelBand band;
  std::vector<CellId> core;
};

FoldBand
foldBand(const Fold& fold,
         double core_y,
         double core_half_width,
         double core_half_length)
{
  std::set<std::array<int, 3>> cells, core;
  for (double x = -kHalf; x <= kHalf; x += 0.2)
    for (double y = -kHalf; y <= kHalf; y += 0.2) {
      const Eigen::Vector3d p = fold.at(x, y);
      const std::array<int, 3> c{{static_cast<int>(std::floor(p.x())),
                                  static_cast<int>(std::floor(p.y())),
                                  static_cast<int>(std::floor(p.z()))}};
      cells.insert(c);
      if (std::abs(y - core_y) <= core_half_width && std::abs(x) <= core_half_length)
        core.insert(c);
    }
  std::vector<CellCoord> coords;
  for (const auto& c : cells)
    coords.emplace_back(c[0], c[1], c[2]);
  FoldBand result{VoxelBand::fromCells(visfeat_test::cubeGrid(kGrid), coords, {}), {}};
  for (const auto& c : core)
    result.core.push_back(result.band.find(CellCoord(c[0], c[1], c[2])));
  return result;
}

bool
flat(const FoldBand& fold)
{
  std::vector<std::uint32_t> stamp(fold.band.size(), 0);
  std::uint32_t next = 0;
  return visfeat::flatCore(fold.band, fold.core, stamp, next);
}

TEST(FlatCores, APlaneIsFlatAndACreaseIsNotUnderAnyRotation)
{
  std::mt19937_64 rng(20261202);
  for (int r = 0; r < 4; ++r) {
    Fold fold;
    fold.rotation = visfeat_test::randomRotationMatrix(rng);
    for (const double turn : {0.0, 42.0, 90.0}) {
      fold.turn = turn;
      // a core 3 cells wide along the middle line, where the fold is
      const FoldBand band = foldBand(fold, 0.0, 1.5, 20.0);
      ASSERT_GE(band.core.size(), 120u);
      // 42 degrees: the icosahedron's edges, the shallowest of the generated models
      EXPECT_EQ(flat(band), turn == 0.0) << "rotation " << r << ", turn " << turn;
    }
  }
}

TEST(FlatCores, ACoreBesideTheCreaseReachesItWithinTheRadius)
{
  // a strip core 6 cells from a 90-degree crease: its patches take in the bend
  std::mt19937_64 rng(7);
  Fold fold;
  fold.turn = 90.0;
  fold.rotation = visfeat_test::randomRotationMatrix(rng);
  EXPECT_FALSE(flat(foldBand(fold, 6.0, 1.5, 20.0)));
  // and 20 cells from it (more than kFlatCoreRadius): flat
  EXPECT_TRUE(flat(foldBand(fold, 20.0, 1.5, 20.0)));
}

/** Components of a fold's band with radius 16 on the cells of `band.core` and 8
 * elsewhere. */
visfeat::ComponentSet
paintedCores(const FoldBand& band, bool flat_core_faces)
{
  std::vector<std::uint8_t> radii(band.band.size(), 8);
  for (const CellId c : band.core)
    radii[static_cast<std::size_t>(c)] = 16;
  visfeat::VisibilityMap::Parameters map_parameters;
  map_parameters.max_radius = 16;
  const auto map = visfeat::VisibilityMap::fromRadii(map_parameters, radii);
  visfeat::ComponentParameters parameters; // min_radius 16, face_min_depth 4
  parameters.narrow_face_persistence = 0;
  parameters.flat_core_faces = flat_core_faces;
  return visfeat::ComponentSet::extract(band.band, map, parameters, false);
}

TEST(FlatCores, AThinCoreIsAFaceOnAFlatPartAndAnEdgeOnACrease)
{
  std::mt19937_64 rng(11);
  Fold fold;
  fold.rotation = visfeat_test::randomRotationMatrix(rng);
  for (const double turn : {0.0, 90.0}) {
    fold.turn = turn;
    // 3 cells wide (depth below 4), 70 cells long: more than min_radius^2 = 256 cells
    const FoldBand band = foldBand(fold, 0.0, 1.5, 35.0);
    ASSERT_GE(band.core.size(), 256u);
    for (const bool rule : {true, false}) {
      const visfeat::ComponentSet set = paintedCores(band, rule);
      ASSERT_EQ(set.components().size(), 1u);
      EXPECT_LT(set.components()[0].depth, 4u);
      EXPECT_EQ(set.components()[0].feature_class,
                rule && turn == 0.0 ? FeatureClass::kFace : FeatureClass::kEdge)
        << "turn " << turn << ", rule " << rule;
    }
  }
  // fewer than min_radius^2 cells on the plane: an edge (a speck of a rough band)
  fold.turn = 0.0;
  const FoldBand small = foldBand(fold, 0.0, 1.5, 8.0);
  ASSERT_LT(small.core.size(), 256u);
  const visfeat::ComponentSet set = paintedCores(small, true);
  ASSERT_EQ(set.components().size(), 1u);
  EXPECT_EQ(set.components()[0].feature_class, FeatureClass::kEdge);
}

} // namespace
