// One direction along which a contact exchanges impulse between its two
// bodies, and the small block solves of friction's two tangents.
//
// A linear row pushes A by j d and B by -j d at the contact point: with the
// offsets r from each centre, Δv = j d / m and ΔΩ = I⁻¹(r ∧ j d). The speed
// it reads is d · (v_A(p) - v_B(p)); with v(p) = v + r ⌋ Ω,
// d · (r ⌋ Ω) = (d ∧ r) ⌋ Ω, a scalar of two bivectors, precomputed as the arm.
//
// An angular row turns A by the angular impulse j U and B by -j U, for a unit
// bivector U (U U = -1): ΔΩ = I⁻¹(j U). The speed it reads is the rate of
// turning in U, -U ⌋ (Ω_A - Ω_B) = ~U ⌋ (Ω_A - Ω_B): its arm is ~U.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <type_traits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "gaphys/algebra.hpp"
#include "gaphys/body.hpp"
#include "gaphys/ga/compiler.hpp"
#include "precision.hpp"

namespace gaphys::detail {

// What the sweeps read and change of each body, packed together: the sweeps
// visit bodies in contact order, and whole body objects would spread them
// over many cache lines. One cache line each: at 56 bytes most bodies
// straddled two, and the sweeps' reads of a contact's two bodies are
// scattered.
struct alignas(64) solver_body {
  vector velocity;
  bivector angular_velocity;
  real inverse_mass;
};

// What the sweeps of plain contacts (contact_solver::solve_plain_contacts:
// through the centres, frictionless) read and change of a body: half a
// solver_body, where every contact is plain (a pile of frictionless
// spheres). Each contact reads two bodies scattered over the list: with
// these the sweeps missed the first-level cache a fifth less often (1,000
// spheres, whose plain bodies take 32 KB; callgrind's model of a 48 KB
// cache), and the step took 2-4% less time.
struct alignas(32) plain_body {
  vector velocity;
  real inverse_mass;
};

// A row's angular terms: the speed's (arms) and the turns its impulse
// gives. Kept apart from the rest where most rows turn nothing: a contact's
// normal row (contact_solver::constraint), which the sweeps stream.
struct row_arms {
  bivector arm_a{}, arm_b{};    // the speed's angular terms
  bivector turn_a{}, turn_b{};  // ΔΩ of A (and -ΔΩ of B) per unit impulse
};

// std::max(x, 0), the same for every x (a NaN, -0), without a branch: the
// normal impulse's clamp goes either way from contact to contact
// (contact_solver::normal_impulse), and GCC compiles any comparison of it
// to a branch. SSE's max(0, x) is 0 > x ? 0 : x, as std::max(x, 0) is.
template <class T>
GAPHYS_ALWAYS_INLINE T at_least_zero(T x) {
#if defined(__SSE2__)
  if constexpr (std::is_same_v<T, double>) {
    return _mm_cvtsd_f64(_mm_max_sd(_mm_setzero_pd(), _mm_set_sd(x)));
  } else if constexpr (std::is_same_v<T, float>) {
    return _mm_cvtss_f32(_mm_max_ss(_mm_setzero_ps(), _mm_set_ss(x)));
  } else {
    return std::max(x, T(0));
  }
#else
  return std::max(x, T(0));
#endif
}

// The speed a row along d reads, and its impulse j: `arms` null where the
// row turns neither body (both arms zero). Without arms, the rows read
// solver_body or plain_body alike.
template <class Body>
GAPHYS_ALWAYS_INLINE real row_speed(const vector& d, const Body& a, const Body& b) {
  return e3ga::scp(d, a.velocity - b.velocity);
}
GAPHYS_ALWAYS_INLINE real row_speed(const vector& d, const row_arms* arms, const solver_body& a,
                                    const solver_body& b) {
  const real linear_speed = row_speed(d, a, b);
  if (!arms) return linear_speed;
  return linear_speed + e3ga::lc(arms->arm_a, a.angular_velocity) -
         e3ga::lc(arms->arm_b, b.angular_velocity);
}
// Only a body with mass changes: static and kinematic ones are only read,
// so contacts solved at once on several threads may share them.
GAPHYS_ALWAYS_INLINE void row_apply(const vector& d, const row_arms* arms, solver_body& a,
                                    solver_body& b, real j) {
  if (a.inverse_mass > 0) {
    a.velocity = a.velocity + (j * a.inverse_mass) * d;
    if (arms) a.angular_velocity = a.angular_velocity + j * arms->turn_a;
  }
  if (b.inverse_mass > 0) {
    b.velocity = b.velocity - (j * b.inverse_mass) * d;
    if (arms) b.angular_velocity = b.angular_velocity - j * arms->turn_b;
  }
}
// The same for a row that turns neither body, on solver_body or plain_body.
template <class Body>
GAPHYS_ALWAYS_INLINE void row_apply(const vector& d, Body& a, Body& b, real j) {
  if (a.inverse_mass > 0) a.velocity = a.velocity + (j * a.inverse_mass) * d;
  if (b.inverse_mass > 0) b.velocity = b.velocity - (j * b.inverse_mass) * d;
}
// How much a unit impulse of the row (other, other_arms) changes the speed
// of the row (d, arms), an entry of the effective-mass matrix K of a block
// (a row that turns nothing is given zero arms).
inline real row_coupling(const vector& d, const row_arms& arms, const vector& other,
                         const row_arms& other_arms, real inverse_masses) {
  return inverse_masses * e3ga::scp(d, other) + e3ga::lc(arms.arm_a, other_arms.turn_a) +
         e3ga::lc(arms.arm_b, other_arms.turn_b);
}

// The sweeps' hot path (speed, apply, the friction block's solve) is forced
// inline: split into solve_contact, GCC 12 stopped inlining it and a step
// of 1,000 boxes took 5% longer.
struct impulse_row : row_arms {
  vector linear{};        // d, unit; zero for an angular row
  bool turns = true;      // false: both arms zero, the row turns neither body
  real mass_inverse = 0;  // speed change per unit impulse; 0: left out

