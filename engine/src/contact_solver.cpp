#include "contact_solver.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include "timed_impact.hpp"

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

bool is_plane(const body& b) { return b.shape() && b.shape()->kind() == shape_kind::plane; }

// Every shape's contact normal passes through the centre of a sphere or a
// point (the line of centres, a plane's normal), so the arm n ∧ r of such a
// body is zero; computed from the contact point it would be rounding only.
bool central(const body& b) { return b.shape() && !is_plane(b); }

// Where a body touches the other, from its centre: a sphere's surface point
// along the normal (towards -n for A, which the normal points to, +n for
// B), a point's centre. A plane's is the contact point (planes are static,
// so it never turns them).
vector contact_offset(const body& x, const contact& c, const vector& n, real side) {
  const shape& s = *x.shape();
  switch (s.kind()) {
    case shape_kind::sphere:
      return (side * s.radius()) * n;
    case shape_kind::point:
      return vector{};
    case shape_kind::plane:
      break;
  }
  return c.geometry.point - x.position();
}

// The smaller radius of the contact's spheres; 0 when it has none.
real rolling_radius(const body& a, const body& b) {
  real radius = 0;
  for (const body* x : {&a, &b}) {
    if (x->shape()->kind() != shape_kind::sphere) continue;
    radius = radius > 0 ? std::min(radius, x->shape()->radius()) : x->shape()->radius();
  }
  return radius;
}

// Two unit tangents t1, t2 with (t1, t2, n) right-handed: t1 from the basis
// vector least along n, t2 = n × t1, the dual of n ∧ t1 (written out: e3ga has
// no trivector products in the engine's spec).
std::array<vector, 2> tangents(const vector& n) {
  const real ax = std::fabs(n.e1()), ay = std::fabs(n.e2()), az = std::fabs(n.e3());
  const vector axis = ax <= ay && ax <= az ? vector{1, 0, 0}
                      : ay <= az           ? vector{0, 1, 0}
                                           : vector{0, 0, 1};
  vector t1 = axis - e3ga::scp(axis, n) * n;
  t1 = (1 / e3ga::norm(t1)) * t1;
  const vector t2{n.e2() * t1.e3() - n.e3() * t1.e2(), n.e3() * t1.e1() - n.e1() * t1.e3(),
                  n.e1() * t1.e2() - n.e2() * t1.e1()};
  return {t1, t2};
}

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
  constraint k;
  k.body_a = c.body_a;
  k.body_b = c.body_b;
  k.inverse_masses = a.inverse_mass() + b.inverse_mass();
  k.surface = c.material;
  k.gap = -c.geometry.depth;
  k.bounces = c.material.restitution > 0 &&
              approach_speed(a, b, start_a, start_b, c) < -settings_.restitution_threshold;
  const bool central_a = central(a) || a.is_static();
  const bool central_b = central(b) || b.is_static();
  vector n = c.geometry.normal;
  if (k.bounces && central_a && central_b) {
    // Bounced at the moment the surfaces meet, along the normal then.
    k.timing = time_impact(a, b, c, start_a, start_b, h);
    if (k.timing) n = k.timing->normal;
  }
  // A bounce whose surfaces meet only in a later step waits for it.
  k.waits = k.bounces && k.gap > 0 && !k.timing;

  const vector r_a = contact_offset(a, c, n, -1);
  const vector r_b = contact_offset(b, c, n, 1);
  // The denominator of eq. 3.20 / 4.7, with the inertias as linear maps:
  // 1/mA + 1/mB + n . (rA ⌋ I_A⁻¹(rA ∧ n)) + n . (rB ⌋ I_B⁻¹(rB ∧ n)).
  k.normal = detail::linear_row(n, r_a, r_b, a, b);
  k.normal.turns = !(central_a && central_b);
  k.target_speed = k.gap > 0 ? -k.gap / h : real(0);

  k.frame = tangents(n);
  k.planes = {e3ga::op(n, k.frame[0]), e3ga::op(n, k.frame[1]),
              e3ga::op(k.frame[0], k.frame[1])};
  if (k.surface.friction > 0) {
    k.friction.rows = {detail::linear_row(k.frame[0], r_a, r_b, a, b),
                       detail::linear_row(k.frame[1], r_a, r_b, a, b)};
    k.friction.prepare(k.inverse_masses);
  }
  k.rolling_radius = rolling_radius(a, b);
  if (k.surface.rolling_resistance > 0 && k.rolling_radius > 0) {
    k.rolling.rows = {detail::angular_row(k.planes[0], a, b), detail::angular_row(k.planes[1], a, b)};
    k.rolling.prepare(k.inverse_masses);
  }
  if (k.surface.spinning_friction > 0 && k.rolling_radius > 0) {
    k.spinning = detail::angular_row(k.planes[2], a, b);
  }
  return k;
}

