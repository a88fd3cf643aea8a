// The distance between two convex solids given only their support
// functions (Gilbert, Johnson and Keerthi 1988): the point of the Minkowski
// difference A - B nearest the origin, found on a simplex of at most four of
// its support points that moves towards the origin until it can get no
// closer. For polytopes (boxes, hulls, a capsule's segment) the simplex ends
// on the exact nearest feature, so the distance is exact to rounding.
#pragma once

#include "gaphys/algebra.hpp"
#include "gaphys/contact.hpp"

namespace gaphys::detail {

// A convex solid as GJK sees it: its farthest point along a direction (any
// one of them on a tie; the direction need not be unit). A context pointer
// and a plain function, so that no call allocates; make_support() wraps a
// callable that outlives the support_function.
struct support_function {
  const void* context;
  vector (*farthest)(const void* context, const vector& direction);

  vector operator()(const vector& direction) const { return farthest(context, direction); }
};

template <class Callable>
support_function make_support(const Callable& farthest) {
  return {&farthest, +[](const void* context, const vector& direction) -> vector {
            return (*static_cast<const Callable*>(context))(direction);
          }};
}

// The support of a placed box or convex hull (placed.polyhedron in the frame
// of placed.center and placed.attitude); `placed` must outlive it.
support_function polyhedron_support(const placed_shape& placed);

// The support of the segment from p to q (a capsule's core; p == q is a
// point); `segment` must outlive it.
struct segment {
  vector p, q;
};
support_function segment_support(const segment& s);

struct gjk_result {
  real distance;   // >= 0; 0 when the solids touch or overlap
  vector point_a;  // the nearest points of A and of B (world); when the
  vector point_b;  // solids overlap, one common point of both
  // Unit, from B towards A: the nearest point of A - B over its length,
  // which keeps its accuracy where point_a - point_b, a difference of
  // nearly equal points, loses it (a gap of 1e-9 m). Zero on overlap.
  vector normal;
  bool overlap;  // the origin lies in A - B (within rounding)
};

// The distance between A and B and their nearest points. `first_direction`
// only seeds the search (e.g. centre of A minus centre of B); any nonzero
// vector works. Stops when the nearest point of the simplex cannot move by
// more than a relative 1e-13 of its distance, or the support point repeats.
gjk_result gjk_distance(const support_function& a, const support_function& b,
                        const vector& first_direction = vector{1, 0, 0});

}  // namespace gaphys::detail
