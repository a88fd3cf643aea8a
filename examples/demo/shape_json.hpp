// Bodies and their shapes as JSON, as the demo writes them into a JSON
// trajectory (--out FILE.json) and into the viewer page's scene: what a reader
// needs to draw each body in its own frame, whose pose the frames then give.
#pragma once

#include <string>

#include "gaphys/world.hpp"

namespace demo {

// [x, y, z] and [scalar, e12, e13, e23], numbers as json_number writes them.
std::string json_vector(const gaphys::vector& v);
std::string json_rotor(const gaphys::rotor& r);

// One shape in the frame it is given in: its "kind" and parameters.
//   sphere:      "radius"
//   plane:       "normal", "offset" (the half-space normal . x <= offset)
//   point:       nothing more
//   box:         "half_extents" [hx, hy, hz], edges along the frame's axes
//   capsule:     "half_height", "radius": the segment from -half_height e3 to
//                +half_height e3, rounded by the radius
//   convex_hull: "vertices" [[x, y, z], ...] and "faces" [[i, j, k, ...], ...],
//                each face's vertex indices counter-clockwise seen from outside
std::string json_shape(const gaphys::shape& s);

// A body: "id", "static", "shape" (its first shape as json_shape, or null:
// the field of the older format, which knew one shape a body centred on it),
// "shapes" (each as json_shape, with its pose in the body's frame, "position"
// p and "attitude" R: x_body = p + R x_shape ~R; p is the attached shape's
// offset, named so as not to clash with a plane's "offset"), and the body's
// "position" and "attitude" now.
std::string json_body(const gaphys::body& b, gaphys::body_id id);

}  // namespace demo
