// What every gaphys benchmark shares: seeded input pools, the loop that calls
// a function over a pool, and the "seconds per 10,000,000 calls" counter that
// puts our figures next to the thesis's table 5.1.
#pragma once

#include <benchmark/benchmark.h>

#include "operands.hpp"

#include <cstddef>
#include <cstdint>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace gaphys_bench {

// The thesis timed 10,000,000 calls of each function (table 5.1).
inline constexpr double thesis_calls = 1e7;

// Index of the pool entry `step` places after i.
inline std::size_t next(std::size_t i, std::size_t step) { return (i + step) % pool_size; }

// Calls f(i) for every pool index i in each iteration and reports CPU
// seconds per 10M calls (counter s_per_10M). DoNotOptimize on every result
// (it also clobbers memory) keeps each call alive and makes the next one
// reload its inputs.
template <class F>
void run_over_pool(benchmark::State& state, F f) {
  for (auto _ : state) {
    for (std::size_t i = 0; i < pool_size; ++i) {
      auto r = f(i);
      benchmark::DoNotOptimize(r);
    }
  }
  const double calls = static_cast<double>(state.iterations()) * static_cast<double>(pool_size);
  state.SetItemsProcessed(static_cast<std::int64_t>(calls));
  // A rate of (calls / 1e7) per CPU second, inverted: CPU seconds per 1e7 calls.
  state.counters["s_per_10M"] = benchmark::Counter(
      calls / thesis_calls, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

template <class F>
void register_benchmark(const std::string& name, F fn) {
  benchmark::RegisterBenchmark(name.c_str(), std::move(fn));
}

// The benchmarks' main: registers them, records the variant (set by CMake as
// GAPHYS_BENCH_VARIANT) in the JSON context, runs what the flags select.
template <class Register>
int run_main(int argc, char** argv, Register register_all) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::AddCustomContext("gaphys_variant", GAPHYS_BENCH_VARIANT);
  register_all();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

}  // namespace gaphys_bench
