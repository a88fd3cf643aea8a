#include "turning_reach.hpp"

#include <algorithm>
#include <cmath>

#include "gaphys/convex_polyhedron.hpp"
#include "precision.hpp"
#include "vec3.hpp"

namespace gaphys::detail {

namespace {

// One turn about the unit axis k by angles in [0, angle], read along a
// direction d. A point x (from the centre) turns to
//   x(φ) = x - x_p + x_p cos φ + (k × x) sin φ,   x_p = x - (x . k) k,
// so x(φ) . d - x . d = a (cos φ - 1) + b sin φ with a = x . d_p and
// b = (k × x) . d = x . (d × k), d_p = d - (d . k) k.
struct turn_along {
  vec3 d, d_p, d_q;   // d, its part in the plane of the turn, and d × k
  real cosine, sine;  // of the whole angle
  bool half_turn;     // the angle reaches π: every phase of the turn comes
                      // within reach (a bound; exact from 2π on)

  turn_along(const vec3& towards, const vec3& axis, real angle)
      : d(towards),
        d_p(towards - dot(towards, axis) * axis),
        d_q(cross(towards, axis)),
        cosine(std::cos(angle)),
        sine(std::sin(angle)),
        half_turn(angle >= pi) {}

  // The farthest x(φ) . d for φ in [0, angle].
  real farthest(const vec3& x) const {
    const real along = dot(x, d);
    const real a = dot(x, d_p), b = dot(x, d_q);
    // a cos φ + b sin φ is at its most, hypot(a, b), at the angle of (a, b);
    // within [0, angle] when (a, b) lies between (1, 0) and (cos, sin).
    const bool peak_within = half_turn || (b >= 0 && a * sine - b * cosine >= 0);
    const real swing =
        peak_within ? std::hypot(a, b) - a : std::max(real(0), a * (cosine - 1) + b * sine);
    return along + swing;
  }
};

}  // namespace

real turning_approach(const placed_shape& shape, const vector& centre,
                      const bivector& angular_velocity, real time, const vector& towards) {
  // ω's axis: the velocity of a point x from the centre is x ⌋ ω = Ω × x.
  const vec3 axis{angular_velocity.e23(), -angular_velocity.e13(), angular_velocity.e12()};
  const real rate = length(axis);
  if (!(rate > 0) || shape.kind == shape_kind::plane) return 0;
  const turn_along turn(to_vec3(towards), (1 / rate) * axis, rate * time);
  const vec3 from_centre = to_vec3(shape.center) - to_vec3(centre);
  real before = -INFINITY, swept = -INFINITY;
  const auto corner = [&](const vec3& x) {
    before = std::max(before, dot(x, turn.d));
    swept = std::max(swept, turn.farthest(x));
  };
  switch (shape.kind) {
    case shape_kind::box:
    case shape_kind::convex_hull: {
      const rigid_frame frame = frame_of(shape.attitude, shape.center);
      for (const vector& v : shape.polyhedron->vertices) {
        corner(from_centre + frame.rotate(to_vec3(v)));
      }
      break;
    }
    case shape_kind::capsule: {  // the segment's ends (the radius turns with them)
      const vec3 half = shape.half_height * to_vec3(shape.axis);
      corner(from_centre + half);
      corner(from_centre - half);
      break;
    }
    default:  // a sphere or point: its centre
      corner(from_centre);
      break;
  }
  return std::max(real(0), swept - before);
}

}  // namespace gaphys::detail