  const row_arms* arms() const { return turns ? this : nullptr; }
  GAPHYS_ALWAYS_INLINE real speed(const solver_body& a, const solver_body& b) const {
    return row_speed(linear, arms(), a, b);
  }
  GAPHYS_ALWAYS_INLINE void apply(solver_body& a, solver_body& b, real j) const {
    row_apply(linear, arms(), a, b, j);
  }

  // How much this row's impulse changes another row's speed: the entries of
  // the effective-mass matrix K of a block (K_ii is mass_inverse).
  real coupling(const impulse_row& other, real inverse_masses) const {
    return row_coupling(linear, *this, other.linear, other, inverse_masses);
  }
};

// What the rows read of a body, once per step: its inverse mass, whether it
// is static, and I⁻¹ in the world frame as a map on bivectors. The contact
// phase builds a few rows per contact (a box's: the normal and two friction
// rows, for each of its two bodies), and body::world_inverse_inertia takes a
// bivector into the body frame and back, two rotor sandwiches, for a map
// that stays the same all step. Zero for a static or kinematic body.
struct row_body {
  real inverse_mass = 0;
  bool is_static = true;  // its arms count for nothing: its Ω stays zero
  bool isotropic = true;  // I⁻¹ = inverse_moment times the identity
  real inverse_moment = 0;
  std::array<bivector, 3> columns{};  // else: the images of e12, e13, e23

  static row_body of(const body& b) {
    row_body r;
    r.inverse_mass = b.inverse_mass();
    r.is_static = b.is_static();
    if (!b.is_dynamic()) return r;
    const inertia& i = b.body_inertia();
    if (i.is_isotropic()) {
      // (As body::world_inverse_inertia: the same rounding.)
      r.inverse_moment = 1 / i.isotropic_moment();
      return r;
    }
    r.isotropic = false;
    r.columns = {b.world_inverse_inertia(bivector{1, 0, 0}),
                 b.world_inverse_inertia(bivector{0, 1, 0}),
                 b.world_inverse_inertia(bivector{0, 0, 1})};
    return r;
  }

