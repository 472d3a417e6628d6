#include "../common/angles.h"
#include <visfeat/core/band/organized_triangles.h>
#include <visfeat/core/common/error.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>

namespace visfeat {

namespace {

/** The lower median of v (reordered); NaN when v is empty. */
double
lowerMedian(std::vector<double>& v)
{
  if (v.empty())
    return std::numeric_limits<double>::quiet_NaN();
  const auto middle = v.begin() + static_cast<std::ptrdiff_t>((v.size() - 1) / 2);
  std::nth_element(v.begin(), middle, v.end());
  return *middle;
}

/** The image with its rays and the cut thresholds. */
class PixelGrid
{
public:
  PixelGrid(const std::vector<Eigen::Vector3d>& points,
            int width,
            const Eigen::Vector3d& origin,
            const OrganizedTriangleParameters& parameters)
      : points_(points)
      , width_(static_cast<std::size_t>(width))
      , origin_(origin)
      , range_(points.size(), 0.0)
      , max_ratio_(parameters.max_edge_ratio)
      , min_cos_(detail::cosineOfDegrees(parameters.max_view_angle_degrees))
  {
    // range 0: no return (non-finite, or at the sensor itself)
    for (std::size_t i = 0; i < points.size(); ++i)
      if (points[i].allFinite())
        range_[i] = (points[i] - origin).norm();
    const double h = pitch(1), v = pitch(width_);
    pitch_[0] = 0.0;
    pitch_[1] = h;
    pitch_[2] = v;
    pitch_[3] = std::hypot(h, v);
  }

  bool valid(std::size_t i) const { return range_[i] > 0.0; }

  /** Appends triangle (a, b, c) when its edges and view angle pass, oriented
   * counter-clockwise seen from the sensor. */
  void add(std::uint32_t a,
           std::uint32_t b,
           std::uint32_t c,
           std::vector<TriangleIndices>& out) const
  {
    if (!edgeFits(a, b) || !edgeFits(b, c) || !edgeFits(c, a))
      return;
    const Eigen::Vector3d& pa = points_[a];
    const Eigen::Vector3d normal = (points_[b] - pa).cross(points_[c] - pa);
    const Eigen::Vector3d ray = (pa + points_[b] + points_[c]) / 3.0 - origin_;
    const double scale = normal.norm() * ray.norm();
    const double along = normal.dot(ray);
    if (!(scale > 0.0) || std::abs(along) < min_cos_ * scale)
      return; // degenerate, or seen too obliquely
    if (along > 0.0)
      out.push_back({a, c, b}); // the normal pointed away from the sensor
    else
      out.push_back({a, b, c});
  }

private:
  /** The median ray angle (radians) between the returns i and i + step. */
  double pitch(std::size_t step) const
  {
    std::vector<double> angles;
    angles.reserve(points_.size());
    for (std::size_t i = 0; i + step < points_.size(); ++i) {
      if (step == 1 && (i + 1) % width_ == 0)
        continue; // no right neighbour at the end of a row
      if (!valid(i) || !valid(i + step))
        continue;
      const Eigen::Vector3d a = points_[i] - origin_, b = points_[i + step] - origin_;
      angles.push_back(std::atan2(a.cross(b).norm(), a.dot(b)));
    }
    const double median = lowerMedian(angles);
    return std::isnan(median) ? 0.0 : median;
  }

  /** Whether the edge between neighbouring returns i and j is no depth jump. */
  bool edgeFits(std::uint32_t i, std::uint32_t j) const
  {
    const std::size_t columns = i % width_ != j % width_ ? 1 : 0;
    const std::size_t rows = i / width_ != j / width_ ? 2 : 0;
    const double footprint = std::min(range_[i], range_[j]) * pitch_[columns + rows];
    return (points_[i] - points_[j]).norm() <= max_ratio_ * footprint;
  }

  const std::vector<Eigen::Vector3d>& points_;
  std::size_t width_;
  Eigen::Vector3d origin_;
  std::vector<double> range_;
  double max_ratio_;
  double min_cos_;
  /** Angular pitch (radians) by offset: [none, horizontal, vertical, diagonal]. */
  double pitch_[4] = {0.0, 0.0, 0.0, 0.0};
};

void
checkInput(const std::vector<Eigen::Vector3d>& points,
           int width,
           int height,
           const Eigen::Vector3d& sensor_origin)
{
  std::ostringstream msg;
  if (width < 1 || height < 1)
    msg << "organizedTriangles: the image size " << width << "x" << height
        << " must be at least 1x1";
  else if (points.size() !=
           static_cast<std::size_t>(width) * static_cast<std::size_t>(height))
    msg << "organizedTriangles: " << points.size() << " points for an image of "
        << width << "x" << height << " pixels";
  else if (points.size() > std::numeric_limits<std::uint32_t>::max())
    msg << "organizedTriangles: " << points.size()
        << " points are more than 32-bit indices address";
  else if (!sensor_origin.allFinite())
    msg << "organizedTriangles: the sensor origin must be finite";
  if (!msg.str().empty())
    throw Error(msg.str());
}

} // namespace

void
OrganizedTriangleParameters::validate() const
{
  checkRange("max_edge_ratio", max_edge_ratio, kMaxEdgeRatioRange, "pixel footprints");
  checkRange("max_view_angle_degrees", max_view_angle_degrees, kMaxViewAngleRange,
             "degrees");
}

std::vector<TriangleIndices>
organizedTriangles(const std::vector<Eigen::Vector3d>& points,
                   int width,
                   int height,
                   const Eigen::Vector3d& sensor_origin,
                   const OrganizedTriangleParameters& parameters)
{
  parameters.validate();
  checkInput(points, width, height, sensor_origin);
  const PixelGrid grid(points, width, sensor_origin, parameters);
  const std::uint32_t w = static_cast<std::uint32_t>(width);
  std::vector<TriangleIndices> triangles;
  for (std::uint32_t row = 0; row + 1 < static_cast<std::uint32_t>(height); ++row)
    for (std::uint32_t column = 0; column + 1 < w; ++column) {
      // a b
      // c d
      const std::uint32_t a = row * w + column, b = a + 1, c = a + w, d = c + 1;
      const bool va = grid.valid(a), vb = grid.valid(b), vc = grid.valid(c),
                 vd = grid.valid(d);
      if (va && vb && vc && vd) {
        if ((points[a] - points[d]).squaredNorm() <=
            (points[b] - points[c]).squaredNorm()) {
          grid.add(a, b, d, triangles);
          grid.add(a, d, c, triangles);
        } else {
          grid.add(a, b, c, triangles);
          grid.add(b, d, c, triangles);
        }
      } else if (static_cast<int>(va) + vb + vc + vd == 3) {
        if (!va)
          grid.add(b, d, c, triangles);
        else if (!vb)
          grid.add(a, d, c, triangles);
        else if (!vc)
          grid.add(a, b, d, triangles);
        else
          grid.add(a, b, c, triangles);
      }
    }
  return triangles;
}

} // namespace visfeat
