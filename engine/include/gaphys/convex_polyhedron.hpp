// A convex polyhedron in its body's frame: the geometry behind shape::box and
// shape::convex_hull. Coplanar facets are merged into one face (a box has 6
// quadrilateral faces, not 12 triangles), so a face lying on another gives a
// contact manifold of its corners, not of triangle corners.
#pragma once

#include <cstdint>
#include <vector>

#include "gaphys/algebra.hpp"

namespace gaphys {

struct polyhedron_face {
  vector normal;  // unit, outward
  real offset;    // the face's plane is normal . x = offset
  // The face's corners are vertex_indices[first, first + count), counter-
  // clockwise seen from outside (right-handed about the normal).
  std::uint32_t first;
  std::uint32_t count;
};

// An edge between two faces: `left` is the face that walks it from tail to
// head counter-clockwise, `right` the face that walks it from head to tail.
struct polyhedron_edge {
  std::uint32_t tail, head;
  std::uint32_t left, right;
};

struct convex_polyhedron {
  std::vector<vector> vertices;
  std::vector<polyhedron_face> faces;
  std::vector<std::uint32_t> vertex_indices;
  std::vector<polyhedron_edge> edges;  // each edge once
  real bounding_radius = 0;            // max |vertex| about the frame's origin

  // The box [-h, h] on each axis (each h finite and > 0). Corner i has the
  // sign of bit k of i on axis k; the faces are -x, +x, -y, +y, -z, +z.
  static convex_polyhedron box(const vector& half_extents);
  // The convex hull of the points (quickhull, exact on a fine grid). Its
  // vertices are the given points that are corners, in the given order and
  // with their given coordinates; the same points give the same polyhedron.
  // Lengths below 1e-9 of the points' extent (1e-5 in a float engine)
  // count as zero: points that close count once, faces that flat merge,
  // points that close to an edge or face are not corners. Throws
  // invalid_input for a non-finite point, fewer than 4 points, or points all
  // (nearly) on one plane or line.
  static convex_polyhedron hull(const std::vector<vector>& points);
};

}  // namespace gaphys
