#include <visfeat/core/common/error.h>
#include <visfeat/core/grid/grid_spec.h>

#include <cmath>
#include <limits>
#include <sstream>

namespace visfeat {

GridSpec
GridSpec::fromBounds(const Eigen::Vector3d& min,
                     const Eigen::Vector3d& max,
                     int resolution)
{
  if (resolution < kMinResolution || resolution > kMaxResolution) {
    std::ostringstream msg;
    msg << "resolution " << resolution << " is out of range [" << kMinResolution << ", "
        << kMaxResolution << "] (cells along the longest side of the bounding box)";
    throw Error(msg.str());
  }
  if (!min.allFinite() || !max.allFinite() || (max.array() < min.array()).any())
    throw Error("the bounding box of the points is empty or not finite");

  const Eigen::Vector3d size = max - min;
  const double extent = size.maxCoeff();
  if (!(extent > 0.0))
    throw Error("all finite points coincide: the bounding box is a single point, "
                "so there is no extent to divide into cells");

  GridSpec grid;
  grid.cell_size = extent / resolution;
  // Points are floats: a cell must span many representable values, or the cells
  // would depend on rounding rather than on the geometry.
  const double magnitude =
    std::max(min.cwiseAbs().maxCoeff(), max.cwiseAbs().maxCoeff());
  if (grid.cell_size < 64.0 * std::numeric_limits<float>::epsilon() * magnitude) {
    std::ostringstream msg;
    msg << "cell size " << grid.cell_size
        << " is below the float precision of coordinates of "
        << "magnitude " << magnitude
        << ": lower the resolution or move the cloud near the origin";
    throw Error(msg.str());
  }
  grid.origin = min - Eigen::Vector3d::Constant(kPadding * grid.cell_size);
  for (int a = 0; a < 3; ++a) {
    const double cells = std::floor(size[a] / grid.cell_size);
    grid.dims[a] =
      static_cast<int>(std::min(cells, double(resolution))) + 1 + 2 * kPadding;
  }
  return grid;
}

} // namespace visfeat
