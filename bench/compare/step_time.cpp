// M6. Wall time of one step with N spheres falling into a box, after a
// warm-up that lets the lower layers land (so the contacts are there). The
// median is the typical step; the 99th percentile shows the slow ones
// (broad-phase rebuilds, solver spikes). Each engine times its whole step:
// broad phase, narrow phase, solver and integration.
// F5 is the same scene and timing with friction 0.5 on every sphere and
// plane: the friction rows' cost at the same contact count.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "metrics.hpp"
#include "number.hpp"
#include "scenes.hpp"
#include "timing.hpp"

namespace gaphys_compare {

namespace {

// Times the falling-spheres scene at each size with friction mu; `metric`
// only names the progress lines.
void time_steps(const engine& e, const options& o, recorder& out, const std::string& metric,
                std::vector<int> sizes, double mu) {
  constexpr int min_timed_steps = 10;
  bool too_slow = false;
  std::sort(sizes.begin(), sizes.end());
  for (const int count : sizes) {
    const scene s = with_friction(falling_spheres(count), mu);
    const scene_label label{s.name, static_cast<double>(count)};
    if (too_slow) {
      out.add_missing(label, "median ms/step", "skipped (too slow)");
      out.add_missing(label, "p99 ms/step", "skipped (too slow)");
      out.add_missing(label, "mean height at end (m)", "skipped");
      continue;
    }
    std::cerr << "  " << metric << " " << e.name << " " << s.name << "\n";
    auto adapter = e.make();
    adapter->build(s);
    std::vector<double> samples;
    double timed = 0;
    for (int i = 0; i < o.m6_warmup + o.m6_steps && !too_slow; ++i) {
      const double seconds = timed_step(*adapter, time_step);
      too_slow = seconds > o.m6_step_budget;
      if (i < o.m6_warmup) continue;
      samples.push_back(seconds);
      timed += seconds;
      if (timed > o.m6_size_budget && static_cast<int>(samples.size()) >= min_timed_steps) break;
    }
    if (too_slow) {
      const std::string why = "skipped (step > " + number(o.m6_step_budget) + " s)";
      out.add_missing(label, "median ms/step", why);
      out.add_missing(label, "p99 ms/step", why);
      out.add_missing(label, "mean height at end (m)", "skipped");
      continue;
    }
    out.add(label, "median ms/step", 1e3 * percentile(samples, 0.5));
    out.add(label, "p99 ms/step", 1e3 * percentile(samples, 0.99));
    out.add_detail(label, "steps timed", static_cast<double>(samples.size()));
    // Not a speed: a check that the engines simulated the same thing (the
    // spheres fell and stayed in the box), so their times compare.
    double height = 0;
    for (std::size_t i = 0; i < s.bodies.size(); ++i) height += adapter->state(i).position.z;
    out.add(label, "mean height at end (m)", height / static_cast<double>(s.bodies.size()));
  }
}

}  // namespace

void step_time(const engine& e, const options& o, recorder& out) {
  time_steps(e, o, out, "M6", o.m6_sizes, 0);
}

void friction_step_time(const engine& e, const options& o, recorder& out) {
  time_steps(e, o, out, "F5", o.f5_sizes, 0.5);
}

}  // namespace gaphys_compare
