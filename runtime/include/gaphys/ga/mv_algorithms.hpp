// Algorithms on general multivectors that are not a single table lookup:
// exp, log, the general inverse, printing. They are written once against the
// generated `basic_mv` interface (c, bits, size, grade_mask, basis_blade,
// blade_name) and the algebra's gp, found by argument-dependent lookup. The
// few primitives that read coefficients (max_abs, keep_grades,
// linear_combination, scalar_part, ...) also take the sparse mv of an algebra
// of more than 5 dimensions (sparse_mv.hpp), so everything above them works
// on both.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <ostream>
#include <stdexcept>
#include <utility>
#include <vector>

#include "scalar_functions.hpp"
#include "sparse_mv.hpp"

namespace gaphys::ga {

// x.bits without the bits of coefficients that are exactly zero: the bitmap
// a profile would key x on (the profile's recorder also drops rounding
// residues; this exact test never changes a result).
// How many bits are set: sums of bit pairs, nibbles, then bytes. Inline on
// every target, where __builtin_popcount without -mpopcnt is a library call.
constexpr int bit_count(std::uint32_t bits) {
  bits = bits - ((bits >> 1) & 0x55555555u);
  bits = (bits & 0x33333333u) + ((bits >> 2) & 0x33333333u);
  bits = (bits + (bits >> 4)) & 0x0f0f0f0fu;
  return static_cast<int>((bits * 0x01010101u) >> 24);
}

// The index of the lowest set bit of a nonzero bitmap.
inline int lowest_bit(std::uint32_t bits) {
#if defined(__GNUC__) || defined(__clang__)
  return __builtin_ctz(bits);
#else
  int i = 0;
  for (; !(bits >> i & 1); ++i) {
  }
  return i;
#endif
}

// Visits only the set bits, without a branch on the values: dispatchers call
// this on every miss, with sparse arguments whose zeros follow no pattern.
template <class MV>
std::uint32_t exact_bits(const MV& x) {
  std::uint32_t bits = x.bits;
  for (std::uint32_t rest = x.bits; rest != 0; rest &= rest - 1) {
    const int i = lowest_bit(rest);
    bits &= ~(std::uint32_t(x.c[i] == 0) << i);
  }
  return bits;
}

template <class MV>
typename MV::scalar_type max_abs(const MV& x) {
  typename MV::scalar_type m = 0;
  if constexpr (is_sparse_v<MV>) {
    for (const auto& t : x.terms) m = std::max(m, std::abs(t.value));
  } else {
    for (int i = 0; i < MV::size; ++i) m = std::max(m, std::abs(x.c[i]));
  }
  return m;
}

// The scalar part <x>_0.
template <class MV>
typename MV::scalar_type scalar_part(const MV& x) {
  if constexpr (is_sparse_v<MV>)
    return sparse::coefficient(x, 0);
  else
    return x.c[0];
}

// How many coefficients x stores: a bound on how many are nonzero.
template <class MV>
int coefficient_count(const MV& x) {
  if constexpr (is_sparse_v<MV>)
    return int(x.terms.size());
  else
    return MV::size;
}

// Sum of c_i d_i over the coefficients (the blade basis's Euclidean product).
template <class MV>
typename MV::scalar_type coefficient_dot(const MV& x, const MV& y) {
  typename MV::scalar_type sum = 0;
  if constexpr (is_sparse_v<MV>) {
    for (const auto& t : x.terms) sum += t.value * sparse::coefficient(y, t.blade);
  } else {
    for (int i = 0; i < MV::size; ++i) sum += x.c[i] * y.c[i];
  }
  return sum;
}

template <class MV>
MV keep_grades(const MV& x, std::uint32_t mask) {
  if constexpr (is_sparse_v<MV>) {
    return sparse::keep_grades(x, mask);
  } else {
    MV r = x;
    for (int i = 0; i < MV::size; ++i)
      if (!(mask >> i & 1)) r.c[i] = 0;
    r.bits &= mask;
    return r;
  }
}

template <class MV>
MV linear_combination(typename MV::scalar_type a, const MV& x, typename MV::scalar_type b,
                      const MV& y) {
  if constexpr (is_sparse_v<MV>) {
    return sparse::linear_combination(a, x, b, y);
  } else {
    MV r;
    for (int i = 0; i < MV::size; ++i) r.c[i] = a * x.c[i] + b * y.c[i];
    r.bits = x.bits | y.bits;
    return r;
  }
}

template <class MV>
MV plus_scalar(const MV& x, typename MV::scalar_type s) {
  if constexpr (is_sparse_v<MV>) {
    return sparse::plus_scalar(x, s);
  } else {
    MV r = x;
    r.c[0] += s;
    r.bits |= 1;
    return r;
  }
}

// s x, and -x (not -1 x: the same, except for the sign of zeros).
template <class MV>
MV scaled(const MV& x, typename MV::scalar_type s) {
  MV r = x;
  if constexpr (is_sparse_v<MV>) {
    for (auto& t : r.terms) t.value *= s;
  } else {
    for (auto& v : r.c) v *= s;
  }
  return r;
}
template <class MV>
MV negated(const MV& x) {
  MV r = x;
  if constexpr (is_sparse_v<MV>) {
    for (auto& t : r.terms) t.value = -t.value;
  } else {
    for (auto& v : r.c) v = -v;
  }
  return r;
}

// x with each blade's coefficient times its sign: `signs` is an array by
// canonical index (dense mv) or a rule by grade (grade_signs, sparse mv).
template <class MV, class Signs>
MV with_signs(const MV& x, const Signs& signs) {
  using T = typename MV::scalar_type;
  MV r = x;
  if constexpr (is_sparse_v<MV>) {
    for (auto& t : r.terms) t.value *= T(signs(bitwise::grade(t.blade)));
  } else {
    for (int i = 0; i < MV::size; ++i) r.c[i] *= T(signs[i]);
  }
  return r;
}

// Tolerance for "numerically zero" relative to a magnitude, and never below
// the rounding of numbers of size 1.
template <class T>
T tolerance(T magnitude) {
  return std::numeric_limits<T>::epsilon() * T(256) * std::max(T(1), magnitude);
}

// The rounding error of a few operations on numbers of the given size, however
// small: for terms that are small in their own right, not only next to 1.
template <class T>
T relative_tolerance(T magnitude) {
  return std::numeric_limits<T>::epsilon() * T(256) * magnitude;
}

// True when x is a scalar up to rounding.
template <class MV>
bool is_numerically_scalar(const MV& x, typename MV::scalar_type magnitude) {
  return max_abs(keep_grades(x, ~std::uint32_t(1))) <= tolerance(magnitude);
}

// exp(x) = c + k x when x^2 is a scalar.
template <class MV>
MV exp_simple(const MV& x, typename MV::scalar_type square) {
  const auto f = exp_of_square(square);
  return plus_scalar(linear_combination(f.k, x, typename MV::scalar_type(0), x), f.c);
}

// Taylor series with scaling and squaring: exp(x) = exp(x / 2^m)^(2^m).
template <class MV>
MV exp_series(const MV& x) {
  using T = typename MV::scalar_type;
  int m = 0;
  T scale = max_abs(x) * T(coefficient_count(x));
  while (scale > T(0.5)) {
    scale /= 2;
    ++m;
  }
  const MV y = linear_combination(std::ldexp(T(1), -m), x, T(0), x);
  MV sum = MV::basis_blade(0), term = MV::basis_blade(0);
  for (int k = 1; k <= 18; ++k) {
    term = gp(term, y);
    term = linear_combination(T(1) / T(k), term, T(0), term);
    sum = linear_combination(T(1), sum, T(1), term);
  }
  for (int i = 0; i < m; ++i) sum = gp(sum, sum);
  return sum;
}

// Splits a bivector B into commuting parts B = b1 + b2 with scalar squares
// l1, l2 (the invariant decomposition), as every bivector of up to 5
// dimensions splits.
// With W = <B^2>_4 / 2 = b1 b2: B^2 = l1 + l2 + 2W and W^2 = l1 l2, so l1, l2
// solve l^2 - <B^2>_0 l + <W^2>_0 = 0, and (l1 - W) B = (l1 - l2) b1.
// Returns false when the roots are complex or coincide, or B turns in more
// than two planes.
// Each test compares a quantity with the rounding of the terms it is made of,
// never with 1: a part much smaller than 1 is still a part (a c2ga bivector
// with |W^2| = 5e-6 lost its small rotation to an absolute test, and exp(B)
// its fifth digit in float).
template <class MV>
bool split_bivector(const MV& b, MV& b1, MV& b2, typename MV::scalar_type& l1,
                    typename MV::scalar_type& l2) {
  using T = typename MV::scalar_type;
  const MV square = gp(b, b);
  const MV w = linear_combination(T(0.5), keep_grades(square, MV::grade_mask(4)), T(0), square);
  const T s0 = scalar_part(square);
  const MV w_square = gp(w, w);
  const T w2 = scalar_part(w_square);
  const T w_size = max_abs(w);
  if constexpr (is_sparse_v<MV>) {
    // From 6 dimensions on B may turn in three planes (or more), where W^2
    // has a part of grade 4 and no two commuting parts make B: the caller
    // then takes the series.
    if (MV::algebra::dimension > 5 &&
        max_abs(keep_grades(w_square, ~std::uint32_t(1))) > relative_tolerance(w_size * w_size)) {
      return false;
    }
  }
  // W is rounded to about eps times the products of B's coefficients that
  // reach it. Those pair a part that is not null (about sqrt|<B^2>_0|) with
  // any part (at most |B|): null parts, large as they may be (a translation,
  // or the offset of an axis), multiply to zero. So W^2 is known to about
  // eps |W| |B| sqrt|<B^2>_0|, and below that W counts as null. (Relative to
  // |B|^2 a large translation hides a real second plane; relative to 1, a
  // small one.)
  if (std::abs(w2) <= relative_tolerance(w_size * max_abs(b) * std::sqrt(std::abs(s0)))) {
    // W is null (W^2 = 0): a screw motion in conformal space, whose parts are a
    // rotation (l1 = <B^2>_0) and a null translation along the axis (l2 = 0).
    // Taking the roots directly avoids the rounding of W^2 in a square root,
    // which swamps l1^2 when the rotation is small.
    if (s0 == 0) return false;
    l1 = s0;
    l2 = 0;
  } else {
    const T disc = s0 * s0 - T(4) * w2;
    const T scale = s0 * s0 + T(4) * std::abs(w2);  // disc is rounded to about eps times this
    if (disc < -relative_tolerance(scale)) return false;
    const T root = std::sqrt(std::max(disc, T(0)));
    if (root <= std::sqrt(relative_tolerance(scale))) return false;
    // l1, the root of larger magnitude, from the formula; l2 = W^2 / l1 from
    // the product of the roots, without the cancellation of s0 - l1.
    l1 = s0 >= 0 ? (s0 + root) / 2 : (s0 - root) / 2;
    l2 = w2 / l1;
  }
  const MV l1_minus_w = plus_scalar(linear_combination(T(-1), w, T(0), w), l1);
  b1 = keep_grades(gp(l1_minus_w, b), MV::grade_mask(2));
  b1 = linear_combination(T(1) / (l1 - l2), b1, T(0), b1);
  b2 = linear_combination(T(1), b, T(-1), b1);
  return true;
}

// exp of any multivector: closed forms for bivectors (rotors, boosts,
// translators, screw motions), the series otherwise.
template <class MV>
MV exp_general(const MV& x) {
  using T = typename MV::scalar_type;
  if ((x.bits & ~MV::grade_mask(2)) != 0) return exp_series(x);
  const MV square = gp(x, x);
  // Taking x for simple errs by about <x^2>_4 (the product of two planes),
  // next to exp(x)'s scalar part of about 1: the tolerance of 1's rounding
  // (tolerance(), not relative_tolerance()) is the one that bounds that.
  if (is_numerically_scalar(square, max_abs(square))) return exp_simple(x, scalar_part(square));
  MV b1, b2;
  T l1, l2;
  if (!split_bivector(x, b1, b2, l1, l2)) return exp_series(x);
  return gp(exp_simple(b1, l1), exp_simple(b2, l2));
}

// The basis bivectors a log may turn in, in canonical order. Of a dense mv,
// `planes` is a bitmap of canonical indices; of a sparse one, a bitmap of
// grades (every bivector if it has grade_mask(2)), or a plane_list.
template <class MV>
std::vector<MV> basis_planes(std::uint32_t planes) {
  std::vector<MV> found;
  if constexpr (is_sparse_v<MV>) {
    if (!(planes & MV::grade_mask(2))) return found;
    const int n = MV::algebra::dimension;
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j)
        found.push_back(MV::from_blades({{(std::uint32_t(1) << i) | (std::uint32_t(1) << j), 1}}));
  } else {
    const std::uint32_t bivectors = MV::grade_mask(2) & planes;
    for (int i = 0; i < MV::size; ++i)
      if (bivectors >> i & 1) found.push_back(MV::basis_blade(i));
  }
  return found;
}

