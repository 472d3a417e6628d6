#include "band_fixtures.h"

#include <support/portable_random.h>
#include <support/synthetic_shapes.h>
#include <visfeat/voxel_band_from_cloud.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <sstream>
#include <stdexcept>

namespace visfeat_test {

namespace {

Eigen::Vector3d
centreOf(const CellCoord& c)
{
  return c.cast<double>() + Eigen::Vector3d::Constant(0.5);
}

double
l1(const Eigen::Vector3d& v)
{
  return v.cwiseAbs().sum();
}

/** Every cell of the grid (with a margin) whose centre satisfies `keep`. */
template <typename Pred>
std::vector<CellCoord>
cellsWhere(const GridSpec& grid, int margin, Pred keep)
{
  std::vector<CellCoord> out;
  for (int z = margin; z < grid.dims.z() - margin; ++z)
    for (int y = margin; y < grid.dims.y() - margin; ++y)
      for (int x = margin; x < grid.dims.x() - margin; ++x) {
        const CellCoord c(x, y, z);
        if (keep(centreOf(c)))
          out.push_back(c);
      }
  return out;
}

} // namespace

SampledCadModel
sampleCadCloud(const visfeat::synthetic::CadModel& model,
               int resolution,
               std::uint64_t seed,
               double noise_cells)
{
  namespace synthetic = visfeat::synthetic;
  synthetic::SamplingOptions options;
  options.count = synthetic::samplesForSpacing(model, resolution, 0.5);
  options.seed = seed;
  options.noise_sigma = noise_cells * synthetic::cellSize(model, resolution);
  return sampleCadCloud(model, options);
}

SampledCadModel
sampleCadCloud(const visfeat::synthetic::CadModel& model,
               const visfeat::synthetic::SamplingOptions& options)
{
  SampledCadModel sampled;
  sampled.samples = visfeat::synthetic::sampleCadModel(model, options);
  sampled.cloud = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  for (const Eigen::Vector3f& p : sampled.samples.points)
    sampled.cloud->push_back(pcl::PointXYZ(p.x(), p.y(), p.z()));
  return sampled;
}

GridSpec
cubeGrid(int n)
{
  GridSpec g;
  g.origin = Eigen::Vector3d::Zero();
  g.cell_size = 1.0;
  g.dims = Eigen::Vector3i::Constant(n);
  return g;
}

Eigen::Matrix3d
randomRotationMatrix(std::mt19937_64& rng)
{
  visfeat::synthetic::Normal normal(0.0, 1.0);
  Eigen::Quaterniond q(normal(rng), normal(rng), normal(rng), normal(rng));
  q.normalize();
  return q.toRotationMatrix();
}

CellBand
ballShells(std::uint64_t seed)
{
  std::mt19937_64 rng(seed);
  visfeat::synthetic::UniformReal centre(7.0, 13.0);
  visfeat::synthetic::UniformReal rad(2.5, 4.5);
  struct Ball
  {
    Eigen::Vector3d c;
    double r;
  };
  std::vector<Ball> balls;
  for (int i = 0; i < 3; ++i)
    balls.push_back({Eigen::Vector3d(centre(rng), centre(rng), centre(rng)), rad(rng)});
  CellBand band;
  band.name = "ball_shells_" + std::to_string(seed);
  band.grid = cubeGrid(21);
  band.cells = cellsWhere(band.grid, 2, [&](const Eigen::Vector3d& p) {
    for (const Ball& b : balls)
      if (std::abs((p - b.c).norm() - b.r) <= 0.6)
        return true;
    return false;
  });
  return band;
}

CellBand
randomWalkBlob(std::uint64_t seed)
{
  std::mt19937_64 rng(seed);
  visfeat::synthetic::UniformInt start(6, 11);
  visfeat::synthetic::UniformInt dir(0, 5);
  static const CellCoord kDirs[6] = {CellCoord(-1, 0, 0), CellCoord(1, 0, 0),
                                     CellCoord(0, -1, 0), CellCoord(0, 1, 0),
                                     CellCoord(0, 0, -1), CellCoord(0, 0, 1)};
  std::set<std::array<int, 3>> cells;
  for (int w = 0; w < 4; ++w) {
    CellCoord c(start(rng), start(rng), start(rng));
    cells.insert({c.x(), c.y(), c.z()});
    for (int step = 0; step < 120; ++step) {
      const CellCoord n = c + kDirs[dir(rng)];
      if ((n.array() < 3).any() || (n.array() > 14).any())
        continue;
      c = n;
      cells.insert({c.x(), c.y(), c.z()});
    }
  }
  CellBand band;
  band.name = "random_walk_" + std::to_string(seed);
  band.grid = cubeGrid(18);
  for (const auto& a : cells)
    band.cells.emplace_back(a[0], a[1], a[2]);
  return band;
}

CellBand
digitalPlane(std::uint64_t seed, double disc_radius)
{
  std::mt19937_64 rng(seed);
  const Eigen::Matrix3d r = randomRotationMatrix(rng);
  visfeat::synthetic::UniformReal jitter(-0.5, 0.5);
  const int n = static_cast<int>(std::ceil(2 * disc_radius)) + 8;
  const Eigen::Vector3d c0 = Eigen::Vector3d::Constant(n / 2.0) +
                             Eigen::Vector3d(jitter(rng), jitter(rng), jitter(rng));
  const Eigen::Vector3d normal = r.col(2);
  const double half = l1(normal) / 2.0;
  CellBand band;
  band.name = "digital_plane_" + std::to_string(seed);
  band.grid = cubeGrid(n);
  band.cells = cellsWhere(band.grid, 2, [&](const Eigen::Vector3d& p) {
    const Eigen::Vector3d y = p - c0;
    const double h = normal.dot(y);
    return std::abs(h) <= half && (y - h * normal).norm() <= disc_radius;
  });
  return band;
}

CellBand
creaseBand(std::uint64_t seed, double half_length, double width)
{
  std::mt19937_64 rng(seed);
  const Eigen::Matrix3d r = randomRotationMatrix(rng);
  const Eigen::Vector3d u = r.col(0), v = r.col(1), w = r.col(2);
  const int n = static_cast<int>(std::ceil(2 * std::hypot(half_length, width))) + 6;
  // The crease line passes through c0; the faces open towards +v and +w.
  const Eigen::Vector3d c0 = Eigen::Vector3d::Constant(n / 2.0) - 0.5 * width * (v + w);
  const double half_a = l1(w) / 2.0; // face A = {s u + t v}, normal w
  const double half_b = l1(v) / 2.0; // face B = {s u + t w}, normal v
  CellBand band;
  band.name = "crease_" + std::to_string(seed);
  band.grid = cubeGrid(n);
  band.cells = cellsWhere(band.grid, 2, [&](const Eigen::Vector3d& p) {
    const Eigen::Vector3d y = p - c0;
    const double s = u.dot(y), a = v.dot(y), b = w.dot(y);
    if (std::abs(s) > half_length)
      return false;
    const bool on_a = std::abs(b) <= half_a && a >= -0.5 && a <= width;
    const bool on_b = std::abs(a) <= half_b && b >= -0.5 && b <= width;
    return on_a || on_b;
  });
  return band;
}

CellBand
hollowBox(int sx, int sy, int sz)
{
  const CellCoord lo(2, 3, 2), hi = lo + CellCoord(sx, sy, sz);
  CellBand band;
  band.name = "hollow_box";
  band.grid = cubeGrid(std::max({sx, sy, sz}) + 7);
  for (int z = lo.z(); z <= hi.z(); ++z)
    for (int y = lo.y(); y <= hi.y(); ++y)
      for (int x = lo.x(); x <= hi.x(); ++x) {
        const CellCoord c(x, y, z);
        if ((c.array() == lo.array()).any() || (c.array() == hi.array()).any())
          band.cells.push_back(c);
      }
  return band;
}

BoxRegions
hollowBoxRegions(const visfeat::VoxelBand& band, int sx, int sy, int sz)
{
  const CellCoord lo(2, 3, 2), hi = lo + CellCoord(sx, sy, sz);
  BoxRegions box;
  box.labels.resize(band.size());
  for (std::size_t i = 0; i < band.size(); ++i) {
    const CellCoord& c = band.coord(static_cast<visfeat::CellId>(i));
    std::array<int, 3> sig{};
    int extremes = 0;
    for (int a = 0; a < 3; ++a) {
      sig[static_cast<std::size_t>(a)] = c[a] == lo[a] ? -1 : c[a] == hi[a] ? 1 : 0;
      extremes += sig[static_cast<std::size_t>(a)] != 0 ? 1 : 0;
    }
    if (extremes == 0)
      throw std::runtime_error("hollowBoxRegions: a cell inside the box");
    auto it = box.ids.find(sig);
    if (it == box.ids.end()) {
      it =
        box.ids.emplace(sig, static_cast<std::uint32_t>(box.classes.size() + 1)).first;
      box.classes.push_back(extremes == 1   ? visfeat::FeatureClass::kFace
                            : extremes == 2 ? visfeat::FeatureClass::kEdge
                                            : visfeat::FeatureClass::kVertex);
    }
    box.labels[i] = it->second;
  }
  return box;
}

ThinPlate
thinPlate(std::uint64_t seed, double half_size)
{
  // Cells whose centre is within tau of the surface of the box
  // |u.y| <= R, |v.y| <= R, 0 <= w.y <= gap (y = p - c0).
  //
  // Why the two large faces cannot see each other: the free space of a mixed cell with
  // centre m is the cube |x - m|_inf <= 1 (its subcells and their neighbours). A cell
  // of the band is within tau of the top or bottom plane (in w), or within tau of a rim
  // plane (in u or v). So a free point lies within tau + |w|_1 of the top or bottom
  // plane, or within tau + |u|_1 <= tau + sqrt(3) < 3 of a rim plane. A segment between
  // two cells near opposite faces whose projections lie >= 3 cells inside the rim stays
  // >= 3 cells inside the rim (convexity) and crosses the slab
  // tau + |w|_1 < w.y < gap - tau - |w|_1, of thickness gap - 2 (tau + |w|_1) = 1.25,
  // which touches no free cube: the blocked length is >= 1.25 > 1 cell edge.
  std::mt19937_64 rng(seed);
  const Eigen::Matrix3d r = randomRotationMatrix(rng);
  const Eigen::Vector3d u = r.col(0), v = r.col(1), w = r.col(2);
  const double tau = 0.87;
  const double gap = 2.0 * (tau + l1(w)) + 1.25;
  const double big = half_size;
  const int n = static_cast<int>(
                  std::ceil(2.0 * std::sqrt(2 * big * big + gap * gap / 4) + 2 * tau)) +
                6;
  const Eigen::Vector3d c0 = Eigen::Vector3d::Constant(n / 2.0) - 0.5 * gap * w;
  const Eigen::Vector3d half(big, big, gap / 2.0);

  ThinPlate plate;
  plate.gap = gap;
  plate.band.name = "thin_plate_" + std::to_string(seed);
  plate.band.grid = cubeGrid(n);
  plate.band.cells = cellsWhere(plate.band.grid, 2, [&](const Eigen::Vector3d& p) {
    const Eigen::Vector3d y = p - c0;
    const Eigen::Vector3d local(u.dot(y), v.dot(y), w.dot(y) - gap / 2.0);
    const Eigen::Vector3d excess = local.cwiseAbs() - half;
    double dist;
    if ((excess.array() <= 0.0).all())
      dist = -excess.maxCoeff();
    else
      dist = excess.cwiseMax(0.0).norm();
    return dist <= tau;
  });
  for (const CellCoord& c : plate.band.cells) {
    const Eigen::Vector3d y = centreOf(c) - c0;
    const double a = u.dot(y), b = v.dot(y), h = w.dot(y);
    if (std::abs(a) > big - 3.0 || std::abs(b) > big - 3.0)
      continue;
    if (std::abs(h - gap) <= tau)
      plate.top_inner.push_back(c);
    else if (std::abs(h) <= tau)
      plate.bottom_inner.push_back(c);
  }
  return plate;
}

std::vector<CellBand>
smallCellBands()
{
  return {ballShells(1),          ballShells(2),   randomWalkBlob(3), randomWalkBlob(4),
          digitalPlane(5),        digitalPlane(6), creaseBand(7),     creaseBand(8),
          thinPlate(9, 5.0).band, hollowBox()};
}

pcl::PointCloud<pcl::PointXYZ>
syntheticShapeCloud(const std::string& shape,
                    std::uint64_t seed,
                    int resolution,
                    double spacing_cells)
{
  namespace syn = visfeat::synthetic;
  syn::TriangleMesh base;
  if (shape == "cube")
    base = syn::cube();
  else if (shape == "tetrahedron")
    base = syn::tetrahedron();
  else if (shape == "octahedron")
    base = syn::octahedron();
  else
    base = syn::icosahedron();
  const syn::TriangleMesh mesh = syn::rotated(base, syn::randomRotation(seed));
  const std::size_t count = syn::samplesForSpacing(mesh, resolution, spacing_cells);
  const std::vector<Eigen::Vector3f> pts = syn::sampleSurface(mesh, count, seed + 1000);
  pcl::PointCloud<pcl::PointXYZ> cloud;
  for (const Eigen::Vector3f& p : pts)
    cloud.push_back(pcl::PointXYZ(p.x(), p.y(), p.z()));
  return cloud;
}

pcl::PointCloud<pcl::PointXYZ>
squareCloud(const Eigen::Vector3d& u,
            const Eigen::Vector3d& v,
            std::size_t count,
            std::mt19937_64& rng)
{
  visfeat::synthetic::UniformReal coord(-0.5, 0.5);
  pcl::PointCloud<pcl::PointXYZ> cloud;
  for (std::size_t i = 0; i < count; ++i) {
    const Eigen::Vector3d p = coord(rng) * u + coord(rng) * v;
    cloud.push_back(pcl::PointXYZ(static_cast<float>(p.x()), static_cast<float>(p.y()),
                                  static_cast<float>(p.z())));
  }
  return cloud;
}

pcl::PointCloud<pcl::PointXYZ>
creaseCloud(const Eigen::Matrix3d& frame,
            std::size_t count_per_face,
            std::mt19937_64& rng)
{
  const Eigen::Vector3d u = frame.col(0), v = frame.col(1), w = frame.col(2);
  visfeat::synthetic::UniformReal s(-0.5, 0.5);
  visfeat::synthetic::UniformReal t(0.0, 1.0);
  pcl::PointCloud<pcl::PointXYZ> cloud;
  for (int face = 0; face < 2; ++face)
    for (std::size_t i = 0; i < count_per_face; ++i) {
      const Eigen::Vector3d p = s(rng) * u + t(rng) * (face == 0 ? v : w);
      cloud.push_back(pcl::PointXYZ(static_cast<float>(p.x()),
                                    static_cast<float>(p.y()),
                                    static_cast<float>(p.z())));
    }
  return cloud;
}

visfeat::VoxelBand
bandFromCloud(const pcl::PointCloud<pcl::PointXYZ>& cloud, int resolution, bool repair)
{
  const GridSpec grid = visfeat::gridForCloud(cloud, resolution);
  visfeat::VoxelBand::Options options;
  options.repair = repair;
  return visfeat::buildVoxelBand(cloud, grid, options);
}

const std::vector<std::string>&
referenceBandNames()
{
  static const std::vector<std::string> names = {
    "ball_shells_1",       "ball_shells_2",   "random_walk_3",  "random_walk_4",
    "digital_plane_5",     "digital_plane_6", "crease_7",       "crease_8",
    "thin_plate_9",        "hollow_box",      "cloud_cube_r12", "cloud_tetrahedron_r14",
    "cloud_octahedron_r12"};
  return names;
}

NamedBand
referenceBand(std::size_t index)
{
  const std::string& name = referenceBandNames().at(index);
  visfeat::VoxelBand::Options options;
  options.repair = true;
  CellBand cells;
  switch (index) {
  case 0:
    cells = ballShells(1);
    break;
  case 1:
    cells = ballShells(2);
    break;
  case 2:
    cells = randomWalkBlob(3);
    break;
  case 3:
    cells = randomWalkBlob(4);
    break;
  case 4:
    cells = digitalPlane(5);
    break;
  case 5:
    cells = digitalPlane(6);
    break;
  case 6:
    cells = creaseBand(7);
    break;
  case 7:
    cells = creaseBand(8);
    break;
  case 8:
    cells = thinPlate(9, 5.0).band;
    options.repair = false;
    break;
  case 9:
    cells = hollowBox();
    break;
  case 10:
    return {name, bandFromCloud(syntheticShapeCloud("cube", 11, 12), 12)};
  case 11:
    return {name, bandFromCloud(syntheticShapeCloud("tetrahedron", 12, 14), 14)};
  default:
    return {name, bandFromCloud(syntheticShapeCloud("octahedron", 13, 12), 12)};
  }
  if (cells.name != name)
    throw std::logic_error("referenceBand: name mismatch " + cells.name + " vs " +
                           name);
  return {name, visfeat::VoxelBand::fromCells(cells.grid, cells.cells, options)};
}

bool
coordLess(const CellCoord& a, const CellCoord& b)
{
  return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
}

std::string
toString(const Eigen::Vector3i& c)
{
  std::ostringstream os;
  os << "(" << c.x() << "," << c.y() << "," << c.z() << ")";
  return os.str();
}

} // namespace visfeat_test
