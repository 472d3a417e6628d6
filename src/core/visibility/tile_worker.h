#pragma once

#include <visfeat/core/band/voxel_band.h>
#include <visfeat/core/visibility/band_tiles.h>
#include <visfeat/core/visibility/free_space_window.h>
#include <visfeat/core/visibility/segment_table.h>
#include <visfeat/core/visibility/visibility_map.h>

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

namespace visfeat {
namespace detail {

/** \brief One thread's work on the visibility map, a tile (BandTiles) at a time.
 *
 * For a tile it loads the free-space window around it and a local graph of the mixed
 * cells inside the window (the BFS of a source in the tile never leaves it). The rings
 * of up to 64 sources are grown together, one bit a source in a 64-bit word a cell
 * (a bit-parallel BFS): the sources of a tile are close, so their rings overlap and
 * one sweep over a cell serves them all. Each source then tests the cells of its ring
 * k as in VisibilityMap, and drops out at its first hidden cell.
 *
 * Pairs within a batch: a source s is a ring-k cell of another source t exactly when
 * t is one of s (BFS distance is symmetric), and the test is symmetric too, so the
 * pair is tested once and its result given to both.
 *
 * Known radii: visibility and BFS distance are both symmetric, so a cell a with radius
 * r_a sees every cell of its rings 1..r_a; a target at ring k <= r_a of a source is
 * then visible from it without a test. Radii computed by any thread are used when they
 * are there (relaxed atomic loads of the shared radii, kUnknownRadius otherwise); which
 * ones are there changes the number of tests, never a radius.
 *
 * Cost (2026-12-07, 2 cores, generated icosahedron at 256, 1 thread): the BFS has no
 * branch a neighbour (a missing one is a sentinel id that is always visited; a cell is
 * written to the next ring always, kept when new); a target's table index is two
 * precomputed parts a cell (Place, SegmentTable::rowMiddles) instead of a coordinate
 * difference; the test reads its first check block at a place known from the index
 * alone. Map 1.22-1.30 s -> 1.02-1.10 s, old and new library alternated, the same
 * 51.7 M tests and the same radii.
 */
class TileWorker
{
public:
  /** \brief Radius of a cell not computed yet (radii are at most kMaxRadius). */
  static constexpr std::uint8_t kUnknownRadius = 0xFF;

  /** \brief radii: one per band cell, kUnknownRadius until computed, shared by all
   * workers (read and written with relaxed atomics). */
  TileWorker(const VoxelBand& band,
             const FreeSpace& free_space,
             const BandTiles& tiles,
             const SegmentTable& table,
             const VisibilityMap::Parameters& parameters,
             std::uint8_t* radii);

  /** \brief Radii of the cells of tile t, into the shared radii. */
  void run(std::size_t t);

  /** \brief Pair tests performed so far. */
  std::uint64_t tests() const { return tests_; }

  /** \brief Bytes a worker holds for a window of this many bricks a side, with at most
   * `cells` mixed cells in it. */
  static std::uint64_t estimateBytes(int window_bricks, std::uint64_t cells);

private:
  struct Coord
  {
    std::int16_t x, y, z;
  };
  /** A cell's part of a table offset index (SegmentTable::rowMiddles). */
  struct Place
  {
    std::int32_t row, x;
  };

  void load(std::size_t t);
  void unload();
  /** Radii of sources [first, first + count) of the loaded tile (count <= 64). */
  void runBatch(const CellId* first, int count);
  /** Ring k of the active sources into next_ (returns its count) from ring k - 1. */
  std::size_t growRing(std::uint64_t active);

  const VoxelBand& band_;
  const FreeSpace& free_space_;
  const BandTiles& tiles_;
  const SegmentTable& table_;
  const VisibilityMap::Parameters& parameters_;
  std::uint8_t* radii_;
  FreeSpaceWindow window_;
  std::array<std::int32_t, 6> steps_{};

  // the local graph: window byte -> local id (-1: not mixed), and per local id
  std::vector<std::int32_t> local_of_;
  std::vector<std::int32_t> window_index_;
  std::vector<Coord> coord_; // window-local cells
  std::vector<Place> place_;
  // local ids; no neighbour: the sentinel id n (n local cells), always visited
  std::vector<std::array<std::int32_t, 6>> adjacent_;
  std::vector<std::uint8_t> known_;
  // bit-parallel BFS state, one bit a source of the batch
  std::vector<std::uint64_t> visited_, ring_bits_, next_bits_; // and the sentinel's
  std::vector<std::int32_t> ring_, next_; // n + 1 entries, the first *_count_ used
  std::size_t ring_count_ = 0;
  // the tests of one target: source bit and table offset index
  std::array<std::pair<int, std::size_t>, 64> pending_{};
  // pairs of sources of the batch already tested: slot of a local cell in the batch
  // (-1: not a source), and per source the bits of the sources it sees / does not see
  std::vector<std::int8_t> slot_;
  std::array<std::uint64_t, 64> sees_{}, hidden_{};
  std::uint64_t tests_ = 0;
};

} // namespace detail
} // namespace visfeat
