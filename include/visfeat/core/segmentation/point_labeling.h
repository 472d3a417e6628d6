#pragma once

#include <visfeat/core/band/voxel_band.h>
#include <visfeat/core/common/feature_class.h>
#include <visfeat/core/graph/topology_graph.h>
#include <visfeat/core/segmentation/feature_segmentation.h>

#include <Eigen/Core>

#include <cstdint>
#include <utility>
#include <vector>

namespace visfeat {

/** \brief The region and class of one point. */
struct PointLabel
{
  /** \brief Region label (1-based, as FeatureSegmentation::cellLabels()), 0 = none. */
  std::uint32_t label = 0;
  FeatureClass feature_class = FeatureClass::kNone;
};

/** \brief Per-point assignment: the region and class of a point from those of the
 * cells around it (the last step of VisibilityFeatureEstimation, PCL-free).
 *
 * Cells are coarser than the points, and the cores of obtuse edges are several cells
 * wide, so a point does not simply take its cell's label. With
 * point_feature_distance d > 0 and the segmentation's skeleton (complete regions):
 *  1. Only points whose cell lies within reach() = max(2, ceil(d)) cells (Chebyshev:
 *     the 5x5x5 block of cells around it for d <= 2) of a skeleton cell are examined;
 *     every other point takes its cell's label and class.
 *  2. Each skeleton cell s in that block around the point's cell stands for a
 *     piece of its middle line: the segment through skeletonCentres()[s] along
 *     skeletonTangents()[s], kHalfPiece (1.5) cells each way (a zero tangent makes it
 *     the centre alone). The point's distance to each piece is measured, in cells.
 *  3. If the nearest piece of a vertex's skeleton is within d, the point takes that
 *     vertex (a corner keeps its points even where its edges' line pieces, which reach
 *     into the corner, are as near). Otherwise, if the nearest piece of any skeleton
 *     is within d, the point takes its region and class.
 *  4. Otherwise a point whose cell is an edge or vertex cell goes to the face cell
 *     whose centre is nearest to it among the 3x3x3 block around its cell (26
 *     neighbours and itself); with no face cell there it keeps its cell's label.
 * Ties keep the first cell in z, y, x scan order (dz, dy, dx from -reach to reach).
 * With d = 0 or without a skeleton, every point takes its cell's label and class.
 *
 * The skeleton cells within reach() of each band cell are listed once, at
 * construction (in that scan order), so a point reads its cell's list instead of
 * looking up the (2 reach() + 1)^3 cells around it; the 3x3x3 face search of step 4
 * runs only for the points that reach it.
 *
 * The object keeps references to the band and the segmentation (or the arrays): they
 * must outlive it.
 */
class PointLabeling
{
public:
  /** \brief Half length of the line piece a skeleton cell stands for, in cells: points
   * in a gap of up to 3 cells between skeleton cells (noise thins the ridge) still
   * find the line. */
  static constexpr double kHalfPiece = 1.5;
  /** \brief Least reach of the skeleton search around a point's cell (Chebyshev,
   * cells); reach() is larger for a point_feature_distance above it. */
  static constexpr int kSkeletonReach = 2;
  /** \brief Reach of the face search around a point's cell (Chebyshev, cells). */
  static constexpr int kFaceReach = 1;

  /** \param[in] band the band the segmentation was computed on
   * \param[in] segmentation its regions, skeleton, centres and tangents
   * \param[in] point_feature_distance d above, in cells; 0 = points take their cell's
   *            label (SegmentationParameters::point_feature_distance)
   * \throws visfeat::Error when the segmentation's cell vectors do not match the band
   *         or d is negative or not finite. */
  PointLabeling(const VoxelBand& band,
                const FeatureSegmentation& segmentation,
                double point_feature_distance);

  /** \brief The same from plain arrays (as FeatureSegmentation gives them).
   * \param[in] cell_labels per band cell, its region label (1-based), 0 = none
   * \param[in] region_classes region_classes[label - 1] is the class of a region
   * \param[in] skeleton per band cell, 1 on an edge's or vertex's skeleton; empty =
   *            no skeleton (points take their cell's label)
   * \param[in] skeleton_centres per band cell (skeleton cells only), the middle of the
   *            skeleton around it, in cell units
   * \param[in] skeleton_tangents per band cell (skeleton cells only), the unit
   *            direction of the middle line there, or zero
   * The arrays are referenced, not copied: they must outlive the object.
   * \throws visfeat::Error when sizes do not match the band, a label exceeds the
   *         regions, or d is negative or not finite. */
  PointLabeling(const VoxelBand& band,
                const std::vector<std::uint32_t>& cell_labels,
                std::vector<FeatureClass> region_classes,
                const std::vector<char>& skeleton,
                const std::vector<Eigen::Vector3f>& skeleton_centres,
                const std::vector<Eigen::Vector3f>& skeleton_tangents,
                double point_feature_distance);

