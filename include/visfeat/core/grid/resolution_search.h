#pragma once

#include <string>

namespace visfeat {

/** \brief The automatic resolution's search goes no finer than this (a resolution set
 * with setResolution() may be finer). 1024 = kTopologyResolution (256) after
 * kMaxSearchSteps doublings. Measured 2026-12-05 on 2 cores, meshes with the default
 * 1,000,000 output points: the public CGAL part, CGAL pinion and ABC 00000050 still
 * show narrow faces at 512 and at 1024 take 20 s, 61 s (1.1 GiB peak) and 15 s, with
 * counts 2/5/6, 73/115/43 and 17/83/39 (truth 2/5/5, 80/122/43, 4/32; at 512: 4/14/9,
 * 46/94/41, 25/66/31). The limit was 512 while the pinion took 1,133 s at 1024. */
constexpr int kMaxSearchResolution = 1024;

/** \brief Whether the search also goes finer for a closed mesh (meshIsClosed()) whose
 * topology graph is not that of a closed part (findGraphGaps()): edges ending at a
 * corner on one side only, or not between two faces, are features closer than about
 * 2 min_radius cells that no narrow face shows. Measured 2026-12-02 on the public
 * V-HACD block (no narrow face at 256; 12 of 34 edges with one corner): per-point F1
 * 0.81 at 256 -> 0.94 at 512, 2.7 s -> 5.9 s. A cloud counts when its band encloses
 * a volume (bandIsClosed(): sampled all around a solid); an open scan does not, as its
 * border leaves such gaps too, and nor does a one-view depth image. */
constexpr bool kSearchOnGraphGaps = true;

/** \brief Finer resolutions the search tries after the first, at most, up to
 * kMaxSearchResolution (searchSteps() for another cap). */
constexpr int kMaxSearchSteps = 2;

/** \brief Each step of the search doubles the resolution. A face's peak does not tell
 * how much finer it must be: the generated stepped block's risers (21 cells at 256)
 * peak at 14 rings, because a concave crease hides little, so 17/14 of 256 (320)
 * looked enough and gave their cores, yet the risers still merged with the treads
 * (6/10/7 for 16/24/10); 384 gave 11/19/10 and 448 and 512 the exact counts. */
constexpr double kSearchStep = 2.0;

/** \brief A step shorter than this factor (where the cap stops a doubling) is not
 * taken: it would change little. */
constexpr double kMinSearchStep = 1.25;

/** \brief Persistence (rings a peak of the visibility map rises above the valley that
 * separates it from a higher peak) of a narrow face (visfeat::narrowFaces()) that the
 * search resolves. Measured: the 7 generated models (10,000 points to dense clouds,
 * 256 cells) have no peak of persistence 3 or more larger than 84 cells; the narrow
 * faces of the public fandisk and CGAL part meshes at 256 have 300-950. */
constexpr int kNarrowFacePersistence = 3;

/** \brief Cells a narrow face needs above its saddle for the search to resolve it, as a
 * multiple of min_radius^2 (a core's patch): see kNarrowFacePersistence. */
constexpr int kNarrowFaceCoreAreas = 1;

/** \brief The next resolution of the search: kSearchStep times `resolution`, at most
 * `cap`; 0 when that leaves less than kMinSearchStep times `resolution`.
 * \param[in] resolution the current resolution, cells along the longest side
 * \param[in] cap the finest resolution allowed (fill, memory, kMaxSearchResolution) */
int nextSearchResolution(int resolution, int cap);

/** \brief Steps the search may take up to a cap of `max_resolution` cells (the
 * estimator's setMaxSearchResolution()): kMaxSearchSteps, plus one for each step of
 * kSearchStep that the cap lies above kMaxSearchResolution (2048: 3). Measured
 * 2026-12-06 on 2 cores, meshes with the default 1,000,000 output points and a cap of
 * 2048 (each from 256): the public CGAL part 2/5/5 (truth 2/5/5) in 53 s, 1.9 GB
 * peak; CGAL pinion 80/122/43 (truth 80/122/43) in 194 s, 4.9 GB; ABC 00000050
 * 19/52/40 in 31 s, 1.1 GB; but the fandisk 30/46/16 (truth 24/34/12) in 67 s and
 * the CGAL joint 14/56/73 (truth 12/22/10; 12/28/23 at 1024) in 163 s, 5.6 GB: its
 * coarse facets become faces. Hence 1024 by default. */
int searchSteps(int max_resolution);

} // namespace visfeat
