// How long a cache line takes to go from one of two OpenMP threads to the
// other and back (docs/benchmarks.md, "Threads"). On a shared machine the
// two cores this program runs on can change: sharing a last-level cache,
// a round trip here took 100-200 ns; across caches 450-550 ns, and then the
// engine's step gained nothing from the second thread (every part of it
// reads what the other thread wrote in the part before) while loops that
// share nothing still ran at 0.5x. A threads figure means little without it.
#pragma once

#include <omp.h>

#include <atomic>
#include <limits>
#include <vector>

#include "median.hpp"

namespace gaphys_bench {

// The median of `samples` timings, each of `round_trips` round trips, in
// ns per round trip; NaN when OpenMP gives fewer than two threads.
inline double handoff_round_trip_ns(int samples = 9, int round_trips = 2000) {
  alignas(64) std::atomic<long> turn{0};
  std::vector<double> ns;
  bool two = true;
  for (int s = 0; s < samples && two; ++s) {
    turn.store(0);
    double start = 0, end = 0;
#pragma omp parallel num_threads(2)
    {
      if (omp_get_num_threads() < 2) {
#pragma omp single
        two = false;
      } else {
        const long me = omp_get_thread_num();
#pragma omp barrier
        if (me == 0) start = omp_get_wtime();
        // Thread 0 moves turn from even to odd, thread 1 from odd to even.
        for (long t = me; t < 2L * round_trips; t += 2) {
          while (turn.load(std::memory_order_acquire) != t) {
          }
          turn.store(t + 1, std::memory_order_release);
        }
        if (me == 0) {
          while (turn.load(std::memory_order_acquire) != 2L * round_trips) {
          }
          end = omp_get_wtime();
        }
      }
    }
    if (two) ns.push_back((end - start) * 1e9 / round_trips);
  }
  if (!two) return std::numeric_limits<double>::quiet_NaN();
  return median(ns);
}

}  // namespace gaphys_bench
