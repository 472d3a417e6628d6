// The fill's creases and faces: triangles across a crease rebuilt sharp (right, acute
// and obtuse angles, a box corner to its apex) and the faces' tangent planes measuring
// noise, not curvature.

#include "band_fixtures.h"
#include "fill_fixtures.h"

#include <visfeat/core/band/crease_fill.h>
#include <visfeat/core/band/crease_strips.h>
#include <visfeat/core/band/local_triangles.h>
#include <visfeat/core/band/triangle_cells.h>
#include <visfeat/core/band/voxel_band.h>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <set>
#include <vector>

namespace {

using namespace visfeat_test::fill;
using visfeat::CellCoord;

/** Jittered points on two half-planes meeting at a right angle along the x axis: y >= 0
 * in z = 0 and z >= 0 in y = 0 (cell units, spacing 3 cells). */
std::vector<Eigen::Vector3d>
rightAngleCrease(std::mt19937& rng)
{
  std::uniform_real_distribution<double> jitter(-0.8, 0.8);
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < 14; ++i)
    for (int j = 0; j < 7; ++j) {
      const double x = 8.0 + 3.0 * i + jitter(rng),
                   s = 0.5 + 3.0 * j + 0.6 * jitter(rng);
      points.emplace_back(x, s, 0.0);
      points.emplace_back(x + jitter(rng), 0.0, s);
    }
  return points;
}

TEST(CreaseFill, RebuildsACreaseSharp)
{
  std::mt19937 rng(9);
  const std::vector<Eigen::Vector3d> raw = rightAngleCrease(rng);
  // the crease at y = z = 20.5 in cell units, a grid of unit cells
  std::vector<Eigen::Vector3d> points;
  for (const Eigen::Vector3d& p : raw)
    points.push_back(p + Eigen::Vector3d(0.0, 20.5, 20.5));
  const visfeat::GridSpec grid = visfeat_test::cubeGrid(64);
  visfeat::LocalTriangleParameters parameters;
  const int k = parameters.neighbours + 1;
  const auto neighbours = nearest(points, k);
  const auto triangles =
    visfeat::umbrellaTriangles(points, neighbours, k, parameters, 1);
  const auto planes = visfeat::tangentPlanes(points, neighbours, k, 1);
  // normals away from the crease are the faces' own
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3d d = points[i] - Eigen::Vector3d(0.0, 20.5, 20.5);
    if (std::min(d.y(), d.z()) > -1.0 && std::max(d.y(), d.z()) > 4.0) {
      EXPECT_GT(std::abs(planes[i].normal[d.y() > d.z() ? 2 : 1]), 0.99) << i;
    }
  }
  // cells inside the right angle, off both faces (face cells have y or z = 20): the
  // chords' wedge, which the rebuilt crease leaves out
  auto wedge = [](const std::vector<CellCoord>& cells) {
    std::size_t n = 0;
    for (const CellCoord& c : cells)
      if (c.x() > 12 && c.x() < 44 && c.y() >= 21 && c.z() >= 21)
        ++n;
    return n;
  };
  const auto sharp = visfeat::creaseFillCells(grid, points, planes, triangles, 20.0, 2);
  const auto plain =
    visfeat::creaseFillCells(grid, points, planes, triangles, 180.0, 1);
  EXPECT_EQ(plain, visfeat::rasterizeTriangles(grid, points, triangles, 1));
  EXPECT_GT(wedge(plain), 25u) << "the chords fill the wedge";
  EXPECT_LT(wedge(sharp), wedge(plain) / 4) << "the rebuilt crease does not";
  // and the crease line itself is there: the cells of the corner column (y, z = 20)
  std::set<Key> found;
  for (const CellCoord& c : sharp)
    found.insert(key(c));
  int on_line = 0;
  for (int x = 14; x < 42; ++x)
    on_line += found.count({x, 20, 20}) > 0;
  EXPECT_GE(on_line, 26);
  EXPECT_EQ(sharp, visfeat::creaseFillCells(grid, points, planes, triangles, 20.0, 1))
    << "thread count";
}

