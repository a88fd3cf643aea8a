// The contact phase's sweeps on batches: `contact_lanes` runs of one colour
// (contact_colouring.hpp), which share no body the solver changes, solved at
// once, lane i the run in lane i. Each lane does exactly what the scalar
// solve (impulse_row.hpp, contact_solver::solve_contact) does to its contact,
// the same operations on the same numbers in the same order, with masks
// where the scalar solve branches; so a step is the same to the bit whichever
// runs share a batch, and with batches or without (test_contact_batches.cpp).
//
// The rows and bodies are e3ga's named types on packs (e3ga/batch.hpp), so
// the speeds and impulses run the generated kernels on W contacts at once.
// A body's velocities are gathered into lanes once per batch of runs and
// stay there while the run's contacts (a manifold's points, which all share
// the run's two bodies) are solved one after the other.
#pragma once

#include <array>
#include <e3ga/batch.hpp>

#include "gaphys/world.hpp"
#include "impulse_row.hpp"

namespace gaphys::detail {

// As wide as the target's vector registers (2 doubles with SSE2, 4 with
// AVX2, 8 with AVX-512): their masks are registers too, and a select is a
// few bitwise operations (a fixed-size pack's mask is a bit set, and
// turning it into a register took longer than the solve).
using pack = std::experimental::native_simd<real>;
using pack_mask = typename pack::mask_type;
inline constexpr int contact_lanes = static_cast<int>(pack::size());

// Whether `batching` puts a run of contacts in a batch here (runs with
// rolling or spinning resistance, which the packs leave out, never go).
// automatic: where a batch holds 4 or more lanes, the runs that turn a body
// or rub; not plain runs (frictionless contacts through the centres, a few
// products each: no faster on batches than their gathers cost). Measured in
// docs/benchmarks.md, "Contact batches": with 2 doubles (SSE2) even boxes
// lose.
inline bool batches_take(contact_batching batching, bool plain) {
  if (batching != contact_batching::automatic) return batching == contact_batching::on;
  return contact_lanes >= 4 && !plain;
}

using vector_pack = e3ga::basic_vector<pack>;
using bivector_pack = e3ga::basic_bivector<pack>;

// x where `mask`, else `otherwise`: per coordinate of a named type.
template <template <class> class Named>
GAPHYS_ALWAYS_INLINE Named<pack> select(const pack_mask& mask, const Named<pack>& x,
                                        Named<pack> otherwise) {
  for (int k = 0; k < Named<pack>::size; ++k) where(mask, otherwise.c[k]) = x.c[k];
  return otherwise;
}
GAPHYS_ALWAYS_INLINE pack select(const pack_mask& mask, const pack& x, pack otherwise) {
  where(mask, otherwise) = x;
  return otherwise;
}

// The velocities of one body per lane, as solver_body.
struct body_pack {
  vector_pack velocity;
  bivector_pack angular_velocity;
  pack inverse_mass;
  pack_mask moves;  // it has mass: static and kinematic bodies are only read

  // The bodies from[0 .. contact_lanes). (Their angular velocities even
  // where no lane turns them: zeros in their place, chosen by a branch,
  // made GCC 12 fail at -O3.)
  GAPHYS_ALWAYS_INLINE static body_pack gather(const solver_body* const* from) {
    body_pack x{no_init};
    for (int c = 0; c < 3; ++c) {
      x.velocity.c[c] = pack([&](auto lane) { return from[lane]->velocity.c[c]; });
      x.angular_velocity.c[c] = pack([&](auto lane) { return from[lane]->angular_velocity.c[c]; });
    }
    x.inverse_mass = pack([&](auto lane) { return from[lane]->inverse_mass; });
    x.moves = x.inverse_mass > 0;
    return x;
  }

 private:
  // (Value-initialized, the packs were zeroed before every gather: a
  // quarter of a sweep over spheres' contacts.)
  struct uninitialized {};
  static constexpr uninitialized no_init{};
  explicit body_pack(uninitialized) {}
};

// impulse_row, one per lane.
struct row_pack {
  vector_pack linear;
  bivector_pack arm_a, arm_b, turn_a, turn_b;
  pack mass_inverse{};

  void set_lane(int i, const impulse_row& row) {
    ga::set_lane(linear, i, row.linear);
    ga::set_lane(arm_a, i, row.arm_a);
    ga::set_lane(arm_b, i, row.arm_b);
    ga::set_lane(turn_a, i, row.turn_a);
    ga::set_lane(turn_b, i, row.turn_b);
    mass_inverse[i] = row.mass_inverse;
  }

