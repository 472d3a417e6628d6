// Random numbers that are the same on every platform, for the generated test data.
//
// std::mt19937_64 is specified bit for bit by the C++ standard, but the distributions
// (uniform_real_distribution, normal_distribution, uniform_int_distribution) are not:
// libstdc++, libc++ and MSVC give different numbers for the same seed, so a generated
// cloud (and every figure measured on it) would depend on the standard library. These
// distributions are written out here. Their algorithms are those of GCC 12's libstdc++
// (Debian 12), so the clouds generated before they existed are unchanged; the
// portable_random test checks that they agree with std:: there.
#pragma once

#include <cstddef>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

namespace visfeat {
namespace synthetic {

/** \brief The engine of all generated data: 64-bit Mersenne Twister (portable). */
using RandomEngine = std::mt19937_64;

/** \brief A double in [0, 1): the engine's next 64 bits scaled by 2^-64 (rounded to
 * the nearest double; a result of 1 becomes the largest double below 1). As
 * std::generate_canonical<double, 53> with a 64-bit engine in libstdc++. */
double canonical(RandomEngine& engine);

/** \brief Uniform in [a, b): a + (b - a) canonical, as libstdc++'s
 * uniform_real_distribution. */
class UniformReal
{
public:
  explicit UniformReal(double a = 0.0, double b = 1.0)
      : a_(a)
      , b_(b)
  {}

  double operator()(RandomEngine& engine) const
  {
    return canonical(engine) * (b_ - a_) + a_;
  }

private:
  double a_;
  double b_;
};

/** \brief Normal (Gaussian) by Marsaglia's polar method, which makes the numbers in
 * pairs: the second is kept for the next call, so an object must be reused with the
 * same engine (as libstdc++'s normal_distribution). */
class Normal
{
public:
  explicit Normal(double mean = 0.0, double sigma = 1.0)
      : mean_(mean)
      , sigma_(sigma)
  {}

  double operator()(RandomEngine& engine);

private:
  double mean_;
  double sigma_;
  bool saved_available_ = false;
  double saved_ = 0.0;
};

/** \brief Uniform integer in [a, b] (both included) by Lemire's nearly divisionless
 * method on the engine's 64 bits, as GCC 12's uniform_int_distribution. */
class UniformInt
{
public:
  UniformInt(int a, int b);

  int operator()(RandomEngine& engine) const;

private:
  int a_;
  std::uint64_t range_; // b - a + 1
};

/** \brief Fisher-Yates shuffle with UniformInt: the same permutation everywhere (the
 * algorithm of std::shuffle is left to the standard library). */
template <typename T>
void
shuffle(std::vector<T>& items, RandomEngine& engine)
{
  for (std::size_t i = items.size(); i > 1; --i) {
    const auto j =
      static_cast<std::size_t>(UniformInt(0, static_cast<int>(i - 1))(engine));
    std::swap(items[i - 1], items[j]);
  }
}

} // namespace synthetic
} // namespace visfeat
