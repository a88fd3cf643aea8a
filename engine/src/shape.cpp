#include "gaphys/shape.hpp"

#include "validate.hpp"

namespace gaphys {

shape shape::sphere(real radius) {
  detail::require_positive(radius, "sphere radius");
  return shape(shape_kind::sphere, radius, vector{}, 0);
}

shape shape::plane(const vector& normal, real offset) {
  detail::require_finite(normal, "plane normal");
  detail::require_finite(offset, "plane offset");
  const real length = e3ga::norm(normal);
  if (!(length > 0)) detail::reject("plane normal must be nonzero");
  return shape(shape_kind::plane, 0, normal / length, offset);
}

shape shape::point() { return shape(shape_kind::point, 0, vector{}, 0); }

shape shape::with(real material::*field, real value) const {
  shape copy = *this;
  copy.material_.*field = value;
  return copy;
}

shape shape::with_restitution(real restitution) const {
  if (!(restitution >= 0 && restitution <= 1)) {
    detail::reject("restitution must be in [0, 1] (got ", restitution, ")");
  }
  return with(&material::restitution, restitution);
}

shape shape::with_friction(real mu) const {
  detail::require_non_negative(mu, "friction");
  return with(&material::friction, mu);
}

shape shape::with_rolling_resistance(real c) const {
  detail::require_non_negative(c, "rolling resistance");
  return with(&material::rolling_resistance, c);
}

shape shape::with_spinning_friction(real c) const {
  detail::require_non_negative(c, "spinning friction");
  return with(&material::spinning_friction, c);
}

}  // namespace gaphys
