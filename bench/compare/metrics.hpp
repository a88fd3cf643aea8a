// The metrics of the comparison, each written once against engine_adapter
// and run on every engine with the same scene and step: M1-M6 frictionless,
// F1-F5 with Coulomb friction, B1-B5 boxes (with friction).
#pragma once

#include <string>
#include <vector>

#include "engine_adapter.hpp"
#include "gaphys/scenes.hpp"
#include "options.hpp"
#include "result.hpp"

namespace gaphys_compare {

// Every engine steps at gaphys's scene step, 1/240 s.
inline constexpr double time_step = gaphys::scenes::time_step;

// M1: a torque-free asymmetric body: drift of kinetic energy, angular
// momentum and attitude norm.
void free_rotation(const engine& e, const options& o, recorder& out);
// M2: elastic impacts: momentum, energy and the law of impact.
void elastic_impacts(const engine& e, const options& o, recorder& out);
// M3: rebound apex against e^2, and its drift over 20 elastic bounces.
void restitution(const engine& e, const options& o, recorder& out);
// M4: resting columns: penetration and residual energy.
void resting_columns(const engine& e, const options& o, recorder& out);
// M5: the lowest speed at which a sphere passes through its target.
void tunnelling(const engine& e, const options& o, recorder& out);
// M6: wall time per step of N spheres falling into a box.
void step_time(const engine& e, const options& o, recorder& out);
// F1: a ball launched sliding: the change to rolling at 5/7 v0.
void sliding_to_rolling(const engine& e, const options& o, recorder& out);
// F2: a ball with backspin: final velocity (5 v0 - 2 r w0) / 7.
void backspin(const engine& e, const options& o, recorder& out);
// F3: a ball on a 30 degree slope, rolling or sliding: distance in 2 s.
void incline(const engine& e, const options& o, recorder& out);
// F4: deceleration and heading of a sliding ball at 0, 30 and 45 degrees.
void friction_isotropy(const engine& e, const options& o, recorder& out);
// F5: M6's wall time per step with friction 0.5 on every shape.
void friction_step_time(const engine& e, const options& o, recorder& out);
// B1: a unit box on a 20 degree slope: held (mu 0.5) or sliding (mu 0.2).
void box_incline(const engine& e, const options& o, recorder& out);
// B2: a unit box sliding to a stop, along a face normal and at 45 degrees.
void sliding_box(const engine& e, const options& o, recorder& out);
// B3: a tower of 10 unit boxes: drift over --stack-seconds.
void box_tower(const engine& e, const options& o, recorder& out);
// B4: a pyramid of 55 unit boxes: drift over --stack-seconds.
void box_pyramid(const engine& e, const options& o, recorder& out);
// B5: N boxes falling into M6's box: wall time per step, depth, energy.
void falling_boxes(const engine& e, const options& o, recorder& out);

struct metric {
  std::string id;     // "m1": the --metrics name
  std::string label;  // "M1"
  std::string title;
  // (A function pointer: a metric and its scene may share a name, scenes.hpp.)
  void (*run)(const engine&, const options&, recorder&);
};

const std::vector<metric>& all_metrics();

}  // namespace gaphys_compare
