#include "ray_shape.hpp"

#include <algorithm>
#include <cmath>

#include "precision.hpp"
#include "vec3.hpp"

namespace gaphys::detail {

namespace {

// The conformal point of x: no + x + ½ x² ni.
conformal::normalized_point up(const vector& x) {
  return conformal::normalized_point{x.e1(), x.e2(), x.e3(), real(0.5) * e3ga::scp(x, x)};
}

std::optional<shape_hit> inside(const vector& direction) { return shape_hit{0, -direction}; }

// A sphere of radius r. In the frame of its centre (so that no large
// coordinates cancel), σ = no - ½ r² ni and, with o the origin relative to
// the centre, X(t) . σ = X(o) . σ + t (-d . o) - ½ t²: its roots are
// t = b ± sqrt(b² + 2 X(o) . σ) with b = -d . o.
std::optional<shape_hit> cast_at_sphere(const placed_shape& s, const vector& origin,
                                        const vector& direction, real max_distance) {
  const vector o = origin - s.center;
  const conformal::dual_sphere sigma{1, 0, 0, 0, -real(0.5) * s.radius * s.radius};
  const real at_origin = c3ga::scp(up(o), sigma);  // > 0: the ray starts inside
  if (at_origin >= 0) return inside(direction);
  const real b = -e3ga::scp(direction, o);
  if (b < 0) return std::nullopt;  // going away
  // b² + 2 X(o) . σ, written as 2 X(m) . σ with m = o + b d the line's point
  // nearest the centre: the sum would cancel to rounding for a grazing ray
  // far off (Haines et al., Ray Tracing Gems, ch. 7).
  const real discriminant = 2 * c3ga::scp(up(o + b * direction), sigma);
  if (discriminant < 0) return std::nullopt;  // the line misses
  // The nearer root, written so that it does not cancel: t = -2 X(o).σ / (b + sqrt).
  const real t = -2 * at_origin / (b + std::sqrt(discriminant));
  if (!(t <= max_distance)) return std::nullopt;
  const vector point = o + t * direction;
  return shape_hit{t, (1 / e3ga::norm(point)) * point};
}

// The half-space n . x <= offset: π = n + offset ni, X(t) . π = offset - n . x(t)
// (with the dual_sphere type's no coefficient 0), linear in t.
std::optional<shape_hit> cast_at_plane(const placed_shape& s, const vector& origin,
                                       const vector& direction, real max_distance) {
  const conformal::dual_sphere pi{0, -s.normal.e1(), -s.normal.e2(), -s.normal.e3(), -s.offset};
  const real at_origin = c3ga::scp(up(origin), pi);  // offset - n . o: >= 0 inside
  if (at_origin >= 0) return inside(direction);
  const real slope = -e3ga::scp(s.normal, direction);  // d/dt of X(t) . π
  if (!(slope > 0)) return std::nullopt;               // parallel or leaving
  const real t = -at_origin / slope;
  if (!(t <= max_distance)) return std::nullopt;
  return shape_hit{t, s.normal};
}

// A box or hull: the ray enters the solid at the last face plane it crosses
// inwards and leaves it at the first it crosses outwards (the slab test), in
// the shape's frame.
std::optional<shape_hit> cast_at_polyhedron(const placed_shape& s, const vector& origin,
                                            const vector& direction, real max_distance) {
  const rigid_frame frame = frame_of(s.attitude, s.center);
  const vec3 o = frame.to_local(to_vec3(origin));
  const vec3 d = frame.unrotate(to_vec3(direction));
  real enter = -infinity, leave = max_distance;
  const polyhedron_face* entered = nullptr;
  for (const polyhedron_face& face : s.polyhedron->faces) {
    const vec3 n = to_vec3(face.normal);
    const real height = dot(n, o) - face.offset;  // > 0 outside this face's plane
    const real approach = dot(n, d);
    if (approach == 0) {
      if (height > 0) return std::nullopt;  // parallel to the face, outside it
      continue;
    }
    const real t = -height / approach;
    if (approach < 0) {
      if (t > enter) enter = t, entered = &face;
    } else if (t < leave) {
      leave = t;
    }
    if (enter > leave) return std::nullopt;
  }
  if (!(leave >= 0)) return std::nullopt;
  if (enter <= 0 || !entered) return inside(direction);
  return shape_hit{enter, to_vector(frame.rotate(to_vec3(entered->normal)))};
}

// A capsule: the points within r of the segment c + s a, |s| <= h. The ray
// enters where its distance from the segment first falls to r: on the
// cylinder about the segment's line within the ends, or else on an end's
// sphere; the nearer of those entries.
std::optional<shape_hit> cast_at_capsule(const placed_shape& s, const vector& origin,
                                         const vector& direction, real max_distance) {
  const vec3 a = to_vec3(s.axis), o = to_vec3(origin - s.center), d = to_vec3(direction);
  const real r = s.radius, h = s.half_height;
  // Inside: the origin's nearest point of the segment is within r.
  const real along_origin = std::clamp(dot(o, a), -h, h);
  const vec3 off = o - along_origin * a;
  if (dot(off, off) <= r * r) return inside(direction);

  real best = infinity;
  vector normal{};
  // The infinite cylinder: |(o + t d)⊥|² = r², ⊥ the part across a.
  const vec3 o_across = o - dot(o, a) * a, d_across = d - dot(d, a) * a;
  const real qa = dot(d_across, d_across), qb = dot(o_across, d_across);
  const real qc = dot(o_across, o_across) - r * r;
  if (qa > 0 && qb < 0) {
    const real discriminant = qb * qb - qa * qc;
    if (discriminant >= 0) {
      const real t = qc / (-qb + std::sqrt(discriminant));  // the nearer root, stably
      const real along = dot(o, a) + t * dot(d, a);
      if (t >= 0 && std::fabs(along) <= h) {
        best = t;
        const vec3 p = o + t * d;
        const vec3 radial = p - along * a;
        normal = to_vector((1 / length(radial)) * radial);
      }
    }
  }
  // The two end spheres.
  for (const real end : {-h, h}) {
    placed_shape cap;
    cap.center = s.center + end * s.axis;
    cap.radius = r;
    const std::optional<shape_hit> hit = cast_at_sphere(cap, origin, direction, max_distance);
    if (hit && hit->distance < best) best = hit->distance, normal = hit->normal;
  }
  if (!(best < infinity)) return std::nullopt;  // the end spheres kept within max_distance
  if (!(best <= max_distance)) return std::nullopt;
  return shape_hit{best, normal};
}

}  // namespace

std::optional<shape_hit> cast_ray(const placed_shape& s, const vector& origin,
                                  const vector& direction, real max_distance) {
  switch (s.kind) {
    case shape_kind::sphere:
      return cast_at_sphere(s, origin, direction, max_distance);
    case shape_kind::plane:
      return cast_at_plane(s, origin, direction, max_distance);
    case shape_kind::box:
    case shape_kind::convex_hull:
      return cast_at_polyhedron(s, origin, direction, max_distance);
    case shape_kind::capsule:
      return cast_at_capsule(s, origin, direction, max_distance);
    case shape_kind::point:
      break;
  }
  return std::nullopt;
}

}  // namespace gaphys::detail
