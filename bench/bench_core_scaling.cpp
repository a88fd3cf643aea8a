// The machine's own ceiling for two threads (docs/benchmarks.md, "Threads"):
// what a loop with no serial part and nothing shared gains from a second
// core here, to read bench_threads' ratios against.
//
// Three kernels, each a fixed amount of work split evenly over the threads
// of one OpenMP region: `latency`, one chain of dependent multiply-adds per
// share (bound by the floating-point latency); `throughput`, eight
// independent chains (bound by the floating-point units, as the engine's
// kernels are more nearly); `stream`, a sum over 64 MiB (bound by memory).
// Like bench_threads, each alternates one and two threads (1, 2, 2, 1, ...)
// so that both see the shared machine's good and bad moments.
//
// Counters: the median ms per pass on one thread and on two, and their
// ratio (2 / 1; 0.5 is a perfect second core). These loops share nothing,
// so they cannot tell whether the two cores share a cache; `handoff` does
// (core_handoff.hpp): the median round trip of a cache line between the
// two threads, in ns. `private_sweep`: how much longer two threads take
// each to sweep a buffer of its own that fits one core's L2 cache than one
// thread alone (core_handoff.hpp): near 1 where the threads have a core
// each, up to 2 where they are two hyperthreads of one core.
#include <benchmark/benchmark.h>
#include <omp.h>

#include <chrono>
#include <cstddef>
#include <utility>
#include <vector>

#include "core_handoff.hpp"
#include "median.hpp"

namespace {

constexpr int shares = 8;      // per pass, split over the threads
constexpr long steps = 2000000;  // per share, for the chains

double latency_share(long n, double seed) {
  double a = seed, c = 0.5;
  for (long i = 0; i < n; ++i) {
    a = a * 1.0000001 + c;
    c = c * 0.9999999 + 1e-9;
  }
  return a + c;
}

double throughput_share(long n, double seed) {
  double a[8];
  for (int k = 0; k < 8; ++k) a[k] = seed + k;
  for (long i = 0; i < n; ++i) {
    for (double& x : a) x = x * 1.0000001 + 1e-9;
  }
  double sum = 0;
  for (const double x : a) sum += x;
  return sum;
}

template <class Pass>
void alternate(benchmark::State& state, const Pass& pass) {
  std::vector<double> one, two;
  for (auto _ : state) {
    for (int round = 0; round < 24; ++round) {
      const bool on_one = (round % 4 == 0) || (round % 4 == 3);
      const auto start = std::chrono::steady_clock::now();
      benchmark::DoNotOptimize(pass(on_one ? 1 : 2));
      const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
      (on_one ? one : two).push_back(took.count());
    }
  }
  const double one_ms = 1e3 * gaphys_bench::median(one), two_ms = 1e3 * gaphys_bench::median(two);
  state.counters["one_thread_ms"] = one_ms;
  state.counters["threads_ms"] = two_ms;
  state.counters["ratio"] = two_ms / one_ms;
}

template <class Share>
double chains(int threads, const Share& share) {
  double sum = 0;
#pragma omp parallel for num_threads(threads) schedule(static) reduction(+ : sum)
  for (int s = 0; s < shares; ++s) sum += share(steps, s);
  return sum;
}

void latency(benchmark::State& state) {
  alternate(state, [](int threads) { return chains(threads, latency_share); });
}

void throughput(benchmark::State& state) {
  alternate(state, [](int threads) { return chains(threads, throughput_share); });
}

void stream(benchmark::State& state) {
  const std::vector<double> data(std::size_t{8} << 20, 1.0);  // 64 MiB
  alternate(state, [&](int threads) {
    const auto count = static_cast<std::ptrdiff_t>(data.size());
    double sum = 0;
#pragma omp parallel for num_threads(threads) schedule(static) reduction(+ : sum)
    for (std::ptrdiff_t i = 0; i < count; ++i) sum += data[static_cast<std::size_t>(i)];
    return sum;
  });
}

void handoff(benchmark::State& state) {
  double ns = 0;
  for (auto _ : state) ns = gaphys_bench::handoff_round_trip_ns(25);
  state.counters["round_trip_ns"] = ns;
}

void private_sweep(benchmark::State& state) {
  double ratio = 0;
  for (auto _ : state) ratio = gaphys_bench::private_sweep_ratio(std::size_t{768} << 10, 25);
  state.counters["ratio"] = ratio;
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  for (const auto& [name, run] :
       {std::pair{"cores/latency", &latency}, std::pair{"cores/throughput", &throughput},
        std::pair{"cores/stream", &stream}, std::pair{"cores/handoff", &handoff},
        std::pair{"cores/private_sweep", &private_sweep}}) {
    benchmark::RegisterBenchmark(name, run)
        ->Iterations(1)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
