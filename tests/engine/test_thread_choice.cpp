// The threads a step runs on where world_settings::threads is 0
// (gaphys/detail/thread_choice.hpp): fed the step times of a simulated
// machine, the choice keeps every core where they pay, takes one thread
// where it is faster, follows the machine or the world when they change,
// and probes rarely; and a world that chooses steps to the same bits as
// one on a fixed count.
#include <omp.h>

#include <algorithm>
#include <cstddef>
#include <functional>
#include <random>
#include <set>
#include <vector>

#include "engine_test_support.hpp"
#include "gaphys/detail/thread_choice.hpp"
#include "gaphys/scenes.hpp"

namespace gaphys::testing {
namespace {

constexpr int cores = 8;

// A machine: the seconds step `step` takes on `threads` threads, where the
// data are already on the cores that read them. A step on another count
// than the step before also moves the data: half as long again.
using machine = std::function<double(std::size_t step, int threads)>;

// The counts `choice` gives `steps` steps on `m` (threads setting 0).
std::vector<int> run(detail::thread_choice& choice, const machine& m, std::size_t steps) {
  std::vector<int> counts;
  int last = 0;
  for (std::size_t i = 0; i < steps; ++i) {
    const int threads = choice.next(0, cores);
    const double moved = last != 0 && threads != last ? 1.5 : 1.0;
    choice.record(moved * m(i, threads));
    counts.push_back(threads);
    last = threads;
  }
  return counts;
}

std::size_t count_of(const std::vector<int>& counts, int threads, std::size_t from = 0) {
  std::size_t n = 0;
  for (std::size_t i = from; i < counts.size(); ++i) n += counts[i] == threads;
  return n;
}

// The most steps in a row on `threads` from step `from` on: a probe makes
// two; a count chosen, more.
std::size_t longest_run(const std::vector<int>& counts, int threads, std::size_t from = 0) {
  std::size_t longest = 0, run = 0;
  for (std::size_t i = from; i < counts.size(); ++i) {
    run = counts[i] == threads ? run + 1 : 0;
    longest = std::max(longest, run);
  }
  return longest;
}

TEST(thread_choice_test, a_set_count_or_one_core_is_used_as_it_is) {
  detail::thread_choice choice;
  for (int i = 0; i < 100; ++i) {
    ASSERT_EQ(choice.next(3, cores), 3);
    choice.record(1e-3);
    ASSERT_EQ(choice.next(0, 1), 1);
    choice.record(1e-3);
  }
}

TEST(thread_choice_test, every_core_is_kept_where_it_is_faster_and_probed_rarely) {
  // 10,000 spheres on near cores: 5 ms a step on every core, 9 on one.
  detail::thread_choice choice;
  const machine near = [](std::size_t, int threads) { return threads == 1 ? 9e-3 : 5e-3; };
  const std::vector<int> counts = run(choice, near, 10000);
  // The first probe once eight steps are timed; then 256 steps later, and
  // 1,024 apart.
  EXPECT_EQ(counts[7], cores);
  EXPECT_EQ(counts[8], 1);
  EXPECT_EQ(counts[9], 1);
  EXPECT_EQ(counts[10], cores);
  EXPECT_EQ(longest_run(counts, 1), 2u);
  EXPECT_LE(count_of(counts, 1), 24u);  // under 0.25% of the steps
}

TEST(thread_choice_test, one_thread_is_chosen_where_it_is_faster) {
  // 1,000 spheres on far cores: 1.6 ms a step on every core, 0.8 on one.
  detail::thread_choice choice;
  const machine far = [](std::size_t, int threads) { return threads == 1 ? 0.8e-3 : 1.6e-3; };
  const std::vector<int> counts = run(choice, far, 10000);
  EXPECT_EQ(counts[8], 1);
  EXPECT_EQ(counts[9], 1);
  // From the probe on, every core only in the probes back: two steps at a
  // time, few.
  EXPECT_EQ(longest_run(counts, cores, 10), 2u);
  EXPECT_LE(count_of(counts, cores, 10), 24u);
}

TEST(thread_choice_test, a_count_that_pays_a_little_is_kept) {
  // Every core 0.95 of one thread's time: not worth a change either way.
  detail::thread_choice choice;
  const machine close = [](std::size_t, int threads) { return threads == 1 ? 1e-3 : 0.95e-3; };
  const std::vector<int> counts = run(choice, close, 5000);
  EXPECT_EQ(longest_run(counts, 1), 2u);
  EXPECT_LE(count_of(counts, 1), 2u * 10);  // 2 a probe, 32 x 2, x 4, ..., then 1,024 apart
}

TEST(thread_choice_test, the_count_follows_the_machine_when_it_changes) {
  // Far cores for 3,000 steps (one thread faster), then near ones (every
  // core faster), then far again. A thread's own time does not change, so
  // only the probes can tell: each change is followed within the longest
  // interval between them.
  detail::thread_choice choice;
  const auto phase = [](std::size_t step) { return step < 3000 ? 0 : step < 6000 ? 1 : 2; };
  const machine changing = [&](std::size_t step, int threads) {
    if (threads == 1) return 1e-3;
    return phase(step) == 1 ? 0.55e-3 : 2e-3;
  };
  const std::vector<int> counts = run(choice, changing, 9000);
  const std::size_t bound = detail::thread_choice::longest_interval + 4;
  EXPECT_EQ(counts[2999], 1);
  EXPECT_EQ(counts[3000 + bound], cores);
  EXPECT_EQ(counts[5999], cores);
  EXPECT_EQ(counts[6000 + bound], 1);
  EXPECT_EQ(counts[8999], 1);
}

TEST(thread_choice_test, a_world_that_grows_is_weighed_again_at_once) {
  // An empty world's steps are faster on one thread (0.05 against 0.1 ms);
  // at step 500, 10,000 bodies arrive: 5 ms on every core, 9 on one. The
  // one-thread steps take 180 times as long: eight of them timed, a probe.
  detail::thread_choice choice;
  const machine growing = [](std::size_t step, int threads) {
    if (step < 500) return threads == 1 ? 0.05e-3 : 0.1e-3;
    return threads == 1 ? 9e-3 : 5e-3;
  };
  const std::vector<int> counts = run(choice, growing, 1000);
  EXPECT_EQ(counts[499], 1);
  for (std::size_t i = 520; i < 1000; ++i) {
    ASSERT_TRUE(counts[i] == cores || counts[i] == 1) << i;
  }
  EXPECT_EQ(count_of(counts, cores, 520), 480u - count_of(counts, 1, 520));
  EXPECT_LE(count_of(counts, 1, 520), 4u);
}

TEST(thread_choice_test, noisy_steps_do_not_change_a_count_that_pays) {
  // Every core 5 ms and one thread 6 ms, each step up to 25% off at random:
  // a probe's step must beat nine tenths of the fastest of the last eight.
  detail::thread_choice choice;
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> noise(0.75, 1.25);
  const machine noisy = [&](std::size_t, int threads) {
    return (threads == 1 ? 6e-3 : 5e-3) * noise(random);
  };
  const std::vector<int> counts = run(choice, noisy, 20000);
  EXPECT_EQ(longest_run(counts, 1), 2u);
}

TEST(thread_choice_test, a_world_on_every_core_steps_as_on_one_whatever_it_chooses) {
  // The choice is timing, not state: a world left at threads 0 steps to the
  // bits of one on a single thread, on the counts it chooses (its first
  // probe, on the other count, comes after eight steps).
  world a = scenes::falling_spheres_in_box(400, 3);
  world b = scenes::falling_spheres_in_box(400, 3);
  a.set_sleeping(false), b.set_sleeping(false);
  a.set_threads(0), b.set_threads(1);
  std::set<int> counts;
  for (int i = 0; i < 40; ++i) {
    a.step(scenes::time_step);
    b.step(scenes::time_step);
    ASSERT_EQ(a.state_hash(), b.state_hash()) << "step " << i + 1;
    counts.insert(a.last_step_timings().threads);
    ASSERT_EQ(b.last_step_timings().threads, 1);
  }
  const int every = omp_get_num_procs();
  if (every > 1) {
    EXPECT_EQ(counts, (std::set<int>{1, every}));
  } else {
    EXPECT_EQ(counts, std::set<int>{1});
  }
}

}  // namespace
}  // namespace gaphys::testing