TEST(TangentPlanes, MeasureTheNoiseOfTheFaces)
{
  // noise-free faces and a crease: 0 (the crease's points are a minority)
  std::mt19937 rng(21);
  const std::vector<Eigen::Vector3d> clean = rightAngleCrease(rng);
  const int k = visfeat::LocalTriangleParameters{}.neighbours + 1;
  double noise = -1.0;
  visfeat::tangentPlanes(clean, nearest(clean, k), k, 2, &noise);
  EXPECT_LT(noise, 1e-9);
  // Gaussian noise of sigma per coordinate: the RMS about a plane fitted to 11 points
  // is about sqrt(8 / 11) sigma = 0.85 sigma
  for (const double sigma : {0.1, 0.4}) {
    std::normal_distribution<double> gauss(0.0, sigma);
    std::vector<Eigen::Vector3d> noisy = clean;
    for (Eigen::Vector3d& p : noisy)
      p += Eigen::Vector3d(gauss(rng), gauss(rng), gauss(rng));
    visfeat::tangentPlanes(noisy, nearest(noisy, k), k, 1, &noise);
    EXPECT_GT(noise, 0.7 * sigma) << sigma;
    EXPECT_LT(noise, 1.0 * sigma) << sigma;
  }
}

TEST(TangentPlanes, TellTheSpreadOfASparseCleanCloudFromNoise)
{
  // A corrugated sheet sampled sparsely: folds of 90 degrees 3 spacings apart, so the
  // 10 nearest neighbours of most points span a fold and the median RMS about their
  // plane reads the shape; the neighbourhoods inside a strip still lie exactly flat.
  // Gaussian noise of 5% of the spacing on a flat sheet leaves none flat.
  std::mt19937 rng(27);
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  const auto fold = [](double x) { // period 6, slopes +-1
    const double t = std::fmod(x, 6.0);
    return t < 3.0 ? t : 6.0 - t;
  };
  std::vector<Eigen::Vector3d> corrugated, flat;
  std::normal_distribution<double> gauss(0.0, 0.05);
  for (int i = 0; i < 40; ++i)
    for (int j = 0; j < 20; ++j) {
      // spacing 1 along the sheet: x steps of 1 / sqrt(2) across the 45-degree strips
      const double x = (i + jitter(rng)) / std::sqrt(2.0), y = j + jitter(rng);
      corrugated.emplace_back(x, y, fold(x));
      flat.emplace_back(i + jitter(rng), y, gauss(rng));
    }
  const int k = visfeat::LocalTriangleParameters{}.neighbours + 1;
  double noise = -1.0, flat_share = -1.0;
  visfeat::tangentPlanes(corrugated, nearest(corrugated, k), k, 2, &noise, &flat_share);
  EXPECT_GT(noise, 0.05); // the shape: above the noisy sheet's reading
  EXPECT_GE(flat_share, visfeat::kShapeNotNoiseShare);
  EXPECT_LT(flat_share, 0.5); // most neighbourhoods span a fold
  visfeat::tangentPlanes(flat, nearest(flat, k), k, 1, &noise, &flat_share);
  EXPECT_GT(noise, 0.03);
  EXPECT_LT(flat_share, 0.01);
  // a noise-free crease: most neighbourhoods lie on one face
  const std::vector<Eigen::Vector3d> clean = rightAngleCrease(rng);
  visfeat::tangentPlanes(clean, nearest(clean, k), k, 1, &noise, &flat_share);
  EXPECT_GT(flat_share, 0.5);
}

TEST(TangentPlanes, TheCurvatureOfASparseCurvedFaceIsNotNoise)
{
  // A cylinder of radius 3 sampled about 0.43 apart (11 neighbours within about 0.8):
  // a plane's residual reads the curvature (about 0.8^2 / 4 / 6 = 0.027), the
  // quadric's only its fourth-order rest (about 0.002 at the rim); Gaussian noise
  // still reads about 0.85 sigma.
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> angle(0.0, 2.0 * std::acos(-1.0)),
    height(0.0, 20.0);
  std::vector<Eigen::Vector3d> clean;
  for (int i = 0; i < 2000; ++i) {
    const double a = angle(rng);
    clean.emplace_back(3.0 * std::cos(a), 3.0 * std::sin(a), height(rng));
  }
  const int k = visfeat::LocalTriangleParameters{}.neighbours + 1;
  double noise = -1.0;
  visfeat::tangentPlanes(clean, nearest(clean, k), k, 2, &noise);
  EXPECT_LT(noise, 0.005);
  const double sigma = 0.05;
  std::normal_distribution<double> gauss(0.0, sigma);
  std::vector<Eigen::Vector3d> noisy = clean;
  for (Eigen::Vector3d& p : noisy)
    p += Eigen::Vector3d(gauss(rng), gauss(rng), gauss(rng));
  visfeat::tangentPlanes(noisy, nearest(noisy, k), k, 1, &noise);
  EXPECT_GT(noise, 0.7 * sigma);
  EXPECT_LT(noise, 1.0 * sigma);
}

