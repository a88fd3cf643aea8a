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

}  // namespace gaphys::detail
