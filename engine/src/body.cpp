#include "gaphys/body.hpp"

#include <algorithm>
#include <atomic>
#include <array>
#include <limits>
#include <utility>

#include "pose_changes.hpp"
#include "validate.hpp"

namespace gaphys {

namespace detail {

namespace {
std::atomic<std::uint64_t> pose_change_count{0};
}  // namespace

std::uint64_t pose_changes() { return pose_change_count.load(std::memory_order_relaxed); }
void note_pose_change() { pose_change_count.fetch_add(1, std::memory_order_relaxed); }

}  // namespace detail

namespace {

void require_static_at_rest(bool is_static, bool at_rest, const char* what) {
  if (is_static && !at_rest) detail::reject("a static body cannot have a nonzero ", what);
}

using detail::is_zero;

void require_damping(const std::optional<real>& rate, const char* what) {
  if (rate) detail::require_non_negative(*rate, what);
}

bool is_plane(const attached_shape& s) { return s.shape.kind() == shape_kind::plane; }

// The definition's shapes in one list: `shape` first, at the body origin.
std::vector<attached_shape> all_shapes(const body_definition& d) {
  std::vector<attached_shape> shapes;
  if (d.shape) shapes.push_back(attached_shape{*d.shape, vector{}, rotor{1, 0, 0, 0}});
  shapes.insert(shapes.end(), d.shapes.begin(), d.shapes.end());
  return shapes;
}

bool has_solid(const std::vector<attached_shape>& shapes) {
  return std::any_of(shapes.begin(), shapes.end(), [](const attached_shape& s) {
    return is_solid(s.shape) && !s.shape.is_sensor();
  });
}

// Validates everything before the body is built, so a throw leaves no trace.
const body_definition& validated(const body_definition& d) {
  if (!d.is_static) detail::require_positive(d.mass, "body mass");
  if (d.density) detail::require_positive(*d.density, "body density");
  if (d.density && d.inertia) detail::reject("give a body density or an inertia, not both");
  detail::require_finite(d.position, "body position");
  detail::require_steppable(d.velocity, "body velocity");
  detail::require_steppable(d.angular_velocity, "body angular velocity");
  detail::unit_rotor(d.attitude, "body attitude");
  detail::require_finite(d.gravity_scale, "body gravity scale");
  require_damping(d.linear_damping, "body linear damping");
  require_damping(d.angular_damping, "body angular damping");
  if (d.is_static && d.is_kinematic) detail::reject("a body cannot be both static and kinematic");
  require_static_at_rest(d.is_static, is_zero(d.velocity), "velocity");
  require_static_at_rest(d.is_static, is_zero(d.angular_velocity), "angular velocity");
  const std::vector<attached_shape> shapes = all_shapes(d);
  for (const attached_shape& s : shapes) {
    detail::require_offset(s.offset, "shape offset");
    detail::unit_rotor(s.attitude, "shape attitude");
    if (is_plane(s) && !d.is_static) detail::reject("a plane shape needs a static body");
    // The broad phase bounds a plane's body by the plane alone.
    if (is_plane(s) && shapes.size() > 1) detail::reject("a plane must be its body's only shape");
    const bool posed =
        !is_zero(s.offset) || s.attitude.c[1] != 0 || s.attitude.c[2] != 0 || s.attitude.c[3] != 0;
    if (is_plane(s) && posed) {
      detail::reject(
          "a plane shape takes no offset or attitude: give them in its normal and offset");
    }
  }
  if (!d.is_static && !d.is_kinematic && !d.inertia && !has_solid(shapes)) {
    detail::reject("a dynamic body without a solid shape needs an explicit inertia");
  }
  return d;
}

// The body's mass properties about the origin it will have: given, or those
// of its solid shapes (by density, or scaled to the given mass), whose
// centre then becomes the origin. Static bodies never turn or move: they
// keep their frame, and their inertia is never used.
struct initial_mass {
  real inverse_mass;
  gaphys::inertia inertia;
  vector center;  // body frame: where the origin moves to
};

// 1 / mass, which every step uses: a mass whose inverse overflows (1e-310
// kg) is rejected here, rather than by each step after as a body that would
// move too far. (One from a density solid_mass_properties checks itself.)
real inverse_of_mass(real mass) {
  const real inverse = 1 / mass;
  if (!std::isfinite(inverse)) {
    detail::reject("body mass ", mass, " kg is too small or too large to invert in real numbers");
  }
  return inverse;
}

initial_mass initial_mass_properties(const body_definition& d,
                                     const std::vector<attached_shape>& shapes) {
  if (d.is_static || d.is_kinematic) {
    return {0, d.inertia.value_or(inertia::principal(1, 1, 1)), vector{}};
  }
  if (d.inertia) return {inverse_of_mass(d.mass), *d.inertia, vector{}};
  const mass_properties solid = solid_mass_properties(shapes, d.density.value_or(1));
  if (d.density) return {1 / solid.mass, solid.inertia, solid.center};
  const real inverse_mass = inverse_of_mass(d.mass);
  std::array<real, 9> rows = solid.inertia.rows();
  for (real& x : rows) x *= d.mass / solid.mass;
  // (A mass of 1e-308 kg on a unit box scales its moments to 2e-309 kg m^2,
  // whose inverses real numbers cannot hold.)
  bool invertible = true;
  for (const int i : {0, 4, 8}) {
    invertible = invertible && rows[i] > 0 && std::isfinite(rows[i]) && std::isfinite(1 / rows[i]);
  }
  if (!invertible) {
    detail::reject("body mass ", d.mass, " kg gives these shapes moments of inertia (", rows[0],
                   ", ", rows[4], ", ", rows[8],
                   " kg m^2) too small or too large to invert in real numbers; give an inertia");
  }
  return {inverse_mass, inertia::tensor(rows), solid.center};
}

// The shapes about the new origin, and how far they reach from it.
std::vector<attached_shape> recentred(std::vector<attached_shape> shapes, const vector& center) {
  for (attached_shape& s : shapes) {
    s.offset = s.offset - center;
    s.attitude = detail::unit_rotor(s.attitude, "shape attitude");
  }
  return shapes;
}

real reach(const std::vector<attached_shape>& shapes) {
  real radius = 0;
  for (const attached_shape& s : shapes) {
    radius = std::max(radius, e3ga::norm(s.offset) + s.shape.bounding_radius());
  }
  return radius;
}

}  // namespace

body::body(const body_definition& definition) {
  const body_definition& d = validated(definition);
  std::vector<attached_shape> shapes = all_shapes(d);
  const initial_mass m = initial_mass_properties(d, shapes);
  is_static_ = d.is_static;
  is_kinematic_ = d.is_kinematic;
  inverse_mass_ = m.inverse_mass;
  inertia_ = m.inertia;
  shapes_ = recentred(std::move(shapes), m.center);
  bounding_radius_ = reach(shapes_);
  attitude_ = detail::unit_rotor(d.attitude, "body attitude");
  position_ = d.position + e3ga::apply(attitude_, m.center);
  velocity_ = d.velocity;
  angular_velocity_ = d.angular_velocity;
  gravity_scale_ = d.gravity_scale;
  linear_damping_ = d.linear_damping;
  angular_damping_ = d.angular_damping;
  can_sleep_ = d.can_sleep;
}

real body::mass() const {
  return is_dynamic() ? 1 / inverse_mass_ : std::numeric_limits<real>::infinity();
}

void body::set_position(const vector& position) {
  detail::require_finite(position, "body position");
  position_ = position;
  detail::note_pose_change();
  wake_up();
}

void body::set_velocity(const vector& velocity) {
  detail::require_steppable(velocity, "body velocity");
  require_static_at_rest(is_static_, is_zero(velocity), "velocity");
  velocity_ = velocity;
  wake_up();
}

// The position moves by h v; the attitude turns by exp(-h Ω / 2) (as
// world::step moves a kinematic body), which is the target's T ~R when
// Ω = -(2 / h) log(T ~R), with T's sign taken for the shorter turn.
void body::move_to(const vector& position, const rotor& attitude, real h) {
  detail::require_finite(position, "target position");
  const rotor target = detail::unit_rotor(attitude, "target attitude");
  detail::require_positive(h, "time step");
  if (!is_kinematic_) detail::reject("move_to needs a kinematic body");
  rotor turn = e3ga::gp(target, e3ga::reverse(attitude_));
  if (turn.c[0] < 0) turn = -turn;
  const vector velocity = (1 / h) * (position - position_);
  const bivector angular_velocity = (-2 / h) * e3ga::log(turn);
  detail::require_steppable(velocity, "move_to's velocity (the distance over h)");
  detail::require_steppable(angular_velocity, "move_to's angular velocity (the turn over h)");
  velocity_ = velocity;
  angular_velocity_ = angular_velocity;
  wake_up();
}

void body::set_attitude(const rotor& attitude) {
  attitude_ = detail::unit_rotor(attitude, "body attitude");
  detail::note_pose_change();
  wake_up();
}

void body::set_angular_velocity(const bivector& angular_velocity) {
  detail::require_steppable(angular_velocity, "body angular velocity");
  require_static_at_rest(is_static_, is_zero(angular_velocity), "angular velocity");
  angular_velocity_ = angular_velocity;
  wake_up();
}

void body::apply_force(const vector& force, const vector& offset) {
  detail::require_finite(force, "force");
  detail::require_finite(offset, "force offset");
  // τ = r ∧ f with r the offset turned into the world frame.
  accumulate(force, e3ga::op(e3ga::apply(attitude_, offset), force));
}

void body::apply_force_at_world_point(const vector& force, const vector& world_point) {
  detail::require_finite(force, "force");
  detail::require_finite(world_point, "force point");
  accumulate(force, e3ga::op(world_point - position_, force));
}

void body::apply_torque(const bivector& torque) {
  detail::require_finite(torque, "torque");
  accumulate(vector{}, torque);
}

// Adds to the force and torque the next step applies, if both stay
// steppable (else throws, and neither changes).
void body::accumulate(const vector& force, const bivector& torque) {
  const vector total_force = force_ + force;
  const bivector total_torque = torque_ + torque;
  detail::require_steppable(total_force, "the body's total force");
  detail::require_steppable(total_torque, "the body's total torque");
  force_ = total_force;
  torque_ = total_torque;
  wake_dynamic();
}

// The angular momentum changes by r ∧ J; Ω = I_w⁻¹(L) is linear in L, so
// Ω changes by I_w⁻¹(r ∧ J), as a contact impulse changes it.
void body::apply_impulse(const vector& impulse, const vector& world_point) {
  detail::require_finite(impulse, "impulse");
  detail::require_finite(world_point, "impulse point");
  if (!is_dynamic()) return;
  const vector velocity = velocity_ + inverse_mass_ * impulse;
  const bivector angular_velocity =
      angular_velocity_ + world_inverse_inertia(e3ga::op(world_point - position_, impulse));
  detail::require_steppable(velocity, "the body's velocity after the impulse");
  detail::require_steppable(angular_velocity, "the body's angular velocity after the impulse");
  wake_up();
  velocity_ = velocity;
  angular_velocity_ = angular_velocity;
}

void body::set_gravity_scale(real scale) {
  detail::require_finite(scale, "body gravity scale");
  gravity_scale_ = scale;
  wake_dynamic();
}

void body::set_damping(std::optional<real> linear, std::optional<real> angular) {
  require_damping(linear, "body linear damping");
  require_damping(angular, "body angular damping");
  linear_damping_ = linear;
  angular_damping_ = angular;
  wake_dynamic();
}

// The world sees woken_ at the next step: it wakes the body's island, or,
// for a static or kinematic body, the sleeping bodies it now reaches.
void body::wake_up() {
  asleep_ = false;
  still_time_ = 0;
  woken_ = true;
}

// Forces and settings that move nothing but a dynamic body.
void body::wake_dynamic() {
  if (is_dynamic()) wake_up();
}

void body::set_can_sleep(bool can_sleep) {
  can_sleep_ = can_sleep;
  if (!can_sleep) wake_up();
}

bivector body::world_inertia(const bivector& b) const {
  if (!is_dynamic()) return bivector{};
  if (inertia_.is_isotropic()) return inertia_.isotropic_moment() * b;
  return e3ga::apply(attitude_, inertia_(e3ga::apply(e3ga::reverse(attitude_), b)));
}

bivector body::world_inverse_inertia(const bivector& l) const {
  if (!is_dynamic()) return bivector{};
  if (inertia_.is_isotropic()) return (1 / inertia_.isotropic_moment()) * l;
  return e3ga::apply(attitude_, inertia_.inverse(e3ga::apply(e3ga::reverse(attitude_), l)));
}

vector body::velocity_at(const vector& world_point) const {
  return body_velocity{velocity_, angular_velocity_}.at_offset(world_point - position_);
}

// Bivectors square to minus their squared magnitude, hence the sign of the
// rotational term: E = 1/2 m v^2 + 1/2 <Ω ~L>.
real body::kinetic_energy() const {
  if (!is_dynamic()) return 0;  // infinite mass: none to speak of
  const real linear = e3ga::scp(velocity_, velocity_) / inverse_mass_;
  const real angular = e3ga::scp(angular_velocity_, e3ga::reverse(angular_momentum()));
  return real(0.5) * (linear + angular);
}

vector body::to_world(const vector& body_point) const {
  return position_ + e3ga::apply(attitude_, body_point);
}

}  // namespace gaphys
