// An engine-neutral scene: what every adapter builds, in the same units and
// conventions, so that every engine starts from the same numbers (rounded to
// float where the engine computes in float).
// Friction is Coulomb's coefficient of the surface, 0 (frictionless) unless a
// scene sets it; each adapter combines a pair's values so that two surfaces
// of the same mu make a contact of mu. Rolling and spinning resistance are
// always 0.
#pragma once

#include <string>
#include <vector>

#include "vec3.hpp"

namespace gaphys_compare {

// A static half-space {x : normal · x <= offset}: the solid is below the
// surface, normal (unit) points out of it into free space. gaphys, Bullet's
// btStaticPlaneShape and ODE's dCreatePlane all use this convention.
struct plane_description {
  vec3 normal;
  double offset = 0;
  double restitution = 0;
  double friction = 0;
};

// A body's shape: a solid sphere (radius > 0), a solid box (half_extents
// nonzero, its edges along the body's axes), or none (a free body).
struct body_description {
  double mass = 1;        // kg; ignored when static
  double radius = 0;      // m: a solid sphere; 0: not a sphere
  vec3 half_extents;      // m: a solid box; all 0: not a box
  vec3 inertia;           // principal moments about the body's x, y, z (kg m^2)
  vec3 position;          // m
  quat attitude;          // body to world (unit); identity unless a scene turns it
  vec3 velocity;          // m/s
  vec3 angular_velocity;  // rad/s, world frame (axis times rate)
  double restitution = 0;
  double friction = 0;
  bool is_static = false;  // static spheres: targets that never move

  bool is_box() const { return half_extents.x > 0; }
  bool has_shape() const { return radius > 0 || is_box(); }
};

struct scene {
  std::string name;
  vec3 gravity;  // m/s^2
  std::vector<plane_description> planes;
  std::vector<body_description> bodies;
};

}  // namespace gaphys_compare
