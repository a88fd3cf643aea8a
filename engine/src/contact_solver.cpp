#include "contact_solver.hpp"

#include <algorithm>
#include <utility>

namespace gaphys {

namespace {

// The normal speed n . (v_A(p) - v_B(p)): < 0 while the contact approaches.
real normal_speed(const body& a, const body& b, const contact& c) {
  const vector& p = c.geometry.point;
  return e3ga::scp(a.velocity_at(p) - b.velocity_at(p), c.geometry.normal);
}

// n . (r ⌋ I⁻¹(r ∧ n)): how much a unit impulse along n at offset r changes the
// normal speed of that point through the body's rotation.
real angular_term(const body& x, const vector& r, const vector& n) {
  return e3ga::scp(n, e3ga::lc(r, x.world_inverse_inertia(e3ga::op(r, n))));
}

}  // namespace

void contact_solver::apply_impulse(body& a, body& b, const vector& normal, const constraint& k,
                                   real j) {
  const vector impulse = j * normal;
  a.velocity_ = a.velocity_ + a.inverse_mass_ * impulse;
  a.angular_velocity_ = a.angular_velocity_ + a.world_inverse_inertia(e3ga::op(k.offset_a, impulse));
  b.velocity_ = b.velocity_ - b.inverse_mass_ * impulse;
  b.angular_velocity_ = b.angular_velocity_ - b.world_inverse_inertia(e3ga::op(k.offset_b, impulse));
}

void contact_solver::solve_velocities(std::vector<body>& bodies, std::vector<contact>& contacts,
                                      const std::vector<contact>& previous) {
  constraints_.clear();
  for (const contact& c : contacts) {
    const body& a = bodies[c.body_a];
    const body& b = bodies[c.body_b];
    const vector& n = c.geometry.normal;
    constraint k;
    k.offset_a = c.geometry.point - a.position();
    k.offset_b = c.geometry.point - b.position();
    // The denominator of eq. 3.20 / 4.7, with the inertias as linear maps.
    k.effective_mass_inverse = a.inverse_mass() + b.inverse_mass() +
                               angular_term(a, k.offset_a, n) + angular_term(b, k.offset_b, n);
    const real approach = normal_speed(a, b, c);
    k.target_speed =
        approach < -settings_.restitution_threshold ? -c.restitution * approach : real(0);
    constraints_.push_back(k);
  }

  // Warm start: both lists are sorted by body pair, so one merge finds the
  // contacts that persist. The sweeps below correct the old impulse as
  // needed (down to zero), so the result does not depend on it, only how
  // fast the sweeps get there.
  auto old = previous.begin();
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const contact& c = contacts[i];
    const auto key = std::make_pair(c.body_a, c.body_b);
    while (old != previous.end() && std::make_pair(old->body_a, old->body_b) < key) ++old;
    if (old == previous.end() || std::make_pair(old->body_a, old->body_b) != key) continue;
    constraint& k = constraints_[i];
    if (!(k.effective_mass_inverse > 0)) continue;
    k.accumulated = old->impulse;
    apply_impulse(bodies[c.body_a], bodies[c.body_b], c.geometry.normal, k, k.accumulated);
  }

  // Sequential impulses: each sweep drives every contact to its target with
  // the impulse j n on A and -j n on B; the total per contact stays >= 0
  // (contacts push, never pull).
  for (int sweep = 0; sweep < settings_.solver_iterations; ++sweep) {
    for (std::size_t i = 0; i < contacts.size(); ++i) {
      const contact& c = contacts[i];
      constraint& k = constraints_[i];
      if (!(k.effective_mass_inverse > 0)) continue;
      body& a = bodies[c.body_a];
      body& b = bodies[c.body_b];
      const real wanted = (k.target_speed - normal_speed(a, b, c)) / k.effective_mass_inverse;
      const real total = std::max(k.accumulated + wanted, real(0));
      apply_impulse(a, b, c.geometry.normal, k, total - k.accumulated);
      k.accumulated = total;
    }
  }
  for (std::size_t i = 0; i < contacts.size(); ++i) contacts[i].impulse = constraints_[i].accumulated;
}

void contact_solver::correct_positions(std::vector<body>& bodies,
                                       const std::vector<contact>& contacts, real h) const {
  for (const contact& c : contacts) {
    body& a = bodies[c.body_a];
    body& b = bodies[c.body_b];
    const real inverse_masses = a.inverse_mass_ + b.inverse_mass_;
    if (!(inverse_masses > 0)) continue;
    const vector& n = c.geometry.normal;
    // The depth now, to first order: the positions moved by h v since the
    // narrow phase measured it.
    const real depth = c.geometry.depth - h * e3ga::scp(a.velocity_ - b.velocity_, n);
    const real push = settings_.position_correction * (depth - settings_.linear_slop);
    if (!(push > 0)) continue;
    a.position_ = a.position_ + (push * a.inverse_mass_ / inverse_masses) * n;
    b.position_ = b.position_ - (push * b.inverse_mass_ / inverse_masses) * n;
  }
}

}  // namespace gaphys
