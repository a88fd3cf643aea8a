// The engine's stable counting sort on the threads (engine/src/counting_sort.hpp)
// against std::stable_sort: the same order and the same key starts on any
// number of threads, with empty keys, keys holding most items, and fewer
// items than a thread's share.
#include <algorithm>
#include <cstddef>
#include <numeric>
#include <random>
#include <vector>

#include "counting_sort.hpp"
#include "engine_test_support.hpp"

namespace gaphys::testing {
namespace {

struct sorted {
  std::vector<std::size_t> order;   // the item at each place
  std::vector<std::size_t> starts;  // where each key's items begin
};

sorted by_counting_sort(const std::vector<std::size_t>& keys, std::size_t key_count, int threads,
                        std::size_t per_thread) {
  sorted out;
  out.order.assign(keys.size(), keys.size());
  std::vector<std::size_t> scratch;
  detail::counting_sort(
      threads, per_thread, keys.size(), key_count, [&](std::size_t i) { return keys[i]; },
      out.starts, scratch, [&](std::size_t i, std::size_t at) { out.order[at] = i; });
  return out;
}

sorted by_stable_sort(const std::vector<std::size_t>& keys, std::size_t key_count) {
  sorted out;
  out.order.resize(keys.size());
  std::iota(out.order.begin(), out.order.end(), std::size_t{0});
  std::stable_sort(out.order.begin(), out.order.end(),
                   [&](std::size_t a, std::size_t b) { return keys[a] < keys[b]; });
  out.starts.assign(key_count + 1, 0);
  for (std::size_t k = 0; k <= key_count; ++k) {
    out.starts[k] = static_cast<std::size_t>(
        std::lower_bound(out.order.begin(), out.order.end(), k,
                         [&](std::size_t item, std::size_t key) { return keys[item] < key; }) -
        out.order.begin());
  }
  return out;
}

TEST(counting_sort_test, orders_as_a_stable_sort_on_any_number_of_threads) {
  std::mt19937 random(7);
  for (const std::size_t count : {0, 1, 5, 1000, 50000}) {
    for (const std::size_t key_count : {1, 3, 100, 40000}) {
      // Half the items on a few keys, the rest anywhere (most keys empty
      // where there are more keys than items).
      std::vector<std::size_t> keys(count);
      for (std::size_t& k : keys) {
        k = random() % 2 == 0 ? random() % std::min<std::size_t>(key_count, 3)
                              : random() % key_count;
      }
      const sorted expected = by_stable_sort(keys, key_count);
      for (const int threads : {1, 2, 3, 8}) {
        for (const std::size_t per_thread : {std::size_t{1}, std::size_t{4096}}) {
          const sorted got = by_counting_sort(keys, key_count, threads, per_thread);
          EXPECT_EQ(got.order, expected.order)
              << count << " items, " << key_count << " keys, " << threads << " threads";
          EXPECT_EQ(got.starts, expected.starts)
              << count << " items, " << key_count << " keys, " << threads << " threads";
        }
        // Inside an outer parallel region, where a nested region gets one
        // thread whatever it asks for.
        sorted nested;
#pragma omp parallel num_threads(2)
#pragma omp single
        nested = by_counting_sort(keys, key_count, threads, 1);
        EXPECT_EQ(nested.order, expected.order) << count << " items, nested";
        EXPECT_EQ(nested.starts, expected.starts) << count << " items, nested";
      }
    }
  }
}

// The engine keeps the starts and the scratch between steps: whatever they
// hold from a sort of other sizes (or garbage), the next sort is right.
TEST(counting_sort_test, leftovers_in_the_starts_and_scratch_change_nothing) {
  std::mt19937 random(11);
  std::vector<std::size_t> starts(90000, 12345), scratch(200000, 54321);
  for (const int threads : {2, 3, 1, 8}) {
    for (const std::size_t count : {50000, 1000, 20000}) {
      for (const std::size_t key_count : {40000, 7, 3000}) {
        std::vector<std::size_t> keys(count);
        for (std::size_t& k : keys) k = random() % key_count;
        const sorted expected = by_stable_sort(keys, key_count);
        sorted got;
        got.order.assign(count, count);
        detail::counting_sort(
            threads, 1, count, key_count, [&](std::size_t i) { return keys[i]; }, starts, scratch,
            [&](std::size_t i, std::size_t at) { got.order[at] = i; });
        EXPECT_EQ(got.order, expected.order) << count << " items, " << key_count << " keys";
        EXPECT_EQ(starts, expected.starts) << count << " items, " << key_count << " keys";
        std::fill(scratch.begin(), scratch.end(), 54321);
      }
    }
  }
}

}  // namespace
}  // namespace gaphys::testing
