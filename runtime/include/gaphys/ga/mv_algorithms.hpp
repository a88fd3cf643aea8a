// Algorithms on general multivectors that are not a single table lookup:
// exp, log, the general inverse, printing. They are written once against the
// generated `basic_mv` interface (c, bits, size, grade_mask, basis_blade,
// blade_name) and the algebra's gp, found by argument-dependent lookup.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <ostream>
#include <stdexcept>

#include "scalar_functions.hpp"

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
  for (int i = 0; i < MV::size; ++i) m = std::max(m, std::abs(x.c[i]));
  return m;
}

// Sum of c_i d_i over the coefficients (the blade basis's Euclidean product).
template <class MV>
typename MV::scalar_type coefficient_dot(const MV& x, const MV& y) {
  typename MV::scalar_type sum = 0;
  for (int i = 0; i < MV::size; ++i) sum += x.c[i] * y.c[i];
  return sum;
}

template <class MV>
MV keep_grades(const MV& x, std::uint32_t mask) {
  MV r = x;
  for (int i = 0; i < MV::size; ++i)
    if (!(mask >> i & 1)) r.c[i] = 0;
  r.bits &= mask;
  return r;
}

template <class MV>
MV linear_combination(typename MV::scalar_type a, const MV& x, typename MV::scalar_type b, const MV& y) {
  MV r;
  for (int i = 0; i < MV::size; ++i) r.c[i] = a * x.c[i] + b * y.c[i];
  r.bits = x.bits | y.bits;
  return r;
}

template <class MV>
MV plus_scalar(const MV& x, typename MV::scalar_type s) {
  MV r = x;
  r.c[0] += s;
  r.bits |= 1;
  return r;
}

