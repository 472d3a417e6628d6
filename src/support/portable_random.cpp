#include <support/portable_random.h>
#include <visfeat/core/common/error.h>

#include <cmath>
#include <string>

namespace visfeat {
namespace synthetic {

double
canonical(RandomEngine& engine)
{
  // 2^64: the engine's range (max - min + 1).
  constexpr double kRange = 18446744073709551616.0;
  const double u = static_cast<double>(engine()) / kRange;
  return u < 1.0 ? u : std::nextafter(1.0, 0.0);
}

double
Normal::operator()(RandomEngine& engine)
{
  double value;
  if (saved_available_) {
    saved_available_ = false;
    value = saved_;
  } else {
    double x, y, r2;
    do {
      x = 2.0 * canonical(engine) - 1.0;
      y = 2.0 * canonical(engine) - 1.0;
      r2 = x * x + y * y;
    } while (r2 > 1.0 || r2 == 0.0);
    const double multiplier = std::sqrt(-2.0 * std::log(r2) / r2);
    saved_ = x * multiplier;
    saved_available_ = true;
    value = y * multiplier;
  }
  return value * sigma_ + mean_;
}

UniformInt::UniformInt(int a, int b)
    : a_(a)
{
  if (b < a)
    throw Error("UniformInt: empty range [" + std::to_string(a) + ", " +
                std::to_string(b) + "]");
  range_ = static_cast<std::uint64_t>(static_cast<std::int64_t>(b) - a) + 1;
}

namespace {

/** The 128-bit product a * b as its high and low 64 bits (no compiler extension). */
void
multiply(std::uint64_t a, std::uint64_t b, std::uint64_t& high, std::uint64_t& low)
{
  constexpr std::uint64_t kLow32 = 0xffffffffu;
  const std::uint64_t p0 = (a & kLow32) * (b & kLow32);
  const std::uint64_t p1 = (a & kLow32) * (b >> 32);
  const std::uint64_t p2 = (a >> 32) * (b & kLow32);
  const std::uint64_t p3 = (a >> 32) * (b >> 32);
  const std::uint64_t middle = (p0 >> 32) + (p1 & kLow32) + (p2 & kLow32);
  low = (middle << 32) | (p0 & kLow32);
  high = p3 + (p1 >> 32) + (p2 >> 32) + (middle >> 32);
}

} // namespace

int
UniformInt::operator()(RandomEngine& engine) const
{
  // Lemire, "Fast Random Integer Generation in an Interval" (ACM TOMACS 29(1), 2019):
  // the high 64 bits of x * range, rejecting the few low products that would bias it.
  std::uint64_t high, low;
  multiply(engine(), range_, high, low);
  if (low < range_) {
    const std::uint64_t threshold = (0 - range_) % range_;
    while (low < threshold)
      multiply(engine(), range_, high, low);
  }
  return static_cast<int>(static_cast<std::int64_t>(a_) +
                          static_cast<std::int64_t>(high));
}

} // namespace synthetic
} // namespace visfeat
