// What a settled pile costs asleep against awake: M6's N spheres (the
// scenes library's falling_spheres_in_box) dropped into the open box and
// stepped until every sphere sleeps (docs/benchmarks.md, "Sleeping"). Both
// benchmarks then step a copy of that settled pile: one as it is, asleep,
// one with sleeping switched off (every sphere awake again, at rest in the
// same place). One iteration is one step of 1/240 s; the counters give the
// simulated seconds the pile took to fall asleep.
#include <benchmark/benchmark.h>

#include <map>
#include <stdexcept>

#include "gaphys/scenes.hpp"
#include "gaphys/world.hpp"

namespace {

constexpr gaphys::real h = gaphys::scenes::time_step;

bool all_asleep(const gaphys::world& w) {
  for (const gaphys::body& b : w.bodies()) {
    if (b.is_dynamic() && !b.is_sleeping()) return false;
  }
  return true;
}

struct settled_pile {
  gaphys::world world;
  double seconds_to_sleep;
};

// Built once per size, shared by both benchmarks.
const settled_pile& pile(int count) {
  static std::map<int, settled_pile> piles;
  auto found = piles.find(count);
  if (found != piles.end()) return found->second;
  gaphys::world w = gaphys::scenes::falling_spheres_in_box(count, 1);
  int steps = 0;
  while (!all_asleep(w)) {
    w.step(h);
    if (++steps > 60 * 240) throw std::runtime_error("the pile did not fall asleep within 60 s");
  }
  return piles.emplace(count, settled_pile{w, steps * double(h)}).first->second;
}

void step_pile(benchmark::State& state, bool sleeping) {
  const settled_pile& settled = pile(static_cast<int>(state.range(0)));
  gaphys::world w = settled.world;
  w.set_sleeping(sleeping);
  for (auto _ : state) w.step(h);
  state.counters["seconds_to_sleep"] = settled.seconds_to_sleep;
  state.counters["awake"] = all_asleep(w) ? 0 : 1;
}

void settled_pile_asleep(benchmark::State& state) { step_pile(state, true); }
void settled_pile_awake(benchmark::State& state) { step_pile(state, false); }

BENCHMARK(settled_pile_asleep)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond);
BENCHMARK(settled_pile_awake)->Arg(100)->Arg(1000)->Arg(10000)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