/** The sparse fill with its creases rebuilt, as localTriangleCells() puts it together:
 * the local triangles (chords lifted) and the crease strips, the strips checked to be
 * the same on one thread as on two. */
std::vector<CellCoord>
sharpCells(const visfeat::GridSpec& grid,
           const std::vector<Eigen::Vector3d>& points,
           const std::vector<visfeat::TangentPlane>& planes,
           const std::vector<std::uint32_t>& neighbours,
           int k,
           const visfeat::LocalTriangleParameters& parameters)
{
  const auto triangles =
    visfeat::umbrellaTriangles(points, neighbours, k, parameters, 1);
  std::vector<CellCoord> cells = visfeat::creaseFillCells(
    grid, points, planes, triangles, parameters.crease_degrees, 2);
  const std::vector<CellCoord> strips = visfeat::creaseStripCells(
    grid, points, planes, neighbours, k, parameters.crease_degrees, 2);
  EXPECT_EQ(strips, visfeat::creaseStripCells(grid, points, planes, neighbours, k,
                                              parameters.crease_degrees, 1))
    << "thread count";
  cells.insert(cells.end(), strips.begin(), strips.end());
  return cells;
}

/** Two half-planes meeting at the line y = z = 32.3 (along x) at `degrees` (the
 * dihedral angle), sampled every 3 cells with jitter and no point closer than 1.5 cells
 * to the crease: the chords there cut it by about a cell. */
std::vector<Eigen::Vector3d>
creaseAtAngle(double degrees, std::mt19937& rng)
{
  std::uniform_real_distribution<double> jitter(-0.7, 0.7);
  const double a = degrees * 3.14159265358979323846 / 180.0;
  const Eigen::Vector3d apex(0.0, 32.3, 32.3), da(0.0, -1.0, 0.0),
    db(0.0, -std::cos(a), std::sin(a));
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < 16; ++i)
    for (int j = 0; j < 7; ++j) {
      const double x = 6.0 + 3.0 * i;
      points.push_back(apex + Eigen::Vector3d::UnitX() * (x + jitter(rng)) +
                       da * (2.2 + 3.0 * j + jitter(rng)));
      points.push_back(apex + Eigen::Vector3d::UnitX() * (x + 1.5 + jitter(rng)) +
                       db * (2.2 + 3.0 * j + jitter(rng)));
    }
  return points;
}

TEST(CreaseFill, RebuildsAcuteAndObtuseCreasesToTheApex)
{
  for (const double degrees : {55.0, 70.5, 90.0, 120.0, 138.0}) {
    std::mt19937 rng(static_cast<unsigned>(degrees * 10));
    const std::vector<Eigen::Vector3d> points = creaseAtAngle(degrees, rng);
    const visfeat::GridSpec grid = visfeat_test::cubeGrid(64);
    visfeat::LocalTriangleParameters parameters;
    const int k = parameters.neighbours + 1;
    const auto neighbours = nearest(points, k);
    const auto planes = visfeat::tangentPlanes(points, neighbours, k, 1);
    const std::vector<CellCoord> cells =
      sharpCells(grid, points, planes, neighbours, k, parameters);
    std::set<Key> found;
    for (const CellCoord& c : cells)
      found.insert(key(c));
    // the apex line runs through the cells (x, 32, 32)
    int on_line = 0, line = 0;
    for (int x = 12; x < 48; ++x, ++line)
      on_line += found.count({x, 32, 32}) > 0;
    EXPECT_GE(on_line, line - 1) << degrees << " degrees: the apex is cut";
    // no cell whose nearest point lies more than a cell off both half-planes
    const double a = degrees * 3.14159265358979323846 / 180.0;
    const Eigen::Vector2d da(-1.0, 0.0), db(-std::cos(a), std::sin(a));
    int off = 0;
    for (const CellCoord& c : cells) {
      if (c.x() < 12 || c.x() >= 48)
        continue;
      double nearest_surface = std::numeric_limits<double>::infinity();
      for (int cy = 0; cy <= 1; ++cy)
        for (int cz = 0; cz <= 1; ++cz) {
          // the cell's corners in the crease's cross-section
          const Eigen::Vector2d q(c.y() + cy - 32.3, c.z() + cz - 32.3);
          for (const Eigen::Vector2d& d : {da, db})
            nearest_surface =
              std::min(nearest_surface, (q - std::max(0.0, q.dot(d)) * d).norm());
        }
      off += nearest_surface > 1.0;
    }
    EXPECT_EQ(off, 0) << degrees << " degrees: cells off the surface";
  }
}

