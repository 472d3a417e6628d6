#include <visfeat/core/common/error.h>
#include <visfeat/core/grid/grid_spec.h>
#include <visfeat/core/grid/resolution.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace visfeat {
namespace {

/** \brief "st", "nd", "rd" or "th" for a rank >= 1. */
const char*
ordinalSuffix(int k)
{
  const int tens = k % 100;
  if (tens >= 11 && tens <= 13)
    return "th";
  const int last = k % 10;
  return last == 1 ? "st" : last == 2 ? "nd" : last == 3 ? "rd" : "th";
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

namespace {

/** \brief The median of `values` (the upper one of an even count). */
template <typename T>
T
median(std::vector<T> values)
{
  auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

/** \brief Per query: the distance to the k-th neighbour not coinciding with it (the
 * last one in the row when there are not that many). */
std::vector<double>
apparentDistances(const NeighbourDistanceTable& table, int k, double coincident)
{
  std::vector<double> distances;
  distances.reserve(table.queries());
  for (std::size_t q = 0; q < table.queries(); ++q) {
    std::size_t same = 0;
    while (same < table.per_query && table.at(q, same + 1) <= coincident)
      ++same;
    const std::size_t rank =
      std::min(table.per_query, same + static_cast<std::size_t>(k));
    distances.push_back(table.at(q, rank));
  }
  return distances;
}

} // namespace

ResolutionEstimate
resolutionFromNeighbourTable(const NeighbourDistanceTable& table, int k, double extent)
{
  const std::size_t queries = table.queries();
  if (queries == 0)
    throw Error("the nearest-neighbour search found no neighbours");
  if (k < 1 || static_cast<std::size_t>(k) > table.per_query)
    throw Error("neighbour rank " + std::to_string(k) + " is outside [1, " +
                std::to_string(table.per_query) + "]");
  // 1. the apparent spacing: every point counted, copies included
  const double apparent =
    spacingFromNeighbourDistance(median(apparentDistances(table, k, 1e-9 * extent)), k);
  // 2. copies: points within copy_radius of a queried point, itself included
  const double copy_radius = kCopyRadiusSpacings * apparent;
  const int most = static_cast<int>(
    std::min<std::size_t>(kMaxCopies, table.per_query / static_cast<std::size_t>(k)));
  std::vector<int> counts(queries, 1);
  for (std::size_t q = 0; q < queries; ++q)
    for (std::size_t rank = 1; rank <= table.per_query && counts[q] < most &&
                               table.at(q, rank) <= copy_radius;
         ++rank)
      ++counts[q];
  const int copies = std::max(1, median(counts));
  // 3. the spacing of the sites: the (k copies)-th neighbour
  std::vector<double> distances(queries);
  const std::size_t rank =
    static_cast<std::size_t>(k) * static_cast<std::size_t>(copies);
  for (std::size_t q = 0; q < queries; ++q)
    distances[q] = table.at(q, rank);
  ResolutionEstimate estimate;
  try {
    estimate = resolutionFromNeighbourDistances(std::move(distances), k, extent);
  } catch (const Error&) {
    throw Error("cannot estimate the point spacing: most points have " +
                std::to_string(rank) + " or more copies");
  }
  estimate.copies = copies;
  estimate.copy_radius = copy_radius;
  if (copies > 1) {
    char line[240];
    std::snprintf(line, sizeof(line),
                  "; %d copies of most points (points within %.3g of each other: "
                  "duplicates or overlapping scans), counted as one: the %d%s "
                  "neighbour is the %zu%s point",
                  copies, copy_radius, k, ordinalSuffix(k), rank,
                  ordinalSuffix(static_cast<int>(rank)));
    estimate.reason += line;
  }
  return estimate;
}

} // namespace visfeat
