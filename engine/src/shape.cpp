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

shape shape::with_restitution(real restitution) const {
  if (!(restitution >= 0 && restitution <= 1)) {
    detail::reject("restitution must be in [0, 1] (got ", restitution, ")");
  }
  shape copy = *this;
  copy.material_.restitution = restitution;
  return copy;
}

shape shape::with_friction(real mu) const {
  detail::require_non_negative(mu, "friction");
  shape copy = *this;
  copy.material_.friction = mu;
  return copy;
}

shape shape::with_rolling_resistance(real c) const {
  detail::require_non_negative(c, "rolling resistance");
  shape copy = *this;
  copy.material_.rolling_resistance = c;
  return copy;
}

shape shape::with_spinning_friction(real c) const {
  detail::require_non_negative(c, "spinning friction");
  shape copy = *this;
  copy.material_.spinning_friction = c;
  return copy;
}

}  // namespace gaphys
