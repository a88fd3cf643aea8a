#include "gaphys/body.hpp"

#include <limits>

#include "validate.hpp"

namespace gaphys {

namespace {

rotor normalized(const rotor& r, const char* what) {
  detail::require_finite(r, what);
  const real length = e3ga::norm(r);
  if (!(length > 0)) detail::reject(what, " must be a nonzero rotor");
  return r / length;
}

void require_static_at_rest(bool is_static, bool at_rest, const char* what) {
  if (is_static && !at_rest) detail::reject("a static body cannot have a nonzero ", what);
}

bool is_zero(const vector& v) { return v.e1() == 0 && v.e2() == 0 && v.e3() == 0; }
bool is_zero(const bivector& b) { return b.e12() == 0 && b.e13() == 0 && b.e23() == 0; }

inertia initial_inertia(const body_definition& d) {
  if (d.inertia) return *d.inertia;
  if (d.shape && d.shape->kind() == shape_kind::sphere) {
    return inertia::solid_sphere(d.is_static ? 1 : d.mass, d.shape->radius());
  }
  if (d.is_static) return inertia::principal(1, 1, 1);  // never used: static bodies do not turn
  detail::reject("a dynamic body without a sphere shape needs an explicit inertia");
}

// Validates everything before the body is built, so a throw leaves no trace.
const body_definition& validated(const body_definition& d) {
  if (!d.is_static) detail::require_positive(d.mass, "body mass");
  detail::require_finite(d.position, "body position");
  detail::require_finite(d.velocity, "body velocity");
  detail::require_finite(d.angular_velocity, "body angular velocity");
  normalized(d.attitude, "body attitude");
  require_static_at_rest(d.is_static, is_zero(d.velocity), "velocity");
  require_static_at_rest(d.is_static, is_zero(d.angular_velocity), "angular velocity");
  if (d.shape && d.shape->kind() == shape_kind::plane && !d.is_static) {
    detail::reject("a plane shape needs a static body");
  }
  return d;
}

}  // namespace

body::body(const body_definition& definition)
    : is_static_(validated(definition).is_static),
      inverse_mass_(definition.is_static ? 0 : 1 / definition.mass),
      inertia_(initial_inertia(definition)),
      shape_(definition.shape),
      position_(definition.position),
      velocity_(definition.velocity),
      attitude_(normalized(definition.attitude, "body attitude")),
      angular_velocity_(definition.angular_velocity) {}

real body::mass() const {
  return is_static_ ? std::numeric_limits<real>::infinity() : 1 / inverse_mass_;
}

void body::set_position(const vector& position) {
  detail::require_finite(position, "body position");
  position_ = position;
}

void body::set_velocity(const vector& velocity) {
  detail::require_finite(velocity, "body velocity");
  require_static_at_rest(is_static_, is_zero(velocity), "velocity");
  velocity_ = velocity;
}

void body::set_attitude(const rotor& attitude) { attitude_ = normalized(attitude, "body attitude"); }

void body::set_angular_velocity(const bivector& angular_velocity) {
  detail::require_finite(angular_velocity, "body angular velocity");
  require_static_at_rest(is_static_, is_zero(angular_velocity), "angular velocity");
  angular_velocity_ = angular_velocity;
}

void body::apply_force(const vector& force, const vector& offset) {
  detail::require_finite(force, "force");
  detail::require_finite(offset, "force offset");
  force_ = force_ + force;
  // τ = r ∧ f with r the offset turned into the world frame.
  torque_ = torque_ + e3ga::op(e3ga::apply(attitude_, offset), force);
}

void body::apply_torque(const bivector& torque) {
  detail::require_finite(torque, "torque");
  torque_ = torque_ + torque;
}

bivector body::world_inertia(const bivector& b) const {
  if (is_static_) return bivector{};
  if (inertia_.is_isotropic()) return inertia_.isotropic_moment() * b;
  return e3ga::apply(attitude_, inertia_(e3ga::apply(e3ga::reverse(attitude_), b)));
}

bivector body::world_inverse_inertia(const bivector& l) const {
  if (is_static_) return bivector{};
  if (inertia_.is_isotropic()) return (1 / inertia_.isotropic_moment()) * l;
  return e3ga::apply(attitude_, inertia_.inverse(e3ga::apply(e3ga::reverse(attitude_), l)));
}

vector body::velocity_at(const vector& world_point) const {
  return body_velocity{velocity_, angular_velocity_}.at_offset(world_point - position_);
}

// Bivectors square to minus their squared magnitude, hence the sign of the
// rotational term: E = 1/2 m v^2 + 1/2 <Ω ~L>.
real body::kinetic_energy() const {
  if (is_static_) return 0;
  const real linear = e3ga::scp(velocity_, velocity_) / inverse_mass_;
  const real angular = e3ga::scp(angular_velocity_, e3ga::reverse(angular_momentum()));
  return real(0.5) * (linear + angular);
}

vector body::to_world(const vector& body_point) const {
  return position_ + e3ga::apply(attitude_, body_point);
}

}  // namespace gaphys
