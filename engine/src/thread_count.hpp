// How many threads a parallel part of a step runs on (docs/engine.md,
// "Threads"). Results never depend on it: each part splits its work so that
// every thread computes what one thread would, in the same order.
#pragma once

#include <algorithm>
#include <cstddef>

#include <omp.h>

namespace gaphys::detail {

// `setting` threads (world_settings::threads; 0: every core), but none that
// would get fewer than `per_thread` items: a thread barely worth waking
// costs more than it saves.
inline int threads_for(int setting, std::size_t items, std::size_t per_thread) {
  const int wanted = setting > 0 ? setting : omp_get_num_procs();
  const std::size_t useful = std::min<std::size_t>(items / per_thread, 1024);
  return std::max(1, std::min(wanted, static_cast<int>(useful)));
}

// Calls visit(i) for every i in [0, count), on threads_for(setting, count,
// per_thread) threads, each taking contiguous blocks of a quarter of
// per_thread as it finishes the last (a core slowed by other programs
// takes fewer). For loops whose iterations write nothing another iteration
// reads.
template <class Visit>
void parallel_for(int setting, std::size_t count, std::size_t per_thread, const Visit& visit) {
  const int threads = threads_for(setting, count, per_thread);
  if (threads == 1) {
    for (std::size_t i = 0; i < count; ++i) visit(i);
    return;
  }
  const auto end = static_cast<std::ptrdiff_t>(count);
  const int block = static_cast<int>(std::max<std::size_t>(per_thread / 4, 1));
#pragma omp parallel for num_threads(threads) schedule(dynamic, block)
  for (std::ptrdiff_t i = 0; i < end; ++i) visit(static_cast<std::size_t>(i));
}

}  // namespace gaphys::detail
