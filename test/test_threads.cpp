// visfeat::parallelFor: every index once, in chunks, on any thread count; the first
// exception of a body comes back to the caller.
#include <visfeat/core/common/threads.h>

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <vector>

TEST(ParallelFor, CoversEveryIndexOnceInChunks)
{
  for (int threads : {1, 2, 3, 0})
    for (std::size_t count : {0u, 1u, 7u, 1000u, 1001u})
      for (std::size_t chunk : {1u, 3u, 64u, 5000u}) {
        std::vector<std::atomic<int>> hits(count);
        std::atomic<std::size_t> calls{0};
        visfeat::parallelFor(count, threads, chunk, [&](std::size_t b, std::size_t e) {
          ASSERT_LT(b, e);
          ASSERT_LE(e - b, chunk);
          ASSERT_LE(e, count);
          ++calls;
          for (std::size_t i = b; i < e; ++i)
            ++hits[i];
        });
        for (std::size_t i = 0; i < count; ++i)
          ASSERT_EQ(hits[i].load(), 1) << "index " << i << " of " << count << ", chunk "
                                       << chunk << ", threads " << threads;
        EXPECT_EQ(calls.load(), (count + chunk - 1) / chunk);
      }
}

TEST(ParallelFor, RethrowsTheBodysException)
{
  for (int threads : {1, 2, 4}) {
    EXPECT_THROW(visfeat::parallelFor(100, threads, 10,
                                      [](std::size_t b, std::size_t) {
                                        if (b >= 50)
                                          throw std::runtime_error("chunk failed");
                                      }),
                 std::runtime_error);
  }
  EXPECT_THROW(visfeat::parallelFor(10, 2, 0, [](std::size_t, std::size_t) {}),
               std::invalid_argument);
}

TEST(ResolveThreads, ZeroMeansAllAndIsAtLeastOne)
{
  EXPECT_GE(visfeat::resolveThreads(0), 1);
  EXPECT_EQ(visfeat::resolveThreads(3), 3);
  EXPECT_GE(visfeat::resolveThreads(-2), 1);
}