// Over-relaxation speeds up coupled contacts (a row of balls, a stack),
// whose impulses disturb each other; a contact alone on its dynamic bodies
// is met exactly by one plain impulse, which relaxation would only turn
// into a geometric approach.
void contact_solver::set_relaxation(const std::vector<body>& bodies) {
  contacts_per_body_.assign(bodies.size(), 0);
  for (const constraint& k : constraints_) {
    if (!bodies[k.body_a].is_static()) ++contacts_per_body_[k.body_a];
    if (!bodies[k.body_b].is_static()) ++contacts_per_body_[k.body_b];
  }
  for (constraint& k : constraints_) {
    if (contacts_per_body_[k.body_a] > 1 || contacts_per_body_[k.body_b] > 1) {
      k.relaxation = settings_.solver_relaxation;
    }
  }
}

// One impact of one contact, if it has one now: a bouncing contact takes the
// impulse that reverses its approach speed times e, read from the bodies'
// velocities as the step's start and its earlier impacts left them (for a
// timed bounce whose bodies nothing else has struck yet, the speed at the
// moment of impact), with friction bounded by μ times that impulse. The
// same impulse changes the solved velocities. Each such impulse removes
// (1 - e²) of the kinetic energy of the pair's approach and friction only
// takes energy away, so the impacts of a step create none, whatever their
// order.
bool contact_solver::impact(constraint& k, real h) {
  if (!(k.surface.restitution > 0) || !(k.normal.mass_inverse > 0)) return false;
  solver_body& a = impact_bodies_[k.body_a];
  solver_body& b = impact_bodies_[k.body_b];
  const bool untouched = !impacted_[k.body_a] && !impacted_[k.body_b];
  real speed;
  bool timed_now = false;
  if (untouched) {
    // Nothing has struck either body this step: the start velocities and
    // the timing decide.
    if (!k.bounces || k.waits) return false;
    if (k.timing) {
      speed = k.timing->speed;
      timed_now = true;
    } else {
      speed = -k.normal.speed(a, b);
    }
  } else {
    // Struck by an earlier impact: a contact that now approaches faster than
    // the threshold, and touches or closes its gap within the step, bounces.
    const real normal_speed = k.normal.speed(a, b);
    if (!(normal_speed < -settings_.restitution_threshold)) return false;
    if (k.gap > 0 && !(k.gap <= -normal_speed * h)) return false;
    speed = -normal_speed;
  }
  if (!(speed > 0)) return false;

  const real j = (1 + k.surface.restitution) * speed / k.normal.mass_inverse;
  solver_body& solved_a = solver_bodies_[k.body_a];
  solver_body& solved_b = solver_bodies_[k.body_b];
  k.normal.apply(a, b, j);
  k.normal.apply(solved_a, solved_b, j);
  k.impact_normal += j;
  vector linear_impulse = j * k.normal.linear;
  if (k.friction.active()) {
    const std::array<real, 2> total =
        k.friction.stopping_total(a, b, k.impact_tangent, k.surface.friction * k.impact_normal);
    const std::array<real, 2> step{total[0] - k.impact_tangent[0], total[1] - k.impact_tangent[1]};
    k.friction.apply(a, b, step);
    k.friction.apply(solved_a, solved_b, step);
    k.impact_tangent = total;
    linear_impulse = linear_impulse + step[0] * k.frame[0] + step[1] * k.frame[1];
  }
  if (timed_now) {
    k.timed = true;
    k.timed_impulse = linear_impulse;
  }
  if (a.inverse_mass > 0) impacted_[k.body_a] = 1;
  if (b.inverse_mass > 0) impacted_[k.body_b] = 1;
  return true;
}