  // I⁻¹(l) in the world frame.
  bivector inverse_inertia(const bivector& l) const {
    if (isotropic) return inverse_moment * l;
    return l.e12() * columns[0] + l.e13() * columns[1] + l.e23() * columns[2];
  }
};

// The row along d at offsets r_a, r_b of two bodies (a static body's arm
// counts for nothing: its Ω stays zero): its arms into `row` and its speed
// change per unit impulse into `mass_inverse`, or (below) the whole row.
// Written in place, every field: the contact phase builds thousands of
// rows a step, and a row built aside and copied in cost a copy each.
inline void set_linear_row(row_arms& row, real& mass_inverse, const vector& d, const vector& r_a,
                           const vector& r_b, const row_body& a, const row_body& b) {
  if (!a.is_static) {
    row.arm_a = e3ga::op(d, r_a);
    row.turn_a = a.inverse_inertia(e3ga::op(r_a, d));
  } else {
    row.arm_a = row.turn_a = bivector{};
  }
  if (!b.is_static) {
    row.arm_b = e3ga::op(d, r_b);
    row.turn_b = b.inverse_inertia(e3ga::op(r_b, d));
  } else {
    row.arm_b = row.turn_b = bivector{};
  }
  mass_inverse = a.inverse_mass + b.inverse_mass + e3ga::lc(row.arm_a, row.turn_a) +
                 e3ga::lc(row.arm_b, row.turn_b);
}
inline void set_linear_row(impulse_row& row, const vector& d, const vector& r_a, const vector& r_b,
                           const row_body& a, const row_body& b) {
  row.linear = d;
  row.turns = true;
  set_linear_row(row, row.mass_inverse, d, r_a, r_b, a, b);
}

// The row that turns A by U and B by -U.
inline impulse_row angular_row(const bivector& u, const row_body& a, const row_body& b) {
  impulse_row row;
  const bivector arm = e3ga::reverse(u);
  if (!a.is_static) row.arm_a = arm, row.turn_a = a.inverse_inertia(u);
  if (!b.is_static) row.arm_b = arm, row.turn_b = b.inverse_inertia(u);
  row.mass_inverse = e3ga::lc(row.arm_a, row.turn_a) + e3ga::lc(row.arm_b, row.turn_b);
  return row;
}

// v scaled back onto the disk |v| <= bound if it lies outside. (Not
// std::hypot: its care for overflow made it a third of a step with friction.)
inline std::array<real, 2> within_disk(const std::array<real, 2>& v, real bound) {
  const real squared = v[0] * v[0] + v[1] * v[1];
  if (!(squared > bound * bound)) return v;
  const real scale = bound / std::sqrt(squared);
  return {v[0] * scale, v[1] * scale};
}

// Newton's method for the disk's root (below), shared by the scalar solve
// and the batches (contact_batch.hpp), which must round alike. In units of
// K's larger eigenvalue (k = (1, k1), k1 <= 1, ν the same way) and of the
// bound (w, the eigen-coordinates of λ*): λ(ν) = (w0 / d0, k1 w1 / d1) with
// d = (1 + ν, k1 + ν), or (a, b) / D with a = w0 d1, b = k1 w1 d0, D = d0 d1.
// The step on 1/|λ| - 1, (1 - |λ|) |λ|² / (λ0² / d0 + λ1² / d1), is
// (D - √(a² + b²)) (a² + b²) / (a² d1 + b² d0): one division.
template <class T>
GAPHYS_ALWAYS_INLINE T disk_root_step(const T& k1, const std::array<T, 2>& w, const T& nu) {
  using std::sqrt;
  const T d0 = T(1) + nu, d1 = k1 + nu;
  const T a = w[0] * d1, b = k1 * w[1] * d0;
  const T squared = a * a + b * b;
  return (d0 * d1 - sqrt(squared)) * squared / (a * a * d1 + b * b * d0);
}

// λ(ν) of disk_root_step, in units of the bound.
template <class T>
GAPHYS_ALWAYS_INLINE std::array<T, 2> disk_point(const T& k1, const std::array<T, 2>& w,
                                                 const T& nu) {
  const T d0 = T(1) + nu, d1 = k1 + nu;
  const T inverse = T(1) / (d0 * d1);
  return {w[0] * d1 * inverse, k1 * w[1] * d0 * inverse};
}

// Newton's method stops after a step below this share of 1 + ν. It
// converges quadratically and 1/|λ| is nearly linear in ν: over a pile of
// 1,000 boxes (B5), the step after one below 1e-4 was below 1e-8, mostly
// 1e-10 to 1e-12; after one below 1e-5, below 1e-10. (In float: 3e-4, 1e-7.)
inline constexpr real disk_root_tolerance = by_precision(1e-5, 3e-4);

// The point of the circle |λ| = bound nearest to `outside` in K's metric,
// in K's eigenbasis: there λ_i = k_i w_i / (k_i + ν) with w the eigen-
// coordinates of `outside`, and Newton's method on 1/|λ(ν)| - 1/bound,
// which is nearly linear in ν, converges in a few steps.
//
// `eigen_ratio` (k1) and `eigenbasis` are K's (disk_block), `slip_rate` the
// last sweep's root (in units of the larger eigenvalue), updated.
//
// Unless `exact`, λ is λ(ν) at the last sweep's root, scaled onto the
// circle, and the root takes one Newton step for the next sweep: a sweep
// before a contact's last needs no exact root, and from sweep to sweep the
// steps converge as Newton's iteration does (the sweeps' speeds change
// little from one to the next). λ then waits on one square root and one
// division, the step being off its path. The last sweep iterates to
// disk_root_tolerance. (The root's steps, a square root and a division
// each, had been a third of the sweeps over 1,000 boxes; a sliding solve
// took 1.76 of them, all on the path of the contact's update.)
inline std::array<real, 2> nearest_on_disk(const std::array<real, 2>& outside, real bound,
                                           real eigen_ratio, const std::array<real, 2>& eigenbasis,
                                           real& slip_rate, bool exact) {
  const real c = eigenbasis[0], s = eigenbasis[1];
  // In units of the bound and of k0: λ scales with λ* and the bound, ν
  // with K, and the iteration's numbers stay near 1. (In impulses, an
  // impulse of 1e-16 N s squared and times another gave 1e-48: zero in
  // float, and a step of infinity.)
  const real inverse_bound = 1 / bound;
  const std::array<real, 2> w{(c * outside[0] + s * outside[1]) * inverse_bound,
                              (-s * outside[0] + c * outside[1]) * inverse_bound};
  const real k1 = eigen_ratio;
  // The root lies in [k1, 1] (|w| - 1). From its lower end Newton's method
  // on this concave function climbs to the root without overshooting (for
  // an isotropic K it is the root); from above it, one step lands below
  // and the climb goes on from there. Start at the last sweep's root where
  // it lies in the bracket.
  const real excess = std::sqrt(w[0] * w[0] + w[1] * w[1]) - 1;
  const real lowest = k1 * excess;
  // (Not std::clamp: where |w| lies a rounding error below the bound, excess
  // is below zero and the bracket's ends come the wrong way round, which
  // clamp does not allow.)
  real nu = std::min(std::max(slip_rate, lowest), excess);
  if (!exact) {
    // λ(ν) (disk_point) is along (w0 d1, k1 w1 d0).
    const real at = slip_rate >= 0 ? slip_rate : lowest;
    const real a = w[0] * (k1 + at), b = k1 * w[1] * (1 + at);
    const real scale = bound / std::sqrt(a * a + b * b);
    slip_rate = std::max(nu - disk_root_step(k1, w, nu), lowest);
    return {(c * a - s * b) * scale, (s * a + c * b) * scale};
  }
  for (int iteration = 0; iteration < 20; ++iteration) {
    const real step = disk_root_step(k1, w, nu);
    nu = std::max(nu - step, lowest);
    if (!(std::fabs(step) > disk_root_tolerance * (nu + 1))) break;
  }
  slip_rate = nu;
  const std::array<real, 2> l = disk_point(k1, w, nu);
  return within_disk({(c * l[0] - s * l[1]) * bound, (s * l[0] + c * l[1]) * bound}, bound);
}

// The total impulse of a block whose stopping impulse `total` lies outside
// the disk |λ| <= bound (disk_block::stopping_total): the nearest point of
// the disk in the metric of K.
inline std::array<real, 2> outside_disk(const std::array<real, 2>& total, real bound,
                                        real eigen_ratio, const std::array<real, 2>& eigenbasis,
                                        real& slip_rate, bool exact) {
  if (!(bound > 0)) return {0, 0};
  // A bound this small next to λ* holds nothing that matters (and the
  // root below would underflow): scale onto the disk.
  if (!(bound > by_precision(1e-9, 1e-4) * (std::fabs(total[0]) + std::fabs(total[1])))) {
    return within_disk(total, bound);
  }
  // An isotropic K (a contact through a sphere's centre): the nearest
  // point is λ* scaled onto the disk, no root to find.
  if (!(1 - eigen_ratio > by_precision(1e-9, 1e-4))) return within_disk(total, bound);
  return nearest_on_disk(total, bound, eigen_ratio, eigenbasis, slip_rate, exact);
}

// Two rows solved together, their accumulated impulse kept within a disk
// |λ| <= bound: friction's two tangents (the Coulomb cone), or rolling
// resistance's two planes. Solving both at once with the 2x2 effective mass
// and projecting on the disk makes the friction isotropic: a pyramid of
// two clamped rows would let a body slide at 45° to them feel √2 μ.
struct disk_block {
  std::array<impulse_row, 2> rows;
  std::array<real, 3> inverse{};      // K⁻¹ as (00, 01, 11)
  real eigen_ratio = 1;               // K's smaller eigenvalue over its larger, in (0, 1]
  std::array<real, 2> eigenbasis{1, 0};  // (cos, sin) of the first eigenvector's angle
  std::array<real, 2> accumulated{};
  // ν of the last sliding solve, in units of K's larger eigenvalue (< 0: none
  // yet): the next sweep's root is near it, and Newton's method started
  // there needs a step or two.
  real slip_rate = -1;

