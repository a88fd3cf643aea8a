#include "gaphys/contact.hpp"

#include <algorithm>
#include <cmath>

#include "convex_contact.hpp"
#include "round_meet.hpp"

namespace gaphys {

placed_shape place(const shape& s, const vector& position, const rotor& attitude) {
  placed_shape placed{s.kind(), position, vector{}, s.radius(), 0};
  placed.attitude = attitude;
  switch (s.kind()) {
    case shape_kind::sphere:
    case shape_kind::point:
      break;
    case shape_kind::plane: {  // n . x = d, n and d in the world frame
      placed.normal = e3ga::apply(attitude, s.normal());
      placed.offset = s.offset() + e3ga::scp(placed.normal, position);
      break;
    }
    case shape_kind::capsule:
      placed.half_height = s.half_height();
      placed.axis = e3ga::apply(attitude, vector{0, 0, 1});
      break;
    case shape_kind::box:
      placed.half_extents = s.half_extents();
      placed.polyhedron = s.polyhedron();
      break;
    case shape_kind::convex_hull:
      placed.polyhedron = s.polyhedron();
      break;
  }
  return placed;
}

conformal::mv dual_of(const placed_shape& s) { return detail::dual_of(s, vector{}); }

std::optional<contact_geometry> find_contact(const placed_shape& a, const placed_shape& b,
                                             real lookahead, const vector& velocity_a,
                                             const vector& velocity_b) {
  // (In the frame at the pair: detail::meet_origin.)
  const vector origin = detail::meet_origin(a, b);
  const auto with = [&](const auto& dual_a, const auto& dual_b) {
    return detail::contact_from(a, b, detail::read_terms(detail::terms_of(dual_a, dual_b)), origin,
                                lookahead, velocity_a, velocity_b);
  };
  const bool sphere_a = a.kind == shape_kind::sphere, sphere_b = b.kind == shape_kind::sphere;
  const bool plane_a = a.kind == shape_kind::plane, plane_b = b.kind == shape_kind::plane;
  using detail::dual_plane_of, detail::dual_sphere_of;
  if (sphere_a && sphere_b) return with(dual_sphere_of(a, origin), dual_sphere_of(b, origin));
  if (sphere_a && plane_b) return with(dual_sphere_of(a, origin), dual_plane_of(b, origin));
  if (plane_a && sphere_b) return with(dual_plane_of(a, origin), dual_sphere_of(b, origin));
  return with(detail::dual_of(a, origin), detail::dual_of(b, origin));
}

void find_contacts(const placed_shape& a, const placed_shape& b, real lookahead,
                   const vector& velocity_a, const vector& velocity_b, real margin,
                   contact_manifold& out) {
  out.count = 0;
  if (!detail::is_round(a.kind) || !detail::is_round(b.kind)) {
    detail::collide_convex(a, b, margin, out);
    return;
  }
  if (auto geometry = find_contact(a, b, lookahead, velocity_a, velocity_b)) {
    out.points[0] = contact_point{*geometry, 0};
    out.count = 1;
  }
}

bool touching(const placed_shape& a, const placed_shape& b, contact_manifold& scratch) {
  find_contacts(a, b, 0, vector{}, vector{}, 0, scratch);
  for (int k = 0; k < scratch.count; ++k) {
    if (scratch.points[k].geometry.depth >= 0) return true;
  }
  return false;
}

}  // namespace gaphys