// Tolerance for "numerically zero" relative to a magnitude.
template <class T>
T tolerance(T magnitude) {
  return std::numeric_limits<T>::epsilon() * T(256) * std::max(T(1), magnitude);
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
  T scale = max_abs(x) * T(MV::size);
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

// Splits a bivector B of an algebra of dimension <= 5 into commuting parts
// B = b1 + b2 with scalar squares l1, l2 (the invariant decomposition).
// With W = <B^2>_4 / 2 = b1 b2: B^2 = l1 + l2 + 2W and W^2 = l1 l2, so l1, l2
// solve l^2 - <B^2>_0 l + <W^2>_0 = 0, and (l1 - W) B = (l1 - l2) b1.
// Returns false when the roots are complex or coincide.
template <class MV>
bool split_bivector(const MV& b, MV& b1, MV& b2, typename MV::scalar_type& l1, typename MV::scalar_type& l2) {
  using T = typename MV::scalar_type;
  const MV square = gp(b, b);
  const MV w = linear_combination(T(0.5), keep_grades(square, MV::grade_mask(4)), T(0), square);
  const T s0 = square.c[0];
  const T w2 = gp(w, w).c[0];
  const T w_size = max_abs(w);
  if (std::abs(w2) <= tolerance(w_size * w_size)) {
    // W is null (W^2 = 0): a screw motion in conformal space, whose parts are a
    // rotation (l1 = <B^2>_0) and a null translation along the axis (l2 = 0).
    // Taking the roots directly avoids a square root that loses half the digits
    // when the rotation is small.
    if (s0 == 0) return false;
    l1 = s0;
    l2 = 0;
  } else {
    const T disc = s0 * s0 - T(4) * w2;
    const T scale = std::max(T(1), s0 * s0);
    if (disc < -tolerance(scale)) return false;
    const T root = std::sqrt(std::max(disc, T(0)));
    if (root <= std::sqrt(tolerance(scale))) return false;
    // Order so that l2 is the root nearer zero.
    l1 = s0 >= 0 ? (s0 + root) / 2 : (s0 - root) / 2;
    l2 = s0 - l1;
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
  const T magnitude = max_abs(square);
  if (is_numerically_scalar(square, magnitude)) return exp_simple(x, square.c[0]);
  MV b1, b2;
  T l1, l2;
  if (!split_bivector(x, b1, b2, l1, l2)) return exp_series(x);
  return gp(exp_simple(b1, l1), exp_simple(b2, l2));
}

// A plane to rotate in when log meets -1 (rotation by 2 pi): the first basis
// bivector that squares to -1.
template <class MV>
MV log_fallback() {
  using T = typename MV::scalar_type;
  for (int i = 0; i < MV::size; ++i) {
    if (!(MV::grade_mask(2) >> i & 1)) continue;
    const MV e = MV::basis_blade(i);
    if (gp(e, e).c[0] == T(-1)) return linear_combination(T(3.14159265358979323846), e, T(0), e);
  }
  throw std::domain_error("log: -1 has no logarithm in this algebra");
}

// log of an even versor of grades 0, 2 (and 4 for screw motions): the
// bivector L with exp(L) = r. Rotation angles come out in [0, pi] per plane.
// For a screw r = exp(b1) exp(b2), b1 a rotation (b1^2 = -t^2), b2 null and
// commuting with b1: <r>_0 = cos t, <r>_2 = sin t u1 + cos t b2 (u1 = b1/t),
// <r>_4 = sin t u1 b2, hence b2 = cos t <r>_2,null - (sin t u1) <r>_4.
template <class MV>
MV log_general(const MV& r) {
  using T = typename MV::scalar_type;
  const T magnitude = max_abs(r);
  const std::uint32_t even = MV::grade_mask(0) | MV::grade_mask(2) | MV::grade_mask(4);
  if (max_abs(keep_grades(r, ~even)) > tolerance(magnitude))
    throw std::domain_error("log: argument is not an even versor (grades 0, 2, 4)");
  const T c = r.c[0];
  const MV b = keep_grades(r, MV::grade_mask(2));
  const MV q = keep_grades(r, MV::grade_mask(4));
  const MV square = gp(b, b);
  // r is a simple rotation, boost or translation when its 4-vector part q
  // (= sin(t) u1 b2 for a screw, see below) is negligible next to the
  // rotation's own size sqrt|<b^2>_0|. An absolute test is not enough: near a
  // full turn sin(t) is tiny while the translation b2 is not.
  const T s0 = square.c[0];
  const bool simple = max_abs(q) <= tolerance(T(1)) * std::sqrt(std::abs(s0)) * std::max(T(1), magnitude);
  if (simple && max_abs(keep_grades(square, ~(MV::grade_mask(0) | MV::grade_mask(4)))) <= tolerance(max_abs(square))) {
    if (log_needs_fallback(square.c[0], c)) return log_fallback<MV>();
    return linear_combination(log_factor(square.c[0], c), b, T(0), b);
  }
  // A screw: r = (c + s u1)(1 + b2) with u1^2 = -1, b2 null and commuting
  // with u1 (rotation about an axis, translation along it). So
  //   <r>_2 = b = s u1 + c b2,   <r>_4 = q = s u1 b2,   <b^2>_0 = -s^2,
  //   d := <b q>_2 = (s u1 + c b2)(s u1 b2) = -s^2 b2        (b2^2 = 0).
  // d gives the direction of b2 (from products of small numbers: accurate),
  // and its length two ways: c b2 is b's part along d, and b2 = -d / s^2.
  // Combining them as c (c b2) + s^2 b2 = b2 divides by nothing, so the result
  // L = angle/s (b - c b2) + b2 has exp(L) = r to rounding even near a full
  // turn, where r fixes the axis only through O(s) terms. (Coefficient-wise
  // projection on d: the rotation's translation-like part is orthogonal to it
  // in the blade basis, as in the conformal model.)
  const T sin2 = -s0;
  const MV d = keep_grades(gp(b, q), MV::grade_mask(2));
  const T d_norm2 = coefficient_dot(d, d), b_along = coefficient_dot(b, d);
  if (!(sin2 > 0) || !(d_norm2 > 0) || max_abs(gp(d, d)) > tolerance(d_norm2))
    throw std::domain_error("log: only rotations, boosts, translations and screw motions are supported");
  const T d_norm = std::sqrt(d_norm2);
  const T length = c * b_along / d_norm - d_norm;  // b2 = length * d / |d|
  const MV b2 = linear_combination(length / d_norm, d, T(0), d);
  MV rotation = linear_combination(T(1), b, -c, b2);  // s u1
  // s u1 has no part along d, but computing it cancels O(1) numbers; what is
  // left along d would be amplified by angle/s into the translation, to which
  // exp is fully sensitive. Project it out (exact in exact arithmetic).
  rotation = linear_combination(T(1), rotation, -coefficient_dot(rotation, d) / d_norm2, d);
  const T s = std::sqrt(sin2);
  return linear_combination(std::atan2(s, c) / s, rotation, T(1), b2);
}

// The inverse of any invertible multivector: solves x y = 1 for y by Gaussian
// elimination on the matrix of left multiplication by x.
template <class MV>
MV general_inverse(const MV& x) {
  using T = typename MV::scalar_type;
  constexpr int n = MV::size;
  std::array<std::array<T, n + 1>, n> m{};
  for (int j = 0; j < n; ++j) {
    const MV column = gp(x, MV::basis_blade(j));
    for (int i = 0; i < n; ++i) m[i][j] = column.c[i];
  }
  m[0][n] = 1;
  const T scale = max_abs(x);
  for (int col = 0; col < n; ++col) {
    int pivot = col;
    for (int i = col + 1; i < n; ++i)
      if (std::abs(m[i][col]) > std::abs(m[pivot][col])) pivot = i;
    if (!(std::abs(m[pivot][col]) > tolerance(scale) * scale))
      throw std::domain_error("general_inverse: the multivector is not invertible");
    std::swap(m[pivot], m[col]);
    for (int i = 0; i < n; ++i) {
      if (i == col || m[i][col] == 0) continue;
      const T f = m[i][col] / m[col][col];
      for (int k = col; k <= n; ++k) m[i][k] -= f * m[col][k];
    }
  }
  MV y;
  for (int i = 0; i < n; ++i) {
    y.c[i] = m[i][n] / m[i][i];
    if (y.c[i] != 0) y.bits |= std::uint32_t(1) << i;
  }
  return y;
}

// Prints "1.5*e1 - 2*e1^e2", or "0".
template <class MV>
std::ostream& print(std::ostream& out, const MV& x) {
  bool first = true;
  for (int i = 0; i < MV::size; ++i) {
    const auto v = x.c[i];
    if (v == 0) continue;
    if (!first) out << (v < 0 ? " - " : " + ");
    else if (v < 0) out << "-";
    out << std::abs(v);
    if (i != 0) out << "*" << MV::blade_name(i);
    first = false;
  }
  if (first) out << "0";
  return out;
}

}  // namespace gaphys::ga
