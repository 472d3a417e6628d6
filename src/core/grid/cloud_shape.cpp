#include <visfeat/core/grid/cloud_shape.h>

#include <sstream>

namespace visfeat {

CloudShape
cloudShape(const std::vector<Eigen::Vector3d>& points)
{
  return cloudShape([&points](const auto& visit) {
    for (const Eigen::Vector3d& p : points)
      if (p.allFinite())
        visit(p);
  });
}

bool
hasExtent(const CloudShape& shape)
{
  return shape.finite >= 2 && shape.extent > 0.0;
}

bool
isCollinear(const CloudShape& shape)
{
  return hasExtent(shape) && shape.widths[1] <= kFlatRelativeWidth * shape.widths[0];
}

bool
isCoplanar(const CloudShape& shape)
{
  return hasExtent(shape) && shape.widths[2] <= kFlatRelativeWidth * shape.widths[0];
}

std::string
shapeProblem(const CloudShape& shape, int resolution)
{
  if (!hasExtent(shape))
    return "";
  if (isCollinear(shape))
    return "all " + std::to_string(shape.finite) +
           " finite points lie on a line (collinear): there is no surface to label";
  if (resolution <= 0)
    return "";
  const double cell = shape.extent / resolution;
  if (shape.widths[1] < kMinCellsAcross * cell) {
    std::ostringstream s;
    s << "the points lie within " << shape.widths[1] / cell
      << " cells of a line at resolution " << resolution
      << ": a surface needs at least " << kMinCellsAcross
      << " cells across; raise the resolution";
    return s.str();
  }
  return "";
}

std::string
shapeNote(const CloudShape& shape)
{
  if (!isCoplanar(shape))
    return "";
  return "all points lie in a plane: expect one face and no edges or vertices (the "
         "outline of a flat patch is a boundary, not a crease)";
}

} // namespace visfeat
