#pragma once

// Internal to the core (not installed): angles given in degrees, as the parameters
// take them, turned into the cosines the tests compare.

#include <cmath>

namespace visfeat {
namespace detail {

inline constexpr double kPi = 3.14159265358979323846;

/** \brief cos(degrees), the angle in degrees. */
inline double
cosineOfDegrees(double degrees)
{
  return std::cos(degrees * kPi / 180.0);
}

} // namespace detail
} // namespace visfeat
