// What a shape's surface is made of, and how two surfaces' values combine
// into the one a contact uses.
//
// - restitution e in [0, 1]: the share of the normal approach speed a bounce
//   gives back (default 0.5).
// - friction μ >= 0: Coulomb's coefficient; the tangential impulse of a
//   contact stays within the cone |λ_t| <= μ λ_n (default 0.5, the value
//   most engines start from: wood or rubber on a hard floor).
// - rolling_resistance c_r >= 0, dimensionless (default 0): the classic
//   rolling resistance coefficient. Rolling is resisted by an angular
//   impulse in the planes n ∧ t that hold the normal, bounded by
//   c_r ρ λ_n (a resisting force c_r N at the contact, at lever arm ρ, the
//   contact's rolling radius). A solid ball rolling on a floor slows at
//   5/7 c_r g and stops.
// - spinning_friction c_s >= 0, dimensionless (default 0): spinning about
//   the normal is resisted by an angular impulse in the tangent plane,
//   bounded by c_s ρ λ_n. A solid ball spinning on a floor slows at
//   5 c_s g / (2 ρ) rad/s² and stops.
//
// The rolling radius ρ of a contact is the smaller radius of its round
// shapes (spheres and capsules); a contact with none resists neither rolling
// nor spin.
#pragma once

#include <algorithm>
#include <cmath>

#include "gaphys/algebra.hpp"

namespace gaphys {

struct material {
  real restitution = real(0.5);
  real friction = real(0.5);
  real rolling_resistance = 0;
  real spinning_friction = 0;
};

// How a contact combines its two shapes' values x and y of one material
// property (world_settings picks one rule per property).
enum class combine_rule {
  geometric_mean,  // sqrt(x y): either surface can make the contact frictionless
  average,         // (x + y) / 2
  min,             // the smaller: either surface can make a contact dead
  max,             // the larger
  multiply,        // x y
};

// (Inline: the narrow phase combines the two shapes' values of every
// contact it makes.)
inline real combine(combine_rule rule, real x, real y) {
  switch (rule) {
    case combine_rule::geometric_mean:
      return std::sqrt(x * y);
    case combine_rule::average:
      return (x + y) / 2;
    case combine_rule::min:
      return std::min(x, y);
    case combine_rule::max:
      return std::max(x, y);
    case combine_rule::multiply:
      return x * y;
  }
  return x;  // unreachable: world_settings are validated
}

// One rule per property. The defaults: friction by the geometric mean (as
// Jolt does; a frictionless surface makes every contact with it frictionless),
// restitution by the larger value (a
// bouncy ball still bounces on a default floor), rolling resistance and
// spinning friction by the larger value (setting them on either shape is
// enough).
struct material_combine_rules {
  combine_rule restitution = combine_rule::max;
  combine_rule friction = combine_rule::geometric_mean;
  combine_rule rolling_resistance = combine_rule::max;
  combine_rule spinning_friction = combine_rule::max;
};

// The values a contact between surfaces a and b uses.
inline material combine(const material_combine_rules& rules, const material& a, const material& b) {
  return {combine(rules.restitution, a.restitution, b.restitution),
          combine(rules.friction, a.friction, b.friction),
          combine(rules.rolling_resistance, a.rolling_resistance, b.rolling_resistance),
          combine(rules.spinning_friction, a.spinning_friction, b.spinning_friction)};
}

}  // namespace gaphys
