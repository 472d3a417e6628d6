#include <visfeat/core/common/error.h>
#include <visfeat/core/grid/grid_spec.h>
#include <visfeat/core/grid/resolution.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace visfeat {
namespace {

const char*
ordinalSuffix(int k)
{
  return k == 1 ? "st" : k == 2 ? "nd" : k == 3 ? "rd" : "th";
}

} // namespace

double
spacingFromNeighbourDistance(double r, int k)
{
  return r * std::sqrt(3.14159265358979323846 / (k - 1.0 / 3.0));
}

int
resolutionForSpacing(double extent, double spacing)
{
  const double r = std::round(extent / (kSpacingsPerCell * spacing));
  if (!(r >= GridSpec::kMinResolution))
    return GridSpec::kMinResolution;
  if (r > GridSpec::kMaxResolution)
    return GridSpec::kMaxResolution;
  return static_cast<int>(r);
}

ResolutionEstimate
resolutionFromNeighbourDistances(std::vector<double> distances, int k, double extent)
{
  if (distances.empty())
    throw Error("the nearest-neighbour search found no neighbours");
  ResolutionEstimate estimate;
  estimate.k = k;
  estimate.queries = distances.size();
  estimate.extent = extent;
  auto middle = distances.begin() + static_cast<std::ptrdiff_t>(distances.size() / 2);
  std::nth_element(distances.begin(), middle, distances.end());
  const double r = *middle;
  if (!(r > 0.0))
    throw Error("cannot estimate the point spacing: most points have " +
                std::to_string(k) + " or more duplicates");
  estimate.spacing = spacingFromNeighbourDistance(r, k);
  estimate.resolution = resolutionForSpacing(extent, estimate.spacing);
  estimate.unclamped = std::round(extent / (kSpacingsPerCell * estimate.spacing));
  estimate.clamped = estimate.unclamped < GridSpec::kMinResolution ||
                     estimate.unclamped > GridSpec::kMaxResolution;
  char line[320];
  std::snprintf(
    line, sizeof(line),
    "point spacing %.6g (median distance to the %d%s nearest neighbour over "
    "%zu points), %g spacings per cell, extent %.6g",
    estimate.spacing, k, ordinalSuffix(k), estimate.queries, kSpacingsPerCell, extent);
  estimate.reason = line;
  if (estimate.clamped) {
    std::snprintf(line, sizeof(line), " (clamped from %.0f)", estimate.unclamped);
    estimate.reason += line;
  }
  return estimate;
}

} // namespace visfeat
