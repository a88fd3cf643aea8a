#include "mechanics.hpp"

namespace gaphys_compare {

vec3 angular_momentum(const body_description& body, const body_state& state) {
  // I_w ω = R (I (R^T ω)): into the body frame, the principal moments, back.
  const vec3 local = rotate(conjugate(state.attitude), state.angular_velocity);
  const vec3 spun{body.inertia.x * local.x, body.inertia.y * local.y, body.inertia.z * local.z};
  return rotate(state.attitude, spun);
}

double kinetic_energy(const body_description& body, const body_state& state) {
  if (body.is_static) return 0;
  const double linear = body.mass * dot(state.velocity, state.velocity);
  return 0.5 * (linear + dot(state.angular_velocity, angular_momentum(body, state)));
}

vec3 total_momentum(const scene& s, const std::vector<body_state>& states) {
  vec3 p;
  for (std::size_t i = 0; i < s.bodies.size(); ++i) {
    if (!s.bodies[i].is_static) p = p + s.bodies[i].mass * states[i].velocity;
  }
  return p;
}

double total_kinetic_energy(const scene& s, const std::vector<body_state>& states) {
  double energy = 0;
  for (std::size_t i = 0; i < s.bodies.size(); ++i) {
    energy += kinetic_energy(s.bodies[i], states[i]);
  }
  return energy;
}

vec3 contact_slip(const body_description& sphere, const body_state& state,
                  const plane_description& plane) {
  const vec3 n = plane.normal;
  const vec3 u = state.velocity + cross(state.angular_velocity, (-sphere.radius) * n);
  return u - dot(u, n) * n;
}

std::vector<body_state> states_of(const engine_adapter& adapter, const scene& s) {
  std::vector<body_state> states;
  states.reserve(s.bodies.size());
  for (std::size_t i = 0; i < s.bodies.size(); ++i) states.push_back(adapter.state(i));
  return states;
}

}  // namespace gaphys_compare
