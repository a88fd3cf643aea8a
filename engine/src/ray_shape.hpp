// A ray against one placed shape: where it enters the shape's solid.
//
// Round shapes and planes by the conformal inner product: with X(t) the
// conformal point of x(t) = o + t d and σ the dual sphere (or plane), X(t) . σ
// is > 0 inside, 0 on and < 0 outside the solid, and as a function of t it
// is a quadratic (a sphere: ½ r² - ½ |x(t) - c|²) or linear (a plane:
// offset - n . x(t)) polynomial whose roots are the two points of the meet
// of the ray's line with the sphere (or its one point with the plane). Its
// value at t = 0 says whether the ray starts inside; its slope there, whether
// it leaves. Boxes and hulls by their face planes (the slab test); capsules
// by the nearest points of the ray's line and the segment.
#pragma once

#include <optional>

#include "gaphys/contact.hpp"

namespace gaphys::detail {

struct shape_hit {
  real distance;  // along the unit direction, in [0, max_distance]
  vector normal;  // unit, the solid's outward normal where the ray enters
};

// Where the ray from `origin` along the unit `direction` enters the shape's
// solid within max_distance (which may be infinite). A ray that starts
// inside (or on the surface of) the solid hits it at distance 0 with the
// normal -direction. A point shape, having no extent, is never hit.
std::optional<shape_hit> cast_ray(const placed_shape& s, const vector& origin,
                                  const vector& direction, real max_distance);

}  // namespace gaphys::detail
