#include "contact_solver.hpp"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <optional>
#include <type_traits>
#include <utility>

#include "huge_pages.hpp"
#include "prefetch.hpp"
#include "thread_count.hpp"
#include "timed_impact.hpp"
#include "turning_reach.hpp"

namespace gaphys {

namespace {

// The normal speed n . (v_A(p) - v_B(p)) the bodies had at the start of the
// step: < 0 while the contact approaches.
real separation_speed(const body& a, const body& b, const body_velocity& start_a,
                      const body_velocity& start_b, const contact& c) {
  const vector& p = c.geometry.point;
  return e3ga::scp(start_a.at_offset(p - a.position()) - start_b.at_offset(p - b.position()),
                   c.geometry.normal);
}

// For a speculative contact whose shapes cannot meet in a step of h seconds
// (each body's own speed towards the other and its turning, the support's
// real growth (turning_reach.hpp), close less than the gap): how much
// farther its point closes by its bodies' turning read along its tangents,
// r ⌋ ω, as the solver's rows read it, than the shapes come. A box spinning
// at 50 rad/s whose corner sweeps past a floor 1 mm below it was otherwise
// stopped by its corner's tangent speed, and thrown. 0 where the shapes can
// meet (then the row must hold them: an impulse that slows the turning
// would let them close more than the gap), where the tangents understate
// it (another corner leads), and where the turning is too slow to matter:
// the tangent departs from the arc by r (h |ω|)^2 / 2 at most.
real turning_overshoot(const body& a, const body& b, const contact& c, real gap, real margin,
                       real h) {
  const vector& p = c.geometry.point;
  const vector& n = c.geometry.normal;
  const vector r_a = p - a.position(), r_b = p - b.position();
  const real tangential = h * (e3ga::scp(e3ga::lc(r_b, b.angular_velocity()), n) -
                               e3ga::scp(e3ga::lc(r_a, a.angular_velocity()), n));
  if (!(tangential > 0)) return 0;
  // (A plane's bounding radius is infinite, and a plane does not turn.)
  const auto departure_of = [h](const body& x) {
    const real turn = h * e3ga::norm(x.angular_velocity());
    return turn > 0 ? x.bounding_radius() * turn * turn / 2 : real(0);
  };
  const real departure = departure_of(a) + departure_of(b);
  if (!(departure > real(1e-3) * margin)) return 0;
  const real linear = h * (std::max(real(0), -e3ga::scp(a.velocity(), n)) +
                           std::max(real(0), e3ga::scp(b.velocity(), n)));
  if (linear >= gap) return 0;
  const real swept = detail::turning_approach(space::placed(a, a.shapes()[c.shape_a]), a.position(),
                                              a.angular_velocity(), h, -n) +
                     detail::turning_approach(space::placed(b, b.shapes()[c.shape_b]), b.position(),
                                              b.angular_velocity(), h, n);
  if (linear + swept >= gap) return 0;
  return std::max(real(0), tangential - swept);
}

bool is_plane(const body& b) { return b.shape() && b.shape()->kind() == shape_kind::plane; }

// A body whose one shape is a sphere or a point about its centre: every
// contact normal of such a shape passes through the centre (the line of
// centres, a plane's normal), so its arm n ∧ r is zero; computed from the
// contact point it would be rounding only.
bool central(const body& b) {
  if (b.shapes().size() != 1) return false;
  const attached_shape& s = b.shapes().front();
  const bool round = s.shape.kind() == shape_kind::sphere || s.shape.kind() == shape_kind::point;
  return round && s.offset.e1() == 0 && s.offset.e2() == 0 && s.offset.e3() == 0;
}

// The radius a touching shape rolls on: a sphere's or a capsule's; 0 for
// flat shapes.
real rolling_radius_of(const shape& s) {
  return s.kind() == shape_kind::sphere || s.kind() == shape_kind::capsule ? s.radius() : 0;
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
// timed_impact.hpp); only for central contacts of round shapes, whose normal
// is a plane's or the line of centres.
std::optional<timed_impact> contact_solver::time_impact(const body& a, const body& b,
                                                        const contact& c,
                                                        const body_velocity& start_a,
                                                        const body_velocity& start_b,
                                                        real h) const {
  const body_velocity now_a = timing_velocity(a, c.body_a, c.body_b, start_a);
  const body_velocity now_b = timing_velocity(b, c.body_b, c.body_a, start_b);
  const relative_motion motion{a.position() - b.position(), start_a.linear - start_b.linear,
                               now_a.linear - now_b.linear};
  if (shape_summaries_[c.body_a].plane || shape_summaries_[c.body_b].plane) {
    return impact_across_plane(-c.geometry.depth, c.geometry.normal, motion, h);
  }
  return impact_of_centres(e3ga::norm(motion.offset) + c.geometry.depth, motion, h);
}

std::optional<timed_impact> contact_solver::time_point_impact(const body& a, const body& b,
                                                              const contact& c, real gap,
                                                              const body_velocity& start_a,
                                                              const body_velocity& start_b,
                                                              real h) const {
  const vector& p = c.geometry.point;
  const vector r_a = p - a.position(), r_b = p - b.position();
  const body_velocity now_a = timing_velocity(a, c.body_a, c.body_b, start_a);
  const body_velocity now_b = timing_velocity(b, c.body_b, c.body_a, start_b);
  const relative_motion motion{vector{}, start_a.at_offset(r_a) - start_b.at_offset(r_b),
                               now_a.at_offset(r_a) - now_b.at_offset(r_b)};
  return impact_across_plane(gap, c.geometry.normal, motion, h);
}

body_velocity contact_solver::timing_velocity(const body& x, std::size_t index, std::size_t other,
                                              const body_velocity& start) const {
  const std::array<std::size_t, 2>& under = supports_[index];
  const bool rests = (under[0] != no_support && under[0] != other) ||
                     (under[1] != no_support && under[1] != other);
  return rests ? start : body_velocity{x.velocity_, x.angular_velocity_};
}

unsigned char contact_solver::resting_sides(const world_settings& settings,
                                            const contact& c) const {
  if (!(c.geometry.depth >= -settings.contact_margin)) return 0;
  // (x rests on the other if the contact's normal towards x opposes the
  // velocity the step's forces gave x.)
  const vector& n = c.geometry.normal;
  return static_cast<unsigned char>((e3ga::scp(forced_[c.body_a], n) < 0 ? 1 : 0) |
                                    (e3ga::scp(forced_[c.body_b], -n) < 0 ? 2 : 0));
}

void contact_solver::find_supports(std::size_t bodies) {
  supports_.assign(bodies, {no_support, no_support});
  const auto add = [&](std::size_t x, std::size_t support) {
    std::array<std::size_t, 2>& under = supports_[x];
    if (under[0] == no_support) {
      under[0] = support;
    } else if (under[0] != support && under[1] == no_support) {
      under[1] = support;
    }
  };
  for (std::size_t i = 0; i < rests_.size(); ++i) {
    if (rests_[i] == 0) continue;
    const auto [a, b] = colouring_.pairs[i];
    if (rests_[i] & 1) add(a, b);
    if (rests_[i] & 2) add(b, a);
  }
}

contact_solver::shape_summary contact_solver::summarize(const body& b) {
  shape_summary s;
  s.central = central(b);
  s.plane = is_plane(b);
  s.sphere = s.central && b.shape()->kind() == shape_kind::sphere;
  if (s.sphere) s.radius = b.shape()->radius();
  if (b.shapes().size() == 1) s.rolling_radius = rolling_radius_of(b.shapes().front().shape);
  return s;
}

// Where a body touches the other, from its centre: a central sphere's
// surface point along the normal (towards -n for A, which the normal points
// to, +n for B), a central point's centre; for every other shape the
// contact point, midway between the two surfaces.
vector contact_solver::contact_offset(const body& x, const shape_summary& shapes, const contact& c,
                                      const vector& n, real side) {
  if (shapes.central) return shapes.sphere ? (side * shapes.radius) * n : vector{};
  return c.geometry.point - x.position();
}

// The smaller of two shapes' rolling radii; 0 when neither rolls.
static real smaller_rolling_radius(real ra, real rb) {
  if (ra > 0 && rb > 0) return std::min(ra, rb);
  return ra > 0 ? ra : rb;
}

// The smaller rolling radius of the contact's two shapes (from the bodies'
// summaries).
real contact_solver::rolling_radius(const body& a, const body& b, const contact& c) const {
  const real own_a = shape_summaries_[c.body_a].rolling_radius;
  const real own_b = shape_summaries_[c.body_b].rolling_radius;
  return smaller_rolling_radius(
      own_a >= 0 ? own_a : rolling_radius_of(a.shapes()[c.shape_a].shape),
      own_b >= 0 ? own_b : rolling_radius_of(b.shapes()[c.shape_b].shape));
}

// Which of a contact's optional terms it has: friction, rolling or spinning
// (surface terms), and of them rolling or spinning (resistance terms).
// (From the shapes themselves: it is read before the bodies' summaries.)
contact_solver::term_counts contact_solver::terms_of(const body& a, const body& b,
                                                     const contact& c) {
  const material& m = c.material;
  const bool resists = (m.rolling_resistance > 0 || m.spinning_friction > 0) &&
                       smaller_rolling_radius(rolling_radius_of(a.shapes()[c.shape_a].shape),
                                              rolling_radius_of(b.shapes()[c.shape_b].shape)) > 0;
  return {m.friction > 0 || resists ? 1u : 0u, resists ? 1u : 0u};
}

// The terms of one contact that stay fixed while the sweeps run (attitudes do
// not change, so neither do the world inertias), into constraints_[slot],
// impacts_[slot] and, where terms_of gives them, surfaces_[at.surfaces] and
// resistances_[at.resistances]; nothing else is written, so contacts are
// built on several threads at once.
void contact_solver::build_constraint(const world_settings& settings, const body& a,
                                      const body& b, const contact& c,
                                      const body_velocity& start_a, const body_velocity& start_b,
                                      real h, std::size_t slot, const term_counts& at) {
  constraint& k = constraints_[slot];
  impact_terms& impact = impacts_[slot];
  const detail::row_body& row_a = row_bodies_[c.body_a];
  const detail::row_body& row_b = row_bodies_[c.body_b];
  // (Field by field, each written once: these here, every other field of
  // both further down, in every case; a new field must be set here too.
  // Cleared whole first, most of both were written twice: a tenth of
  // building a sphere's contact.)
  k.accumulated = 0;
  k.surface = -1;
  k.struck = false;
  impact.timing.reset();
  impact.normal = 0;
  impact.timed = false;
  impact.timed_impulse = vector{};
  k.body_a = static_cast<std::uint32_t>(c.body_a);
  k.body_b = static_cast<std::uint32_t>(c.body_b);
  k.place_a = place_[c.body_a];
  k.place_b = place_[c.body_b];
  k.restitution = c.material.restitution;
  k.gap = -c.geometry.depth;
  if (k.gap > 0) k.gap += turning_overshoot(a, b, c, k.gap, settings.contact_margin, h);
  const real closing = -separation_speed(a, b, start_a, start_b, c);
  impact.approach_speed = closing;
  k.bounces = k.restitution > 0 && closing > settings.restitution_threshold;
  const shape_summary& shapes_a = shape_summaries_[c.body_a];
  const shape_summary& shapes_b = shape_summaries_[c.body_b];
  const bool round_a = shapes_a.central, round_b = shapes_b.central;
  const bool central_a = round_a || a.is_static();
  const bool central_b = round_b || b.is_static();
  vector n = c.geometry.normal;
  // (Only a sphere or point about its centre, or a plane, moves with its
  // body's centre as timed_impact assumes.)
  if (k.bounces && (round_a || shapes_a.plane) && (round_b || shapes_b.plane)) {
    // Bounced at the moment the surfaces meet, along the normal then.
    impact.timing = time_impact(a, b, c, start_a, start_b, h);
    if (impact.timing) n = impact.timing->normal;
  } else if (k.bounces && k.gap > 0) {
    // Any other speculative bounce (boxes, capsules, hulls, compounds, whose
    // contact points turn with their bodies): timed along its normal, held
    // fixed, from its point's speeds. Left to wait for the next step like
    // one whose gap does not close in this one, it let the bodies overlap by
    // up to the step's travel first, and a box at 50 m/s went through a
    // 4 cm wall (test_boxes.cpp).
    impact.timing = time_point_impact(a, b, c, k.gap, start_a, start_b, h);
  }
  // A bounce whose surfaces meet only in a later step waits for it.
  k.waits = k.bounces && k.gap > 0 && !impact.timing;

  const vector r_a = contact_offset(a, shapes_a, c, n, -1);
  const vector r_b = contact_offset(b, shapes_b, c, n, 1);
  // The denominator of eq. 3.20 / 4.7, with the inertias as linear maps:
  // 1/mA + 1/mB + n . (rA ⌋ I_A⁻¹(rA ∧ n)) + n . (rB ⌋ I_B⁻¹(rB ∧ n)).
  // Where both are central, both arms are zero (r_a and r_b along n): the
  // impulse turns neither body.
  k.normal = n;
  k.turns = !(central_a && central_b);
  if (k.turns) {
    detail::set_linear_row(normal_arms_[slot], k.mass_inverse, n, r_a, r_b, row_a, row_b);
  } else {
    k.mass_inverse = a.inverse_mass() + b.inverse_mass();
  }
  k.normal_mass = k.mass_inverse > 0 ? 1 / k.mass_inverse : real(0);
  k.target_speed = k.gap > 0 ? -k.gap / h : real(0);
  k.relaxation = relaxation_of(settings, a, b, c);
  // What the impact phase first asks of it (resolve_impacts).
  impact_filters_[slot] = {k.restitution > 0 && k.mass_inverse > 0, k.bounces && !k.waits};

  const material& m = c.material;
  // (The radius only where something resists rolling or spinning.)
  const real radius =
      m.rolling_resistance > 0 || m.spinning_friction > 0 ? rolling_radius(a, b, c) : real(0);
  const bool rolls = m.rolling_resistance > 0 && radius > 0;
  const bool spins = m.spinning_friction > 0 && radius > 0;
  if (m.friction > 0 || rolls || spins) {
    surface_terms& t = surfaces_[at.surfaces];
    surface_frame& f = frames_[at.surfaces];
    // (Field by field: zeroing the terms first, then writing them, cost a
    // tenth of building a box's contact.)
    f.frame = tangents(n);
    f.impact_tangent = {};
    const real inverse_masses = a.inverse_mass() + b.inverse_mass();
    if (m.friction > 0) {
      detail::disk_block& block = t.friction;
      detail::set_linear_row(block.rows[0], f.frame[0], r_a, r_b, row_a, row_b);
      detail::set_linear_row(block.rows[1], f.frame[1], r_a, r_b, row_a, row_b);
      block.prepare(inverse_masses);
      block.accumulated = {};
      // (A normal row that turns nothing couples through its zero arms.)
      static const detail::row_arms no_arms{};
      const detail::row_arms* turning = normal_arms(slot);
      const detail::row_arms& arms = turning ? *turning : no_arms;
      t.normal_coupling = {
          detail::row_coupling(block.rows[0].linear, block.rows[0], n, arms, inverse_masses),
          detail::row_coupling(block.rows[1].linear, block.rows[1], n, arms, inverse_masses)};
    } else {
      t.friction = detail::disk_block{};
      t.normal_coupling = {};
    }
    t.friction_coefficient = m.friction > 0 ? m.friction : real(0);
    t.resistance = -1;
    if (rolls || spins) {
      resistance_terms& r = resistances_[at.resistances];
      r = resistance_terms{};
      r.planes = {e3ga::op(n, f.frame[0]), e3ga::op(n, f.frame[1]),
                  e3ga::op(f.frame[0], f.frame[1])};
      if (rolls) {
        r.rolling.rows = {detail::angular_row(r.planes[0], row_a, row_b),
                          detail::angular_row(r.planes[1], row_a, row_b)};
        r.rolling.prepare(inverse_masses);
        r.rolling_bound = m.rolling_resistance * radius;
      }
      if (spins) {
        r.spinning = detail::angular_row(r.planes[2], row_a, row_b);
        r.spinning_bound = m.spinning_friction * radius;
      }
      t.resistance = static_cast<int>(at.resistances);
    }
    k.surface = static_cast<int>(at.surfaces);
  }
}

// Over-relaxation speeds up coupled contacts (a row of balls, a stack),
// whose impulses disturb each other; a contact alone on its dynamic bodies
// is met exactly by one plain impulse, which relaxation would only turn
// into a geometric approach.
// Two dynamic bodies whose masses differ by more than twice: there the
// over-relaxed impulses of a stack overshoot on the lighter body, and a
// stack of cubes of 1 and 10 kg in turn gained energy from them for as long
// as it was stepped (a sixth cube sideways by 35 cm in 20 s); with plain
// impulses it settles.
// (Static and kinematic bodies have no inverse mass.)
static bool disparate(real inverse_mass_a, real inverse_mass_b) {
  if (!(inverse_mass_a > 0) || !(inverse_mass_b > 0)) return false;
  const real lighter = std::max(inverse_mass_a, inverse_mass_b);
  const real heavier = std::min(inverse_mass_a, inverse_mass_b);
  return lighter > 2 * heavier;
}

// How many contacts each body is in (relaxation_of reads those of the
// bodies with mass), from the colouring's list of each contact's bodies.
void contact_solver::count_contacts(std::size_t bodies, const std::vector<body_pair>& pairs) {
  contacts_per_body_.assign(bodies, 0);
  for (const auto& [a, b] : pairs) ++contacts_per_body_[a], ++contacts_per_body_[b];
}

real contact_solver::relaxation_of(const world_settings& settings, const body& a, const body& b,
                                   const contact& c) const {
  if (disparate(a.inverse_mass(), b.inverse_mass())) return 1;
  const auto shares = [&](const body& x, std::size_t index) {
    return x.inverse_mass() > 0 && contacts_per_body_[index] > 1;
  };
  return shares(a, c.body_a) || shares(b, c.body_b) ? settings.solver_relaxation : real(1);
}

// Whether a contact bounces now, and at what approach speed: a bouncing
// contact's speed is read from the bodies' velocities as the step's start
// and its earlier impacts left them (for a timed bounce whose bodies nothing
// else has struck yet, the speed at the moment of impact; `timed_now`).
std::optional<real> contact_solver::impact_speed(std::size_t index, real threshold, real h,
                                                 bool& timed_now) const {
  const constraint& k = constraints_[index];
  timed_now = false;
  if (!(k.restitution > 0) || !(k.mass_inverse > 0)) return std::nullopt;
  const impact_terms& record = impacts_[index];
  const solver_body& a = impact_bodies_[k.place_a];
  const solver_body& b = impact_bodies_[k.place_b];
  const bool untouched = !impacted_[k.body_a] && !impacted_[k.body_b];
  real speed;
  if (untouched) {
    // Nothing has struck either body this step: the start velocities and
    // the timing decide.
    if (!k.bounces || k.waits) return std::nullopt;
    if (record.timing) {
      speed = record.timing->speed;
      timed_now = true;
    } else {
      speed = -normal_speed(index, a, b);
    }
  } else {
    // Struck by an earlier impact: a contact that now approaches faster than
    // the threshold, and touches or closes its gap within the step, bounces.
    // (A timed one touches at its impact: a box's four corners reaching a
    // wall at once, each struck by the others' bounces.)
    const real approach = normal_speed(index, a, b);
    if (!(approach < -threshold)) return std::nullopt;
    if (k.gap > 0 && !record.timing && !(k.gap <= -approach * h)) return std::nullopt;
    speed = -approach;
  }
  if (!(speed > 0)) return std::nullopt;
  return speed;
}

// One impact of one contact, if it has one now: the impulse that reverses
// its approach speed times e, with friction bounded by μ times that
// impulse. The same impulse changes the solved velocities. Each such
// impulse removes (1 - e²) of the kinetic energy of the pair's approach and
// friction only takes energy away, so the impacts of a step create none,
// whatever their order.
bool contact_solver::impact(std::size_t index, real threshold, real h) {
  bool timed_now = false;
  const std::optional<real> speed = impact_speed(index, threshold, h, timed_now);
  if (!speed) return false;
  bounce(index, *speed, timed_now);
  return true;
}

// A contact's impact at approach speed `speed` (impact_speed's).
void contact_solver::bounce(std::size_t index, real speed, bool timed_now) {
  const constraint& k = constraints_[index];
  const real j = (1 + k.restitution) * speed / k.mass_inverse;
  apply_impact_normal(index, j);
  finish_impact(index, j, timed_now);
}

void contact_solver::apply_impact_normal(std::size_t index, real j) {
  const constraint& k = constraints_[index];
  apply_normal(index, impact_bodies_[k.place_a], impact_bodies_[k.place_b], j);
  apply_normal(index, solver_bodies_[k.place_a], solver_bodies_[k.place_b], j);
}

// What follows a contact's normal impulse j of the impact phase (applied):
// its record, friction, and the timing of the correction.
void contact_solver::finish_impact(std::size_t index, real j, bool timed_now) {
  constraint& k = constraints_[index];
  impact_terms& record = impacts_[index];
  solver_body& a = impact_bodies_[k.place_a];
  solver_body& b = impact_bodies_[k.place_b];
  record.normal += j;
  k.struck = true;
  vector linear_impulse = j * k.normal;
  if (k.surface >= 0 && surfaces_[k.surface].friction.active()) {
    surface_terms& t = surfaces_[k.surface];
    surface_frame& f = frames_[k.surface];
    const std::array<real, 2> total = t.friction.stopping_total(
        a, b, f.impact_tangent, t.friction_coefficient * record.normal);
    const std::array<real, 2> step{total[0] - f.impact_tangent[0], total[1] - f.impact_tangent[1]};
    t.friction.apply(a, b, step);
    t.friction.apply(solver_bodies_[k.place_a], solver_bodies_[k.place_b], step);
    f.impact_tangent = total;
    linear_impulse = linear_impulse + step[0] * f.frame[0] + step[1] * f.frame[1];
  }
  if (timed_now) {
    record.timed = true;
    record.timed_impulse = linear_impulse;
  }
  if (a.inverse_mass > 0) impacted_[k.body_a] = 1;
  if (b.inverse_mass > 0) impacted_[k.body_b] = 1;
}

// The impacts of a run of contacts between the same two bodies (contacts
// first .. end - 1, in contact order): the points of one patch, a box's
// corners on a floor, bounce at once. One by one, the first corner's
// impulse turned the box and the others bounced from that: a box dropped
// flat on a floor with e = 0.5 climbed back to 3% of its height instead of
// e² = 25%, spinning at 14 rad/s. Together, each point's impulse is found
// (projected Gauss-Seidel over the run, impulses >= 0) such that each
// separates at e times the speed it approached at, where the impulses can.
// One bouncing point alone bounces as impact() bounces it.
bool contact_solver::impact_run(std::size_t first, std::size_t end, real threshold, real h) {
  run_bounces_.clear();
  real largest_target = 0;
  for (std::size_t i = first; i < end; ++i) {
    const std::size_t index = slot_[i];
    if (!impact_filters_[index].can_bounce) continue;
    bool timed_now = false;
    if (const std::optional<real> speed = impact_speed(index, threshold, h, timed_now)) {
      // The speed impact() would leave: its impulse's (1 + e) speed on top
      // of the speed now (for a timed bounce, `speed` is the one at its
      // moment, which gravity made faster than the step's start).
      const constraint& k = constraints_[index];
      const real now = normal_speed(index, impact_bodies_[k.place_a], impact_bodies_[k.place_b]);
      const real target = now + (1 + k.restitution) * *speed;
      run_bounces_.push_back({index, *speed, target, 0, timed_now});
      largest_target = std::max(largest_target, (1 + k.restitution) * *speed);
    }
  }
  if (run_bounces_.empty()) return false;
  if (run_bounces_.size() == 1) {
    const run_bounce& only = run_bounces_[0];
    bounce(only.index, only.speed, only.timed);
    return true;
  }
  const constraint& first_k = constraints_[run_bounces_[0].index];
  const solver_body& a = impact_bodies_[first_k.place_a];
  const solver_body& b = impact_bodies_[first_k.place_b];
  // (Converged when no impulse changes any point's speed by more than
  // 1e-12 of the speeds at stake; 64 sweeps at most.)
  for (int sweep = 0; sweep < 64; ++sweep) {
    real largest_change = 0;
    for (run_bounce& x : run_bounces_) {
      const constraint& k = constraints_[x.index];
      const real wanted = (x.target - normal_speed(x.index, a, b)) * k.normal_mass;
      const real total = std::max(x.total + wanted, real(0));
      const real j = total - x.total;
      x.total = total;
      if (j == 0) continue;
      apply_impact_normal(x.index, j);
      largest_change = std::max(largest_change, std::fabs(j) * k.mass_inverse);
    }
    if (!(largest_change > detail::by_precision(1e-12, 1e-6) * largest_target)) break;
  }
  bool any = false;
  for (const run_bounce& x : run_bounces_) {
    if (!(x.total > 0)) continue;
    finish_impact(x.index, x.total, x.timed);
    any = true;
  }
  return any;
}

// The impact phase: sweeps over the contacts until none bounces. A row of
// touching balls struck at one end passes the impact on one contact per
// impact (Newton's cradle: the far ball leaves, the rest stop), however
// the contacts are ordered; sweeps that meet the row against its order
// need one sweep per ball.
void contact_solver::resolve_impacts(const world_settings& settings, real h) {
  // The same per run of contacts between the same two bodies (consecutive
  // in contact order, they bounce together: impact_run), with its bodies:
  // whether a contact of it can bounce, and whether one bounces by itself.
  // (The sweeps below read only these: reading each contact's bodies and
  // filter in each sweep, they took 0.4 ms of a 10,000-sphere step.)
  const std::vector<std::size_t>& begins = colouring_.run_begins;
  const std::size_t runs = begins.size() - 1;
  impact_runs_.resize(runs);
  detail::parallel_for(settings.threads, runs, 4096, [&](std::size_t r) {
    const auto [body_a, body_b] = colouring_.pairs[begins[r]];
    impact_run_filter& run = impact_runs_[r];
    run = {static_cast<std::uint32_t>(body_a), static_cast<std::uint32_t>(body_b), false, false};
    for (std::size_t i = begins[r]; i < begins[r + 1]; ++i) {
      const impact_filter& f = impact_filters_[slot_[i]];
      run.can_bounce = run.can_bounce || f.can_bounce;
      run.starts = run.starts || (f.can_bounce && f.starts);
    }
  });
  // Impacts start only at contacts that bounce from the start velocities.
  const bool any_bounce = std::any_of(impact_runs_.begin(), impact_runs_.end(),
                                      [](const impact_run_filter& run) { return run.starts; });
  if (!any_bounce) return;
  const real threshold = settings.restitution_threshold;
  for (int sweep = 0; sweep < settings.impact_iterations; ++sweep) {
    bool any = false;
    for (std::size_t r = 0; r < runs; ++r) {
      const impact_run_filter& run = impact_runs_[r];
      // (impact() would return false: no restitution, or neither body struck
      // yet and no contact bounces by itself.)
      if (!run.starts && !(run.can_bounce && (impacted_[run.body_a] || impacted_[run.body_b]))) {
        continue;
      }
      const std::size_t i = begins[r], end = begins[r + 1];
      any =
          (end - i == 1 ? impact(slot_[i], threshold, h) : impact_run(i, end, threshold, h)) || any;
    }
    if (!any) break;
  }
}

// The last step's contact at the same point as contact i, searched in the
// run of contacts from `run` on that share its bodies and have not warm
// started a contact yet (previous_used_): the same two shapes and the same
// feature ids, or else (a feature the narrow phase names differently now,
// such as a corner that crossed a side of the face it rests on by a
// rounding error) the nearest point of the same two shapes within 5% of the
// smaller shape's size. previous.size() when there is none. (Read from the
// keys, 12 bytes a contact, where the contacts are 248.)
std::size_t contact_solver::same_point(std::size_t i, std::size_t run,
                                       const std::vector<contact>& contacts,
                                       const std::vector<contact>& previous,
                                       const std::vector<body>& bodies) const {
  const std::size_t end = previous.size();
  const body_pair& pair = colouring_.pairs[i];
  const point_key& key = keys_[i];
  const auto candidate = [&](std::size_t k) { return k < end && previous_pairs_[k] == pair; };
  if (!candidate(run)) return end;  // (a pair that begins)
  const auto same_shapes = [&](const point_key& o) {
    return o.shape_a == key.shape_a && o.shape_b == key.shape_b;
  };
  for (std::size_t k = run; candidate(k); ++k) {
    if (!previous_used_[k] && same_shapes(previous_keys_[k]) &&
        previous_keys_[k].feature == key.feature)
      return k;
  }
  const contact& c = contacts[i];
  const real size = std::min(bodies[c.body_a].shapes()[c.shape_a].shape.bounding_radius(),
                             bodies[c.body_b].shapes()[c.shape_b].shape.bounding_radius());
  real nearest = real(0.05) * size;
  std::size_t found = end;
  for (std::size_t k = run; candidate(k); ++k) {
    if (previous_used_[k] || !same_shapes(previous_keys_[k])) continue;
    const real distance = e3ga::norm(previous[k].geometry.point - c.geometry.point);
    if (distance < nearest) nearest = distance, found = k;
  }
  return found;
}

// Warm start: both lists are sorted by body pair, so one merge finds the
// pairs that persist, and within a pair the same shapes' same feature ids
// the points that do. The sweeps correct the old impulses as needed (down
// to zero), so the result does not depend on them, only how fast the sweeps
// get there. Friction and resistance impulses are kept as world-frame
// vectors and bivectors and read in the new contact frame.
void contact_solver::cut_for_matches(const std::vector<contact>& contacts,
                                     const std::vector<contact>& previous, int shares) {
  // Each old contact warm starts one new one at most: two new points near
  // one old one would both take its whole impulse.
  previous_used_.assign(previous.size(), 0);
  matches_.resize(contacts.size());
  // Both lists cut before the same pairs (pair_cuts.hpp): a contact only
  // matches old ones of its own pair, so each share marks only its own old
  // contacts used, and the shares can run on any threads.
  detail::cut_at_pairs(previous, contacts, shares, warm_cuts_);
}

void contact_solver::match_share(int share, const std::vector<body>& bodies,
                                 const std::vector<contact>& contacts,
                                 const std::vector<contact>& previous) {
  std::size_t run = warm_cuts_.old[share];
  for (std::size_t i = warm_cuts_.now[share]; i < warm_cuts_.now[share + 1]; ++i) {
    const body_pair& pair = colouring_.pairs[i];
    while (run < previous.size() && previous_pairs_[run] < pair) ++run;
    const std::size_t match = same_point(i, run, contacts, previous, bodies);
    matches_[i] = match;
    if (match != previous.size()) previous_used_[match] = 1;
  }
}

// Up to `sweeps` sweeps over the colours (contact_colouring.hpp): in each,
// solve(sweep, colour, block, part, result) for the parts of every colour's
// blocks, colour by colour, then sequential(sweep, result) for the
// sequential group; a sweep whose results (each thread's, gathered) have
// `converged` is the last. On one thread, the whole of each colour in
// order (block 0's own runs); on several, each thread its block of each
// colour (solve_in_parts), the sequential group on one of them after
// every colour is done, and a barrier per sweep before the threads read
// each other's results. The runs of a colour share no body that moves, so
// every body changes in the same order on any number of threads.
template <class Solve, class Sequential, class Converged>
void contact_solver::sweep_colours(int sweeps, const Solve& solve, const Sequential& sequential,
                                   const Converged& converged) {
  using part = detail::contact_colouring::part;
  const std::size_t colours = colouring_.colours();
  const auto threads = static_cast<std::size_t>(sweep_threads_);
  if (threads == 1) {
    for (int sweep = 0; sweep < sweeps; ++sweep) {
      sweep_result result;
      for (std::size_t colour = 0; colour < colours; ++colour) {
        solve(sweep, colour, std::size_t{0}, part::own_runs, result);
      }
      sequential(sweep, result);
      if (converged(result)) break;
    }
    return;
  }
  // Each thread's sweep results, in two rows used in turn by alternate
  // sweeps: a thread may write the next sweep's while another still reads
  // this one's.
  thread_results_.assign(2 * threads, sweep_result{});
  reset_shared_solved();
#pragma omp parallel num_threads(sweep_threads_)
  {
    const auto thread = static_cast<std::size_t>(omp_get_thread_num());
    const auto team = static_cast<std::size_t>(omp_get_num_threads());
    for (int sweep = 0; sweep < sweeps; ++sweep) {
      sweep_result mine;
      for (std::size_t colour = 0; colour < colours; ++colour) {
        solve_in_parts(
            colour, static_cast<std::uint64_t>(sweep) * colours + colour, thread, team,
            [&](std::size_t c, std::size_t block, part p) { solve(sweep, c, block, p, mine); });
      }
      // Every colour done, on every thread.
#pragma omp barrier
#pragma omp single nowait
      sequential(sweep, mine);
      sweep_result* row = &thread_results_[(sweep % 2) * threads];
      row[thread] = mine;
      // The sequential group is done and every result written.
#pragma omp barrier
      sweep_result all;
      for (std::size_t t = 0; t < threads; ++t) {
        all.largest_change = std::max(all.largest_change, row[t].largest_change);
        all.any = all.any || row[t].any;
      }
      if (converged(all)) break;
    }
  }
}

// Calls visit(first, end) over the slots [first, end) of the sweeps' order,
// colour by colour, the sequential group last: one sweep of sweep_colours.
// The runs of a colour share no body that moves, so what visit adds to
// each body adds up in the same order on any number of threads.
template <class Visit>
void contact_solver::by_colours(const Visit& visit) {
  sweep_colours(
      1,
      [&](int, std::size_t colour, std::size_t block, detail::contact_colouring::part p,
          sweep_result&) {
        const auto [first, end] = slots_of(colour, block, p);
        visit(first, end);
      },
      [&](int, sweep_result&) {
        const auto [first, end] = sequential_slots();
        visit(first, end);
      },
      [](const sweep_result&) { return true; });
}

std::pair<std::size_t, std::size_t> contact_solver::slots_of(
    std::size_t colour, std::size_t block, detail::contact_colouring::part p) const {
  const auto [first_run, end_run] =
      colouring_.runs_of(colour, block, static_cast<std::size_t>(sweep_threads_), p);
  return {colouring_.run_starts[first_run], colouring_.run_starts[end_run]};
}

std::pair<std::size_t, std::size_t> contact_solver::sequential_slots() const {
  return {colouring_.run_starts[colouring_.colour_starts.back()], colouring_.run_starts.back()};
}

// One thread's share of colour `colour` (on `team` threads of the sweep's
// T): visit(colour, block, part) for its block's shared runs, once every
// other thread has visited its shared runs of the colours before (`count`
// colours, counted on across sweeps, in shared_solved_, from
// reset_shared_solved), then for its own runs, which no other thread's
// runs move (contact_colouring.hpp). While one thread visits its own runs,
// the others' shared runs of the colour get done: a thread waits only
// where the others fall behind by a whole colour. (With a barrier between
// colours, the two threads of 10,000 spheres' sweeps waited for each other
// a fifth of the time.) Where OpenMP gave fewer threads than asked (inside
// an application's own parallel region, one), a thread visits the missing
// threads' blocks too, with a barrier after each colour.
template <class Visit>
void contact_solver::solve_in_parts(std::size_t colour, std::uint64_t count, std::size_t thread,
                                    std::size_t team, const Visit& visit) {
  using part = detail::contact_colouring::part;
  const auto threads = static_cast<std::size_t>(sweep_threads_);
  if (team != threads) {
    for (std::size_t owner = thread; owner < threads; owner += team) {
      visit(colour, owner, part::shared_runs);
      visit(colour, owner, part::own_runs);
    }
#pragma omp barrier
    return;
  }
  for (std::size_t other = 0; other < threads; ++other) {
    if (other != thread) detail::wait_until_at_least(shared_solved_[other].value, count);
  }
  visit(colour, thread, part::shared_runs);
  shared_solved_[thread].value.store(count + 1, std::memory_order_release);
  visit(colour, thread, part::own_runs);
}

void contact_solver::reset_shared_solved() {
  if (shared_solved_count_ < sweep_threads_) {
    shared_solved_ = std::make_unique<detail::cache_padded<std::atomic<std::uint64_t>>[]>(
        static_cast<std::size_t>(sweep_threads_));
    shared_solved_count_ = sweep_threads_;
  }
  for (int t = 0; t < sweep_threads_; ++t) {
    shared_solved_[t].value.store(0, std::memory_order_relaxed);
  }
}

void contact_solver::warm_start(const std::vector<contact>& previous) {
  // The old impulses in the sweeps' order (by_colours). (In contact order,
  // on one thread, they took 0.5-0.6 ms of a 10,000-sphere step on two
  // threads, the second idle; 0.25-0.3 ms so.)
  by_colours([&](std::size_t first, std::size_t end) { warm_start_slots(first, end, previous); });
}

void contact_solver::warm_start_slots(std::size_t first, std::size_t end,
                                      const std::vector<contact>& previous) {
  for (std::size_t s = first; s < end; ++s) {
    const std::size_t match = matches_[colouring_.order[s]];
    if (match == previous.size()) continue;
    const contact* old = &previous[match];
    constraint& k = constraints_[s];
    if (!(k.mass_inverse > 0) || k.waits) continue;
    solver_body& a = solver_bodies_[k.place_a];
    solver_body& b = solver_bodies_[k.place_b];
    const contact_impulse& resting = old->resting;
    k.accumulated = resting.normal;
    apply_normal(s, a, b, k.accumulated);
    if (k.surface < 0) continue;
    surface_terms& t = surfaces_[k.surface];
    const surface_frame& f = frames_[k.surface];
    if (t.friction.active()) {
      const std::array<real, 2> held{e3ga::scp(resting.tangent, f.frame[0]),
                                     e3ga::scp(resting.tangent, f.frame[1])};
      t.friction.start_from(a, b, detail::within_disk(held, t.friction_coefficient * k.accumulated));
    }
    if (t.resistance < 0) continue;
    resistance_terms& r = resistances_[t.resistance];
    // An angular impulse L = Σ λ_i U_i on unit planes reads back λ_i = -L . U_i.
    if (r.rolling.active()) {
      const std::array<real, 2> held{-e3ga::scp(resting.angular, r.planes[0]),
                                     -e3ga::scp(resting.angular, r.planes[1])};
      r.rolling.start_from(a, b, detail::within_disk(held, r.rolling_bound * k.accumulated));
    }
    if (r.spinning.mass_inverse > 0) {
      const real bound = r.spinning_bound * k.accumulated;
      r.spinning_accumulated = std::clamp(-e3ga::scp(resting.angular, r.planes[2]), -bound, bound);
      r.spinning.apply(a, b, r.spinning_accumulated);
    }
  }
}

// The contact phase: sequential impulses. Each sweep drives every contact
// to its normal target with the impulse j n on A and -j n on B, the total
// per contact kept >= 0 (contacts push, never pull), then its friction
// towards no slip within the cone |λ_t| <= μ λ_n, and its rolling and
// spin towards none within c ρ λ_n. A sweep that changes no speed by more
// than the tolerance has converged, and ends the solve early.
//
// The sweeps visit the contacts colour by colour (contact_colouring.hpp):
// the runs of a colour share no body the solver changes, so they are
// solved on all the threads at once, and the result is the same to the bit
// with any number of threads.
void contact_solver::solve_contacts(const world_settings& settings) {
  // Every contact gets solver_iterations sweeps; contacts that turn a body
  // get turning_iterations more (a stack of boxes converges slowly). Where
  // none turns (settling_ false: none turns or rubs), there are none more:
  // the first would only find that out, at a wait per colour.
  const int sweeps = settings.solver_iterations + (settling_ ? settings.turning_iterations : 0);
  const std::size_t runs = colouring_.runs();
  const auto kind_of = [&](int sweep) {
    // The last sweep of a contact is plain: it takes back what
    // over-relaxation pushed contacts apart beyond their targets.
    return sweep_kind{sweep >= settings.solver_iterations, sweep + 1 == settings.solver_iterations,
                      sweep + 1 == sweeps, static_cast<std::uint64_t>(sweep) * runs};
  };
  const auto converged = [&](const sweep_result& r) {
    return !r.any || r.largest_change <= settings.solver_tolerance;
  };
  settle_tolerance_ = settings.solver_tolerance;
  // Plain contacts (frictionless, through the centres) cost about as much to
  // solve as to check and record: where all are plain (1,000 frictionless
  // spheres), passing settled runs by made the sweeps run 40% more
  // instructions, so there every run is solved in every sweep. (settling_:
  // whether any is not, set by solve_velocities.)
  if (settling_) {
    run_states_.resize(runs);
    for (std::size_t run = 0; run < runs; ++run) {
      const constraint& first = constraints_[colouring_.run_starts[run]];
      run_states_[run] = {0, first.place_a, first.place_b};
    }
    body_disturbed_.assign(solver_bodies_.size(), 0);
    body_drift_.assign(solver_bodies_.size(), 0);
  }
  const std::size_t sequential = colouring_.colour_starts.back();
  // (Every contact plain and none on batches: the sweeps read half a body
  // each, detail::plain_body.)
  plain_sweeps_ = !settling_ && groups_.empty();
  plain_lanes_ = plain_sweeps_ ? plain_lanes() : 0;
  if (plain_sweeps_) copy_to_plain_bodies();
  if (plain_lanes_ > 0) put_plain_contacts();
  sweep_colours(
      sweeps,
      [&](int sweep, std::size_t colour, std::size_t block, detail::contact_colouring::part p,
          sweep_result& result) {
        solve_part(part_index(colour, block, p), kind_of(sweep), result);
      },
      [&](int sweep, sweep_result& result) {
        solve_runs(sequential, runs, kind_of(sweep), result);
      },
      converged);
  if (plain_lanes_ > 0) store_plain_impulses();
  if (plain_sweeps_) copy_from_plain_bodies();
}

// Runs first_run .. end_run - 1 of the colouring, in order, but for the
// settled ones (settled_run) where the step passes them by.
void contact_solver::solve_runs(std::size_t first_run, std::size_t end_run, const sweep_kind& kind,
                                sweep_result& result) {
  if (!settling_) {
    const std::size_t first = colouring_.run_starts[first_run];
    const std::size_t end = colouring_.run_starts[end_run];
    if (plain_sweeps_) {
      solve_plain_contacts(first, end, kind, plain_bodies_, result);
    } else {
      solve_plain_contacts(first, end, kind, solver_bodies_, result);
    }
    return;
  }
  for (std::size_t run = first_run; run < end_run; ++run) {
    if (settled_run(run)) continue;
    sweep_result mine;
    for (std::size_t i = colouring_.run_starts[run]; i < colouring_.run_starts[run + 1]; ++i) {
      solve_contact(i, kind, mine);
    }
    record_run(run, kind.stamps + run + 1, mine.largest_change);
    result.any = result.any || mine.any;
    result.largest_change = std::max(result.largest_change, mine.largest_change);
  }
}

// solve_contact for contacts s in [first, end) where no contact turns a body
// or rubs (settling_ is false): only the normal row, through the centres.
// The same operations on the same numbers as solve_contact; without its
// checks for turning, friction and resistance, and with the sweep's result
// kept in registers, a sphere pile's contact took a third fewer
// instructions. Every impulse is applied, zero or not: whether a contact
// gets none (most speculative ones) follows no pattern from contact to
// contact, and the branch around a zero impulse, mispredicted, cost more
// than adding it (with the clamp branch-free too, at_least_zero: 1,000
// spheres' steps 2.4-3.6% faster, 10,000's 4.4%, on one thread; a zero
// impulse leaves every velocity as it was, but a -0 component, which
// becomes +0). solve_contact keeps the branch: a box's contact, whose
// rows turn it, stepped 1-3% slower without.
//
// (In double on x86-64, the colours' plain sweeps take their contacts two,
// four or eight at a time instead: solve_plain_part, plain_pairs.hpp.)
template <class Body>
void contact_solver::solve_plain_contacts(std::size_t first, std::size_t end,
                                          const sweep_kind& kind, std::vector<Body>& bodies,
                                          sweep_result& result) {
  // (Past solver_iterations only contacts that turn a body are solved.)
  if (kind.turning_only) return;
  real largest_change = 0;
  bool any = false;
  // (The arrays in locals and a loop for each kind of sweep: GCC read the
  // arrays' addresses and the kind again for every contact, as the
  // contact's stores might have changed them; the sweeps' share of the
  // samples of a perf profile of 1,000 spheres fell by 5%.)
  constraint* const rows = constraints_.data();
  Body* const at = bodies.data();
  const auto sweep = [&](auto last) {
    for (std::size_t s = first; s < end; ++s) {
      constraint& k = rows[s];
      if (left_out(k)) continue;
      any = true;
      solve_plain(k, at[k.place_a], at[k.place_b], last(), largest_change);
    }
  };
  if (kind.last_of_all) {
    sweep(std::true_type{});
  } else {
    sweep(std::false_type{});
  }
  result.any = result.any || any;
  result.largest_change = std::max(result.largest_change, largest_change);
}

GAPHYS_ALWAYS_INLINE void contact_solver::solve_contact(std::size_t s, const sweep_kind& kind,
                                                        sweep_result& result) {
  constraint& k = constraints_[s];
  if (left_out(k)) return;
  // The extra sweeps are for stacks, whose contacts push: one that turns a
  // body but holds no impulse after solver_iterations sweeps (mostly a
  // speculative contact a body does not reach in this step) keeps that.
  if (kind.turning_only && (!k.turns || !(k.accumulated > 0))) return;
  result.any = true;
  real& largest_change = result.largest_change;
  const bool last = k.turns ? kind.last_of_turning : kind.last_of_all;
  const detail::row_arms* arms = normal_arms(s);
  solver_body& a = solver_bodies_[k.place_a];
  solver_body& b = solver_bodies_[k.place_b];
  const real j = normal_impulse(k, detail::row_speed(k.normal, arms, a, b), last, largest_change);
  surface_terms* rubbing = k.surface < 0 ? nullptr : &surfaces_[k.surface];
  // Nothing pushes and nothing is held: nothing to rub (a speculative contact).
  if (rubbing && !(k.accumulated > 0) && holds_nothing(*rubbing)) rubbing = nullptr;
  if (rubbing && rubbing->friction.active()) {
    // The normal impulse goes with friction's (disk_block::solve_after).
    surface_terms& t = *rubbing;
    const real change = t.friction.solve_after(a, b, t.friction_coefficient * k.accumulated,
                                               k.normal, arms, j, t.normal_coupling, last);
    largest_change = std::max(largest_change, change * t.friction.rows[0].mass_inverse);
  } else if (j != 0) {
    // (Most speculative contacts hold no impulse and get none.)
    detail::row_apply(k.normal, arms, a, b, j);
  }
  if (!rubbing) return;
  surface_terms& t = *rubbing;
  if (t.resistance < 0) return;
  resistance_terms& r = resistances_[t.resistance];
  if (r.rolling.active()) {
    const real change = r.rolling.solve(a, b, r.rolling_bound * k.accumulated);
    largest_change = std::max(largest_change, change * r.rolling.rows[0].mass_inverse);
  }
  if (r.spinning.mass_inverse > 0) {
    const real change = detail::solve_bounded(r.spinning, r.spinning_accumulated, a, b,
                                              r.spinning_bound * k.accumulated);
    largest_change = std::max(largest_change, change * r.spinning.mass_inverse);
  }
}

// (Forced inline into its one caller, solve_velocities: left to itself,
// GCC stopped inlining it once solve_contacts' loop became sweep_colours,
// and a step of 1,000 spheres ran 0.4% more instructions, 1.6% longer.)
GAPHYS_ALWAYS_INLINE void contact_solver::store_impulses(std::vector<contact>& contacts,
                                                         int threads) const {
  // (On several threads of sweeps, each contact on the thread that solved
  // it, whose cache holds its constraint (for_each_constraint): on the
  // threads in halves of the list, 0.1-0.2 ms slower at 10,000 spheres.)
  const auto store = [&](std::size_t i, std::size_t slot) {
    // (Read in contact order, the constraints are scattered: prefetch.hpp.
    // Asked for here, not as for_each_constraint's `ahead`, which one
    // thread of sweeps does not call.)
    if (i + detail::prefetch_distance < contacts.size()) {
      const std::size_t ahead = slot_[i + detail::prefetch_distance];
      detail::prefetch_bytes(&constraints_[ahead], sizeof(constraint));
      detail::prefetch(&impacts_[ahead]);
    }
    // (Made here and stored whole: cleared in place and read back, the
    // impulses' stores and loads of other widths stalled their forwarding,
    // a fifth of this loop.)
    const constraint& k = constraints_[slot];
    const impact_terms& impact = impacts_[slot];
    contact_impulse resting{};
    resting.normal = k.accumulated;
    contact_impulse total = resting;
    total.normal += impact.normal;
    if (k.surface >= 0) {
      const surface_terms& t = surfaces_[k.surface];
      const surface_frame& f = frames_[k.surface];
      resting.tangent =
          t.friction.accumulated[0] * f.frame[0] + t.friction.accumulated[1] * f.frame[1];
      if (t.resistance >= 0) {
        const resistance_terms& r = resistances_[t.resistance];
        resting.angular = r.rolling.accumulated[0] * r.planes[0] +
                          r.rolling.accumulated[1] * r.planes[1] +
                          r.spinning_accumulated * r.planes[2];
      }
      total.tangent =
          resting.tangent + f.impact_tangent[0] * f.frame[0] + f.impact_tangent[1] * f.frame[1];
      total.angular = resting.angular;
    }
    contact& c = contacts[i];
    c.resting = resting;
    c.impulse = total;
    c.approach_speed = impact.approach_speed;
  };
  for_each_constraint(threads, store, [](std::size_t) {});
}

// Visits each contact i with its slot s, in contact order, by body pair:
// read in the sweeps' order, the contacts and their bodies were a scattered
// read each, a third of solve_velocities' time at 10,000 spheres. On
// several threads of sweeps, each contact on the thread that solves its
// slot in the sweeps (owners_): the constraint is then in that thread's
// cache when the sweeps begin, and no two threads write the neighbouring
// slots of a cache line. (Written from the contacts' order on whichever
// thread took them, the constraints of 10,000 spheres took 1.2 ms on two
// threads against 0.8 on one; visited in each thread's slots' order, the
// contacts, large and scattered, many written by the other core, were
// read 0.1-0.25 ms a step slower than front to back, each thread passing
// by the other's; 2026-12-06, a 2-core Xeon.) There, `ahead(i)` asks for
// what visit will read of contact i, a few contacts later (prefetch.hpp):
// the contacts' bodies are scattered.
template <class Visit, class Ahead>
void contact_solver::for_each_constraint(int threads, const Visit& visit,
                                         const Ahead& ahead) const {
  const std::size_t count = colouring_.order.size();
  if (sweep_threads_ == 1) {
    detail::parallel_for(threads, count, 512, [&](std::size_t i) { visit(i, slot_[i]); });
    return;
  }
  const auto blocks = static_cast<std::size_t>(sweep_threads_);
#pragma omp parallel num_threads(sweep_threads_)
  {
    const auto thread = static_cast<std::size_t>(omp_get_thread_num());
    const auto team = static_cast<std::size_t>(omp_get_num_threads());
    // (Where OpenMP gave fewer threads than asked, the missing threads'
    // contacts too.)
    const auto mine = [&](std::size_t i) {
      return team == blocks ? owners_[i] == thread : owners_[i] % team == thread;
    };
    for (std::size_t i = 0; i < count; ++i) {
      if (!mine(i)) continue;
      if (i + detail::prefetch_distance < count) ahead(i + detail::prefetch_distance);
      visit(i, slot_[i]);
    }
  }
}

// Each contact's slot in the sweeps' order (slot_) and, for T > 1 blocks,
// its thread in the sweeps (owners_: the block of its colour its slot is
// in; the sequential group's, thread 0). On the threads for many contacts,
// each reading the whole order and writing the entries of its own share of
// the contacts, the others' going to a spare: split by slots instead, two
// threads wrote entries of the same lines at random and took the lines
// from each other.
void contact_solver::find_slots(int threads) {
  const std::vector<std::size_t>& order = colouring_.order;
  const std::size_t count = order.size();
  const std::size_t blocks = sweep_threads_ > 1 ? static_cast<std::size_t>(sweep_threads_) : 0;
  slot_.resize(count);
  owners_.resize(blocks > 0 ? count : 0);
  const std::vector<std::size_t>& run_starts = colouring_.run_starts;
  const int shares = detail::threads_for(threads, count, 4096);
#pragma omp parallel num_threads(shares) if (shares > 1)
  {
    const auto team = static_cast<std::size_t>(omp_get_num_threads());
    const auto thread = static_cast<std::size_t>(omp_get_thread_num());
    const std::size_t first = count * thread / team, end = count * (thread + 1) / team;
    std::size_t spare_slot = 0;
    std::uint16_t spare_owner = 0;
    // (Where the entry goes chosen without a branch: half the entries are
    // the other thread's, in no pattern.)
    const auto take = [&](std::size_t from_run, std::size_t end_run, std::size_t owner) {
      for (std::size_t s = run_starts[from_run]; s < run_starts[end_run]; ++s) {
        const std::size_t i = order[s];
        const bool mine = i - first < end - first;
        *(mine ? &slot_[i] : &spare_slot) = s;
        if (blocks > 0) *(mine ? &owners_[i] : &spare_owner) = static_cast<std::uint16_t>(owner);
      }
    };
    const std::size_t coloured = colouring_.colour_starts.back();
    if (blocks > 0) {
      for (std::size_t c = 0; c < colouring_.colours(); ++c) {
        const std::size_t* runs = &colouring_.thread_starts[c * (blocks + 1)];
        for (std::size_t b = 0; b < blocks; ++b) take(runs[b], runs[b + 1], b);
      }
    } else {
      take(0, coloured, 0);
    }
    take(coloured, colouring_.runs(), 0);
  }
}

void contact_solver::solve_velocities(const world_settings& settings, std::vector<body>& bodies,
                                      const std::vector<body_velocity>& start,
                                      std::vector<contact>& contacts,
                                      const std::vector<contact>& previous, bool previous_solved,
                                      real h) {
  // The constraints in the sweeps' order, so that each sweep reads them
  // front to back; where each one's optional terms go, then the terms (on
  // several threads for many contacts: a box's take about 0.2 µs).
  const std::size_t count = contacts.size();
  // (A few hundred contacts per thread: fewer are not worth a wait per colour.)
  sweep_threads_ = detail::threads_for(settings.threads, count, 256);
  // What the step's forces gave each body; then each contact's bodies, and
  // which of them rests on the other (find_supports), in one pass over the
  // contacts. (Read by find_supports itself, on one thread, the contacts
  // took 0.4 ms of a 10,000-sphere step.)
  forced_.resize(bodies.size());
  positions_.resize(bodies.size());
  colouring_.moves.resize(bodies.size());
  detail::parallel_for(settings.threads, bodies.size(), 4096, [&](std::size_t i) {
    const body& b = bodies[i];
    forced_[i] = b.velocity_ - start[i].linear;
    // (What colour_contacts reads of the bodies: whether each has mass, and
    // where it is.)
    colouring_.moves[i] = b.inverse_mass_ > 0;
    positions_[i] = b.position_;
  });
  // The last step's keys, from its pass below where `previous` is the list
  // it solved (else read again); then this step's with the contacts' bodies
  // and resting sides, in one pass over the contacts.
  previous_pairs_.swap(colouring_.pairs);
  previous_keys_.swap(keys_);
  if (!previous_solved || previous_keys_.size() != previous.size()) {
    previous_pairs_.resize(previous.size());
    previous_keys_.resize(previous.size());
    detail::parallel_for(settings.threads, previous.size(), 4096, [&](std::size_t i) {
      previous_pairs_[i] = {previous[i].body_a, previous[i].body_b};
      previous_keys_[i] = key_of_point(previous[i]);
    });
  }
  rests_.resize(count);
  keys_.resize(count);
  own_terms_.resize(count);
  std::atomic<bool> any_terms{false};  // (most worlds: no friction, no resistance)
  detail::read_pairs(contacts, colouring_, settings.threads, [&](std::size_t i) {
    const contact& c = contacts[i];
    rests_[i] = resting_sides(settings, c);
    keys_[i] = key_of_point(c);
    const term_counts own = terms_of(bodies[c.body_a], bodies[c.body_b], c);
    own_terms_[i] = static_cast<unsigned char>(own.surfaces | own.resistances << 1);
    if (own_terms_[i] != 0) detail::raise_flag(any_terms);
  });
  // The colouring is mostly serial (its greedy pass); on two threads or
  // more, one colours while the others prepare what needs no colouring.
  // (One after the other, each on the threads, the colouring left the
  // second thread idle for half a millisecond of a 10,000-sphere step.)
  if (sweep_threads_ > 1) {
    colour_beside_preparation(bodies, start, contacts, previous);
  } else {
    detail::colour_contacts(positions_, colouring_, settings.threads, sweep_threads_);
    prepare_bodies(bodies, start, contacts, previous, settings.threads);
    find_supports(bodies.size());
    count_contacts(bodies.size(), colouring_.pairs);
  }
  find_slots(settings.threads);
  // Where each constraint's optional terms go, in the sweeps' order. (Each
  // contact's own were read with its bodies above: read here in that order,
  // the contacts were a scattered read, 0.12-0.15 ms of a 10,000-sphere
  // step on one or two threads, most often to find none.)
  const bool with_terms = any_terms.load(std::memory_order_relaxed);
  term_counts total;
  if (with_terms) {
    terms_at_.resize(count);
    for (std::size_t s = 0; s < count; ++s) {
      terms_at_[s] = total;
      const unsigned char own = own_terms_[colouring_.order[s]];
      total.surfaces += own & 1u;
      total.resistances += own >> 1;
    }
  }
  detail::resize_in_huge_pages(constraints_, count);
  detail::resize_in_huge_pages(normal_arms_, count);
  detail::resize_in_huge_pages(impacts_, count);
  detail::resize_in_huge_pages(impact_filters_, count);
  surfaces_.resize(total.surfaces);
  frames_.resize(total.surfaces);
  resistances_.resize(total.resistances);
  const auto fetch = [&](std::size_t i) {
    const auto& [a, b] = colouring_.pairs[i];
    detail::prefetch_bytes(&contacts[i], offsetof(contact, impulse));  // (what it reads)
    for (const std::size_t x : {a, b}) {
      detail::prefetch(&bodies[x]);
      detail::prefetch(&bodies[x].position());
      detail::prefetch(&start[x]);
      // (And what the preparation wrote of them, on either thread.)
      detail::prefetch(&row_bodies_[x]);
      detail::prefetch(&shape_summaries_[x]);
      detail::prefetch(&place_[x]);
      detail::prefetch(&contacts_per_body_[x]);
    }
  };
  for_each_constraint(
      settings.threads,
      [&](std::size_t i, std::size_t s) {
        const contact& c = contacts[i];
        build_constraint(settings, bodies[c.body_a], bodies[c.body_b], c, start[c.body_a],
                         start[c.body_b], h, s, with_terms ? terms_at_[s] : term_counts{});
      },
      fetch);

  // Whether any contact turns a body (one of its bodies is neither central
  // nor static: build_constraint's k.turns) or rubs (has surface terms),
  // from the bodies' summaries: read from every constraint instead, on one
  // thread, it took 0.15 ms of a 10,000-sphere step.
  settling_ = !surfaces_.empty();
  for (std::size_t i = 0; i < bodies.size() && !settling_; ++i) {
    settling_ = in_contact_[i] && !shape_summaries_[i].central && !bodies[i].is_static();
  }
  impacted_.assign(bodies.size(), 0);

  resolve_impacts(settings, h);
  warm_start(previous);
  pack_batches(settings);
  solve_contacts(settings);
  unpack_batches();
  store_impulses(contacts, settings.threads);
  detail::parallel_for(settings.threads, bodies.size(), 2048, [&](std::size_t i) {
    body& b = bodies[i];
    // (Placed by the sweeps' threads, the solver's copies are scattered.)
    if (i + detail::prefetch_distance < bodies.size()) {
      detail::prefetch(&solver_bodies_[place_[i + detail::prefetch_distance]]);
    }
    if (!b.is_dynamic()) return;  // contacts never change a static or kinematic body
    const solver_body& solved = solver_bodies_[place_[i]];
    b.velocity_ = solved.velocity;
    b.angular_velocity_ = solved.angular_velocity;
  });
}

void contact_solver::correct_positions(const world_settings& settings, std::vector<body>& bodies,
                                       const std::vector<contact>& contacts, real h) {
  // Each constraint's shifts of its bodies, made and added to them in the
  // sweeps' order (by_colours): they add up on each body in that order on
  // any number of threads. What they read is in the constraints and the
  // solver's copies of the bodies (the same velocities and masses, compact
  // where the bodies are large and scattered), which nothing here changes.
  // (Made first in contact order, from the contacts, into a list of shifts
  // that a second pass added, they took 4% of a 1,000-sphere step.)
  std::atomic<bool> any_turning{false};
  by_colours([&](std::size_t first, std::size_t end) {
    for (std::size_t s = first; s < end; ++s) {
      const constraint& k = constraints_[s];
      const solver_body& a = solver_bodies_[k.place_a];
      const solver_body& b = solver_bodies_[k.place_b];
      const real inverse_masses = a.inverse_mass + b.inverse_mass;
      if (!(inverse_masses > 0)) continue;
      // Only bodies with mass move (a static one may be in several runs of
      // a colour).
      const auto shift = [&](const vector& shift_a, const vector& shift_b) {
        if (a.inverse_mass > 0) {
          body& x = bodies[k.body_a];
          x.position_ = x.position_ + shift_a;
        }
        if (b.inverse_mass > 0) {
          body& x = bodies[k.body_b];
          x.position_ = x.position_ + shift_b;
        }
      };
      const impact_terms& record = impacts_[s];
      if (record.timed) {
        // The impulse J came at impact_time into the step, not at its
        // start: each body moved with its old velocity until then, t ΔV
        // less far.
        const vector moved = record.timing->time * record.timed_impulse;
        shift(-(a.inverse_mass * moved), b.inverse_mass * moved);
        continue;
      }
      // A speculative contact had a gap when the step began (its depth,
      // negative, is -gap; a contact in depth has gap = -depth exactly); if
      // its bodies overlap now (one left to bounce in a later step), the
      // next step meets them for real.
      if (k.gap > 0) continue;
      if (k.turns) {  // corrected below, turning the bodies too
        detail::raise_flag(any_turning);
        continue;
      }
      // The depth now, to first order: the positions moved by h v since the
      // narrow phase measured it, along its normal (the constraint's, but
      // where a timed impact turned that).
      const vector& n = record.timing ? contacts[colouring_.order[s]].geometry.normal : k.normal;
      const real depth = -k.gap - h * e3ga::scp(a.velocity - b.velocity, n);
      const real wanted = settings.position_correction * (depth - settings.linear_slop);
      if (!(wanted > 0)) continue;
      shift((wanted * a.inverse_mass / inverse_masses) * n,
            -((wanted * b.inverse_mass / inverse_masses) * n));
    }
  });
  if (any_turning.load(std::memory_order_relaxed)) correct_turning(settings, bodies, contacts, h);
}

// Contacts whose impulse turns a body (a box's corners, anything off a
// centre) share their bodies' depth: four corners pushing each by its own
// share would lift a box four times too far, and only a turn levels a
// tilted face. So they are corrected together, by pseudo velocities: the
// same sequential impulses as the contact phase, on velocities that start
// at zero, aimed at moving each contact apart by its share of the excess
// depth within the step; the bodies then move and turn by h times them and
// keep their real velocities and angular momenta (no impulse comes from the
// correction).
void contact_solver::correct_turning(const world_settings& settings, std::vector<body>& bodies,
                                     const std::vector<contact>& contacts, real h) {
  // The pseudo velocities where the solver keeps each body's velocities
  // (place_), and the contacts' terms in the sweeps' order (slots), so that
  // the sweeps below read both as the contact phase's sweeps do.
  // (On the threads: in turn on one, these passes took 0.33 ms of a
  // 10,000-box step on two, the second thread idle.) Places [0, bodies)
  // are the bodies', and their copies' masses the bodies'.
  pseudo_bodies_.resize(solver_bodies_.size());
  detail::parallel_for(settings.threads, place_.size(), 2048, [&](std::size_t p) {
    pseudo_bodies_[p] = {vector{}, bivector{}, solver_bodies_[p].inverse_mass};
  });
  const std::size_t count = contacts.size();
  pseudo_targets_.resize(count);
  pseudo_accumulated_.resize(count);
  // The contacts that turn a body take part, each with its depth now taken
  // to first order (the bodies moved and turned by h times their velocities
  // since the narrow phase measured it): one deeper than the slop is pushed
  // apart by its share of the excess; and beside those, every other such
  // contact of a body they push holds: one touching within the slop may not
  // close, one a gap apart may close it but no more. (With the deep ones
  // alone, the correction pushed a light box into the heavy one above it,
  // whose contact it ignored, and back the next step: six cubes of 1 and
  // 10 kg in turn, in float, gained energy for as long as they were stepped.
  // With every contact of a pile, 1,000 boxes stepped 17% slower.)
  constexpr char holds = 1, pushed_apart = 2;
  std::vector<char>& taking_part = pseudo_taking_part_;
  taking_part.resize(count);
  std::atomic<bool> any{false};
  for_each_constraint(
      settings.threads,
      [&](std::size_t i, std::size_t s) {
        pseudo_accumulated_[s] = 0;
        pseudo_targets_[s] = 0;
        taking_part[s] = 0;
        const constraint& k = constraints_[s];
        if (!k.turns || impacts_[s].timed || !(k.mass_inverse > 0)) return;
        const contact& c = contacts[i];
        const real depth = c.geometry.depth - h * normal_speed(s, solver_bodies_[k.place_a],
                                                               solver_bodies_[k.place_b]);
        const real excess = depth - settings.linear_slop;
        if (c.geometry.depth >= 0 && depth >= 0 && excess > 0) {
          pseudo_targets_[s] = settings.position_correction * excess / h;
          taking_part[s] = pushed_apart;
          detail::raise_flag(any);
        } else {
          pseudo_targets_[s] = depth < 0 ? depth / h : real(0);
          taking_part[s] = holds;
        }
      },
      [](std::size_t) {});
  if (!any.load(std::memory_order_relaxed)) return;
  // The bodies pushed apart (one pass, on one thread: two contacts of a
  // body may be on different threads), then the holding contacts of none.
  std::vector<char>& pushed = pseudo_pushed_;
  pushed.assign(bodies.size(), 0);
  for (std::size_t s = 0; s < count; ++s) {
    if (taking_part[s] != pushed_apart) continue;
    const constraint& k = constraints_[s];
    for (const std::size_t x : {k.body_a, k.body_b}) pushed[x] = bodies[x].is_dynamic();
  }
  detail::parallel_for(settings.threads, count, 4096, [&](std::size_t s) {
    if (taking_part[s] != holds) return;
    const constraint& k = constraints_[s];
    if (!pushed[k.body_a] && !pushed[k.body_b]) taking_part[s] = 0;
  });
  // Sequential impulses in the sweeps' order, colour by colour, as the
  // contact phase's: the same bits on any number of threads. (In contact
  // order, on one thread, they took 9% of a 10,000-box step, and a second
  // thread waited: B5 10,000 stepped in 37-41 ms on two threads, 34-35
  // so, 2026-12-06.)
  const auto sweep_slots = [&](std::size_t first, std::size_t end, sweep_result& result) {
    for (std::size_t s = first; s < end; ++s) {
      if (!taking_part[s]) continue;
      const constraint& k = constraints_[s];
      solver_body& a = pseudo_bodies_[k.place_a];
      solver_body& b = pseudo_bodies_[k.place_b];
      const real wanted = (pseudo_targets_[s] - normal_speed(s, a, b)) / k.mass_inverse;
      const real total = std::max(pseudo_accumulated_[s] + wanted, real(0));
      const real j = total - pseudo_accumulated_[s];
      apply_normal(s, a, b, j);
      pseudo_accumulated_[s] = total;
      result.largest_change = std::max(result.largest_change, std::fabs(j) * k.mass_inverse);
    }
  };
  sweep_colours(
      settings.solver_iterations,
      [&](int, std::size_t colour, std::size_t block, detail::contact_colouring::part p,
          sweep_result& result) {
        const auto [first, end] = slots_of(colour, block, p);
        sweep_slots(first, end, result);
      },
      [&](int, sweep_result& result) {
        const auto [first, end] = sequential_slots();
        sweep_slots(first, end, result);
      },
      [&](const sweep_result& r) { return r.largest_change <= settings.solver_tolerance; });
  detail::parallel_for(settings.threads, bodies.size(), 2048, [&](std::size_t i) {
    body& x = bodies[i];
    const solver_body& p = pseudo_bodies_[place_[i]];
    if (!x.is_dynamic()) return;
    x.position_ = x.position_ + h * p.velocity;
    const bivector& w = p.angular_velocity;
    if (w.e12() == 0 && w.e13() == 0 && w.e23() == 0) return;
    // The turn moves the body, and no impulse comes with it: its angular
    // momentum is kept, as integrate_positions keeps it through the step's
    // turn (where the inertia is unlike about some axes, Ω changes with
    // the attitude; a top on a frictionless floor, whose momentum about
    // the vertical nothing changes, lost 43% of it in 16 s).
    const bool isotropic = x.inertia_.is_isotropic();
    const bivector momentum = isotropic ? bivector{} : x.world_inertia(x.angular_velocity_);
    const rotor turned = e3ga::gp(e3ga::exp((-h / 2) * w), x.attitude_);
    x.attitude_ = turned / e3ga::norm(turned);
    if (!isotropic) x.angular_velocity_ = x.world_inverse_inertia(momentum);
  });
}

}  // namespace gaphys
