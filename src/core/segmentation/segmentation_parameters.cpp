#include <visfeat/core/segmentation/feature_segmentation.h>

namespace visfeat {

void
SegmentationParameters::validate(int max_radius) const
{
  components.validate(max_radius);
  checkRange("point_feature_distance", point_feature_distance,
             kPointFeatureDistanceRange, "cells");
  checkRange("vertex_reach", vertex_reach, kVertexReachRange, "cells");
  checkRange("join_distance", join_distance, kJoinDistanceRange, "cells");
  checkRange("feature_width", feature_width, kFeatureWidthRange, "cells");
  checkRange("min_piece_cells", min_piece_cells, kMinPieceCellsRange, "cells");
  checkRange("threads", threads, kThreadsRange, "0 = all available");
}

} // namespace visfeat
