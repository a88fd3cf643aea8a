#include "gaphys/shape.hpp"

#include <limits>
#include <memory>

#include "validate.hpp"

namespace gaphys {

shape shape::sphere(real radius) {
  detail::require_length(radius, "sphere radius");
  shape s(shape_kind::sphere);
  s.radius_ = radius;
  return s;
}

shape shape::plane(const vector& normal, real offset) {
  const vector unit = detail::unit_multiple(normal, "plane normal", " must be nonzero");
  detail::require_offset(offset, "plane offset");
  shape s(shape_kind::plane);
  s.normal_ = unit;
  s.offset_ = offset;
  return s;
}

shape shape::point() { return shape(shape_kind::point); }

shape shape::box(const vector& half_extents) {
  shape s(shape_kind::box);
  s.polyhedron_ = std::make_shared<const convex_polyhedron>(convex_polyhedron::box(half_extents));
  s.half_extents_ = half_extents;
  return s;
}

shape shape::capsule(real half_height, real radius) {
  detail::require_length_or_zero(half_height, "capsule half height");
  detail::require_length(radius, "capsule radius");
  shape s(shape_kind::capsule);
  s.half_height_ = half_height;
  s.radius_ = radius;
  return s;
}

shape shape::convex_hull(const std::vector<vector>& points) {
  shape s(shape_kind::convex_hull);
  s.polyhedron_ = std::make_shared<const convex_polyhedron>(convex_polyhedron::hull(points));
  return s;
}

real shape::bounding_radius() const {
  switch (kind_) {
    case shape_kind::sphere:
      return radius_;
    case shape_kind::plane:
      return std::numeric_limits<real>::infinity();
    case shape_kind::point:
      return 0;
    case shape_kind::capsule:
      return half_height_ + radius_;
    case shape_kind::box:
    case shape_kind::convex_hull:
      return polyhedron_->bounding_radius;
  }
  return 0;
}

shape shape::with_filter(std::uint32_t category, std::uint32_t mask) const {
  shape copy = *this;
  copy.filter_ = collision_filter{category, mask};
  return copy;
}

shape shape::as_sensor() const {
  if (kind_ == shape_kind::plane || kind_ == shape_kind::point) {
    detail::reject("a sensor needs a volume: a plane or a point cannot be one");
  }
  shape copy = *this;
  copy.sensor_ = true;
  return copy;
}

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
