// The mass, centre of mass and inertia of a solid shape, or of several.
#pragma once

#include <vector>

#include "gaphys/algebra.hpp"
#include "gaphys/inertia.hpp"
#include "gaphys/shape.hpp"

namespace gaphys {

struct mass_properties {
  real mass = 0;            // kg
  vector center{};          // the centre of mass, in the frame the shapes are given in
  gaphys::inertia inertia;  // about the centre of mass, axes of that frame
};

// A shape placed in a body's frame: turned by `attitude`, then moved by
// `offset` (x_body = offset + R x_shape ~R).
struct attached_shape {
  gaphys::shape shape;
  vector offset{};
  rotor attitude{1, 0, 0, 0};
};

// The exact mass properties of a solid sphere, box, capsule or convex hull of
// uniform density (kg/m^3, finite and > 0). Planes and points have no
// volume: invalid_input.
mass_properties solid_mass_properties(const shape& s, real density);

// Of shapes at their poses, each of the same density: the parts' masses add,
// their centres average by mass and their inertias, turned by their
// attitudes, move to the common centre (parallel axes). Offsets must be
// finite and attitudes finite and nonzero (they are normalized). Planes,
// points and sensors among them add nothing; with no solid part,
// invalid_input.
mass_properties solid_mass_properties(const std::vector<attached_shape>& shapes, real density);

// Whether the shape encloses a volume: every shape but planes and points.
bool is_solid(const shape& s);

// The solid's volume (m^3); 0 for planes and points.
real volume(const shape& s);

}  // namespace gaphys
