// An engine-neutral scene: what every adapter builds, in the same units and
// conventions, so that every engine starts from the same numbers (rounded to
// float where the engine computes in float).
// Every body starts with the identity attitude.
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

struct body_description {
  double mass = 1;        // kg; ignored when static
  double radius = 0;      // m: a solid sphere; 0: no shape (a free body)
  vec3 inertia;           // principal moments about the body's x, y, z (kg m^2)
  vec3 position;          // m
  vec3 velocity;          // m/s
  vec3 angular_velocity;  // rad/s, world frame (axis times rate)
  double restitution = 0;
  double friction = 0;
  bool is_static = false;  // static spheres: targets that never move
};

struct scene {
  std::string name;
  vec3 gravity;  // m/s^2
  std::vector<plane_description> planes;
  std::vector<body_description> bodies;
};

}  // namespace gaphys_compare
