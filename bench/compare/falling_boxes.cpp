// B5. N boxes (half extents 0.25, 1 kg, μ 0.5, e 0) dropped at random
// attitudes into M6's open box (scenes.hpp, falling_boxes): the cost of a
// step when most bodies touch several others through faces, edges and
// corners. Each engine steps the same scene in the same process; --b5-warmup
// steps let the boxes land (the top layer falls about 4.3 m, 0.95 s), the
// next --b5-steps are timed: the median and 99th percentile of their wall
// times, and the median of their processor times (what the step cost the
// machine, steady when other programs share it). Beside the
// time, what it bought: the deepest overlap at any step (overlap.hpp, from
// the states), the kinetic energy at the end (a pile at rest has none), the
// mean height (that the engines built the same pile) and how many boxes
// ended with their centre outside the container (through a wall or the floor).
#include <algorithm>
#include <iostream>
#include <string>
#include <vector>

#include "budgeted_run.hpp"
#include "mechanics.hpp"
#include "metrics.hpp"
#include "number.hpp"
#include "overlap.hpp"
#include "scenes.hpp"

namespace gaphys_compare {

namespace {

// Bodies whose centre is on the solid side of any plane.
int escaped(const scene& s, const std::vector<body_state>& states) {
  int count = 0;
  for (const body_state& b : states) {
    for (const plane_description& p : s.planes) {
      if (dot(p.normal, b.position) < p.offset) {
        ++count;
        break;
      }
    }
  }
  return count;
}

const char* const quantities[] = {"median ms/step",
                                  "p99 ms/step",
                                  "median CPU ms/step",
                                  "max depth (m)",
                                  "kinetic energy at end (J)",
                                  "mean height at end (m)",
                                  "boxes outside at end"};

}  // namespace

void falling_boxes(const engine& e, const options& o, recorder& out) {
  constexpr double mu = 0.5;
  std::vector<int> sizes = o.b5_sizes;
  std::sort(sizes.begin(), sizes.end());
  std::string skipped;  // why the sizes from here on are not run
  for (const int count : sizes) {
    const scene s = falling_boxes(count, mu);
    const scene_label label{s.name, static_cast<double>(count)};
    if (!skipped.empty()) {
      for (const char* q : quantities) out.add_missing(label, q, skipped);
      continue;
    }
    std::cerr << "  B5 " << e.name << " " << s.name << "\n";
    budgeted_run run(e, s, o);
    double depth = 0;
    for (int i = 0; i < o.b5_warmup + o.b5_steps && run.step(); ++i) {
      depth = std::max(depth, deepest_overlap(s, states_of(run.adapter(), s)));
    }
    if (run.over_budget()) skipped = "skipped (a smaller N was)";
    const std::vector<body_state> end = states_of(run.adapter(), s);
    double height = 0;
    for (const body_state& b : end) height += b.position.z;
    const auto timed = static_cast<std::size_t>(o.b5_warmup);
    run.report(out, label,
               {{quantities[0], run.wall_ms(0.5, timed)},
                {quantities[1], run.wall_ms(0.99, timed)},
                {quantities[2], run.processor_ms(0.5, timed)},
                {quantities[3], depth},
                {quantities[4], total_kinetic_energy(s, end)},
                {quantities[5], height / count},
                {quantities[6], static_cast<double>(escaped(s, end))},
                {"median ms/step, all steps", run.wall_ms(0.5), true}});
  }
}

}  // namespace gaphys_compare
