#include "contact_solver.hpp"

#include "timed_impact.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

namespace gaphys {

namespace {

// The normal speed n . (v_A(p) - v_B(p)) the bodies had at the start of the
// step: < 0 while the contact approaches.
real approach_speed(const body& a, const body& b, const body_velocity& start_a,
                    const body_velocity& start_b, const contact& c) {
  const vector& p = c.geometry.point;
  return e3ga::scp(start_a.at_offset(p - a.position()) - start_b.at_offset(p - b.position()),
                   c.geometry.normal);
}

}  // namespace

// The same normal speed from the constraint's precomputed terms: with
// v(p) = v + r ⌋ Ω, n . (r ⌋ Ω) = (n ∧ r) ⌋ Ω, a scalar of two bivectors.
real contact_solver::normal_speed(const solver_body& a, const solver_body& b, const constraint& k) {
  const real linear = e3ga::scp(k.normal, a.velocity - b.velocity);
  if (k.central) return linear;
  return linear + e3ga::lc(k.arm_a, a.angular_velocity) - e3ga::lc(k.arm_b, b.angular_velocity);
}

// j n on A and -j n on B at the contact point: Δv = j n / m and
// ΔΩ = I⁻¹(r ∧ j n) = j I⁻¹(r ∧ n), precomputed as turn.
void contact_solver::apply_impulse(solver_body& a, solver_body& b, const constraint& k, real j) {
  a.velocity = a.velocity + (j * a.inverse_mass) * k.normal;
  b.velocity = b.velocity - (j * b.inverse_mass) * k.normal;
  if (k.central) return;
  a.angular_velocity = a.angular_velocity + j * k.turn_a;
  b.angular_velocity = b.angular_velocity - j * k.turn_b;
}

namespace {

bool is_plane(const body& b) { return b.shape() && b.shape()->kind() == shape_kind::plane; }

// Every shape's contact normal passes through the centre of a sphere or a
// point (the line of centres, a plane's normal), so the arm n ∧ r of such a
// body is zero; computed from the contact point it would be rounding only.
bool central(const body& b) { return b.shape() && !is_plane(b); }

}  // namespace

// When and along which normal the contact's surfaces meet in this step (see
// timed_impact.hpp); only for central contacts, whose normal is a plane's or
// the line of centres.
std::optional<timed_impact> contact_solver::time_impact(const body& a, const body& b,
                                                        const contact& c,
                                                        const body_velocity& start_a,
                                                        const body_velocity& start_b, real h) {
  const relative_motion motion{a.position() - b.position(), start_a.linear - start_b.linear,
                               a.velocity_ - b.velocity_};
  if (is_plane(a) || is_plane(b)) {
    return impact_across_plane(-c.geometry.depth, c.geometry.normal, motion, h);
  }
  return impact_of_centres(e3ga::norm(motion.offset) + c.geometry.depth, motion, h);
}

// The terms of one contact that stay fixed while the sweeps run (attitudes do
// not change, so neither do the world inertias).
contact_solver::constraint contact_solver::make_constraint(const body& a, const body& b,
                                                           const contact& c,
                                                           const body_velocity& start_a,
                                                           const body_velocity& start_b,
                                                           real h) const {
  const vector& n = c.geometry.normal;
  constraint k;
  k.body_a = c.body_a;
  k.body_b = c.body_b;
  k.normal = n;
  // A static body's arm counts for nothing: its Ω stays zero.
  const bool central_a = central(a) || a.is_static();
  const bool central_b = central(b) || b.is_static();
  if (!central_a) {
    const vector offset_a = c.geometry.point - a.position();
    k.arm_a = e3ga::op(n, offset_a);
    k.turn_a = a.world_inverse_inertia(e3ga::op(offset_a, n));
  }
  if (!central_b) {
    const vector offset_b = c.geometry.point - b.position();
    k.arm_b = e3ga::op(n, offset_b);
    k.turn_b = b.world_inverse_inertia(e3ga::op(offset_b, n));
  }
  k.central = central_a && central_b;
  // The denominator of eq. 3.20 / 4.7, with the inertias as linear maps:
  // 1/mA + 1/mB + n . (rA ⌋ I_A⁻¹(rA ∧ n)) + n . (rB ⌋ I_B⁻¹(rB ∧ n)).
  k.effective_mass_inverse = a.inverse_mass() + b.inverse_mass() + e3ga::lc(k.arm_a, k.turn_a) +
                             e3ga::lc(k.arm_b, k.turn_b);
  const real approach = approach_speed(a, b, start_a, start_b, c);
  const bool bounces = approach < -settings_.restitution_threshold && c.restitution > 0;
  const real gap = -c.geometry.depth;
  if (bounces && k.central) {
    if (const std::optional<timed_impact> impact = time_impact(a, b, c, start_a, start_b, h)) {
      // Bounced at that moment: the normal speed changes by (1 + e) times
      // the impact speed, and correct_positions moves the bodies as if the
      // impulse had come then rather than at the start of the step.
      k.normal = impact->normal;
      k.target_speed = e3ga::scp(impact->normal, a.velocity_ - b.velocity_) +
                       (1 + c.restitution) * impact->speed;
      k.impact_time = impact->time;
      k.timed = true;
      return k;
    }
  }
  if (gap > 0) {  // speculative
    if (bounces) k.effective_mass_inverse = 0;  // meets only in a later step
    k.target_speed = -gap / h;
  } else {
    k.target_speed = bounces ? -c.restitution * approach : real(0);
  }
  return k;
}

void contact_solver::solve_velocities(std::vector<body>& bodies,
                                      const std::vector<body_velocity>& start,
                                      std::vector<contact>& contacts,
                                      const std::vector<contact>& previous, real h) {
  constraints_.clear();
  constraints_.reserve(contacts.size());
  for (const contact& c : contacts) {
    const body& a = bodies[c.body_a];
    const body& b = bodies[c.body_b];
    constraints_.push_back(make_constraint(a, b, c, start[c.body_a], start[c.body_b], h));
  }

  // Over-relaxation speeds up coupled contacts (a row of balls, a stack),
  // whose impulses disturb each other; a contact alone on its dynamic bodies
  // is met exactly by one plain impulse, which relaxation would only turn
  // into a geometric approach.
  contacts_per_body_.assign(bodies.size(), 0);
  for (const contact& c : contacts) {
    if (!bodies[c.body_a].is_static()) ++contacts_per_body_[c.body_a];
    if (!bodies[c.body_b].is_static()) ++contacts_per_body_[c.body_b];
  }
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const contact& c = contacts[i];
    if (contacts_per_body_[c.body_a] > 1 || contacts_per_body_[c.body_b] > 1) {
      constraints_[i].relaxation = settings_.solver_relaxation;
    }
  }

