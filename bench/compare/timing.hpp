// Wall time of engine steps, shared by the speed metrics (M6, F5, B5) and
// the box stacks (B3, B4), which report their step time beside their drift.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <vector>

#include "engine_adapter.hpp"

namespace gaphys_compare {

// One step of h, timed: broad phase, narrow phase, solver and integration,
// whatever the engine does in its step.
inline double timed_step(engine_adapter& adapter, double h) {
  using clock = std::chrono::steady_clock;
  const auto start = clock::now();
  adapter.step(h);
  return std::chrono::duration<double>(clock::now() - start).count();
}

// The processor time (s) the program has used (std::clock: microseconds on
// Linux). On a machine shared with other work it counts what a step cost,
// where wall time also counts waiting for a core; every engine steps in this
// program's one thread.
inline double processor_seconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

// The nearest-rank percentile (p in (0, 1]) of samples; sorts them.
inline double percentile(std::vector<double>& samples, double p) {
  std::sort(samples.begin(), samples.end());
  const auto rank = static_cast<std::size_t>(std::ceil(p * static_cast<double>(samples.size())));
  return samples[std::max<std::size_t>(rank, 1) - 1];
}

}  // namespace gaphys_compare
