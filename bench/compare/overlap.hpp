// How deep the shapes of a scene sink into each other and into its planes,
// computed from the bodies' states alone, one way for every engine (the
// engines' own contact depths differ in margins and in when they are taken).
// A depth is the length of the shortest translation that separates the two
// solids when > 0; <= 0 means apart (for two boxes, not by how much).
#pragma once

#include <vector>

#include "engine_adapter.hpp"
#include "scene.hpp"

namespace gaphys_compare {

// A shape where its body's state puts it.
struct placed_body {
  const body_description* body;
  vec3 position;
  quat attitude;
};

// The depth of a sphere or box below a plane: offset - n · (its lowest point
// along n); for a box the lowest corner.
double plane_depth(const placed_body& a, const plane_description& p);

// The depth of two spheres, a sphere and a box, or two boxes. Two boxes are
// separated along one of 15 axes (each box's 3 face normals and the 9 cross
// products of their edges: the face normals of their Minkowski difference),
// so the smallest overlap of their projections over those axes is the exact
// depth; edge pairs within 1e-6 rad of parallel are left out, whose axis is
// then a face normal's within that angle.
double pair_depth(const placed_body& a, const placed_body& b);

// The deepest overlap (m, >= 0) of any shape with a plane or another shape.
// Pairs come from a sweep along x over bounding spheres: the cost grows with
// the pairs whose bounding spheres overlap, not with all n^2 / 2 pairs.
double deepest_overlap(const scene& s, const std::vector<body_state>& states);

}  // namespace gaphys_compare
