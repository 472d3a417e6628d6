#pragma once

// Scoring feature labels against the ground truth of the generated CAD models: the
// per-point precision / recall / F1 of edge+vertex labels, the best threshold of a
// per-point feature score (for methods that give a score, not labels), and the
// comparison of a topology graph with the model's true vertices, curves and faces.
// PCL-free; the tests and the visfeat_eval tool share it, so they measure alike.

#include <support/cad_models.h>
#include <visfeat/core/graph/topology_graph.h>

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace visfeat {
namespace evaluation {

/** \brief How close to a true sharp curve a point must lie, in cells. */
struct Tolerances
{
  /** Recall counts the points within this distance of a true curve (default 1). */
  double recall_cells = 1.0;
  /** Precision counts a feature point as right within this distance (default 2). */
  double precision_cells = 2.0;
};

/** \brief Per-point counts of a feature labeling and the scores derived from them. */
struct PointScores
{
  /** Points labeled feature (edge or vertex). */
  std::size_t labeled = 0;
  /** Of those, the ones within Tolerances::precision_cells of a true curve. */
  std::size_t labeled_near = 0;
  /** Points within Tolerances::recall_cells of a true curve. */
  std::size_t near = 0;
  /** Of those, the ones labeled feature. */
  std::size_t near_labeled = 0;

  /** labeled_near / labeled; 0 when nothing is labeled. */
  double precision() const;
  /** near_labeled / near; 0 when no point is near a curve. */
  double recall() const;
  /** The harmonic mean of precision and recall; 0 when both are 0. */
  double f1() const;
};

/** \brief Score a per-point feature labeling.
 *
 * Inputs:
 *   is_feature            per point, non-zero when labeled edge or vertex
 *   curve_distance_cells  per point, distance of its true (noise-free) position to
 *                         the nearest true sharp curve, in cells (NaN: never near)
 *   tolerances            recall and precision distances in cells
 * Outputs:
 *   the counts; precision(), recall(), f1().
 * \throws visfeat::Error when the two inputs differ in size. */
PointScores scoreFeaturePoints(const std::vector<std::uint8_t>& is_feature,
                               const std::vector<double>& curve_distance_cells,
                               const Tolerances& tolerances = {});

/** \brief The best threshold of a per-point feature score (feature = score >=
 * threshold) and its scores. */
struct ThresholdSweep
{
  /** The threshold with the highest F1 (the lowest such threshold on ties); NaN when
   * no score is finite. */
  double threshold = 0.0;
  PointScores scores;
  /** How many distinct thresholds were tried. */
  std::size_t candidates = 0;
};

/** \brief Sweep the threshold of a per-point feature score and keep the best F1.
 *
 * Inputs:
 *   score                 per point; higher means more likely on a sharp feature; NaN
 *                         scores are never features
 *   curve_distance_cells  as for scoreFeaturePoints()
 *   quantiles             0: every distinct score value is tried (the exact best);
 *                         Q > 0: the values at the quantiles i/Q, i = 0..Q-1, of the
 *                         finite scores
 *   tolerances            recall and precision distances in cells
 * Outputs:
 *   the best threshold, its counts, the number of thresholds tried. O(n log n).
 * \throws visfeat::Error when the two inputs differ in size. */
ThresholdSweep sweepThreshold(const std::vector<float>& score,
                              const std::vector<double>& curve_distance_cells,
                              std::size_t quantiles = 0,
                              const Tolerances& tolerances = {});

/** \brief A topology graph (regions labeled per point) against a CAD model's truth.
 *
 * Regions are matched to the truth as the pipeline tests always did: an edge region
 * is the true curve nearest to the majority of its edge points; a true vertex is the
 * vertex region holding most of the vertex points within 3 cells of it; a true face
 * is the region holding most of the face-labeled points sampled from it. A region
 * that two true curves, vertices or faces would share matches neither. */
struct TopologyComparison
{
  /** Vertex, edge and face regions of the graph. */
  std::array<std::size_t, 3> found{};
  /** True vertices, curves and faces. */
  std::array<std::size_t, 3> truth{};
  /** True curves with an edge region of their own (no other region claims them). */
  std::size_t curves_matched = 0;
  /** True vertices with a vertex region of their own within 3 cells. */
  std::size_t vertices_matched = 0;
  /** True faces with a face region of their own. */
  std::size_t faces_matched = 0;
  /** True curves whose region links exactly the regions of their two faces and
   * exactly the regions of their end vertices (none for a circle). */
  std::size_t curves_linked = 0;
  /** True vertices whose region links exactly the regions of the faces they lie on. */
  std::size_t vertices_linked = 0;
  /** One line per mismatch, in the order found. */
  std::vector<std::string> problems;

  /** Found counts equal to the truth. */
  bool countsExact() const { return found == truth; }
  /** Every true curve, vertex and face matched and every curve's arcs right. */
  bool arcsCorrect() const;
  /** Exact counts and correct arcs. */
  bool exact() const { return countsExact() && arcsCorrect() && problems.empty(); }
};

/** \brief Compare a labeling and its topology graph with the truth.
 *
 * Inputs:
 *   model          the model as sampled (rotated)
 *   points         the sampled points (as given to the estimator)
 *   point_face     per point, the true face it was sampled from (CadSamples::face)
 *   labels         per point, its region id (the graph's node id; 0 = none)
 *   feature_class  per point, a FeatureClass value
 *   graph          the topology graph of the regions
 *   cell           the cell size (world units): vertex regions within 3 cells
 * Outputs:
 *   the counts, matches and problems.
 * \throws visfeat::Error when the per-point inputs differ in size. */
TopologyComparison compareTopology(const synthetic::CadModel& model,
                                   const std::vector<Eigen::Vector3f>& points,
                                   const std::vector<int>& point_face,
                                   const std::vector<std::uint32_t>& labels,
                                   const std::vector<std::uint8_t>& feature_class,
                                   const TopologyGraph& graph,
                                   double cell);

} // namespace evaluation
} // namespace visfeat
