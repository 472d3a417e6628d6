#include <support/blend_models.h>
#include <visfeat/core/common/error.h>

#include <algorithm>
#include <cmath>

namespace visfeat {
namespace synthetic {
namespace {

constexpr double kPi = 3.14159265358979323846;

/** Adds the quad a b c d (counter-clockwise seen from outside) as two triangles. */
void
addQuad(TriangleMesh& mesh, int a, int b, int c, int d)
{
  mesh.triangles.push_back({{a, b, c}});
  mesh.triangles.push_back({{a, c, d}});
}

/** The convex profile (x, y; counter-clockwise) extruded over z in [z0, z1]: bottom and
 * top fanned from their first vertex, one quad a side. */
TriangleMesh
extrudeConvex(const std::vector<Eigen::Vector2d>& profile, double z0, double z1)
{
  TriangleMesh mesh;
  const int n = static_cast<int>(profile.size());
  for (double z : {z0, z1})
    for (const Eigen::Vector2d& p : profile)
      mesh.vertices.emplace_back(p.x(), p.y(), z);
  for (int i = 1; i + 1 < n; ++i) {
    mesh.triangles.push_back({{0, i + 1, i}});         // bottom, seen from below
    mesh.triangles.push_back({{n, n + i, n + i + 1}}); // top
  }
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    addQuad(mesh, i, j, n + j, n + i);
  }
  return mesh;
}

BlendModel
filletedBox()
{
  const double lx = 40.0, ly = 30.0, lz = 20.0, r = 3.0;
  std::vector<Eigen::Vector2d> profile;
  // corner centres counter-clockwise from (+x, -y); each arc turns 90 degrees
  const Eigen::Vector2d centres[4] = {{0.5 * lx - r, -0.5 * ly + r},
                                      {0.5 * lx - r, 0.5 * ly - r},
                                      {-0.5 * lx + r, 0.5 * ly - r},
                                      {-0.5 * lx + r, -0.5 * ly + r}};
  for (int c = 0; c < 4; ++c)
    for (int s = 0; s <= kFilletSegments; ++s) {
      const double a = (c - 1) * 0.5 * kPi + s * 0.5 * kPi / kFilletSegments;
      profile.push_back(centres[c] + r * Eigen::Vector2d(std::cos(a), std::sin(a)));
    }
  BlendModel model;
  model.name = "filleted_box";
  model.mesh = extrudeConvex(profile, -0.5 * lz, 0.5 * lz);
  model.vertices = 0;
  model.curves = 2;
  model.faces = 3;
  model.arcs = 4;
  model.blend_step = 90.0 / kFilletSegments;
  model.truth = "top and bottom rims (closed, no corner); top, bottom, side wall";
  return model;
}

BlendModel
facetedBoss()
{
  const double half = 20.0, block = 10.0, radius = 10.0, height = 10.0;
  const double z0 = -0.5 * (block + height), z1 = z0 + block, z2 = z1 + height;
  BlendModel model;
  model.name = "faceted_boss";
  TriangleMesh& mesh = model.mesh;
  const int n = kBossFacets;
  // 0..n-1 the boss's base, n..2n-1 its top, 2n..3n-1 the block's top outline (the
  // boss's vertices pushed radially onto the square: the square's corners are among
  // them, at 45 + 90 k degrees), 3n the top's centre, 3n+1.. the block's bottom.
  for (double z : {z1, z2})
    for (int i = 0; i < n; ++i) {
      const double a = (5.0 + 360.0 * i / n) * kPi / 180.0;
      mesh.vertices.emplace_back(radius * std::cos(a), radius * std::sin(a), z);
    }
  for (int i = 0; i < n; ++i) {
    const double a = (5.0 + 360.0 * i / n) * kPi / 180.0;
    const double c = std::cos(a), s = std::sin(a);
    const double scale = half / std::max(std::abs(c), std::abs(s));
    mesh.vertices.emplace_back(scale * c, scale * s, z1);
  }
  mesh.vertices.emplace_back(0.0, 0.0, z2);
  const int centre = 3 * n, bottom = 3 * n + 1;
  for (const auto& [x, y] : {std::pair{-half, -half}, std::pair{half, -half},
                             std::pair{half, half}, std::pair{-half, half}})
    mesh.vertices.emplace_back(x, y, z0);
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    addQuad(mesh, i, j, n + j, n + i);                  // the boss's facets
    mesh.triangles.push_back({{centre, n + i, n + j}}); // its top
    addQuad(mesh, 2 * n + i, 2 * n + j, j, i);          // the block's top around it
  }
  addQuad(mesh, bottom, bottom + 3, bottom + 2, bottom + 1);
  // The block's sides: bottom corner k and the top outline's corners (45 + 90 k deg).
  const int corner_index[4] = {22, 31, 4, 13}; // (5 + 10 i) = 225, 315, 45, 135
  for (int k = 0; k < 4; ++k) {
    const int k1 = (k + 1) % 4;
    // the top outline from corner k to corner k+1 (counter-clockwise)
    for (int i = corner_index[k]; i != corner_index[k1]; i = (i + 1) % n)
      mesh.triangles.push_back({{bottom + k, 2 * n + (i + 1) % n, 2 * n + i}});
    mesh.triangles.push_back({{bottom + k, bottom + k1, 2 * n + corner_index[k1]}});
  }
  model.vertices = 8;
  model.curves = 14;
  model.faces = 8;
  model.arcs = 76;
  model.blend_step = 360.0 / n;
  model.truth = "the block's 8/12/6; the boss's wall and top, its top rim and base "
                "(closed, no corner)";
  return model;
}

} // namespace

std::vector<std::string>
blendModelNames()
{
  return {"filleted_box", "faceted_boss"};
}

BlendModel
blendModelByName(const std::string& name)
{
  if (name == "filleted_box")
    return filletedBox();
  if (name == "faceted_boss")
    return facetedBoss();
  throw Error("unknown blend model '" + name + "' (known: filleted_box, faceted_boss)");
}

} // namespace synthetic
} // namespace visfeat
