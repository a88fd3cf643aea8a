#include "overlap.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>

namespace gaphys_compare {

namespace {

// The box's axes in the world, each scaled to unit length.
std::array<vec3, 3> axes_of(const placed_body& box) {
  return {rotate(box.attitude, {1, 0, 0}), rotate(box.attitude, {0, 1, 0}),
          rotate(box.attitude, {0, 0, 1})};
}

// Half the length of the box's projection on the unit direction l.
double half_projection(const vec3& half, const std::array<vec3, 3>& axes, const vec3& l) {
  return half.x * std::abs(dot(axes[0], l)) + half.y * std::abs(dot(axes[1], l)) +
         half.z * std::abs(dot(axes[2], l));
}

double sphere_box_depth(const placed_body& sphere, const placed_body& box) {
  const vec3& h = box.body->half_extents;
  const vec3 local = rotate(conjugate(box.attitude), sphere.position - box.position);
  const vec3 nearest{std::clamp(local.x, -h.x, h.x), std::clamp(local.y, -h.y, h.y),
                     std::clamp(local.z, -h.z, h.z)};
  const double r = sphere.body->radius;
  if (nearest.x != local.x || nearest.y != local.y || nearest.z != local.z) {
    return r - norm(local - nearest);
  }
  // The centre is inside: the nearest face is the way out.
  return r + std::min({h.x - std::abs(local.x), h.y - std::abs(local.y), h.z - std::abs(local.z)});
}

double box_box_depth(const placed_body& a, const placed_body& b) {
  const std::array<vec3, 3> axes_a = axes_of(a), axes_b = axes_of(b);
  const vec3 d = b.position - a.position;
  double depth = std::numeric_limits<double>::infinity();
  const auto try_axis = [&](const vec3& l) {
    const double overlap = half_projection(a.body->half_extents, axes_a, l) +
                           half_projection(b.body->half_extents, axes_b, l) - std::abs(dot(d, l));
    depth = std::min(depth, overlap);
  };
  for (const vec3& l : axes_a) try_axis(l);
  for (const vec3& l : axes_b) try_axis(l);
  constexpr double parallel = 1e-6;  // sin of the angle between two edges
  for (const vec3& u : axes_a) {
    for (const vec3& v : axes_b) {
      const vec3 l = cross(u, v);
      const double length = norm(l);
      if (length > parallel) try_axis((1 / length) * l);
    }
  }
  return depth;
}

double bounding_radius(const body_description& b) {
  return b.is_box() ? norm(b.half_extents) : b.radius;
}

}  // namespace

double plane_depth(const placed_body& a, const plane_description& p) {
  double reach = a.body->radius;
  if (a.body->is_box()) reach = half_projection(a.body->half_extents, axes_of(a), p.normal);
  return p.offset - (dot(p.normal, a.position) - reach);
}

double pair_depth(const placed_body& a, const placed_body& b) {
  const bool box_a = a.body->is_box(), box_b = b.body->is_box();
  if (box_a && box_b) return box_box_depth(a, b);
  if (box_a) return sphere_box_depth(b, a);
  if (box_b) return sphere_box_depth(a, b);
  return a.body->radius + b.body->radius - norm(a.position - b.position);
}

double deepest_overlap(const scene& s, const std::vector<body_state>& states) {
  std::vector<placed_body> placed;
  std::vector<double> reach;
  for (std::size_t i = 0; i < s.bodies.size(); ++i) {
    if (!s.bodies[i].has_shape()) continue;
    placed.push_back({&s.bodies[i], states[i].position, states[i].attitude});
    reach.push_back(bounding_radius(s.bodies[i]));
  }
  double deepest = 0;
  for (const placed_body& a : placed) {
    for (const plane_description& p : s.planes) deepest = std::max(deepest, plane_depth(a, p));
  }
  // Sweep: bodies by the low end of their x extent; each meets those that
  // start before its own extent ends.
  std::vector<std::size_t> order(placed.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  const auto low = [&](std::size_t i) { return placed[i].position.x - reach[i]; };
  std::sort(order.begin(), order.end(),
            [&](std::size_t i, std::size_t j) { return low(i) < low(j); });
  for (std::size_t k = 0; k < order.size(); ++k) {
    const std::size_t i = order[k];
    const double high = placed[i].position.x + reach[i];
    for (std::size_t m = k + 1; m < order.size() && low(order[m]) <= high; ++m) {
      const std::size_t j = order[m];
      if (norm(placed[i].position - placed[j].position) > reach[i] + reach[j]) continue;
      deepest = std::max(deepest, pair_depth(placed[i], placed[j]));
    }
  }
  return deepest;
}

}  // namespace gaphys_compare
