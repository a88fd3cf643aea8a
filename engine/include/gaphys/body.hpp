// A rigid body (thesis 3.2 and 4.1): mass, inertia on bivectors, position and
// velocity (e3ga vectors), attitude (an e3ga rotor: x_world = R x_body ~R) and
// angular velocity (a world-frame e3ga bivector).
//
// Conventions, used everywhere in the engine and checked by its tests:
// - a point at world offset r from the centre of mass moves with v + r ⌋ Ω;
// - a force f applied at world offset r exerts the torque r ∧ f, so a force
//   e2 at offset e1 spins the body in the e12 plane, turning e1 towards e2,
//   which is also what Ω = e12 and R' = exp(-h Ω / 2) R do.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "gaphys/algebra.hpp"
#include "gaphys/inertia.hpp"
#include "gaphys/mass_properties.hpp"
#include "gaphys/shape.hpp"

namespace gaphys {

class body;

namespace detail {
struct snapshot_access;  // snapshot.cpp: reads and writes every field
enum class motion : unsigned char { fixed, sleeping, mover, awake };
motion motion_of(const body& b);
}  // namespace detail

struct body_definition {
  // kg, finite and > 0; ignored for static bodies, which have infinite mass.
  real mass = 1;
  // kg/m^3: when set, the mass is density times the shapes' volume instead
  // (and the inertia theirs: not with an explicit inertia).
  std::optional<real> density;
  // Body-frame inertia about the body's origin, its centre of mass. Default:
  // the exact inertia of the solid shapes (solid_mass_properties) at the
  // body's mass; a dynamic body without a solid shape must give one.
  std::optional<gaphys::inertia> inertia;
  bool is_static = false;
  // A kinematic body has infinite mass like a static one but moves, at the
  // velocities the user gives it (or to the poses body::move_to aims at):
  // gravity, forces, impulses and contacts never change them, and it pushes
  // dynamic bodies without being pushed. Its frame is where it is given (no
  // centre of mass is sought). Not with is_static; no planes.
  bool is_kinematic = false;
  // Where the body's frame is. With the inertia computed from the shapes,
  // the body's origin is moved to their centre of mass: position() is then
  // this point plus the centre's offset (turned by the attitude), and each
  // shape's offset is kept relative to the centre (body::shapes()).
  vector position{};
  vector velocity{};
  rotor attitude{1, 0, 0, 0};  // normalized on creation; must be nonzero
  bivector angular_velocity{};
  // One shape centred on the body, or several at body-frame poses (a
  // compound body); both may be given. Planes only on static bodies.
  std::optional<gaphys::shape> shape;
  std::vector<attached_shape> shapes;
  // Finite: this body falls with gravity_scale times the world's gravity.
  // 0 floats; a negative scale rises against gravity (a balloon), as in
  // Box2D. Static bodies ignore it.
  real gravity_scale = 1;
  // Damping rates (1/s, finite, >= 0) for this body in place of the
  // world's (world_settings::linear_damping, angular_damping); unset, the
  // body follows the world's.
  std::optional<real> linear_damping;
  std::optional<real> angular_damping;
  // Whether the body may sleep (world_settings::sleeping says when); false
  // keeps it, and every island it touches, awake (a player, a vehicle).
  bool can_sleep = true;
};

// A body's linear and angular velocity at one instant.
struct body_velocity {
  vector linear;
  bivector angular;

  // The velocity of the point at world offset r from the centre: v + r ⌋ Ω.
  vector at_offset(const vector& r) const { return linear + e3ga::lc(r, angular); }
};

class body {
 public:
  // Throws invalid_input (naming the bad field) for non-finite numbers,
  // a non-positive mass, a zero attitude, a plane on a dynamic body, or a
  // dynamic body whose inertia cannot be defaulted.
  explicit body(const body_definition& definition);

  bool is_static() const { return is_static_; }
  bool is_kinematic() const { return is_kinematic_; }
  bool is_dynamic() const { return !is_static_ && !is_kinematic_; }
  real mass() const;  // infinity for static and kinematic bodies
  real inverse_mass() const { return inverse_mass_; }
  const gaphys::inertia& body_inertia() const { return inertia_; }
  // The body's shapes about its centre of mass (the definition's `shape`
  // first, at the origin); shape() is the first, or nullptr.
  const std::vector<attached_shape>& shapes() const { return shapes_; }
  const gaphys::shape* shape() const { return shapes_.empty() ? nullptr : &shapes_.front().shape; }
  // The largest distance of the shapes' solids from the centre of mass.
  real bounding_radius() const { return bounding_radius_; }

  const vector& position() const { return position_; }
  const vector& velocity() const { return velocity_; }
  const rotor& attitude() const { return attitude_; }
  const bivector& angular_velocity() const { return angular_velocity_; }