// The bivector blades a named type of a sparse algebra holds.
struct plane_list {
  std::initializer_list<std::uint32_t> blades;
};
template <class MV>
std::vector<MV> basis_planes(const plane_list& planes) {
  std::vector<MV> found;
  for (std::uint32_t blade : planes.blades)
    if (bitwise::grade(blade) == 2) found.push_back(MV::from_blades({{blade, 1}}));
  return found;
}

// A plane to rotate in when log meets -1 (rotation by 2 pi): the first basis
// bivector among `planes` that squares to -1.
template <class MV, class Planes>
MV log_fallback(const Planes& planes) {
  using T = typename MV::scalar_type;
  for (const MV& e : basis_planes<MV>(planes))
    if (scalar_part(gp(e, e)) == T(-1))
      return linear_combination(T(3.14159265358979323846), e, T(0), e);
  throw std::domain_error(
      "log: -1 is a rotation by 2 pi, and no bivector the result may hold squares to -1");
}

// log of r = exp(B1) exp(B2), B1 and B2 commuting bivectors in orthogonal
// planes that are not null (a double rotation of 4-D space; a boost times a
// rotation): r = (c1 + P1)(c2 + P2), P_i = s_i u_i, u_i^2 = +-1, so
//   <r>_0 = c1 c2,  <r>_2 = b = c2 P1 + c1 P2,  <r>_4 = q = P1 P2.
// The invariant decomposition splits b into c2 P1 + c1 P2 with squares
// l1 = c2^2 P1^2 and l2 = c1^2 P2^2; since P_i^2 = c_i^2 - 1 (cos^2 + sin^2
// = 1, cosh^2 - sinh^2 = 1), c2^2 = c^2 - l1 and c1^2 = c^2 - l2. With
// c2 >= 0 (the other sign gives the same r), P_i = part_i / c_j is read
// from b where the cosine c_j is not small; where it is, from q = P1 P2
// instead (P1 = q P2 / P2^2), and each P_i gets its simple logarithm.
// std::domain_error when the parts do not fit (the planes are isoclinic, or
// r is no such product).
template <class MV>
MV log_two_planes(const MV& r, const MV& b, const MV& q) {
  using T = typename MV::scalar_type;
  const char* const unsupported =
      "log: only rotations, boosts, translations, screw motions and double rotations are supported";
  MV part1, part2;
  T l1, l2;
  if (!split_bivector(b, part1, part2, l1, l2)) throw std::domain_error(unsupported);
  const T c = scalar_part(r);
  const T c2_squared = c * c - l1, c1_squared = c * c - l2;
  if (!(c2_squared >= -tolerance(T(1)) && c1_squared >= -tolerance(T(1))))
    throw std::domain_error(unsupported);
  // The larger cosine from its square, the smaller as c over it: the
  // smaller square is a difference of nearly equal numbers when the other
  // plane is a large boost (c^2 - l1 = cos^2 t, with c^2 and l1 near
  // cosh^2 phi), and a boost of rapidity 6 times a rotation came back too
  // inexact to pass the check below.
  const T sign = c < 0 ? T(-1) : T(1);
  T c1 = 0, c2 = 0;
  if (c2_squared >= c1_squared) {
    c2 = std::sqrt(std::max(c2_squared, T(0)));
    c1 = c2 > 0 ? c / c2 : std::sqrt(std::max(c1_squared, T(0))) * sign;
  } else {
    const T c1_size = std::sqrt(c1_squared);
    c1 = c1_size * sign;
    c2 = std::abs(c) / c1_size;
  }
  // P1 P2 = q, and P_i^2 = c_i^2 - 1: P1 = q P2 / P2^2, P2 = P1 q / P1^2.
  MV p1, p2;
  if (std::min(c2, std::abs(c1)) >= T(0.25)) {  // both from b
    p1 = linear_combination(T(1) / c2, part1, T(0), part1);
    p2 = linear_combination(T(1) / c1, part2, T(0), part2);
  } else if (c2 >= std::abs(c1)) {
    p1 = linear_combination(T(1) / c2, part1, T(0), part1);
    p2 = keep_grades(gp(p1, q), MV::grade_mask(2));
    p2 = linear_combination(T(1) / (c1 * c1 - T(1)), p2, T(0), p2);
  } else {
    p2 = linear_combination(T(1) / c1, part2, T(0), part2);
    p1 = keep_grades(gp(q, p2), MV::grade_mask(2));
    p1 = linear_combination(T(1) / (c2 * c2 - T(1)), p1, T(0), p1);
  }
  const T f1 =
      log_factor(c1 * c1 - T(1), c1, log_case_of(c1 * c1 - T(1), c1, coefficient_dot(p1, p1)));
  const T f2 =
      log_factor(c2 * c2 - T(1), c2, log_case_of(c2 * c2 - T(1), c2, coefficient_dot(p2, p2)));
  const MV log = linear_combination(f1, p1, f2, p2);
  // The decomposition assumed r is such a product: check that it is.
  const MV back = exp_general(log);
  if (max_abs(linear_combination(T(1), back, T(-1), r)) > T(1024) * tolerance(max_abs(r)))
    throw std::domain_error(unsupported);
  return log;
}

