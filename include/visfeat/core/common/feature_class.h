#pragma once

#include <cstdint>

namespace visfeat {

/** \brief What a point or a cell is part of; stored in the feature_class field.
 *
 * Lives in its own PCL-free header so that the PCL-free cores (e.g. TopologyGraph)
 * can use it; visfeat/point_types.h includes it. */
enum class FeatureClass : std::uint8_t
{
  kNone = 0,
  kVertex = 1,
  kEdge = 2,
  kFace = 3,
};

} // namespace visfeat
