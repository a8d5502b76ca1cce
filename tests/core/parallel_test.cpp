// The host pool (parallel.hpp): every item runs once, and a pool made on first use is made once even when
// the first parallel_for calls come from several threads at once (SplitRenderer renders each device's band
// on its own thread: two pools were made and one destroyed under the other's feet, a hang under
// --keep-going).
#include <atomic>
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

}  // namespace
}  // namespace parashade