// log of an even versor of grades 0, 2 (and 4 for screw motions and double
// rotations: log_two_planes): the bivector L with exp(L) = r. Rotation
// angles come out in [0, pi] per plane.
// For a screw r = exp(b1) exp(b2), b1 a rotation (b1^2 = -t^2), b2 null and
// commuting with b1: <r>_0 = cos t, <r>_2 = sin t u1 + cos t b2 (u1 = b1/t),
// <r>_4 = sin t u1 b2, hence b2 = cos t <r>_2,null - (sin t u1) <r>_4.
// A rotation by 2 pi (r = -1) turns in the first bivector of `planes` (a
// bitmap of canonical indices: a named type's log passes its own blades) that
// squares to -1; std::domain_error when there is none, and when r = -exp(B)
// for a boost or null B (no logarithm in B's plane).
template <class MV, class Planes = std::uint32_t>
MV log_general(const MV& r, const Planes& planes = ~std::uint32_t(0)) {
  using T = typename MV::scalar_type;
  const T magnitude = max_abs(r);
  const std::uint32_t even = MV::grade_mask(0) | MV::grade_mask(2) | MV::grade_mask(4);
  if (max_abs(keep_grades(r, ~even)) > tolerance(magnitude))
    throw std::domain_error("log: argument is not an even versor (grades 0, 2, 4)");
  const T c = scalar_part(r);
  const MV b = keep_grades(r, MV::grade_mask(2));
  const MV q = keep_grades(r, MV::grade_mask(4));
  const MV square = gp(b, b);
  // r is a simple rotation, boost or translation c + b, whose log is f b,
  // when its 4-vector part q is negligible. For r = exp(b1) exp(b2) (commuting
  // planes, b2 the smaller), part = |q| / sqrt|<b^2>_0| is about b2's share
  // of the log (the translation of a screw, the small angle of a boost times a
  // rotation), and f b gets that share wrong by the factor f c - 1: t cot t - 1
  // for a rotation (unbounded near a full turn, where sin t is tiny while the
  // translation is not), phi coth phi - 1 for a boost (growing with phi). So
  // the test bounds that error, relative to the size of the log. (A bound on
  // part relative to r's size took, in float, a boost of rapidity 2 times a
  // rotation by 1e-4 for a plain boost, and doubled the rotation.)
  const T s0 = scalar_part(square);
  const T q_size = max_abs(q);
  const log_case where = log_case_of(s0, c, coefficient_dot(b, b));
  // c < 0 with b a boost, a translation or a rotation too small to resolve
  // (sin t <= eps): -exp(B), or a turn by 2 pi whose plane and axis r does not
  // fix. With a 4-vector part too: the translation of a screw about an axis
  // only its O(eps) terms place.
  if (where == log_case::none) require_log_in_plane(where);
  bool simple = q_size == 0;
  if (!simple && s0 != 0) {
    const T part = q_size / std::sqrt(std::abs(s0));
    if (where == log_case::in_plane) {
      const T f = log_factor(s0, c);
      simple = part * std::abs(f * c - T(1)) <= tolerance(std::abs(f) * max_abs(b));
    } else {
      simple = part <= tolerance(magnitude);  // -1: a rotation by 2 pi
    }
  }
  if (simple && max_abs(keep_grades(square, ~(MV::grade_mask(0) | MV::grade_mask(4)))) <=
                    tolerance(max_abs(square))) {
    if (where == log_case::minus_one) return log_fallback<MV>(planes);
    return linear_combination(log_factor(s0, c, where), b, T(0), b);
  }
  // A screw: r = (c + s u1)(1 + b2) with u1^2 = -1, b2 null and commuting
  // with u1 (rotation about an axis, translation along it). So
  //   <r>_2 = b = s u1 + c b2,   <r>_4 = q = s u1 b2,   <b^2>_0 = -s^2,
  //   <b q>_2 = (s u1 + c b2)(s u1 b2) = -s^2 b2        (b2^2 = 0).
  // With m = max|q|, d := <b q/m>_2 = -(s^2/m) b2 gives the direction of b2
  // (from products of small numbers: accurate), and its length two ways:
  // c b2 is b's part along d, and s^2 b2 = -m d. Combining them as
  // c (c b2) + s^2 b2 = b2 divides by nothing, so the result
  // L = angle/s (b - c b2) + b2 has exp(L) = r to rounding even near a full
  // turn, where r fixes the axis only through O(s) terms. (Coefficient-wise
  // projection on d: the rotation's translation-like part is orthogonal to it
  // in the blade basis, as in the conformal model.)
  // Every quantity is scaled to about 1 before it is squared: for a small
  // rotation s^2 |b2| and its square underflow (in float below s ~ 1e-11),
  // and an underflowed d has no direction.
  const MV d = keep_grades(gp(b, linear_combination(T(1) / q_size, q, T(0), q)), MV::grade_mask(2));
  const T d_size = max_abs(d);
  if (!(q_size > 0) || !(d_size > 0))
    throw std::domain_error(
        "log: only rotations, boosts, translations, screw motions and double rotations are "
        "supported");
  const MV u = linear_combination(T(1) / d_size, d, T(0), d);  // d / max|d|
  const T u_norm2 = coefficient_dot(u, u);
  if (max_abs(gp(u, u)) > tolerance(u_norm2))  // b2 is not null: two planes that are not
    return log_two_planes(r, b, q);            // a translation (a 4-D double rotation)
  // b2 = c (b . u) u / |u|^2 + s^2 b2 = (c (b . u) / |u|^2 - m max|d|) u
  const T length = c * coefficient_dot(b, u) / u_norm2 - q_size * d_size;
  const MV b2 = linear_combination(length, u, T(0), u);
  MV rotation = linear_combination(T(1), b, -c, b2);  // s u1
  // s u1 has no part along d, but computing it cancels O(1) numbers; what is
  // left along d would be amplified by angle/s into the translation, to which
  // exp is fully sensitive. Project it out (exact in exact arithmetic).
  rotation = linear_combination(T(1), rotation, -coefficient_dot(rotation, u) / u_norm2, u);
  // s = sin t from s^2 = -<b^2>_0; where s^2 is too small a number for that
  // (float: s below about 1e-19), from s^2 b2 = -m d, s^2 = -m max|d| / length,
  // each factor of which is in range. The first part must be a rotation
  // (s^2 > 0; for a boost, length > 0).
  const T sin2 = -s0;
  const T smallest = std::numeric_limits<T>::min() / std::numeric_limits<T>::epsilon();
  T s = 0;
  if (sin2 >= smallest)
    s = std::sqrt(sin2);
  else if (sin2 > -smallest && length < 0)
    s = std::sqrt(q_size) * std::sqrt(d_size / -length);
  if (!(s > 0))
    throw std::domain_error(
        "log: only rotations, boosts, translations, screw motions and double rotations are "
        "supported");
  return linear_combination(std::atan2(s, c) / s, rotation, T(1), b2);
}