  void prepare(real inverse_masses) {
    const real k00 = rows[0].mass_inverse, k11 = rows[1].mass_inverse;
    const real k01 = rows[0].coupling(rows[1], inverse_masses);
    const real determinant = k00 * k11 - k01 * k01;
    // K's eigenvalues and first eigenvector (at half the angle of
    // (k00 - k11, 2 k01)), for the projection on the disk.
    const real half_gap = (k00 - k11) / 2, radius = std::sqrt(half_gap * half_gap + k01 * k01);
    // (Eigenvalues (k00 + k11) / 2 ± radius; no ratio without them.)
    const real larger = (k00 + k11) / 2 + radius, smaller = (k00 + k11) / 2 - radius;
    eigen_ratio = larger > 0 ? smaller / larger : 1;
    eigenbasis = {1, 0};
    if (radius > 0) {
      // Half-angle formulas from cos 2θ and sin 2θ, each taken where it is
      // not a difference of near equals (atan2, cos and sin took 1.4% of a
      // step of 1,000 boxes).
      const real cos_double = half_gap / radius, sin_double = k01 / radius;
      if (cos_double >= 0) {
        const real c = std::sqrt((1 + cos_double) / 2);
        eigenbasis = {c, sin_double / (2 * c)};
      } else {
        const real s = std::copysign(std::sqrt((1 - cos_double) / 2), sin_double);
        eigenbasis = {sin_double / (2 * s), s};
      }
    }
    slip_rate = -1;
    if (!(determinant > 0)) {
      inverse = {0, 0, 0};
      return;
    }
    inverse = {k11 / determinant, -k01 / determinant, k00 / determinant};
  }

