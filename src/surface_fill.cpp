#include <visfeat/surface_fill.h>

namespace visfeat {

const char*
surfaceFillName(SurfaceFill fill)
{
  switch (fill) {
  case SurfaceFill::kAuto:
    return "auto";
  case SurfaceFill::kPoints:
    return "points";
  case SurfaceFill::kLocalTriangles:
    return "triangles";
  case SurfaceFill::kMesh:
    return "mesh";
  case SurfaceFill::kOrganized:
    return "grid";
  }
  return "auto";
}

bool
parseSurfaceFill(const std::string& name, SurfaceFill& fill)
{
  for (const SurfaceFill f :
       {SurfaceFill::kAuto, SurfaceFill::kPoints, SurfaceFill::kLocalTriangles,
        SurfaceFill::kMesh, SurfaceFill::kOrganized})
    if (name == surfaceFillName(f)) {
      fill = f;
      return true;
    }
  return false;
}

} // namespace visfeat

#ifndef PCL_NO_PRECOMPILE
#include <visfeat/impl/surface_fill.hpp>

#include <pcl/impl/instantiate.hpp>
#include <pcl/point_types.h>

PCL_INSTANTIATE(VisfeatSurfaceFill, PCL_XYZ_POINT_TYPES)
#endif