// The inverse of any invertible multivector: solves x y = 1 for y by Gaussian
// elimination on the matrix of left multiplication by x, 2^n x 2^n: for a
// sparse mv, so only up to 8 basis vectors.
template <class MV>
MV general_inverse(const MV& x) {
  using T = typename MV::scalar_type;
  constexpr int n = MV::size;
  if constexpr (is_sparse_v<MV>) {
    if (MV::algebra::dimension > 8)
      throw std::domain_error(
          "general_inverse: solved on a 2^n x 2^n matrix, so for at most 8 basis vectors");
  }
  // m[i][j], row-major with the right-hand side as column n.
  std::vector<T> m(std::size_t(n) * (n + 1), T(0));
  const auto at = [&](int i, int j) -> T& { return m[std::size_t(i) * (n + 1) + j]; };
  for (int j = 0; j < n; ++j) {
    const MV column = gp(x, MV::basis_blade(j));
    for (int i = 0; i < n; ++i) at(i, j) = column[i];
  }
  at(0, n) = 1;
  const T scale = max_abs(x);
  for (int col = 0; col < n; ++col) {
    int pivot = col;
    for (int i = col + 1; i < n; ++i)
      if (std::abs(at(i, col)) > std::abs(at(pivot, col))) pivot = i;
    if (!(std::abs(at(pivot, col)) > tolerance(scale) * scale))
      throw std::domain_error("general_inverse: the multivector is not invertible");
    for (int k = 0; k <= n; ++k) std::swap(at(pivot, k), at(col, k));
    for (int i = 0; i < n; ++i) {
      if (i == col || at(i, col) == 0) continue;
      const T f = at(i, col) / at(col, col);
      for (int k = col; k <= n; ++k) at(i, k) -= f * at(col, k);
    }
  }
  if constexpr (is_sparse_v<MV>) {
    sparse::terms<T> y;
    for (int i = 0; i < n; ++i)
      y.push_back({blade_of_index(MV::algebra::dimension, i), at(i, n) / at(i, i)});
    return sparse::from_unsorted<MV>(std::move(y));
  } else {
    MV y;
    for (int i = 0; i < n; ++i) {
      y.c[i] = at(i, n) / at(i, i);
      if (y.c[i] != 0) y.bits |= std::uint32_t(1) << i;
    }
    return y;
  }
}

// Prints "1.5*e1 - 2*e1^e2", or "0".
template <class MV>
std::ostream& print(std::ostream& out, const MV& x) {
  using T = typename MV::scalar_type;
  std::vector<std::pair<int, T>> nonzero;  // (canonical index, value), in canonical order
  if constexpr (is_sparse_v<MV>) {
    for (const auto& t : x.terms)
      if (t.value != T(0))
        nonzero.push_back({canonical_index(MV::algebra::dimension, t.blade), t.value});
    std::sort(nonzero.begin(), nonzero.end(),
              [](const auto& p, const auto& q) { return p.first < q.first; });
  } else {
    for (int i = 0; i < MV::size; ++i)
      if (x.c[i] != T(0)) nonzero.push_back({i, x.c[i]});
  }
  bool first = true;
  for (const auto& [i, v] : nonzero) {
    if (!first)
      out << (v < 0 ? " - " : " + ");
    else if (v < 0)
      out << "-";
    out << std::abs(v);
    if (i != 0) out << "*" << MV::blade_name(i);
    first = false;
  }
  if (first) out << "0";
  return out;
}

}  // namespace gaphys::ga
