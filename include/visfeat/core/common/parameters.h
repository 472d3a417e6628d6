#pragma once

#include <visfeat/core/common/error.h>

#include <sstream>
#include <string>

namespace visfeat {

/** \brief Default of ComponentParameters::min_radius (rings), and so of the cap of the
 * visibility map (VisibilityMap::Parameters::max_radius; the trimmed map of DESIGN.md
 * is capped at min_radius: higher caps only cost time).
 *
 * The paper uses 11. Measured on the generated CAD models at resolution 256: at 11,
 * 14-19% of the valley cells 3-5 cells from an icosahedron edge (dihedral 138 degrees)
 * reach the threshold and faces leak into edges; at 16 every face core comes out
 * separate on all 21 model/rotation cases. */
constexpr int kDefaultMinRadius = 16;

/** \brief The closed range [min, max] a parameter may take, with its unit, next to the
 * parameter's struct (e.g. ComponentParameters::kVertexMaxCellsRange), so that tools
 * read the library's limits instead of restating them. */
template <typename T>
struct ParameterRange
{
  T min;
  T max;

  /** \brief min <= value <= max (false for NaN). */
  constexpr bool contains(T value) const { return value >= min && value <= max; }
};

/** \brief The message of a parameter out of range, in one line:
 * "<name> <value> is out of range [<min>, <max>] (<unit>)". */
template <typename T>
std::string
outOfRangeMessage(const std::string& name,
                  T value,
                  const ParameterRange<T>& range,
                  const std::string& unit)
{
  std::ostringstream msg;
  msg << name << " " << value << " is out of range [" << range.min << ", " << range.max
      << "]";
  if (!unit.empty())
    msg << " (" << unit << ")";
  return msg.str();
}

/** \brief Throws visfeat::Error with outOfRangeMessage() unless range contains value.
 */
template <typename T>
void
checkRange(const std::string& name,
           T value,
           const ParameterRange<T>& range,
           const std::string& unit)
{
  if (!range.contains(value))
    throw Error(outOfRangeMessage(name, value, range, unit));
}

} // namespace visfeat
