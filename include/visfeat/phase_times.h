#pragma once

namespace visfeat {

/** \brief Wall-clock milliseconds of each phase of the last successful compute(). */
struct PhaseTimes
{
  double shape_ms = 0.0;        // shape checks and the automatic resolution
  double grid_ms = 0.0;         // bounding box, grid and memory check
  double smoothing_ms = 0.0;    // noise mode: points onto local planes
  double band_ms = 0.0;         // octree, mixed cells, repair, adjacency
  double free_space_ms = 0.0;   // 2x2x2 subcell mask
  double visibility_ms = 0.0;   // visibility map
  double segmentation_ms = 0.0; // components, regions, vertex/edge/face classes
  double output_ms = 0.0;       // per-point fields
  double graph_ms = 0.0;        // topology graph
  double search_ms = 0.0;       // coarser runs of the resolution search, discarded

  double total() const
  {
    return shape_ms + grid_ms + smoothing_ms + band_ms + free_space_ms + visibility_ms +
           segmentation_ms + output_ms + graph_ms + search_ms;
  }
};

} // namespace visfeat
