// The contact sweeps on SIMD batches against one contact at a time
// (world_settings::batch_contacts), on one thread: a step of N spheres
// without friction (M6), with μ 0.5 (F5) and of N boxes (B5) falling into
// an open box. One iteration is one world::step, after the same warm-up
// either way; the engine computes the same states with batches or without,
// so both time the same sequence of steps. The counter response_ms is the
// step's response phase (impulses and position correction), where the
// sweeps run; integration_ms, pairs_ms and narrow_ms are the step's other
// phases (world::last_step_timings).
//
// Side by side in one run, repetitions interleaved:
//   bench_contact_batches --benchmark_repetitions=5
//     --benchmark_enable_random_interleaving=true --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <cstdint>
#include <functional>
#include <string>

#include "bench_common.hpp"
#include "gaphys/scenes.hpp"

namespace {

struct scene_kind {
  const char* name;
  std::function<gaphys::world(int)> make;
  int warm_up_steps;  // until the bodies have landed and pile up
};

const scene_kind scenes[] = {
    {"spheres", [](int n) { return gaphys::scenes::falling_spheres_in_box(n); }, 240},
    {"spheres_friction",
     [](int n) { return gaphys::scenes::falling_spheres_in_box(n, 1, gaphys::real(0.5)); }, 240},
    {"boxes", [](int n) { return gaphys::scenes::falling_boxes_in_box(n); }, 360},
};

constexpr int timed_steps = 120;

void contact_batches(benchmark::State& state, const scene_kind& kind, bool batches) {
  using gaphys::contact_batching;
  gaphys::world w = kind.make(static_cast<int>(state.range(0)));
  w.set_threads(1);
  w.set_sleeping(false);
  w.set_batch_contacts(batches ? contact_batching::on : contact_batching::off);
  for (int i = 0; i < kind.warm_up_steps; ++i) w.step(gaphys::scenes::time_step);
  gaphys::step_timings total;
  double contacts = 0;
  for (auto _ : state) {
    w.step(gaphys::scenes::time_step);
    const gaphys::step_timings& t = w.last_step_timings();
    total.integration += t.integration;
    total.pairs += t.pairs;
    total.narrow_phase += t.narrow_phase;
    total.response += t.response;
    total.events += t.events;
    contacts += static_cast<double>(w.contacts().size());
  }
  const double steps = static_cast<double>(state.iterations());
  state.counters["integration_ms"] = 1e3 * total.integration / steps;
  state.counters["pairs_ms"] = 1e3 * total.pairs / steps;
  state.counters["narrow_ms"] = 1e3 * total.narrow_phase / steps;
  state.counters["response_ms"] = 1e3 * total.response / steps;
  state.counters["events_ms"] = 1e3 * total.events / steps;
  state.counters["contacts"] = contacts / steps;
}

}  // namespace

int main(int argc, char** argv) {
  return gaphys_bench::run_main(argc, argv, [] {
    for (const scene_kind& kind : scenes) {
      for (const bool batches : {false, true}) {
        const std::string name =
            std::string("contact_batches/") + kind.name + (batches ? "/batched" : "/one_by_one");
        benchmark::RegisterBenchmark(name.c_str(), contact_batches, kind, batches)
            ->Arg(1000)
            ->Iterations(timed_steps)
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
      }
    }
  });
}
