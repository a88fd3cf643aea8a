// The convex narrow phase: contacts of boxes, capsules and convex hulls with
// every shape (docs/engine.md, "Convex shapes"). Round pairs (spheres,
// points, planes among themselves) are met in contact.cpp.
#pragma once

#include "gaphys/contact.hpp"

namespace gaphys::detail {

// A and B (at least one a box, capsule or convex hull; a plane is static
// and always B's or A's whole half-space) overlapping, touching or apart by
// at most `margin` metres. Fills `out` with up to 4 points on one normal n
// (unit, from B towards A); each point's depth is the overlap along n
// (-gap when apart), its position midway between the two surfaces.
void collide_convex(const placed_shape& a, const placed_shape& b, real margin,
                    contact_manifold& out);

// The distance between two convex shapes' solids when apart (> 0), or minus
// their penetration depth (the shortest translation that separates them)
// when they overlap, with the unit normal from B towards A along which it is
// measured. For tests against libccd and for the broad checks; not the
// contact manifold.
struct separation {
  real distance;
  vector normal;
};
separation convex_separation(const placed_shape& a, const placed_shape& b);

}  // namespace gaphys::detail
