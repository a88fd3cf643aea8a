// How long a cache line takes to go from one of two OpenMP threads to the
// other and back (docs/benchmarks.md, "Threads"). On a shared machine the
// two cores this program runs on can change: sharing a last-level cache,
// a round trip here took 100-200 ns; across caches 450-550 ns, and then the
// engine's step gained nothing from the second thread (every part of it
// reads what the other thread wrote in the part before) while loops that
// share nothing still ran at 0.5x. A threads figure means little without it,
// nor without private_sweep_ratio below: with the shortest round trips seen
// here (57-77 ns) two threads' sweeps of private L2-sized buffers once took
// twice one thread's time, as two hyperthreads of one core sharing its L2
// would, and the step gained nothing either (docs/benchmarks.md).
#pragma once

#include <omp.h>

#include <atomic>
#include <cstddef>
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

// How much longer two threads take, each sweeping a buffer of its own
// that fits one core's L2 cache (`bytes`; 3/4 of this machine's 1 MiB), than
// one thread alone takes for one buffer: the median time of `samples`
// passes of both over the median of as many of one, alternating (a pass is
// `sweeps` sweeps, a read and a write per cache line). About 1 where the
// threads have a core each; towards 2 where they are two hyperthreads of
// one core, sharing its L2 cache (and its units), which the round trip
// does not tell apart from two cores side by side. NaN when OpenMP gives
// fewer than two threads.
inline double private_sweep_ratio(std::size_t bytes = std::size_t{768} << 10, int samples = 9,
                                  int sweeps = 64) {
  const std::size_t count = bytes / sizeof(double);
  std::vector<double> buffers[2] = {std::vector<double>(count, 1.0),
                                    std::vector<double>(count, 1.0)};
  // (The empty asm after each pass stands for a write of all memory the
  // compiler cannot see through: without it GCC folded the passes into one
  // in one of the two places the sweep is called from, and not in the
  // other, and the ratio read 2.0-2.9 where it was 1.0.)
  const auto sweep = [&](std::vector<double>& data) {
    double sum = 0;
    for (int pass = 0; pass < sweeps; ++pass) {
      for (std::size_t i = 0; i < count; i += 64 / sizeof(double)) sum += data[i] += 1;
      asm volatile("" : : : "memory");
    }
    volatile double kept = sum;
    (void)kept;
  };
  std::vector<double> one, both;
  for (int s = 0; s < samples; ++s) {
    const double start = omp_get_wtime();
    sweep(buffers[0]);
    one.push_back(omp_get_wtime() - start);
    bool two = true;
    double took = 0;
#pragma omp parallel num_threads(2)
    {
      if (omp_get_num_threads() < 2) {
        two = false;
      } else {
#pragma omp barrier
        const double from = omp_get_wtime();
        sweep(buffers[omp_get_thread_num()]);
#pragma omp barrier
#pragma omp master
        took = omp_get_wtime() - from;
      }
    }
    if (!two) return std::numeric_limits<double>::quiet_NaN();
    both.push_back(took);
  }
  return median(both) / median(one);
}

}  // namespace gaphys_bench
