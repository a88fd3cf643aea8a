// The capsule's narrow phase: a capsule against every shape (docs/engine.md,
// "Capsules"). A capsule is the union of the balls of its radius centred on
// its segment, so each pair reduces to a question about the segment: its
// nearest point to a round shape, its ends against a plane, its nearest
// points to another segment or to a polyhedron, or how deep it runs inside
// one.
#pragma once

#include "convex_contact.hpp"
#include "gaphys/contact.hpp"

namespace gaphys::detail {

// A and B, one of them or both capsules, the other a sphere, point, plane,
// capsule, box or convex hull, overlapping, touching or apart by at most
// `margin`. Fills `out` with at most two points on one normal (unit, from B
// towards A), each with its own depth (-gap when apart): one for a round
// shape, a capsule crossing another or touching a polyhedron at one place,
// two for a capsule lying on a plane or a face, alongside another capsule or
// along an edge. Feature ids name the segment end and the polyhedron's face,
// edge or corner, so a resting capsule keeps its ids from step to step.
void collide_capsule(const placed_shape& a, const placed_shape& b, real margin,
                     contact_manifold& out);

// The distance between the solids when apart, minus the penetration depth
// (the shortest translation that separates them) when they overlap, with its
// unit normal from B towards A. Exact to rounding for every pair.
separation capsule_separation(const placed_shape& a, const placed_shape& b);

}  // namespace gaphys::detail
