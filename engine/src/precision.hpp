// Tolerances that exist because of rounding, in the engine's scalar.
//
// A test that must not flip on rounding error (a hull's flat faces, an edge
// parallel to a segment, a degenerate normal, Newton's method that has
// converged) compares with a tolerance above the error of its computation.
// Those errors scale with the scalar's epsilon: 2.2e-16 for double, 1.2e-7
// for float (GAPHYS_REAL=float). Each tolerance is therefore stated for
// both, by what it guards:
// - a few hundred or thousand epsilons of rounding (a guard just above the
//   noise) keeps that multiple: 1e-12 -> 1e-5, 1e-13 -> 1e-6;
// - "far above rounding, far below any size that matters" (1e-9, 1e-8 of a
//   scale) sits near the square root of epsilon: 1e-4 in float.
#pragma once

#include <limits>
#include <type_traits>

#include "gaphys/algebra.hpp"

namespace gaphys::detail {

constexpr real by_precision(double in_double, double in_float) {
  return std::is_same_v<real, double> ? real(in_double) : real(in_float);
}

// The scalar's constants, defined once for every source (a unity build
// compiles several sources as one).
constexpr real infinity = std::numeric_limits<real>::infinity();
constexpr real pi = real(3.14159265358979323846);

}  // namespace gaphys::detail
