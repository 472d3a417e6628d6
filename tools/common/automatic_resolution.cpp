#include "automatic_resolution.h"

#include <visfeat/core/common/error.h>
#include <visfeat/core/grid/grid_spec.h>
#include <visfeat/resolution_estimation.h>

#include <pcl/console/print.h>

namespace visfeat_tools {

bool
checkShapeAndResolution(const std::string& input,
                        const pcl::PointCloud<pcl::PointXYZ>& xyz,
                        bool user_resolution,
                        int& resolution,
                        std::string& error)
{
  using namespace pcl::console;
  const visfeat::CloudShape shape = visfeat::cloudShapeOf(xyz);
  if (!visfeat::hasExtent(shape))
    return true; // the estimator refuses it, saying why (at any resolution)
  // The collinear check needs no resolution: before the (longer) spacing estimate.
  std::string problem = visfeat::shapeProblem(shape, 0);
  if (!problem.empty()) {
    error = "'" + input + "': " + problem;
    return false;
  }
  if (!user_resolution) {
    // The library chooses it from the spacing and the fill (printed after the run).
    resolution = 0;
    return true;
  }
  problem = visfeat::shapeProblem(shape, resolution);
  if (!problem.empty()) {
    const std::string library_advice = "raise the resolution";
    const std::size_t at = problem.rfind(library_advice);
    if (at != std::string::npos)
      problem.replace(at, library_advice.size(), "raise -resolution");
    error = "'" + input + "': " + problem;
    return false;
  }
  return true;
}

} // namespace visfeat_tools
