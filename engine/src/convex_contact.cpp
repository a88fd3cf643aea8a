// The convex narrow phase's table: which collide function a pair of shape
// kinds goes to. Capsules (with anything) go to capsule_contact, boxes and
// hulls (with a box, hull, plane, sphere or point) to polyhedron_contact,
// which takes the polyhedron as A; a pair given the other way round is
// swapped there and its normals turned back.
#include "convex_contact.hpp"

#include "capsule_contact.hpp"
#include "polyhedron_contact.hpp"

namespace gaphys::detail {

namespace {

bool is_polyhedron(const placed_shape& s) {
  return s.kind == shape_kind::box || s.kind == shape_kind::convex_hull;
}

bool is_capsule(const placed_shape& s) { return s.kind == shape_kind::capsule; }

// A polyhedron (as A) against a plane, sphere or point.
void collide_polyhedron_with(const placed_shape& polyhedron, const placed_shape& other, real margin,
                             contact_manifold& out) {
  switch (other.kind) {
    case shape_kind::plane:
      collide_polyhedron_plane(polyhedron, other, margin, out);
      return;
    case shape_kind::sphere:
    case shape_kind::point:
      collide_polyhedron_sphere(polyhedron, other, margin, out);
      return;
    default:
      out.count = 0;
  }
}

separation polyhedron_separation_with(const placed_shape& polyhedron, const placed_shape& other) {
  switch (other.kind) {
    case shape_kind::plane:
      return polyhedron_plane_separation(polyhedron, other);
    default:
      return polyhedron_sphere_separation(polyhedron, other);
  }
}

}  // namespace

void collide_convex(const placed_shape& a, const placed_shape& b, real margin,
                    contact_manifold& out) {
  out.count = 0;
  if (is_capsule(a) || is_capsule(b)) {
    collide_capsule(a, b, margin, out);
  } else if (is_polyhedron(a) && is_polyhedron(b)) {
    collide_polyhedra(a, b, margin, out);
  } else if (is_polyhedron(a)) {
    collide_polyhedron_with(a, b, margin, out);
  } else if (is_polyhedron(b)) {
    collide_polyhedron_with(b, a, margin, out);
    for (int i = 0; i < out.count; ++i) {
      out.points[i].geometry.normal = -out.points[i].geometry.normal;
    }
  }
}

separation convex_separation(const placed_shape& a, const placed_shape& b) {
  if (is_capsule(a) || is_capsule(b)) return capsule_separation(a, b);
  if (is_polyhedron(a) && is_polyhedron(b)) return polyhedra_separation(a, b);
  if (is_polyhedron(a)) return polyhedron_separation_with(a, b);
  separation s = polyhedron_separation_with(b, a);
  s.normal = -s.normal;
  return s;
}

}  // namespace gaphys::detail
