// The six metrics of the comparison, each written once against
// engine_adapter and run on every engine with the same scene and step.
#pragma once

#include <functional>
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

struct metric {
  std::string id;     // "m1": the --metrics name
  std::string label;  // "M1"
  std::string title;
  std::function<void(const engine&, const options&, recorder&)> run;
};

const std::vector<metric>& all_metrics();

}  // namespace gaphys_compare
