#include "gaphys/material.hpp"

#include <algorithm>
#include <cmath>

namespace gaphys {

real combine(combine_rule rule, real x, real y) {
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

material combine(const material_combine_rules& rules, const material& a, const material& b) {
  return {combine(rules.restitution, a.restitution, b.restitution),
          combine(rules.friction, a.friction, b.friction),
          combine(rules.rolling_resistance, a.rolling_resistance, b.rolling_resistance),
          combine(rules.spinning_friction, a.spinning_friction, b.spinning_friction)};
}

}  // namespace gaphys
