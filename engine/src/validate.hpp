// Input checks shared by the engine's public entry points. Each throws
// invalid_input with a message naming the field, before any state changes.
#pragma once

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "gaphys/algebra.hpp"
#include "gaphys/error.hpp"
#include "precision.hpp"

namespace gaphys::detail {

template <class... Parts>
[[noreturn]] void reject(const Parts&... parts) {
  std::ostringstream message;
  message << "gaphys: ";
  (message << ... << parts);
  throw invalid_input(message.str());
}

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

// The rotor scaled to unit length; a non-finite or zero rotor is rejected.
inline rotor unit_rotor(const rotor& r, const char* what) {
  require_finite(r, what);
  const real length = e3ga::norm(r);
  if (std::isfinite(length) && length > by_precision(1e-150, 1e-18)) return r / length;
  // A rotor of 1e200 (whose squared norm overflows) or of 1e-200 (whose
  // squared norm underflows): scaled by its largest coefficient first.
  real largest = 0;
  for (real x : r.c) largest = std::max(largest, std::fabs(x));
  if (!(largest > 0)) reject(what, " must be a nonzero rotor");
  const rotor scaled = r / largest;
  return scaled / e3ga::norm(scaled);
}

}  // namespace gaphys::detail
