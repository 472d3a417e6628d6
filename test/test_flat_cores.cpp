// Unit tests of flatCore() and of the classification it adds to ComponentSet: cores
// thinner than a face by depth are faces on a flat part of the band, edges where the
// band bends across them; an edge ridge joined to a face core is split off it
// (attachedRidges()), and one with the same face on both sides stays a crease (a crease
// fading into its face). Bands are voxelized here from exact surfaces under random
// rotations; the maps are painted on them.

#include "band_fixtures.h"

#include <visfeat/core/segmentation/attached_ridges.h>
#include <visfeat/core/segmentation/components.h>
#include <visfeat/core/segmentation/feature_segmentation.h>
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
using visfeat::FeatureSegmentation;
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

/** The band of a fold and, as core candidates, the cells of its samples (x, y) for
 * which `core` holds. */
FoldBand
foldBand(const Fold& fold, const std::function<bool(double, double)>& core_at)
{
  std::set<std::array<int, 3>> cells, core;
  for (double x = -kHalf; x <= kHalf; x += 0.2)
    for (double y = -kHalf; y <= kHalf; y += 0.2) {
      const Eigen::Vector3d p = fold.at(x, y);
      const std::array<int, 3> c{{static_cast<int>(std::floor(p.x())),
                                  static_cast<int>(std::floor(p.y())),
                                  static_cast<int>(std::floor(p.z()))}};
      cells.insert(c);
      if (core_at(x, y))
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

FoldBand
foldBand(const Fold& fold,
         double core_y,
         double core_half_width,
         double core_half_length)
{
  return foldBand(fold, [&](double x, double y) {
    return std::abs(y - core_y) <= core_half_width && std::abs(x) <= core_half_length;
  });
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

/** A map of a fold's band with radius 16 on the cells of `band.core` and 8 elsewhere.
 */
visfeat::VisibilityMap
paintedMap(const FoldBand& band)
{
  std::vector<std::uint8_t> radii(band.band.size(), 8);
  for (const CellId c : band.core)
    radii[static_cast<std::size_t>(c)] = 16;
  visfeat::VisibilityMap::Parameters map_parameters;
  map_parameters.max_radius = 16;
  return visfeat::VisibilityMap::fromRadii(map_parameters, radii);
}

/** Components of a fold's band with radius 16 on the cells of `band.core` and 8
 * elsewhere. */
visfeat::ComponentSet
paintedCores(const FoldBand& band, bool flat_core_faces)
{
  const auto map = paintedMap(band);
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

/** A crease whose valley fades at one end: a ridge 2 cells wide along the fold
 * (ridge_start <= x <= 35), face cores from 16 cells off it on one side (or both),
 * and beyond the ridge's end a stretch where the map stays high from the face cores to
 * the fold (joined: it overlaps the ridge's end; else it stops 3 cells short of it). */
FoldBand
fadingCreaseBand(const Fold& fold,
                 bool both_sides,
                 bool joined,
                 double ridge_start = -35.0)
{
  const double start = joined ? 34.0 : 38.0;
  return foldBand(fold, [=](double x, double y) {
    const bool ridge = std::abs(y) <= 1.0 && x >= ridge_start && x <= 35.0;
    const bool face = y >= 16.0 || (both_sides && y <= -16.0);
    const bool faded = x >= start && (y >= 0.0 || both_sides);
    return ridge || face || faded;
  });
}

TEST(AttachedRidges, ARidgeJoinedToAFaceCoreIsSplitOffWhereTheBandBends)
{
  std::mt19937_64 rng(20261203);
  for (int r = 0; r < 3; ++r) {
    Fold fold;
    fold.rotation = visfeat_test::randomRotationMatrix(rng);
    for (const double turn : {0.0, 90.0}) {
      fold.turn = turn;
      const FoldBand band = fadingCreaseBand(fold, false, true);
      const visfeat::ComponentSet set = paintedCores(band, true);
      std::size_t faces = 0, edges = 0, edge_cells = 0;
      for (const auto& component : set.components()) {
        faces += component.feature_class == FeatureClass::kFace;
        edges += component.feature_class == FeatureClass::kEdge;
        if (component.feature_class == FeatureClass::kEdge)
          edge_cells += component.cells;
      }
      EXPECT_EQ(faces, 1u) << "rotation " << r << ", turn " << turn;
      // on the plane the ridge is a finger of the face core; on the crease an edge
      // of most of its 70 x 3 cells
      EXPECT_EQ(edges, turn == 0.0 ? 0u : 1u) << "rotation " << r << ", turn " << turn;
      if (turn != 0.0) {
        EXPECT_GT(edge_cells, 120u) << "rotation " << r;
      }
      // cores never touch: a gap of cells in no component between them
      const auto& labels = set.cellLabels();
      for (std::size_t c = 0; c < labels.size(); ++c)
        for (const CellId nb : band.band.neighbours(static_cast<CellId>(c)))
          if (nb != visfeat::kNoCell && labels[c] != 0 &&
              labels[static_cast<std::size_t>(nb)] != 0) {
            ASSERT_EQ(labels[c], labels[static_cast<std::size_t>(nb)])
              << "rotation " << r << ", turn " << turn;
          }
    }
  }
}

TEST(AttachedRidges, AShortRidgeStaysInTheFaceCore)
{
  // 8 cells of ridge: what is left of it beyond the opening (3 steps) and the gap (1)
  // holds fewer than 5 min_radius = 80 cells
  std::mt19937_64 rng(5);
  Fold fold;
  fold.turn = 90.0;
  fold.rotation = visfeat_test::randomRotationMatrix(rng);
  for (const double ridge_start : {27.0, -35.0}) {
    const visfeat::ComponentSet set =
      paintedCores(fadingCreaseBand(fold, false, true, ridge_start), true);
    EXPECT_EQ(set.components().size(), ridge_start == 27.0 ? 1u : 2u)
      << "ridge from x = " << ridge_start;
  }
}

/** The segmentation of a fading crease band: radius 16 on the cores, 8 elsewhere. */
FeatureSegmentation
segmentFading(const FoldBand& band)
{
  const auto map = paintedMap(band);
  visfeat::SegmentationParameters parameters;
  parameters.components.narrow_face_persistence = 0;
  return FeatureSegmentation::compute(band.band, map, parameters);
}

TEST(FadingCreases, ACreaseWithOneFaceOnBothSidesStaysAnEdgeWhereTheBandBends)
{
  std::mt19937_64 rng(31);
  for (int r = 0; r < 3; ++r) {
    Fold fold;
    fold.rotation = visfeat_test::randomRotationMatrix(rng);
    for (const double turn : {0.0, 30.0, 90.0})
      for (const bool joined : {true, false}) {
        fold.turn = turn;
        // one face core reaching around the crease's end: the same face on both sides
        // (55 cells long: fewer than min_radius^2 cells, so that on the plane the
        // ridge alone is no face of its own, flat_core_faces)
        const auto s = segmentFading(fadingCreaseBand(fold, true, joined, -20.0));
        const auto counts = s.classCounts();
        EXPECT_EQ(counts[static_cast<std::size_t>(FeatureClass::kFace)], 1u)
          << "rotation " << r << ", turn " << turn << ", joined " << joined;
        // a 90-degree turn reads about 0.07 (kFadingCreaseVariation 0.02); 30 degrees
        // about 0.014: a blend's or a shallow facet's speck, merged into the face
        EXPECT_EQ(counts[static_cast<std::size_t>(FeatureClass::kEdge)],
                  turn == 90.0 ? 1u : 0u)
          << "rotation " << r << ", turn " << turn << ", joined " << joined;
      }
  }
}

} // namespace
