// Plain 3x3 matrix algebra for the engine tests, written independently of
// the engine's bivector code so that tests can check the one against the
// other: inertia tensors, Rodrigues' rotation matrices, the parallel-axis
// theorem by hand.
#pragma once

#include <array>
#include <cmath>

#include "engine_test_support.hpp"

namespace gaphys::testing {

using matrix = std::array<real, 9>;  // row-major
using triple = std::array<real, 3>;

inline triple as_triple(const vector& v) { return {v.e1(), v.e2(), v.e3()}; }

inline triple cross(const triple& a, const triple& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

inline matrix diagonal(real a, real b, real c) { return {a, 0, 0, 0, b, 0, 0, 0, c}; }

inline triple times(const matrix& m, const triple& v) {
  return {m[0] * v[0] + m[1] * v[1] + m[2] * v[2], m[3] * v[0] + m[4] * v[1] + m[5] * v[2],
          m[6] * v[0] + m[7] * v[1] + m[8] * v[2]};
}

inline matrix product(const matrix& a, const matrix& b) {
  matrix p{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) p[3 * i + j] += a[3 * i + k] * b[3 * k + j];
  return p;
}

inline matrix transposed(const matrix& m) {
  return {m[0], m[3], m[6], m[1], m[4], m[7], m[2], m[5], m[8]};
}

inline matrix plus(const matrix& a, const matrix& b) {
  matrix s;
  for (int i = 0; i < 9; ++i) s[i] = a[i] + b[i];
  return s;
}

// Rodrigues' rotation matrix: `angle` about the unit `axis`, right-handed.
inline matrix rotation(const triple& axis, real angle) {
  const real c = std::cos(angle), s = std::sin(angle), t = 1 - c;
  const real x = axis[0], y = axis[1], z = axis[2];
  // One row of the matrix per line.
  // clang-format off
  return {t * x * x + c,     t * x * y - s * z, t * x * z + s * y,
          t * x * y + s * z, t * y * y + c,     t * y * z - s * x,
          t * x * z - s * y, t * y * z + s * x, t * z * z + c};
  // clang-format on
}

// A rotation axis as its plane: about x is e23, about y e31 = -e13, about z
// e12 (the engine's documented correspondence, checked in test_body).
inline bivector plane_of(const triple& a) { return bivector{a[2], -a[1], a[0]}; }

// The rotor of the same rotation as rotation(axis, angle): R = exp(-angle/2 B)
// with B the plane of the axis, so that x_world = R x ~R turns by +angle.
inline rotor rotor_of(const triple& axis, real angle) {
  return e3ga::exp((-angle / 2) * plane_of(axis));
}

}  // namespace gaphys::testing
