// Contacts of convex polyhedra (boxes, convex hulls) with each other, with
// planes, spheres and points (docs/engine.md, "Convex shapes").
//
// Every function here takes the polyhedron as A: its normals point from B
// towards A, i.e. from the other shape into the polyhedron. Fills `out`
// (count 0: apart by more than `margin`).
//
// Feature ids (contact_point::feature) name what made each point, so that a
// resting box keeps its ids from step to step:
//   bit 31       B's face is the reference face (else A's)
//   bits 29-30   kind: 0 an incident vertex, 1 an incident edge crossing a
//                side of the reference face, 2 a corner of the reference
//                face, 3 an edge of A against an edge of B
//   kinds 0-2:   bits 18-28 the reference face, 12-17 the reference face's
//                side, 0-11 the incident vertex (or the crossing edge's tail)
//   kind 3:      bits 14-27 A's edge, 0-13 B's edge
// Against a plane, a point's id is the vertex index alone. Indices beyond a
// field's width wrap: two points may then share an id (warm starting only
// gets worse), which takes hulls of more than 2048 faces, 4096 vertices or
// 16384 edges, or a face of more than 64 corners.
//
// No call allocates once the scene's shapes have been met: the working
// data (A's polyhedron moved into B's frame, the clipped polygon) live in
// per-thread buffers that grow to the largest polyhedra seen. There is no
// limit on a hull's size; its cost is O(F V) for the face axes and O(E^2)
// for the edge pairs' Gauss map test.
#pragma once

#include <cstdint>

#include "convex_contact.hpp"
#include "gaphys/contact.hpp"

namespace gaphys::detail {

// A and B both boxes or hulls: a face of one against a face of the other
// (the incident face clipped to the reference face, up to 4 points) or an
// edge of each (one point).
void collide_polyhedra(const placed_shape& a, const placed_shape& b, real margin,
                       contact_manifold& out);

// The polyhedron's corners below the plane + margin (its 4 deepest spread
// ones when more).
void collide_polyhedron_plane(const placed_shape& polyhedron, const placed_shape& plane,
                              real margin, contact_manifold& out);

// One point: the sphere's centre (a point shape: radius 0) against the
// polyhedron's nearest point, or its shallowest face when inside.
void collide_polyhedron_sphere(const placed_shape& polyhedron, const placed_shape& sphere,
                               real margin, contact_manifold& out);

// As convex_separation (convex_contact.hpp), normal from B into A.
separation polyhedra_separation(const placed_shape& a, const placed_shape& b);
separation polyhedron_plane_separation(const placed_shape& polyhedron, const placed_shape& plane);
separation polyhedron_sphere_separation(const placed_shape& polyhedron, const placed_shape& sphere);

}  // namespace gaphys::detail
