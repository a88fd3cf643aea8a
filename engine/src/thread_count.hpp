// How many threads a parallel part of a step runs on (docs/engine.md,
// "Threads"). Results never depend on it: each part splits its work so that
// every thread computes what one thread would, in the same order.
#pragma once

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <thread>
#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace gaphys::detail {

// `setting` threads (world_settings::threads; 0: every core), but none that
// would get fewer than `per_thread` items: a thread barely worth waking
// costs more than it saves.
inline int threads_for(int setting, std::size_t items, std::size_t per_thread) {
  const int wanted = setting > 0 ? setting : omp_get_num_procs();
  const std::size_t useful = std::min<std::size_t>(items / per_thread, 1024);
  return std::max(1, std::min(wanted, static_cast<int>(useful)));
}

// Where each thread's part of a loop has got to (visit_parts): one per
// thread, each on its own cache line, zero before the loop.
struct alignas(64) part_progress {
  std::atomic<std::size_t> done{0};
};

// Inside a parallel region of `team` threads: thread `thread`'s share of
// visit(i) for i in [0, count). Each thread owns the t-th of the range and
// takes it front to back in blocks of `block`; done with it, it takes
// blocks from the others' parts where they remain (a core slowed by other
// programs does fewer). Each thread thus finds the same items from step to
// step in its own core's caches, where it left them.
template <class Visit>
void visit_parts(std::size_t team, std::size_t thread, std::size_t count, std::size_t block,
                 part_progress* progress, const Visit& visit) {
  for (std::size_t k = 0; k < team; ++k) {
    const std::size_t part = (thread + k) % team;
    const std::size_t first = count * part / team, end = count * (part + 1) / team;
    for (;;) {
      const std::size_t from =
          first + progress[part].done.fetch_add(block, std::memory_order_relaxed);
      if (from >= end) break;
      const std::size_t upto = std::min(from + block, end);
      for (std::size_t i = from; i < upto; ++i) visit(i);
    }
  }
}

// Calls visit(i) for every i in [0, count) on `threads` threads (> 1),
// each its own part first, in blocks of `block` (visit_parts).
template <class Visit>
void visit_on_threads(int threads, std::size_t count, std::size_t block, const Visit& visit) {
  const std::unique_ptr<part_progress[]> progress(
      new part_progress[static_cast<std::size_t>(threads)]);
#pragma omp parallel num_threads(threads)
  visit_parts(static_cast<std::size_t>(omp_get_num_threads()),
              static_cast<std::size_t>(omp_get_thread_num()), count, block, progress.get(), visit);
}

// Calls visit(i) for every i in [0, count), on threads_for(setting, count,
// per_thread) threads (visit_on_threads, in blocks of a quarter of
// per_thread). For loops whose iterations write nothing another iteration
// reads.
template <class Visit>
void parallel_for(int setting, std::size_t count, std::size_t per_thread, const Visit& visit) {
  const int threads = threads_for(setting, count, per_thread);
  if (threads == 1) {
    for (std::size_t i = 0; i < count; ++i) visit(i);
    return;
  }
  visit_on_threads(threads, count, std::max<std::size_t>(per_thread / 4, 1), visit);
}

// Sets a flag that threads raise as they find something (any contact with
// terms, any turning one): read first, so that once it is up no thread
// writes its cache line again. (Stored by every turning contact of a box
// pile from both threads, the line went back and forth between the cores,
// each store taking it.)
inline void raise_flag(std::atomic<bool>& flag) {
  if (!flag.load(std::memory_order_relaxed)) flag.store(true, std::memory_order_relaxed);
}

// A pause in a loop that waits for another core (on x86, which otherwise
// floods the core's pipeline with loads of the line being waited for).
inline void spin_pause() {
#if defined(__x86_64__) || defined(__i386__)
  _mm_pause();
#endif
}

// Waits until `value` (another thread's count, stored with release) is at
// least `least`: spinning briefly (a few microseconds), as another core's
// count usually comes sooner, then yielding the core, where there are more
// threads than cores and the one to wait for may need this one's core.
// (Spinning 1,024 pauses first, eight threads on two cores stepped 10,000
// spheres in 36-38 ms; 64, in 26, and two threads as fast as before.)
template <class Count>
void wait_until_at_least(const std::atomic<Count>& value, Count least) {
  constexpr int spins_before_yielding = 64;
  for (int spins = 0; value.load(std::memory_order_acquire) < least; ++spins) {
    if (spins < spins_before_yielding) {
      spin_pause();
    } else {
      std::this_thread::yield();
    }
  }
}

}  // namespace gaphys::detail