/** The three faces x, y, z <= 32.3 of a box corner at (32.3, 32.3, 32.3) (the solid is
 * below all three), each sampled every 3 cells with jitter, no point within 1.5 cells
 * of an edge. */
std::vector<Eigen::Vector3d>
boxCorner(std::mt19937& rng)
{
  std::uniform_real_distribution<double> jitter(-0.7, 0.7);
  const double apex = 32.3;
  std::vector<Eigen::Vector3d> points;
  for (int axis = 0; axis < 3; ++axis)
    for (int i = 0; i < 9; ++i)
      for (int j = 0; j < 9; ++j) {
        Eigen::Vector3d p = Eigen::Vector3d::Constant(apex);
        p[(axis + 1) % 3] -= 2.2 + 3.0 * i + jitter(rng);
        p[(axis + 2) % 3] -= 2.2 + 3.0 * j + jitter(rng);
        points.push_back(p);
      }
  return points;
}

TEST(CreaseStrips, RebuildABoxCornerToItsApex)
{
  for (const unsigned seed : {3u, 4u, 5u}) {
    std::mt19937 rng(seed);
    const std::vector<Eigen::Vector3d> points = boxCorner(rng);
    const visfeat::GridSpec grid = visfeat_test::cubeGrid(64);
    visfeat::LocalTriangleParameters parameters;
    const int k = parameters.neighbours + 1;
    const auto neighbours = nearest(points, k);
    const auto planes = visfeat::tangentPlanes(points, neighbours, k, 1);
    // every point takes its own face's plane, even beside the edges and the corner
    for (std::size_t i = 0; i < points.size(); ++i) {
      const int axis = static_cast<int>(i / 81);
      EXPECT_GT(std::abs(planes[i].normal[axis]), 0.9999)
        << "seed " << seed << " " << i;
      EXPECT_NEAR(planes[i].point[axis], 32.3, 1e-9) << "seed " << seed << " " << i;
    }
    const std::vector<CellCoord> cells =
      sharpCells(grid, points, planes, neighbours, k, parameters);
    std::set<Key> found;
    for (const CellCoord& c : cells)
      found.insert(key(c));
    EXPECT_EQ(found.count({32, 32, 32}), 1u) << "seed " << seed << ": the apex";
    // the three edges from the apex, their first 12 cells
    for (int axis = 0; axis < 3; ++axis)
      for (int t = 1; t <= 12; ++t) {
        int c[3] = {32, 32, 32};
        c[axis] -= t;
        EXPECT_EQ(found.count({c[0], c[1], c[2]}), 1u)
          << "seed " << seed << ": edge along axis " << axis << " at " << t;
      }
    // nothing off the faces: a cell holds a point of the surface within one cell
    for (const CellCoord& c : cells) {
      const Eigen::Vector3d lo = c.cast<double>(), hi = lo + Eigen::Vector3d::Ones();
      double off = 0.0; // distance of the cell from the corner's surface
      for (int axis = 0; axis < 3; ++axis)
        off = std::max(off, lo[axis] - 32.3); // outside the solid
      if (off == 0.0) {
        double depth =
          std::numeric_limits<double>::infinity(); // inside: to the nearest face
        for (int axis = 0; axis < 3; ++axis)
          depth = std::min(depth, 32.3 - std::min(hi[axis], 32.3));
        off = depth;
      }
      EXPECT_LE(off, 1.0) << "seed " << seed << ": cell " << c.transpose();
    }
  }
}

} // namespace
