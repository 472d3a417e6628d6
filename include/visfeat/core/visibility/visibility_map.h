#pragma once

#include <visfeat/core/band/voxel_band.h>
#include <visfeat/core/common/parameters.h>
#include <visfeat/core/visibility/free_space.h>

#include <cstdint>
#include <functional>
#include <vector>

namespace visfeat {

/** \brief Called now and then with the cells done so far and the total: every few
 * hundred cells from the calling thread or OpenMP's thread 0, never concurrently, and
 * once more at the end with done == total. Keep it cheap, and do not throw: all calls
 * but the last come from inside an OpenMP parallel region, which an exception must not
 * leave. */
using ProgressCallback = std::function<void(std::size_t done, std::size_t total)>;

/** \brief The trimmed visibility map: a visibility radius for every mixed cell.
 *
 * Ring 1 of a cell c is its mixed 6-neighbours; ring k the mixed cells 6-adjacent to
 * ring k-1 not seen before (BFS layers through the band). The radius of c is the number
 * of successive rings whose cells c all sees (FreeSpace::sees), stopping at the first
 * ring with one hidden cell, and capped at max_radius. A ring left empty because the
 * BFS ran out of cells counts as visible.
 *
 * Cells are independent, so the work is spread over threads brick by brick of 8^3
 * cells (BandTiles), each brick reading a dense FreeSpaceWindow of the sparse mask and
 * running its BFS on marks over the same window cells; the result is the same for any
 * thread count.
 */
class VisibilityMap
{
public:
  static constexpr int kMaxRadius = 64;
  static constexpr double kMaxOpacity = 64.0;
  static constexpr int kMaxThreads = 1024;

  struct Parameters
  {
    /** \brief Cap of the radius, in rings: the trimmed map. Radii above the components
     * threshold min_radius change nothing, so the natural cap is min_radius (the
     * estimator's "auto", its default). Default kDefaultMinRadius (16), range
     * kMaxRadiusRange. Cost grows with the square of the cap (rings grow). */
    int max_radius = kDefaultMinRadius;
    /** \brief Opacity delta in cell edges: a pair still sees each other while the
     * blocked stretches add up to less than this. 0 (default) = exact visibility;
     * the paper uses 3 for noisy scans. Range kOpacityRange. */
    double opacity = 0.0;
    /** \brief OpenMP threads; 0 (default) = all available (OpenMP's default). The
     * result does not depend on it. Range kThreadsRange. */
    int threads = 0;

    /** \brief [1, 64] rings. */
    static constexpr ParameterRange<int> kMaxRadiusRange{1, kMaxRadius};
    /** \brief [0, 64] cell edges. */
    static constexpr ParameterRange<double> kOpacityRange{0.0, kMaxOpacity};
    /** \brief [0, 1024], 0 = all available. */
    static constexpr ParameterRange<int> kThreadsRange{0, kMaxThreads};
  };

  /** \brief Throws visfeat::Error naming the first parameter out of range, with its
   * value, range and unit. */
  static void validate(const Parameters& parameters);

  /** \brief Compute the map of a band. \throws visfeat::Error on bad parameters. */
  static VisibilityMap compute(const VoxelBand& band,
                               const FreeSpace& free_space,
                               const Parameters& parameters,
                               const ProgressCallback& progress = {});

  /** \brief Bytes compute() allocates for a band with these parameters (radii, tiles,
   * and per thread a window with its BFS marks), for memory checks before it runs. */
  static std::uint64_t estimateBytes(const VoxelBand& band,
                                     const Parameters& parameters);

  /** \brief A map with the given radii instead of computed ones: for small hand-made
   * bands in tests, or radii computed elsewhere. radii[c] is the radius of band cell c
   * (rings), one per cell of the band it is used with; testsPerformed() is 0.
   * \throws visfeat::Error on bad parameters or a radius above max_radius. */
  static VisibilityMap fromRadii(const Parameters& parameters,
                                 std::vector<std::uint8_t> radii);

  const std::vector<std::uint8_t>& radii() const { return radii_; }

  std::uint8_t radius(CellId id) const { return radii_[static_cast<std::size_t>(id)]; }

  const Parameters& parameters() const { return parameters_; }

  /** \brief Pair tests performed (a cost figure for benchmarks). Tests that a known
   * radius made needless are not counted, and which radii are known when depends on
   * the threads' timing: the count may change from run to run with more than one
   * thread; the radii never do. */
  std::uint64_t testsPerformed() const { return tests_; }

private:
  Parameters parameters_;
  std::vector<std::uint8_t> radii_;
  std::uint64_t tests_ = 0;
};

} // namespace visfeat