  bool active() const { return inverse[0] > 0; }

  // The total impulse that stops the relative motion the rows read, starting
  // from `held`, when the bound allows it: λ* = held - K⁻¹ s. Else the
  // contact slips, and the impulse is the point of the disk nearest to λ*
  // in the metric of K (the kinetic energy the rows see):
  //   λ = (K + ν 1)⁻¹ K λ*  with ν >= 0 such that |λ| = bound.
  // Its slip afterwards, K (λ - λ*), is -ν λ: against the impulse, Coulomb's
  // law of most dissipation, and each such update takes energy away. Where
  // K is isotropic (a sphere's contact) this is λ* scaled onto the disk;
  // where the rows couple through a turn (a box's corners) scaling would
  // skew the impulse sideways (a sliding box slowed 6% too little).
  // (`exact`: see nearest_on_disk.)
  GAPHYS_ALWAYS_INLINE std::array<real, 2> stopping_total(const solver_body& a,
                                                          const solver_body& b,
                                                          const std::array<real, 2>& held,
                                                          real bound, bool exact = true) {
    return stopping_total({rows[0].speed(a, b), rows[1].speed(a, b)}, held, bound, exact);
  }
  GAPHYS_ALWAYS_INLINE std::array<real, 2> stopping_total(const std::array<real, 2>& speeds,
                                                          const std::array<real, 2>& held,
                                                          real bound, bool exact = true) {
    const real s0 = speeds[0], s1 = speeds[1];
    const std::array<real, 2> total{held[0] - (inverse[0] * s0 + inverse[1] * s1),
                                    held[1] - (inverse[1] * s0 + inverse[2] * s1)};
    if (!(total[0] * total[0] + total[1] * total[1] > bound * bound)) return total;
    return outside_disk(total, bound, eigen_ratio, eigenbasis, slip_rate, exact);
  }

  std::array<real, 2> nearest_on_disk(const std::array<real, 2>& outside, real bound) {
    return gaphys::detail::nearest_on_disk(outside, bound, eigen_ratio, eigenbasis, slip_rate,
                                           true);
  }

