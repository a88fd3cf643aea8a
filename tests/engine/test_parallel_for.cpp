// The engine's loops on the threads (engine/src/thread_count.hpp): every
// index visited exactly once on any number of threads, blocks that do not
// divide the count, fewer items than threads; and a thread slowed in its
// own part has the rest of it taken by the others.
#include <omp.h>

#include <atomic>
#include <chrono>
#include <cstddef>
#include <thread>
#include <vector>

#include "engine_test_support.hpp"
#include "thread_count.hpp"

namespace gaphys::testing {
namespace {

TEST(parallel_for_test, visits_every_index_once_on_any_number_of_threads) {
  for (const int threads : {1, 2, 3, 8}) {
    for (const std::size_t count : {0, 1, 5, 1000, 50001}) {
      for (const std::size_t per_thread : {1, 7, 4096}) {
        std::vector<std::atomic<int>> visits(count);
        detail::parallel_for(threads, count, per_thread,
                             [&](std::size_t i) { visits[i].fetch_add(1); });
        for (std::size_t i = 0; i < count; ++i) {
          ASSERT_EQ(visits[i].load(), 1) << "index " << i << " of " << count << ", " << threads
                                         << " threads, " << per_thread << " per thread";
        }
      }
    }
  }
}

TEST(parallel_for_test, the_others_take_what_a_slowed_thread_has_left) {
  // Two threads over 1,000 items in blocks of 10: thread 0 owns [0, 500),
  // thread 1 [500, 1000). Thread 1's items wait until thread 0 is in item
  // 0, and item 0 waits (5 s at most) until the items outside its block
  // are visited: thread 1 must do its own part and all of thread 0's but
  // the block thread 0 holds.
  constexpr std::size_t count = 1000, block = 10;
  std::vector<int> visitor(count, -1);
  std::vector<detail::part_progress> progress(2);
  std::atomic<bool> stalled{false};
  std::atomic<std::size_t> visited{0};
  int team = 0;
  const auto wait_for = [](const auto& done) {
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(5);
    while (!done() && std::chrono::steady_clock::now() < give_up) std::this_thread::yield();
  };
#pragma omp parallel num_threads(2)
  {
#pragma omp single
    team = omp_get_num_threads();
    const auto me = static_cast<std::size_t>(omp_get_thread_num());
    detail::visit_parts(static_cast<std::size_t>(omp_get_num_threads()), me, count, block,
                        progress.data(), [&](std::size_t i) {
                          if (i == 0) {
                            stalled = true;
                            wait_for([&] { return visited.load() == count - block; });
                          } else if (i >= count / 2 && team == 2) {
                            wait_for([&] { return stalled.load(); });
                          }
                          visitor[i] = static_cast<int>(me);
                          if (i != 0) ++visited;
                        });
  }
  for (std::size_t i = 0; i < count; ++i) ASSERT_GE(visitor[i], 0) << "index " << i;
  if (team < 2) GTEST_SKIP() << "OpenMP gave one thread";
  for (std::size_t i = 0; i < count; ++i) {
    EXPECT_EQ(visitor[i], i < block ? 0 : 1) << "index " << i;
  }
}

}  // namespace
}  // namespace gaphys::testing
