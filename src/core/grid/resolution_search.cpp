#include <visfeat/core/grid/resolution_search.h>

#include <algorithm>
#include <cmath>

namespace visfeat {

int
nextSearchResolution(int resolution, int cap)
{
  if (resolution <= 0 || cap <= resolution)
    return 0;
  const int next = std::min(cap, static_cast<int>(std::ceil(resolution * kSearchStep)));
  return next >= kMinSearchStep * resolution ? next : 0;
}

int
searchSteps(int max_resolution)
{
  int steps = kMaxSearchSteps;
  for (double r = kMaxSearchResolution; r < max_resolution; r *= kSearchStep)
    ++steps;
  return steps;
}

} // namespace visfeat