// The impact phase: sweeps over the contacts until none bounces. A row of
// touching balls struck at one end passes the impact on one contact per
// impact (Newton's cradle: the far ball leaves, the rest stop), however
// the contacts are ordered; sweeps that meet the row against its order
// need one sweep per ball.
void contact_solver::resolve_impacts(real h) {
  for (int sweep = 0; sweep < settings_.impact_iterations; ++sweep) {
    bool any = false;
    for (constraint& k : constraints_) any = impact(k, h) || any;
    if (!any) break;
  }
}

// Warm start: both lists are sorted by body pair, so one merge finds the
// contacts that persist. The sweeps correct the old impulses as needed (down
// to zero), so the result does not depend on them, only how fast the sweeps
// get there. Friction and resistance impulses are kept as world-frame
// vectors and bivectors and read in the new contact frame.
void contact_solver::warm_start(const std::vector<contact>& contacts,
                                const std::vector<contact>& previous) {
  auto old = previous.begin();
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const contact& c = contacts[i];
    const auto key = std::make_pair(c.body_a, c.body_b);
    while (old != previous.end() && std::make_pair(old->body_a, old->body_b) < key) ++old;
    if (old == previous.end() || std::make_pair(old->body_a, old->body_b) != key) continue;
    constraint& k = constraints_[i];
    if (!(k.normal.mass_inverse > 0) || k.waits) continue;
    solver_body& a = solver_bodies_[k.body_a];
    solver_body& b = solver_bodies_[k.body_b];
    const contact_impulse& resting = old->resting;
    k.accumulated = resting.normal;
    k.normal.apply(a, b, k.accumulated);
    const auto within = [](std::array<real, 2> v, real bound) {
      const real length = std::hypot(v[0], v[1]);
      if (length > bound) v = {v[0] * bound / length, v[1] * bound / length};
      return v;
    };
    if (k.friction.active()) {
      const std::array<real, 2> held{e3ga::scp(resting.tangent, k.frame[0]),
                                     e3ga::scp(resting.tangent, k.frame[1])};
      k.friction.start_from(a, b, within(held, k.surface.friction * k.accumulated));
    }
    // An angular impulse L = Σ λ_i U_i on unit planes reads back λ_i = -L . U_i.
    if (k.rolling.active()) {
      const std::array<real, 2> held{-e3ga::scp(resting.angular, k.planes[0]),
                                     -e3ga::scp(resting.angular, k.planes[1])};
      k.rolling.start_from(
          a, b, within(held, k.surface.rolling_resistance * k.rolling_radius * k.accumulated));
    }
    if (k.spinning.mass_inverse > 0) {
      const real bound = k.surface.spinning_friction * k.rolling_radius * k.accumulated;
      k.spinning_accumulated = std::clamp(-e3ga::scp(resting.angular, k.planes[2]), -bound, bound);
      k.spinning.apply(a, b, k.spinning_accumulated);
    }
  }
}

