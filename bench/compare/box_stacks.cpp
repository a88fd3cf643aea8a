// B3 and B4. Boxes stacked exactly touching, under gravity, with friction
// 0.5: nothing pushes any box sideways, so an exact solver leaves every box
// where it started, and the only vertical motion allowed is the little
// sinking each engine's contacts keep (slop, soft contacts: a fraction of a
// millimetre per contact). What the engines show instead is the drift their
// iterative solvers let build up: a tower of 10 boxes (every contact's load
// passes through the one below) and a pyramid with a base of 10, 55 boxes,
// neighbours in a row 5 mm apart (so only the boxes above and below touch
// each box, each resting on two). The reports give the drift after
// --stack-seconds (10 s), the deepest overlap on the way (overlap.hpp), the
// kinetic energy left and the median wall time of a step.
#include <algorithm>
#include <cmath>
#include <iostream>

#include "budgeted_run.hpp"
#include "mechanics.hpp"
#include "metrics.hpp"
#include "number.hpp"
#include "overlap.hpp"
#include "scenes.hpp"

namespace gaphys_compare {

namespace {

constexpr double mu = 0.5;

// Runs s for --stack-seconds and returns the run; `depth` gets the deepest overlap after any step.
budgeted_run stand(const engine& e, const options& o, const scene& s, double& depth) {
  std::cerr << "  " << e.name << " " << s.name << "\n";
  budgeted_run run(e, s, o);
  const int steps = static_cast<int>(std::lround(o.stack_seconds / time_step));
  depth = 0;
  for (int i = 0; i < steps && run.step(); ++i) {
    depth = std::max(depth, deepest_overlap(s, states_of(run.adapter(), s)));
  }
  return run;
}

}  // namespace

void box_tower(const engine& e, const options& o, recorder& out) {
  const scene s = box_tower(10, mu);
  double depth = 0;
  const budgeted_run run = stand(e, o, s, depth);
  const std::vector<body_state> end = states_of(run.adapter(), s);
  const vec3 top = end.back().position - s.bodies.back().position;
  double widest = 0;  // the largest horizontal drift of any box
  for (std::size_t i = 0; i < end.size(); ++i) {
    widest = std::max(widest, norm(horizontal(end[i].position - s.bodies[i].position)));
  }
  run.report(out, s.name + ", mu 0.5",
             {{"top drift, horizontal (m)", norm(horizontal(top))},
              {"top drift, vertical (m)", top.z},
              {"max depth (m)", depth},
              {"kinetic energy at end (J)", total_kinetic_energy(s, end)},
              {"median ms/step", run.wall_ms(0.5)},
              {"median CPU ms/step", run.processor_ms(0.5), true},
              {"max horizontal drift of any box (m)", widest, true}});
}

void box_pyramid(const engine& e, const options& o, recorder& out) {
  const scene s = box_pyramid(10, 0.005, mu);
  double depth = 0;
  const budgeted_run run = stand(e, o, s, depth);
  const std::vector<body_state> end = states_of(run.adapter(), s);
  double widest = 0;
  for (std::size_t i = 0; i < end.size(); ++i) {
    widest = std::max(widest, norm(end[i].position - s.bodies[i].position));
  }
  const vec3 top = end.back().position - s.bodies.back().position;
  run.report(out, s.name + ", mu 0.5",
             {{"max drift of any box (m)", widest},
              {"max depth (m)", depth},
              {"kinetic energy at end (J)", total_kinetic_energy(s, end)},
              {"median ms/step", run.wall_ms(0.5)},
              {"median CPU ms/step", run.processor_ms(0.5), true},
              {"top drift, horizontal (m)", norm(horizontal(top)), true},
              {"top drift, vertical (m)", top.z, true}});
}

}  // namespace gaphys_compare
