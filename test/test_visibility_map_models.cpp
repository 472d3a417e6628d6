// Acceptance (ctest -L acceptance): the visibility map of the sparse mask, its windows
// and its tables against the map as visfeat computed it before them (a dense mask over
// the whole grid, reference/dense_visibility_map.h), whole maps, every cell, on the
// generated CAD models at resolution 256 under random rotations, noise-free and noisy,
// exact and with the paper's opacity.

#include "band_fixtures.h"
#include "reference/dense_visibility_map.h"

#include <support/cad_models.h>
#include <visfeat/core/visibility/free_space.h>
#include <visfeat/core/visibility/visibility_map.h>

#include <gtest/gtest.h>
#include <pcl/point_types.h>

#include <ostream>
#include <sstream>
#include <string>

namespace {

namespace synthetic = visfeat::synthetic;

struct MapCase
{
  std::string model;
  double noise_cells;
  double opacity;
  int max_radius;
};

// For gtest's messages and ctest's test list (instead of the struct's bytes).
void
PrintTo(const MapCase& c, std::ostream* os)
{
  *os << c.model << " noise " << c.noise_cells << " opacity " << c.opacity << " cap "
      << c.max_radius;
}

std::string
caseName(const ::testing::TestParamInfo<MapCase>& info)
{
  std::ostringstream os;
  os << info.param.model << "_noise" << static_cast<int>(100 * info.param.noise_cells)
     << "_opacity" << static_cast<int>(info.param.opacity) << "_cap"
     << info.param.max_radius;
  return os.str();
}

class WholeMapTest : public ::testing::TestWithParam<MapCase>
{};

TEST_P(WholeMapTest, RadiiMatchTheDenseMapOnEveryCell)
{
  constexpr int kResolution = 256;
  const MapCase& c = GetParam();
  const std::uint64_t seed = 7 + c.model.size();
  const synthetic::CadModel model = synthetic::rotated(
    synthetic::cadModelByName(c.model), synthetic::randomRotation(seed * 131));
  const visfeat_test::SampledCadModel sampled =
    visfeat_test::sampleCadCloud(model, kResolution, seed, c.noise_cells);
  const visfeat::VoxelBand band =
    visfeat_test::bandFromCloud(*sampled.cloud, kResolution);
  ASSERT_GT(band.size(), 100000u);

  const visfeat::FreeSpace free_space(band);
  visfeat::VisibilityMap::Parameters parameters;
  parameters.max_radius = c.max_radius;
  parameters.opacity = c.opacity;
  parameters.threads = 2;
  const visfeat::VisibilityMap map =
    visfeat::VisibilityMap::compute(band, free_space, parameters);
  const std::vector<int> expected =
    visfeat_test::reference::denseRadii(band, c.max_radius, c.opacity);

  ASSERT_EQ(map.radii().size(), expected.size());
  std::size_t mismatches = 0, below_cap = 0;
  std::ostringstream first;
  for (std::size_t i = 0; i < expected.size(); ++i) {
    below_cap += expected[i] < c.max_radius;
    const int got = map.radius(static_cast<visfeat::CellId>(i));
    if (got != expected[i] && mismatches++ < 8)
      first << "\n  cell " << visfeat_test::toString(band.coord(static_cast<int>(i)))
            << ": " << got << ", dense map " << expected[i];
  }
  EXPECT_EQ(mismatches, 0u) << band.size() << " cells:" << first.str();
  // Not trivially all at the cap: the creases hold the radius down.
  EXPECT_GT(below_cap, band.size() / 50);
}

INSTANTIATE_TEST_SUITE_P(GeneratedModels256,
                         WholeMapTest,
                         ::testing::Values(MapCase{"cube", 0.0, 0.0, 16},
                                           MapCase{"tetrahedron", 0.0, 0.0, 16},
                                           MapCase{"icosahedron", 0.0, 0.0, 16},
                                           MapCase{"triangular_prism", 0.0, 0.0, 16},
                                           MapCase{"u_prism", 0.0, 0.0, 16},
                                           MapCase{"box_with_hole", 0.0, 0.0, 16},
                                           MapCase{"cylinder", 0.0, 0.0, 16},
                                           MapCase{"icosahedron", 0.32, 3.0, 16},
                                           MapCase{"box_with_hole", 0.32, 3.0, 11},
                                           MapCase{"u_prism", 0.0, 0.0, 24}),
                         caseName);

} // namespace
