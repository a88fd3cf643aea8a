// The scalar parts of the closed-form exp and log, shared by the generated
// kernels and the general algorithms, so every path treats edge cases alike.
#pragma once

#include <cmath>
#include <limits>

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

// log(c + B) = f B for a unit even element c + B with B^2 = s (scalar):
//   s < 0: f = atan2(t, c) / t, t = sqrt(-s)   (angle in [0, pi])
//   s > 0: f = atanh(t / c) / t, t = sqrt(s)
//   s = 0: f = 1 / c
// At t = 0 with c < 0 (a rotation by 2 pi) there is no plane to rotate in; the
// caller supplies one (see log_fallback).
template <class T>
T log_factor(T s, T c) {
  using std::atan2, std::atanh, std::sqrt, std::abs;
  const T t = sqrt(abs(s));
  if (t <= std::numeric_limits<T>::epsilon() * abs(c)) return T(1) / c;
  if (s < 0) return atan2(t, c) / t;
  return atanh(t / c) / t;
}

// True when log(c + B) has no plane: B vanishes and c < 0 (c + B = -1).
template <class T>
bool log_needs_fallback(T s, T c) {
  using std::sqrt, std::abs;
  return c < 0 && sqrt(abs(s)) <= std::numeric_limits<T>::epsilon() * abs(c);
}

}  // namespace gaphys::ga