  // Setters validate first and change nothing when they throw. The attitude
  // is normalized. Static bodies keep zero velocities. Speeds, forces and
  // torques must be steppable: finite, and their squares too (below about
  // 1e154 in double, 1e19 in float), as must what apply_force, apply_torque
  // and apply_impulse add up to.
  void set_position(const vector& position);
  void set_velocity(const vector& velocity);
  void set_attitude(const rotor& attitude);
  void set_angular_velocity(const bivector& angular_velocity);
  // A kinematic body: sets the velocities that carry it to this pose (the
  // attitude normalized, by the shorter turn) in the next step of h seconds
  // (finite, > 0). Throws invalid_input on other bodies.
  void move_to(const vector& position, const rotor& attitude, real h);

  // Accumulated until the next world::step, then cleared. force is in the
  // world frame, offset in the body frame (zero: no torque).
  void apply_force(const vector& force, const vector& offset = vector{});
  // The same with the point of application in the world frame: the torque
  // is (world_point - position()) ∧ force.
  void apply_force_at_world_point(const vector& force, const vector& world_point);
  void apply_torque(const bivector& torque);
  const vector& accumulated_force() const { return force_; }
  const bivector& accumulated_torque() const { return torque_; }

  // An impulse (N s, world frame) at a world point, changing the velocities
  // now: v += impulse / m and Ω += I_w⁻¹(r ∧ impulse), r = world_point -
  // position(). Static bodies ignore it (as in Box2D and Bullet); bad input
  // is rejected on them too.
  void apply_impulse(const vector& impulse, const vector& world_point);

  // Per-body gravity scale and damping (see body_definition); validated,
  // nothing changes when they throw. std::nullopt returns a rate to the
  // world's.
  real gravity_scale() const { return gravity_scale_; }
  void set_gravity_scale(real scale);
  const std::optional<real>& linear_damping() const { return linear_damping_; }
  const std::optional<real>& angular_damping() const { return angular_damping_; }
  void set_damping(std::optional<real> linear, std::optional<real> angular);

  // Sleeping (world_settings::sleeping, docs/engine.md "Sleeping"). Only
  // dynamic bodies sleep: a sleeping body has zero velocities and the world
  // skips it until something wakes its island. Every setter, force, torque
  // and impulse above wakes the body (and restarts the time it has been
  // still), and the world wakes the rest of its island at the next step.
  // A static or kinematic body given a pose or a velocity (or wake_up())
  // wakes the sleeping bodies it then reaches.
  bool is_sleeping() const { return asleep_; }
  void wake_up();
  bool can_sleep() const { return can_sleep_; }
  void set_can_sleep(bool can_sleep);  // false wakes the body

  // World-frame inertia: I_w(B) = R I(~R B R) ~R, and its inverse (zero for
  // static bodies).
  bivector world_inertia(const bivector& b) const;
  bivector world_inverse_inertia(const bivector& l) const;
  bivector angular_momentum() const { return world_inertia(angular_velocity_); }
  vector velocity_at(const vector& world_point) const;
  real kinetic_energy() const;
  vector to_world(const vector& body_point) const;

 private:
  friend class world;
  friend class contact_solver;
  friend struct detail::snapshot_access;

  bool is_static_ = false;
  bool is_kinematic_ = false;
  real inverse_mass_ = 0;
  gaphys::inertia inertia_;
  std::vector<attached_shape> shapes_;
  real bounding_radius_ = 0;

  vector position_{};
  vector velocity_{};
  rotor attitude_{1, 0, 0, 0};
  bivector angular_velocity_{};

  vector force_{};
  bivector torque_{};

  real gravity_scale_ = 1;
  std::optional<real> linear_damping_;
  std::optional<real> angular_damping_;

  // Sleeping (world.hpp, "Sleeping"): whether the body may, whether it does
  // (then its velocities are zero and the world skips it), since when its
  // points have all moved slower than the sleep speeds (s), its sleeping
  // island's label (0: none), and whether a user call woke it since the
  // last step (the world then wakes the rest of its island).
  bool can_sleep_ = true;
  bool asleep_ = false;
  real still_time_ = 0;
  std::uint64_t island_ = 0;
  bool woken_ = false;
  void wake_dynamic();
  void accumulate(const vector& force, const bivector& torque);

  friend detail::motion detail::motion_of(const body& b);
};

namespace detail {

// How a body takes part in a step's candidate pairs: a pair is worth meeting
// when one of its bodies is awake and dynamic, or when a body that moves
// others (a moving kinematic body, or a static or kinematic one the user
// just moved) reaches a sleeping one, which must then wake.
inline motion motion_of(const body& b) {
  if (b.is_dynamic()) return b.asleep_ ? motion::sleeping : motion::awake;
  const bool moving = b.woken_ || b.velocity_.e1() != 0 || b.velocity_.e2() != 0 ||
                      b.velocity_.e3() != 0 || b.angular_velocity_.e12() != 0 ||
                      b.angular_velocity_.e13() != 0 || b.angular_velocity_.e23() != 0;
  return moving ? motion::mover : motion::fixed;
}

inline bool may_meet(motion a, motion b) {
  return a == motion::awake || b == motion::awake ||
         (a == motion::mover && b == motion::sleeping) ||
         (a == motion::sleeping && b == motion::mover);
}

}  // namespace detail

}  // namespace gaphys