// The contact phase: sequential impulses. Each sweep drives every contact
// to its normal target with the impulse j n on A and -j n on B, the total
// per contact kept >= 0 (contacts push, never pull), then its friction
// towards no slip within the cone |λ_t| <= μ λ_n, and its rolling and
// spin towards none within c ρ λ_n. A sweep that changes no speed by more
// than the tolerance has converged, and ends the solve early.
void contact_solver::solve_contacts() {
  for (int sweep = 0; sweep < settings_.solver_iterations; ++sweep) {
    real largest_change = 0;
    // The last sweep is plain: it takes back what over-relaxation pushed
    // contacts apart beyond their targets.
    const bool last = sweep + 1 == settings_.solver_iterations;
    for (constraint& k : constraints_) {
      if (!(k.normal.mass_inverse > 0) || (k.waits && k.impact_normal == 0)) continue;
      solver_body& a = solver_bodies_[k.body_a];
      solver_body& b = solver_bodies_[k.body_b];
      const real relaxation = last ? real(1) : k.relaxation;
      const real wanted =
          relaxation * (k.target_speed - k.normal.speed(a, b)) / k.normal.mass_inverse;
      const real total = std::max(k.accumulated + wanted, real(0));
      const real j = total - k.accumulated;
      k.normal.apply(a, b, j);
      k.accumulated = total;
      largest_change = std::max(largest_change, std::fabs(j) * k.normal.mass_inverse);
      if (!(k.accumulated > 0)) {
        // Nothing pushes, so nothing rubs: any held friction goes too.
        if (k.friction.accumulated[0] == 0 && k.friction.accumulated[1] == 0 &&
            k.rolling.accumulated[0] == 0 && k.rolling.accumulated[1] == 0 &&
            k.spinning_accumulated == 0) {
          continue;
        }
      }
      if (k.friction.active()) {
        const real change = k.friction.solve(a, b, k.surface.friction * k.accumulated);
        largest_change = std::max(largest_change, change * k.friction.rows[0].mass_inverse);
      }
      const real resistance = k.rolling_radius * k.accumulated;
      if (k.rolling.active()) {
        const real change = k.rolling.solve(a, b, k.surface.rolling_resistance * resistance);
        largest_change = std::max(largest_change, change * k.rolling.rows[0].mass_inverse);
      }
      if (k.spinning.mass_inverse > 0) {
        const real change = detail::solve_bounded(k.spinning, k.spinning_accumulated, a, b,
                                                  k.surface.spinning_friction * resistance);
        largest_change = std::max(largest_change, change * k.spinning.mass_inverse);
      }
    }
    if (largest_change <= settings_.solver_tolerance) break;
  }
}

void contact_solver::store_impulses(std::vector<contact>& contacts) const {
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const constraint& k = constraints_[i];
    contact_impulse& resting = contacts[i].resting;
    resting.normal = k.accumulated;
    resting.tangent = k.friction.accumulated[0] * k.frame[0] + k.friction.accumulated[1] * k.frame[1];
    resting.angular = k.rolling.accumulated[0] * k.planes[0] +
                      k.rolling.accumulated[1] * k.planes[1] +
                      k.spinning_accumulated * k.planes[2];
    contact_impulse& total = contacts[i].impulse;
    total = resting;
    total.normal += k.impact_normal;
    total.tangent =
        total.tangent + k.impact_tangent[0] * k.frame[0] + k.impact_tangent[1] * k.frame[1];
  }
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
  set_relaxation(bodies);

  solver_bodies_.resize(bodies.size());
  impact_bodies_.resize(bodies.size());
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const body& b = bodies[i];
    solver_bodies_[i] = {b.velocity_, b.angular_velocity_, b.inverse_mass_};
    impact_bodies_[i] = {start[i].linear, start[i].angular, b.inverse_mass_};
  }
  impacted_.assign(bodies.size(), 0);

  resolve_impacts(h);
  warm_start(contacts, previous);
  solve_contacts();
  store_impulses(contacts);
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
    if (!(k.inverse_masses > 0)) continue;
    if (k.timed) {
      // The impulse J came at impact_time into the step, not at its start:
      // each body moved with its old velocity until then, t ΔV less far.
      const vector shift = k.timing->time * k.timed_impulse;
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
    const vector& n = c.geometry.normal;
    const real depth = c.geometry.depth - h * e3ga::scp(a.velocity_ - b.velocity_, n);
    const real push = settings_.position_correction * (depth - settings_.linear_slop);
    if (!(push > 0)) continue;
    a.position_ = a.position_ + (push * a.inverse_mass_ / k.inverse_masses) * n;
    b.position_ = b.position_ - (push * b.inverse_mass_ / k.inverse_masses) * n;
  }
}

}  // namespace gaphys
