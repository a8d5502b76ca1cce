// The host pool (parallel.hpp): every item runs once, and a pool made on first use is made once even when
// the first parallel_for calls come from several threads at once (SplitRenderer renders each device's band
// on its own thread: two pools were made and one destroyed under the other's feet, a hang under
// --keep-going).
#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "parashade/parallel.hpp"

namespace parashade {
namespace {

TEST(ParallelFor, FirstCallsFromSeveralThreadsShareOnePool) {
  const unsigned before = host_threads();
  for (int round = 0; round < 200; ++round) {
    set_host_threads(2);  // the next parallel_for makes the pool
    std::atomic<int> items{0};
    std::vector<std::thread> callers;
    for (int c = 0; c < 3; ++c)
      callers.emplace_back([&] { parallel_for(64, [&](std::size_t) { items.fetch_add(1); }); });
    for (auto& t : callers) t.join();
    ASSERT_EQ(items.load(), 3 * 64) << "round " << round;
  }
  set_host_threads(before);
}

// Idle workers spin briefly, then block: jobs that follow each other at once (the spin), after a pause
// longer than the spin (a wake-up) and after parallel_rest() all run every item once, and an exception
// still reaches the caller.
TEST(ParallelFor, BackToBackAfterAPauseAndAfterRest) {
  const unsigned before = host_threads();
  set_host_threads(3);
  for (int round = 0; round < 300; ++round) {
    std::vector<std::atomic<int>> hits(257);
    parallel_for(hits.size(), [&](std::size_t i) { hits[i].fetch_add(1); });
    for (std::size_t i = 0; i < hits.size(); ++i) ASSERT_EQ(hits[i].load(), 1) << "round " << round << " item " << i;
    if (round % 50 == 7) std::this_thread::sleep_for(std::chrono::milliseconds(2));
    if (round % 50 == 21) parallel_rest();
  }
  EXPECT_THROW(parallel_for(100, [](std::size_t i) { if (i == 42) throw std::runtime_error("x"); }), std::runtime_error);
  std::atomic<int> items{0};
  parallel_for(100, [&](std::size_t) { items.fetch_add(1); });
  EXPECT_EQ(items.load(), 100);
  set_host_threads(before);
}

TEST(ParallelFor, BalancedChunkGivesAboutFourRangesPerThread) {
  const unsigned before = host_threads();
  set_host_threads(2);
  EXPECT_EQ(balanced_chunk(80000, 512, 8192), 8000u);  // capped: 10 equal ranges of at most 8192
  EXPECT_EQ(balanced_chunk(16000, 512, 8192), 2000u);  // 8 ranges
  // Every range holds at least min_chunk items: below 2 * min_chunk one range (no wake-up) ...
  EXPECT_EQ(balanced_chunk(1000, 512, 8192), 1000u);
  EXPECT_EQ(balanced_chunk(4225, 4096, 8192), 4225u);
  // ... and fewer than four per thread when the items do not fill them.
  EXPECT_EQ(balanced_chunk(8192, 4096, 8192), 4096u);
  EXPECT_EQ(balanced_chunk(12287, 4096, 8192), 6144u);  // 2 ranges, not 3 with a remainder below 4096
  EXPECT_EQ(balanced_chunk(0, 512, 8192), 512u);
  set_host_threads(before);
}

}  // namespace
}  // namespace parashade
