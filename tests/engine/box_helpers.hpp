// Boxes for the behaviour tests of boxes and stacks of them.
#pragma once

#include <algorithm>
#include <cmath>

#include "engine_test_support.hpp"

namespace gaphys::testing {

// A dynamic box that does not bounce (e = 0), with friction μ.
inline body_id add_box(world& w, const vector& position, const vector& half_extents,
                       const rotor& attitude = rotor{1, 0, 0, 0}, const vector& velocity = vector{},
                       real friction = 0.5, real mass = 1) {
  body_definition box;
  box.mass = mass;
  box.position = position;
  box.attitude = attitude;
  box.velocity = velocity;
  box.shape = shape::box(half_extents).with_restitution(0).with_friction(friction);
  return w.create_body(box);
}

// The height of a box body's lowest corner (half extents `half`, centred).
inline real lowest_corner(const body& b, const vector& half) {
  real lowest = INFINITY;
  for (int corner = 0; corner < 8; ++corner) {
    const auto side = [&](int bit, real h) { return corner & bit ? h : -h; };
    const vector offset{side(1, half.e1()), side(2, half.e2()), side(4, half.e3())};
    lowest = std::min(lowest, z(b.to_world(offset)));
  }
  return lowest;
}

// How far a body's e3 axis leans from the world's, in radians.
inline real tilt(const body& b) {
  const vector up = e3ga::apply(b.attitude(), vector{0, 0, 1});
  return std::acos(std::clamp(z(up), real(-1), real(1)));
}

}  // namespace gaphys::testing
