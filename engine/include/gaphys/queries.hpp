// What the world's spatial queries return (world::ray_cast, ray_cast_all,
// overlap_sphere, overlap_box).
#pragma once

#include <cstddef>

#include "gaphys/algebra.hpp"

namespace gaphys {

// A body's handle: world::create_body gives it, world::at takes it. It
// stays valid until the body is removed, and a removed body's id never
// names another body (docs/engine.md, "Bodies and their ids").
using body_id = std::size_t;

// Where a ray enters a body's shape.
struct ray_hit {
  body_id body;
  std::size_t shape;  // which of the body's shapes (an index into body::shapes())
  vector point;       // origin + distance * unit direction
  vector normal;      // unit: the shape's outward normal there
  real distance;      // along the ray, from its origin
};

}  // namespace gaphys
