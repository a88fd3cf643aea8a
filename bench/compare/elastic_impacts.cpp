// M2. Elastic (e = 1) impacts of smooth spheres have a closed form: the
// impulse acts along the line of centres at first touch, conserving momentum
// and, for e = 1, kinetic energy. An engine detects the contact only after
// the spheres overlap, at a slightly different normal, and resolves it with
// its solver; these numbers measure what that costs.
#include <algorithm>
#include <cmath>

#include "mechanics.hpp"
#include "metrics.hpp"
#include "scenes.hpp"

namespace gaphys_compare {

namespace {

// Velocities after the impact of smooth spheres a and b, from the law of
// impact. They first touch at time t when |d + t u| = r_a + r_b, with
// d = x_a - x_b and u = v_a - v_b; the unit normal there is n = (d + t u) /
// (r_a + r_b), and the impulse along it, j = -(1 + e) (u · n) / (1/m_a +
// 1/m_b), changes v_a by j n / m_a and v_b by -j n / m_b.
void law_of_impact(const body_description& a, const body_description& b, double e, vec3& va,
                   vec3& vb) {
  const vec3 d = a.position - b.position, u = a.velocity - b.velocity;
  const double reach = a.radius + b.radius;
  const double uu = dot(u, u), du = dot(d, u);
  const double t = (-du - std::sqrt(du * du - uu * (dot(d, d) - reach * reach))) / uu;
  const vec3 n = (1 / reach) * (d + t * u);
  const double j = -(1 + e) * dot(u, n) / (1 / a.mass + 1 / b.mass);
  va = a.velocity + (j / a.mass) * n;
  vb = b.velocity - (j / b.mass) * n;
}

// Runs s for `steps` and returns the states before and after.
void run(const engine& e, const scene& s, int steps, std::vector<body_state>& before,
         std::vector<body_state>& after) {
  auto adapter = e.make();
  adapter->build(s);
  before = states_of(*adapter, s);
  for (int i = 0; i < steps; ++i) adapter->step(time_step);
  after = states_of(*adapter, s);
}

void conservation(const scene& s, const std::vector<body_state>& before,
                  const std::vector<body_state>& after, recorder& out) {
  const vec3 p0 = total_momentum(s, before);
  out.add(s.name, "|P - P0| / |P0|", norm(total_momentum(s, after) - p0) / norm(p0));
  out.add(s.name, "E after / E before",
          total_kinetic_energy(s, after) / total_kinetic_energy(s, before));
}

}  // namespace

void elastic_impacts(const engine& e, const options&, recorder& out) {
  // 2 s: the spheres meet after 0.75 s and are well apart by the end.
  for (const double offset : {0.0, 0.3}) {
    const scene s = two_spheres(offset);
    std::vector<body_state> before, after;
    run(e, s, 480, before, after);
    conservation(s, before, after, out);
    vec3 va, vb;
    law_of_impact(s.bodies[0], s.bodies[1], 1, va, vb);
    out.add(s.name, "|v1 - v1 closed form| (m/s)", norm(after[0].velocity - va));
    out.add(s.name, "|v2 - v2 closed form| (m/s)", norm(after[1].velocity - vb));
  }

  // The cradle: the striker arrives at 1 s; 4 s leaves time for any chain
  // of follow-up impacts. Ideally (instantaneous impacts passed along the
  // row) the last ball leaves at the striker's 1 m/s and the rest stop.
  const scene s = newtons_cradle();
  std::vector<body_state> before, after;
  run(e, s, 960, before, after);
  conservation(s, before, after, out);
  double deviation = 0;
  for (std::size_t i = 0; i < s.bodies.size(); ++i) {
    const vec3 ideal = i + 1 == s.bodies.size() ? s.bodies[0].velocity : vec3{};
    deviation = std::max(deviation, norm(after[i].velocity - ideal));
    out.add_detail({s.name, static_cast<double>(i + 1)}, "final vx of ball (m/s)",
                   after[i].velocity.x);
  }
  out.add(s.name, "max |v - ideal| (m/s; last ball 1, others 0)", deviation);
}

}  // namespace gaphys_compare