  solver_bodies_.resize(bodies.size());
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const body& b = bodies[i];
    solver_bodies_[i] = {b.velocity_, b.angular_velocity_, b.inverse_mass_};
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
    apply_impulse(solver_bodies_[c.body_a], solver_bodies_[c.body_b], k, k.accumulated);
  }

  // Sequential impulses: each sweep drives every contact to its target with
  // the impulse j n on A and -j n on B; the total per contact stays >= 0
  // (contacts push, never pull).
  // A sweep that changes no contact's normal speed by more than the
  // tolerance has converged, and ends the solve early.
  for (int sweep = 0; sweep < settings_.solver_iterations; ++sweep) {
    real largest_change = 0;
    for (constraint& k : constraints_) {
      if (!(k.effective_mass_inverse > 0)) continue;
      solver_body& a = solver_bodies_[k.body_a];
      solver_body& b = solver_bodies_[k.body_b];
      // The last sweep is plain: it takes back what over-relaxation pushed
      // contacts apart beyond their targets.
      const real relaxation = sweep + 1 < settings_.solver_iterations ? k.relaxation : real(1);
      const real wanted =
          relaxation * (k.target_speed - normal_speed(a, b, k)) / k.effective_mass_inverse;
      const real total = std::max(k.accumulated + wanted, real(0));
      const real j = total - k.accumulated;
      apply_impulse(a, b, k, j);
      k.accumulated = total;
      largest_change = std::max(largest_change, std::fabs(j) * k.effective_mass_inverse);
    }
    if (largest_change <= settings_.solver_tolerance) break;
  }
  for (std::size_t i = 0; i < contacts.size(); ++i) contacts[i].impulse = constraints_[i].accumulated;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    body& b = bodies[i];
    if (b.is_static()) continue;
    b.velocity_ = solver_bodies_[i].velocity;
    b.angular_velocity_ = solver_bodies_[i].angular_velocity;
  }
}

void contact_solver::correct_positions(std::vector<body>& bodies,
                                       const std::vector<contact>& contacts, real h) const {
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const contact& c = contacts[i];
    const constraint& k = constraints_[i];
    body& a = bodies[c.body_a];
    body& b = bodies[c.body_b];
    const real inverse_masses = a.inverse_mass_ + b.inverse_mass_;
    if (!(inverse_masses > 0)) continue;
    const vector& n = c.geometry.normal;
    if (k.timed) {
      // The impulse j came at impact_time into the step, not at its start:
      // each body moved with its old velocity until then, t Δv less far.
      const vector shift = (k.impact_time * k.accumulated) * k.normal;
      a.position_ = a.position_ - a.inverse_mass_ * shift;
      b.position_ = b.position_ + b.inverse_mass_ * shift;
      continue;
    }
    // A speculative contact had a gap when the step began; if its bodies
    // overlap now (one left to bounce in a later step), the next step meets
    // them for real.
    if (c.geometry.depth < 0) continue;
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
