// Input checks shared by the engine's public entry points. Each throws
// invalid_input with a message naming the field, before any state changes.
#pragma once

#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>
#include <string>
#include <type_traits>

#include "gaphys/algebra.hpp"
#include "gaphys/error.hpp"
#include "precision.hpp"

namespace gaphys::detail {

// A number of a message as the shortest text that reads back to it: a
// restitution of 1.0000000000000002 was reported as "(got 1)" by the
// stream's six digits. Other parts as the stream shows them.
template <class Part>
decltype(auto) shown(const Part& part) {
  if constexpr (std::is_floating_point_v<Part>) {
    char text[64];
    const char* end = std::to_chars(text, text + sizeof text, part).ptr;
    return std::string(text, static_cast<std::size_t>(end - text));
  } else {
    return (part);
  }
}

template <class... Parts>
[[noreturn]] void reject(const Parts&... parts) {
  std::ostringstream message;
  message << "gaphys: ";
  (message << ... << shown(parts));
  throw invalid_input(message.str());
}

inline bool is_zero(const vector& v) { return v.e1() == 0 && v.e2() == 0 && v.e3() == 0; }
inline bool is_zero(const bivector& b) { return b.e12() == 0 && b.e13() == 0 && b.e23() == 0; }

inline void require_finite(real value, const char* what) {
  if (!std::isfinite(value)) reject(what, " must be finite (got ", value, ")");
}

inline void require_positive(real value, const char* what) {
  if (!std::isfinite(value) || !(value > 0)) reject(what, " must be finite and > 0 (got ", value, ")");
}

inline void require_non_negative(real value, const char* what) {
  if (!std::isfinite(value) || !(value >= 0)) reject(what, " must be finite and >= 0 (got ", value, ")");
}

template <class Named>
void require_finite(const Named& value, const char* what) {
  for (real x : value.c) {
    if (!std::isfinite(x)) reject(what, " must be finite (got ", e3ga::basic_mv<real>(value), ")");
  }
}

// The sizes and offsets of shapes, and of the shapes queries ask about. The
// narrow phase takes their squares (distances) and their fourth powers (a
// face's area vector, squared to scale it to a normal; a moment of inertia
// by density), so each must keep its fourth power a normal number: between
// 1e-75 and 1e75 m in double, 1e-9 and 1e9 m in float. (A static box of
// half extent 1e-80 had NaN face normals, and a ball landing on it crashed
// the step; a static sphere of radius 1e300 moved a ball by 2e299 m.)
constexpr real smallest_length = by_precision(1e-75, 1e-9);
constexpr real largest_length = by_precision(1e75, 1e9);

inline void require_length(real value, const char* what) {
  require_positive(value, what);
  if (value < smallest_length || value > largest_length) {
    reject(what, " must be between ", smallest_length, " and ", largest_length, " m (got ", value,
           ")");
  }
}

// A length that may also be zero (a capsule's half height).
inline void require_length_or_zero(real value, const char* what) {
  require_non_negative(value, what);
  if (value != 0) require_length(value, what);
}

// An offset (a shape's from its body's origin, a plane's from the world's):
// finite, and no farther than largest_length.
inline void require_offset(real value, const char* what) {
  require_finite(value, what);
  if (std::fabs(value) > largest_length) {
    reject(what, " must be at most ", largest_length, " m from the origin (got ", value, ")");
  }
}

template <class Named>
void require_offset(const Named& value, const char* what) {
  require_finite(value, what);
  // (A norm whose square overflows is infinite, and so too far.)
  if (!(e3ga::norm(value) <= largest_length)) {
    reject(what, " must be at most ", largest_length, " m from the origin (got ",
           e3ga::basic_mv<real>(value), ")");
  }
}

// A speed, force or torque the step can use: finite, and not so large that
// its square (which every norm takes) overflows, as 1e200 m/s would.
template <class Named>
void require_steppable(const Named& value, const char* what) {
  require_finite(value, what);
  if (!std::isfinite(e3ga::norm2(value))) {
    reject(what, " is too large to step: its square overflows (got ", e3ga::basic_mv<real>(value),
           ")");
  }
}

// The finite nonzero value (a direction, a normal, a rotor) scaled to unit
// length, whatever its size; else rejected with `what` and `zero`, the
// message for a zero. One of 1e200 (whose squared norm overflows) or of
// 1e-200 (whose squared norm underflows) is first divided by its largest
// coefficient, both brought near 1 by a power of two (exactly) so that no
// quotient of denormals overflows, and the largest coefficient becomes
// exactly 1.
template <class Named>
Named unit_multiple(const Named& value, const char* what, const char* zero) {
  require_finite(value, what);
  const real length = e3ga::norm(value);
  if (std::isfinite(length) && length > by_precision(1e-150, 1e-18)) return value / length;
  real largest = 0;
  for (real x : value.c) largest = std::max(largest, std::fabs(x));
  if (!(largest > 0)) reject(what, zero);
  int exponent = 0;
  std::frexp(largest, &exponent);
  const real top = std::ldexp(largest, -exponent);
  Named scaled = value;
  for (real& x : scaled.c) x = std::ldexp(x, -exponent) / top;
  return scaled / e3ga::norm(scaled);
}

// The rotor scaled to unit length; a non-finite or zero rotor is rejected.
inline rotor unit_rotor(const rotor& r, const char* what) {
  return unit_multiple(r, what, " must be a nonzero rotor");
}

}  // namespace gaphys::detail
