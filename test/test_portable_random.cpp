// The generator's random numbers (support/portable_random.h): the same algorithms as
// GCC 12's libstdc++, so the data generated before they existed is unchanged, and
// well-behaved where the standard library is another one.

#include <support/portable_random.h>
#include <visfeat/core/common/error.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <vector>

namespace syn = visfeat::synthetic;

namespace {

// libstdc++'s distributions since GCC 11 (uniform_int_distribution changed to Lemire's
// method there); elsewhere only the properties below are checked.
#if defined(__GLIBCXX__) && defined(_GLIBCXX_RELEASE) && _GLIBCXX_RELEASE >= 11
constexpr bool kSameAsThisStandardLibrary = true;
#else
constexpr bool kSameAsThisStandardLibrary = false;
#endif

TEST(PortableRandom, MatchesLibstdcxx)
{
  if (!kSameAsThisStandardLibrary)
    GTEST_SKIP() << "not libstdc++ >= 11: nothing to compare with";
  for (const std::uint64_t seed : {1ull, 2ull, 77ull, 0x9E3779B97F4A7C15ull}) {
    syn::RandomEngine a(seed), b(seed);
    std::uniform_real_distribution<double> std_unit(0.0, 1.0), std_range(-0.5, 2.5);
    std::normal_distribution<double> std_normal(0.0, 1.0), std_scaled(3.0, 0.25);
    std::uniform_int_distribution<int> std_int(0, 5), std_wide(-7, 1000000);
    const syn::UniformReal unit(0.0, 1.0), range(-0.5, 2.5);
    syn::Normal normal(0.0, 1.0), scaled(3.0, 0.25);
    const syn::UniformInt small(0, 5), wide(-7, 1000000);
    for (int i = 0; i < 2000; ++i) {
      ASSERT_EQ(unit(a), std_unit(b)) << "seed " << seed << ", draw " << i;
      ASSERT_EQ(range(a), std_range(b));
      ASSERT_EQ(normal(a), std_normal(b));
      ASSERT_EQ(scaled(a), std_scaled(b));
      ASSERT_EQ(small(a), std_int(b));
      ASSERT_EQ(wide(a), std_wide(b));
    }
    ASSERT_EQ(a(), b()) << "the engines drew the same numbers of values";
  }
}

TEST(PortableRandom, Ranges)
{
  syn::RandomEngine engine(5);
  const syn::UniformReal range(-2.0, 3.0);
  const syn::UniformInt dice(1, 6);
  std::vector<int> seen(7, 0);
  for (int i = 0; i < 60000; ++i) {
    const double u = syn::canonical(engine);
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    const double x = range(engine);
    ASSERT_GE(x, -2.0);
    ASSERT_LT(x, 3.0);
    const int d = dice(engine);
    ASSERT_GE(d, 1);
    ASSERT_LE(d, 6);
    ++seen[static_cast<std::size_t>(d)];
  }
  for (int d = 1; d <= 6; ++d) // 10,000 expected each; 5 standard deviations
    EXPECT_NEAR(seen[static_cast<std::size_t>(d)], 10000, 500) << "face " << d;
  EXPECT_EQ(syn::UniformInt(4, 4)(engine), 4);
  EXPECT_THROW(syn::UniformInt(3, 2), visfeat::Error);
}

TEST(PortableRandom, NormalMoments)
{
  syn::RandomEngine engine(11);
  syn::Normal normal(2.0, 0.5);
  const int n = 100000;
  double sum = 0.0, sum2 = 0.0;
  for (int i = 0; i < n; ++i) {
    const double x = normal(engine);
    sum += x;
    sum2 += x * x;
  }
  const double mean = sum / n;
  const double sd = std::sqrt(sum2 / n - mean * mean);
  EXPECT_NEAR(mean, 2.0, 0.01); // 0.5 / sqrt(n) = 0.0016
  EXPECT_NEAR(sd, 0.5, 0.01);
}

TEST(PortableRandom, ShuffleIsAReproduciblePermutation)
{
  std::vector<int> items(50);
  std::iota(items.begin(), items.end(), 0);
  std::vector<int> a = items, b = items;
  syn::RandomEngine ea(3), eb(3);
  syn::shuffle(a, ea);
  syn::shuffle(b, eb);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, items);
  std::vector<int> sorted = a;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(sorted, items);
  std::vector<int> empty;
  syn::shuffle(empty, ea);
  EXPECT_TRUE(empty.empty());
}

} // namespace
