// The engine's step time: N spheres falling into a box (the shared scene,
// scenes::falling_spheres_in_box), N = 10 ... 10,000 with the uniform grid
// and N = 10 ... 1000 with all pairs (the thesis's broad phase), on the
// algebra variant this executable is built against. One iteration is one world::step; the
// counters split its wall time into the world's phases (step_timings):
// integration, pairs, narrow phase (the conformal meets) and response.
//
// Every repetition rebuilds the scene and runs the same warm-up and the same
// number of steps, so each variant times exactly the same sequence of states
// (the engine is deterministic) and their medians compare like for like.
// bench/print_table.py --engine prints the table of docs/benchmarks.md from the JSON.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <initializer_list>
#include <string>

#include "bench_common.hpp"
#include "gaphys/scenes.hpp"

namespace {

using gaphys::real;

// Warm-up steps before timing: 0.2 s, so the lowest layer has landed and
// the contacts the response handles are there.
constexpr int warm_up_steps = 48;

// Steps timed per repetition: fewer for larger N (and for all pairs, whose
// step is O(N^2)) keep a reference-variant run to minutes.
std::int64_t timed_steps(int spheres, gaphys::broad_phase_kind broad_phase) {
  if (spheres <= 10) return 480;
  if (broad_phase == gaphys::broad_phase_kind::all_pairs) return spheres <= 100 ? 96 : 4;
  if (spheres <= 100) return 240;
  if (spheres <= 1000) return 96;
  if (spheres <= 3000) return 48;
  return 24;
}

void world_step(benchmark::State& state) {
  const int spheres = static_cast<int>(state.range(0));
  const auto broad_phase = static_cast<gaphys::broad_phase_kind>(state.range(1));
  gaphys::world w = gaphys::scenes::falling_spheres_in_box(spheres);
  w.set_broad_phase(broad_phase);
  for (int i = 0; i < warm_up_steps; ++i) w.step(gaphys::scenes::time_step);

  gaphys::step_timings total;
  double contacts = 0;
  double pairs = 0;
  for (auto _ : state) {
    w.step(gaphys::scenes::time_step);
    const gaphys::step_timings& t = w.last_step_timings();
    total.integration += t.integration;
    total.pairs += t.pairs;
    total.narrow_phase += t.narrow_phase;
    total.response += t.response;
    total.events += t.events;
    contacts += static_cast<double>(w.contacts().size());
    pairs += static_cast<double>(t.candidate_pairs);
  }
  // Milliseconds per step in each phase, and the mean candidate pair and contact counts.
  const double steps = static_cast<double>(state.iterations());
  state.counters["integration_ms"] = 1e3 * total.integration / steps;
  state.counters["pairs_ms"] = 1e3 * total.pairs / steps;
  state.counters["narrow_phase_ms"] = 1e3 * total.narrow_phase / steps;
  state.counters["response_ms"] = 1e3 * total.response / steps;
  state.counters["events_ms"] = 1e3 * total.events / steps;
  state.counters["contacts"] = contacts / steps;
  state.counters["candidate_pairs"] = pairs / steps;
  state.counters["bodies"] = static_cast<double>(w.body_count());
}

void register_sizes(const char* name, gaphys::broad_phase_kind broad_phase,
                    std::initializer_list<int> sizes) {
  for (int spheres : sizes) {
    benchmark::RegisterBenchmark(name, world_step)
        ->Args({spheres, static_cast<std::int64_t>(broad_phase)})
        ->ArgNames({"", "broad_phase"})
        ->Iterations(timed_steps(spheres, broad_phase))
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
  }
}

}  // namespace

int main(int argc, char** argv) {
  return gaphys_bench::run_main(argc, argv, [] {
    register_sizes("world_step/falling_spheres", gaphys::broad_phase_kind::uniform_grid,
                   {10, 100, 1000, 3000, 10000});
    register_sizes("world_step_all_pairs/falling_spheres", gaphys::broad_phase_kind::all_pairs,
                   {10, 100, 1000});
  });
}