  // Both rows' impulses at once: one update of each body instead of two in
  // a row, which the sweeps would wait on. (A block's rows always turn:
  // linear_row and angular_row make rows with turns set.)
  GAPHYS_ALWAYS_INLINE void apply(solver_body& a, solver_body& b, const std::array<real, 2>& j) const {
    const vector linear = j[0] * rows[0].linear + j[1] * rows[1].linear;
    if (a.inverse_mass > 0) {
      a.velocity = a.velocity + a.inverse_mass * linear;
      a.angular_velocity = a.angular_velocity + (j[0] * rows[0].turn_a + j[1] * rows[1].turn_a);
    }
    if (b.inverse_mass > 0) {
      b.velocity = b.velocity - b.inverse_mass * linear;
      b.angular_velocity = b.angular_velocity - (j[0] * rows[0].turn_b + j[1] * rows[1].turn_b);
    }
  }

  // One sweep's solve of the accumulated impulse; returns |Δλ_1| + |Δλ_2|.
  GAPHYS_ALWAYS_INLINE real solve(solver_body& a, solver_body& b, real bound) {
    const std::array<real, 2> total = stopping_total(a, b, accumulated, bound);
    const std::array<real, 2> j{total[0] - accumulated[0], total[1] - accumulated[1]};
    apply(a, b, j);
    accumulated = total;
    return std::fabs(j[0]) + std::fabs(j[1]);  // a bound on |Δλ| good enough for convergence
  }

  // solve, for friction's block, after its contact's normal impulse
  // `normal_impulse` along `normal` (its arms `normal_arms`, null where it
  // turns neither body), which is applied with the block's: the
  // rows' speeds are read before it, and moved by what it changes them
  // (`normal_coupling`, per unit impulse). The speeds are then read at once,
  // not after the normal impulse reaches the velocities, and the bodies
  // change once: the sweeps wait on each contact's updates. `exact`: see
  // nearest_on_disk.
  GAPHYS_ALWAYS_INLINE real solve_after(solver_body& a, solver_body& b, real bound,
                                        const vector& normal, const row_arms* normal_arms,
                                        real normal_impulse,
                                        const std::array<real, 2>& normal_coupling, bool exact) {
    // (A block's rows always turn: no test of each row's `turns`.)
    const std::array<real, 2> speeds{
        row_speed(rows[0].linear, &rows[0], a, b) + normal_coupling[0] * normal_impulse,
        row_speed(rows[1].linear, &rows[1], a, b) + normal_coupling[1] * normal_impulse};
    const std::array<real, 2> total = stopping_total(speeds, accumulated, bound, exact);
    const std::array<real, 2> j{total[0] - accumulated[0], total[1] - accumulated[1]};
    const vector linear = normal_impulse * normal + (j[0] * rows[0].linear + j[1] * rows[1].linear);
    if (a.inverse_mass > 0) {
      a.velocity = a.velocity + a.inverse_mass * linear;
      bivector turn = j[0] * rows[0].turn_a + j[1] * rows[1].turn_a;
      if (normal_arms) turn = normal_impulse * normal_arms->turn_a + turn;
      a.angular_velocity = a.angular_velocity + turn;
    }
    if (b.inverse_mass > 0) {
      b.velocity = b.velocity - b.inverse_mass * linear;
      bivector turn = j[0] * rows[0].turn_b + j[1] * rows[1].turn_b;
      if (normal_arms) turn = normal_impulse * normal_arms->turn_b + turn;
      b.angular_velocity = b.angular_velocity - turn;
    }
    accumulated = total;
    return std::fabs(j[0]) + std::fabs(j[1]);
  }

  // Starts from a given impulse (warm starting), already within the bound.
  void start_from(solver_body& a, solver_body& b, const std::array<real, 2>& impulse) {
    accumulated = impulse;
    apply(a, b, impulse);
  }
};

// A single row kept within |λ| <= bound (spinning friction).
inline real solve_bounded(const impulse_row& row, real& accumulated, solver_body& a,
                          solver_body& b, real bound) {
  const real total =
      std::clamp(accumulated - row.speed(a, b) / row.mass_inverse, -bound, bound);
  const real j = total - accumulated;
  row.apply(a, b, j);
  accumulated = total;
  return std::fabs(j);
}

}  // namespace gaphys::detail
