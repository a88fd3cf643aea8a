// M1. Without torque, kinetic energy and world angular momentum are exact
// invariants, so any change is the integrator's error. The body (inertia
// 1:2:3, spun about all three axes) tumbles, so an integrator that drops or
// mistreats the gyroscopic term ω × Iω shows it at once.
#include <algorithm>
#include <cmath>

#include "mechanics.hpp"
#include "metrics.hpp"
#include "number.hpp"
#include "scenes.hpp"

namespace gaphys_compare {

void free_rotation(const engine& e, const options& o, recorder& out) {
  const scene s = spinning_body();
  const body_description& body = s.bodies[0];
  auto adapter = e.make();
  adapter->build(s);

  body_state state = adapter->state(0);
  const double energy = kinetic_energy(body, state);
  const vec3 momentum = angular_momentum(body, state);
  double energy_drift = 0, momentum_drift = 0;
  double norm_error = std::abs(norm(state.attitude) - 1);
  for (int i = 0; i < o.m1_steps; ++i) {
    adapter->step(time_step);
    state = adapter->state(0);
    energy_drift = std::max(energy_drift, std::abs(kinetic_energy(body, state) - energy) / energy);
    momentum_drift =
        std::max(momentum_drift, norm(angular_momentum(body, state) - momentum) / norm(momentum));
    norm_error = std::max(norm_error, std::abs(norm(state.attitude) - 1));
  }
  const std::string scenario = s.name + ", " + number(o.m1_steps) + " steps";
  out.add(scenario, "max |E - E0| / E0", energy_drift);
  out.add(scenario, "max |L - L0| / |L0| (world)", momentum_drift);
  out.add(scenario, "max ||q| - 1|", norm_error);
}

}  // namespace gaphys_compare