  /** \brief The label and class of a point.
   * \param[in] q the point in cell units of the band's grid (GridSpec::toCellUnits)
   * \param[in] cell the band cell holding it (GridSpec::cellOf, VoxelBand::find, or
   *            VoxelBand::pointCell()); kNoCell gives label 0, class none. */
  PointLabel labelOf(const Eigen::Vector3d& q, CellId cell) const;

  /** \brief Reach of the skeleton search: max(kSkeletonReach, ceil(d)) cells. */
  int reach() const { return reach_; }

  /** \brief Per cell, 1 when a skeleton cell lies within reach() cells (empty
   * when point_feature_distance is 0 or there is no skeleton). */
  const std::vector<char>& nearSkeleton() const { return near_skeleton_; }

  /** \brief The skeleton cells within reach() of band cell `cell` (Chebyshev), in
   * z, y, x scan order around it; empty where nearSkeleton() is 0 or empty. */
  std::pair<const CellId*, const CellId*> skeletonAround(CellId cell) const
  {
    if (around_begin_.empty())
      return {nullptr, nullptr};
    const auto c = static_cast<std::size_t>(cell);
    return {around_.data() + around_begin_[c], around_.data() + around_begin_[c + 1]};
  }

private:
  FeatureClass cellClass(CellId cell) const
  {
    const std::uint32_t label = labels_[static_cast<std::size_t>(cell)];
    return label == 0 ? FeatureClass::kNone : classes_[label - 1];
  }

  /** Lists the skeleton cells around every band cell (around_begin_, around_). */
  void listSkeletonAround();

  /** Step 4: the face cell nearest to q among the 3x3x3 block around c; 0 if none. */
  std::uint32_t nearestFace(const Eigen::Vector3d& q, const CellCoord& c) const;

  const VoxelBand& band_;
  int reach_ = kSkeletonReach;
  const std::vector<std::uint32_t>& labels_;
  std::vector<FeatureClass> classes_;
  const std::vector<char>& skeleton_;
  const std::vector<Eigen::Vector3f>& centres_;
  const std::vector<Eigen::Vector3f>& tangents_;
  double distance_;
  std::vector<char> near_skeleton_;
  /** around_[around_begin_[c], around_begin_[c + 1]): skeletonAround(c). */
  std::vector<std::uint32_t> around_begin_;
  std::vector<CellId> around_;
};

/** \brief A vertex region that no point took claims the point nearest to its cells
 * within this many times point_feature_distance (the estimator's last labelling
 * step). With cells finer than the points the estimator sets that distance to one
 * point spacing, and the nearest sample to a corner lies up to about 1.6 spacings away
 * (sparse acceptance: 10,000 points of the icosahedron and the U prism, 5.3-6.3 cells
 * for 4-cell spacings). */
constexpr double kCornerClaimDistances = 2.0;

/** \brief The vertex regions that no point took, for the claim above: a sparse cloud
 * may have no sample within point_feature_distance of a corner, and its vertex would be
 * in the graph but on no point of the labelled cloud.
 * \param[in] cell_labels per band cell, its region label (1-based), 0 = none
 * \param[in] region_classes region_classes[label - 1] is the class of a region
 * \param[in] points_per_label points_per_label[l] = points labelled l (index 0 is
 *            ignored; labels beyond its size count as without points)
 * \return (label, its cells in increasing id) per vertex region with cells and no
 *         point, in label order.
 * \throws visfeat::Error when a cell label exceeds the regions. */
std::vector<std::pair<std::uint32_t, std::vector<CellId>>>
pointlessVertices(const std::vector<std::uint32_t>& cell_labels,
                  const std::vector<FeatureClass>& region_classes,
                  const std::vector<std::uint64_t>& points_per_label);

/** \brief Node geometry of the topology graph from labelled points: per region, the
 * number of its points, their centroid and bounding box (world units). */
class RegionPointGeometry
{
public:
  /** \param[in] regions number of regions (labels 1..regions) */
  explicit RegionPointGeometry(std::size_t regions);

  /** \brief Count point p (world units) for region label; label 0, a label above
   * regions or a non-finite p is ignored. */
  void add(std::uint32_t label, const Eigen::Vector3d& p);

  /** \brief TopologyGraph::setPointGeometry for every region that has points (in label
   * order; points summed in the order they were added). */
  void applyTo(TopologyGraph& graph) const;

private:
  struct Sum
  {
    std::uint64_t n = 0;
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    Eigen::Vector3d min;
    Eigen::Vector3d max;
  };
  std::vector<Sum> sums_;
};

} // namespace visfeat
