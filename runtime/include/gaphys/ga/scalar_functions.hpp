// The scalar parts of the closed-form exp, log and versor inverse, shared by the generated
// kernels and the general algorithms, so every path treats edge cases alike.
#pragma once

#include <cmath>
#include <limits>
#include <stdexcept>

#include "batch_traits.hpp"

namespace gaphys::ga {

template <class T>
struct exp_factors {
  T c;  // exp(x) = c + k x
  T k;
};

// exp(x) for an x whose square is the scalar s:
//   s < 0 (rotation):    cos(t) + sin(t)/t x,   t = sqrt(-s)
//   s > 0 (boost):       cosh(t) + sinh(t)/t x, t = sqrt(s)
//   s = 0 (translation): 1 + x
// Near t = 0 the Taylor series keeps sin(t)/t accurate (no 0/0).
template <class T>
exp_factors<T> exp_of_square(T s) {
  using std::cos, std::cosh, std::sin, std::sinh, std::sqrt, std::abs;
  const T t = sqrt(abs(s));
  if (t < T(1e-4)) {
    // c = 1 + s/2 + s^2/24, k = 1 + s/6 + s^2/120: error O(t^6) < eps.
    return {T(1) + s / T(2) + s * s / T(24), T(1) + s / T(6) + s * s / T(120)};
  }
  if (s < 0) return {cos(t), sin(t) / t};
  return {cosh(t), sinh(t) / t};
}

// log(c + B) = f B for a unit even element c + B with B^2 = s (scalar), where
// log_case_of says the logarithm lies in B's plane:
//   s < 0: f = atan2(t, c) / t, t = sqrt(-s)   (angle in [0, pi])
//   s > 0: f = atanh(t / c) / t, t = sqrt(s); for t > c / 2 (rapidity over
//          0.55), log(c + t) / t, equal for a unit element (c^2 - t^2 = 1):
//          atanh near 1 loses digits as 1 / (1 - (t/c)^2) grows (a boost of
//          rapidity 15 came back as 14.9999, of 19 as NaN, of 20 as inf)
//   s = 0: f = 1 / c
template <class T>
T log_factor(T s, T c) {
  using std::atan2, std::atanh, std::log, std::sqrt, std::abs;
  const T t = sqrt(abs(s));
  if (t <= std::numeric_limits<T>::epsilon() * abs(c)) return T(1) / c;
  if (s < 0) return atan2(t, c) / t;
  if (c > 0 && t > c / T(2)) return log(c + t) / t;
  return atanh(t / c) / t;
}

// Where the logarithm of c + B lies, for B^2 = s (a scalar) and b2 the sum of
// the squares of B's coefficients.
enum class log_case {
  in_plane,   // f B, f = log_factor(s, c)
  minus_one,  // B vanishes and c < 0: c + B = -1, a rotation by 2 pi in some plane
  none,       // c < 0 and B a boost or null: c + B = -exp(B') has no logarithm in
              // B's plane (exp of a bivector there has a scalar part >= 1)
};

// A rotation (s < 0) may have c < 0 (an angle beyond pi/2); a boost
// (cosh >= 1) or a translation (1) may not. B counts as vanishing below eps |c|
// and as a rotation when sqrt(-s) exceeds that; the margin of 4 between the
// two keeps a rotation's -s (equal to b2 up to rounding) out of `none`.
template <class T>
log_case log_case_of(T s, T c, T b2) {
  if (!(c < 0)) return log_case::in_plane;
  const T small = std::numeric_limits<T>::epsilon() * std::abs(c);
  if (b2 <= T(16) * small * small) return log_case::minus_one;
  if (-s > small * small) return log_case::in_plane;
  return log_case::none;
}

// Throws std::domain_error unless the logarithm lies in B's plane
// (minus_one: for a caller with no rotation plane to offer).
inline void require_log_in_plane(log_case where) {
  if (where == log_case::none)
    throw std::domain_error(
        "log: -exp(B) with B a boost or null bivector has no logarithm in the plane of B");
  if (where == log_case::minus_one)
    throw std::domain_error(
        "log: -1 is a rotation by 2 pi, and no bivector the result may hold squares to -1");
}

// f = log_factor(s, c), or std::domain_error when the logarithm leaves B's plane.
template <class T>
T log_factor(T s, T c, log_case where) {
  require_log_in_plane(where);
  return log_factor(s, c);
}

// 1 / <a ~a>_0, the scale of the versor inverse ~a / <a ~a>_0. A null a (<a ~a>_0 = 0, such as
// ni or a point of the conformal model) has no versor inverse: 1/0 would give infinities, and
// NaN where ~a is zero.
template <class T>
T inverse_norm2(T norm2) {
  bool null;
  if constexpr (is_batch_v<T>) {
    null = batch_traits<T>::any_zero(norm2);  // any lane
  } else {
    null = norm2 == T(0);
  }
  if (null)
    throw std::domain_error("inverse: <a ~a>_0 = 0, a null multivector has no versor inverse");
  return T(1) / norm2;
}

}  // namespace gaphys::ga