  // impulse_row::speed of a row that does not turn (linear_speed) and of
  // one that does (speed).
  GAPHYS_ALWAYS_INLINE pack linear_speed(const body_pack& a, const body_pack& b) const {
    return e3ga::scp(linear, e3ga::sub(a.velocity, b.velocity));
  }
  GAPHYS_ALWAYS_INLINE pack speed(const body_pack& a, const body_pack& b) const {
    return linear_speed(a, b) + e3ga::lc(arm_a, a.angular_velocity) -
           e3ga::lc(arm_b, b.angular_velocity);
  }

  // impulse_row::apply in the lanes of `mask`; `turning`: those whose row
  // turns (where it does not, its turns are zero and the angular velocities
  // are left as they are).
  GAPHYS_ALWAYS_INLINE void apply(body_pack& a, body_pack& b, const pack& j, const pack_mask& mask,
                                  const pack_mask& turning) const {
    const pack_mask on_a = mask && a.moves, on_b = mask && b.moves;
    a.velocity =
        select(on_a, e3ga::add(a.velocity, e3ga::smul(j * a.inverse_mass, linear)), a.velocity);
    b.velocity =
        select(on_b, e3ga::sub(b.velocity, e3ga::smul(j * b.inverse_mass, linear)), b.velocity);
    if (none_of(turning)) return;
    a.angular_velocity = select(
        on_a && turning, e3ga::add(a.angular_velocity, e3ga::smul(j, turn_a)), a.angular_velocity);
    b.angular_velocity = select(
        on_b && turning, e3ga::sub(b.angular_velocity, e3ga::smul(j, turn_b)), b.angular_velocity);
  }
};

// What each sweep reads and changes of a contact's normal, one contact per
// lane (contact_solver::constraint).
struct normal_pack {
  row_pack row;
  pack normal_mass{}, target_speed{}, relaxation{}, accumulated{};
  pack_mask solvable{};  // mass_inverse > 0 and not a bounce that waits unstruck
  pack_mask turns{};     // the row turns a body
  int friction = -1;     // its lanes' friction in the friction packs, or -1: no lane rubs
};

// within_disk (impulse_row.hpp) in the lanes of `mask`.
GAPHYS_ALWAYS_INLINE std::array<pack, 2> within_disk(const std::array<pack, 2>& v,
                                                     const pack& bound, const pack_mask& mask) {
  const pack squared = v[0] * v[0] + v[1] * v[1];
  const pack_mask outside = mask && squared > bound * bound;
  if (none_of(outside)) return v;
  const pack scale = bound / sqrt(squared);
  return {select(outside, v[0] * scale, v[0]), select(outside, v[1] * scale, v[1])};
}

// outside_disk and nearest_on_disk (impulse_row.hpp) in the lanes of
// `outside`, their branches as masks and Newton's method run until every
// lane has stopped (one step where not `exact`), each lane's root frozen
// once it stops: each lane takes the steps, and rounds, that its contact
// solved alone would.
inline std::array<pack, 2> outside_disk(const std::array<pack, 2>& total, const pack& bound,
                                        const pack& eigen_ratio,
                                        const std::array<pack, 2>& eigenbasis, pack& slip_rate,
                                        const pack_mask& outside, const pack_mask& exact) {
  std::array<pack, 2> result = total;
  // No bound: nothing holds.
  const pack_mask none = outside && !(bound > 0);
  where(none, result[0]) = 0;
  where(none, result[1]) = 0;
  // A bound tiny next to λ*, or an isotropic K: λ* scaled onto the disk.
  const pack_mask scaled =
      outside && !none &&
      (!(bound > pack(by_precision(1e-9, 1e-4)) * (abs(total[0]) + abs(total[1]))) ||
       !(1 - eigen_ratio > pack(by_precision(1e-9, 1e-4))));
  if (any_of(scaled)) {
    const std::array<pack, 2> on_disk = within_disk(total, bound, scaled);
    result[0] = select(scaled, on_disk[0], result[0]);
    result[1] = select(scaled, on_disk[1], result[1]);
  }
  const pack_mask newton = outside && !none && !scaled;
  if (none_of(newton)) return result;
  const pack c = eigenbasis[0], s = eigenbasis[1];
  const pack inverse_bound = 1 / bound;
  const std::array<pack, 2> w{(c * total[0] + s * total[1]) * inverse_bound,
                              (-s * total[0] + c * total[1]) * inverse_bound};
  const pack k1 = eigen_ratio;
  const pack excess = sqrt(w[0] * w[0] + w[1] * w[1]) - 1;
  const pack lowest = k1 * excess;
  // std::min(std::max(slip_rate, lowest), excess).
  pack nu = slip_rate;
  where(nu < lowest, nu) = lowest;
  where(excess < nu, nu) = excess;
  const pack_mask precise = newton && exact, stepped = newton && !exact;
  if (any_of(stepped)) {
    // λ(ν) at the last sweep's root scaled onto the circle, and one Newton
    // step for the next sweep, as nearest_on_disk does where not exact.
    const pack at = select(slip_rate >= 0, slip_rate, lowest);
    const pack a = w[0] * (k1 + at), b = k1 * w[1] * (1 + at);
    const pack scale = bound / sqrt(a * a + b * b);
    pack next = nu - disk_root_step(k1, w, nu);
    where(next < lowest, next) = lowest;
    slip_rate = select(stepped, next, slip_rate);
    result[0] = select(stepped, (c * a - s * b) * scale, result[0]);
    result[1] = select(stepped, (s * a + c * b) * scale, result[1]);
  }
  if (none_of(precise)) return result;
  pack_mask running = precise;
  for (int iteration = 0; iteration < 20 && any_of(running); ++iteration) {
    const pack step = disk_root_step(k1, w, nu);
    // std::max(nu - step, lowest).
    pack next = nu - step;
    where(next < lowest, next) = lowest;
    nu = select(running, next, nu);
    running = running && abs(step) > pack(disk_root_tolerance) * (nu + 1);
  }
  slip_rate = select(precise, nu, slip_rate);
  const std::array<pack, 2> l = disk_point(k1, w, nu);
  const std::array<pack, 2> on_disk = within_disk(
      {(c * l[0] - s * l[1]) * bound, (s * l[0] + c * l[1]) * bound}, bound, precise);
  result[0] = select(precise, on_disk[0], result[0]);
  result[1] = select(precise, on_disk[1], result[1]);
  return result;
}

// disk_block for friction, one per lane; lanes without friction have
// `present` false.
struct friction_pack {
  std::array<row_pack, 2> rows;
  std::array<pack, 3> inverse{};
  pack eigen_ratio{};
  std::array<pack, 2> eigenbasis{};
  std::array<pack, 2> accumulated{};
  pack slip_rate{};
  pack coefficient{};  // μ
  std::array<pack, 2> normal_coupling{};
  pack_mask present{};

  void set_lane(int i, const disk_block& block, real friction_coefficient,
                const std::array<real, 2>& coupling) {
    normal_coupling[0][i] = coupling[0];
    normal_coupling[1][i] = coupling[1];
    rows[0].set_lane(i, block.rows[0]);
    rows[1].set_lane(i, block.rows[1]);
    for (int k = 0; k < 3; ++k) inverse[k][i] = block.inverse[k];
    eigen_ratio[i] = block.eigen_ratio;
    for (int k = 0; k < 2; ++k) {
      eigenbasis[k][i] = block.eigenbasis[k];
      accumulated[k][i] = block.accumulated[k];
    }
    slip_rate[i] = block.slip_rate;
    coefficient[i] = friction_coefficient;
    present[i] = block.active();
  }

  // disk_block::solve_after in the lanes of `mask`, with each lane's bound,
  // after the normal impulse `jn` of `normal` (whose lanes that turn are
  // `turning`); adds each lane's |Δλ_1| + |Δλ_2| times its first row's
  // mass_inverse to `largest` as solve_contact does. `exact`: the lanes in
  // their contact's last sweep (nearest_on_disk).
  GAPHYS_ALWAYS_INLINE void solve_after(body_pack& a, body_pack& b, const pack& bound,
                                        const row_pack& normal, const pack& jn,
                                        const pack_mask& turning, const pack_mask& mask,
                                        const pack_mask& exact, pack& largest) {
    const pack s0 = rows[0].speed(a, b) + normal_coupling[0] * jn;
    const pack s1 = rows[1].speed(a, b) + normal_coupling[1] * jn;
    std::array<pack, 2> total{accumulated[0] - (inverse[0] * s0 + inverse[1] * s1),
                              accumulated[1] - (inverse[1] * s0 + inverse[2] * s1)};
    // Lanes whose stopping impulse lies outside the disk slip: the nearest
    // point of the disk (outside_disk below).
    const pack_mask outside = mask && (total[0] * total[0] + total[1] * total[1] > bound * bound);
    if (any_of(outside)) {
      total = outside_disk(total, bound, eigen_ratio, eigenbasis, slip_rate, outside, exact);
    }
    const pack j0 = total[0] - accumulated[0], j1 = total[1] - accumulated[1];
    // The bodies' updates of disk_block::solve_after.
    using e3ga::add, e3ga::sub, e3ga::smul;
    const vector_pack linear =
        add(smul(jn, normal.linear), add(smul(j0, rows[0].linear), smul(j1, rows[1].linear)));
    const pack_mask on_a = mask && a.moves, on_b = mask && b.moves;
    const auto turn = [&](const bivector_pack& normal_turn, const bivector_pack& turn0,
                          const bivector_pack& turn1) {
      const bivector_pack rubbing = add(smul(j0, turn0), smul(j1, turn1));
      return select(turning, add(smul(jn, normal_turn), rubbing), rubbing);
    };
    a.velocity = select(on_a, add(a.velocity, smul(a.inverse_mass, linear)), a.velocity);
    a.angular_velocity =
        select(on_a, add(a.angular_velocity, turn(normal.turn_a, rows[0].turn_a, rows[1].turn_a)),
               a.angular_velocity);
    b.velocity = select(on_b, sub(b.velocity, smul(b.inverse_mass, linear)), b.velocity);
    b.angular_velocity =
        select(on_b, sub(b.angular_velocity, turn(normal.turn_b, rows[0].turn_b, rows[1].turn_b)),
               b.angular_velocity);
    accumulated[0] = select(mask, total[0], accumulated[0]);
    accumulated[1] = select(mask, total[1], accumulated[1]);
    const pack change = (abs(j0) + abs(j1)) * rows[0].mass_inverse;
    where(mask && largest < change, largest) = change;
  }
};

// Which contacts a sweep solves, as contact_solver::sweep_kind.
struct sweep_lanes {
  bool turning_only, last_of_all, last_of_turning;
};

// contact_solver::solve_contact on one contact per lane, the lanes' bodies
// in a and b: the normal impulse, then friction where a lane has it.
// `largest` takes each lane's largest speed change; returns whether any
// lane was solved.
GAPHYS_ALWAYS_INLINE bool solve_lanes(normal_pack& k, friction_pack* friction, body_pack& a,
                                      body_pack& b, const sweep_lanes& kind, const pack_mask& open,
                                      pack& largest) {
  pack_mask active = k.solvable && open;
  if (kind.turning_only) active = active && k.turns && k.accumulated > 0;
  if (none_of(active)) return false;
  // The last sweep of a contact is plain (no over-relaxation).
  pack_mask last(false);
  if (kind.last_of_turning) last = last || k.turns;
  if (kind.last_of_all) last = last || !k.turns;
  const pack relaxation = select(last, pack(1), k.relaxation);
  const pack speed = any_of(k.turns) ? select(k.turns, k.row.speed(a, b), k.row.linear_speed(a, b))
                                     : k.row.linear_speed(a, b);
  const pack wanted = relaxation * (k.target_speed - speed) * k.normal_mass;
  pack total = k.accumulated + wanted;
  where(total < 0, total) = 0;
  const pack j = total - k.accumulated;
  k.accumulated = select(active, total, k.accumulated);
  const pack change = abs(j) * k.row.mass_inverse;
  where(active && largest < change, largest) = change;
  // Nothing pushes and nothing is held: nothing to rub (a speculative contact).
  pack_mask rubs(false);
  if (friction) {
    rubs = active && friction->present &&
           (k.accumulated > 0 || friction->accumulated[0] != 0 || friction->accumulated[1] != 0);
  }
  // The lanes that rub apply the normal impulse with friction's
  // (disk_block::solve_after). (Most speculative contacts hold no impulse
  // and get none.)
  k.row.apply(a, b, j, active && !rubs && j != 0, k.turns);
  if (any_of(rubs)) {
    friction->solve_after(a, b, friction->coefficient * k.accumulated, k.row, j, k.turns, rubs,
                          last, largest);
  }
  return true;
}

}  // namespace gaphys::detail
