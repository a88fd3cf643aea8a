#include "gjk.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <utility>

#include "precision.hpp"
#include "vec3.hpp"

namespace gaphys::detail {

namespace {

// A point of the Minkowski difference, w = a - b, with the points of A and B
// it came from (their weights give the nearest points at the end).
struct simplex_vertex {
  vec3 w, a, b;
};

// The simplex and, after reduce(), its point nearest the origin: the
// vertices left are those that support it, with its barycentric weights.
struct simplex {
  std::array<simplex_vertex, 4> vertex;
  std::array<real, 4> weight{};
  int count = 0;
  vec3 nearest;

  void keep(std::initializer_list<int> which, std::initializer_list<real> weights) {
    std::array<simplex_vertex, 4> kept;
    int n = 0;
    for (int i : which) kept[n++] = vertex[i];
    n = 0;
    for (real x : weights) weight[n++] = x;
    vertex = kept;
    count = n;
  }
};

// The nearest point to the origin of the segment a b: the origin's
// projection t = -a.(b - a) / |b - a|² on its line, clamped to the segment.
struct segment_nearest {
  int which;  // 0: a alone, 1: b alone, 2: inside
  real t;
};
segment_nearest nearest_on_segment(const vec3& a, const vec3& b) {
  const vec3 ab = b - a;
  const real along = -dot(a, ab);
  if (!(along > 0)) return {0, 0};
  const real squared = dot(ab, ab);
  if (!(along < squared)) return {1, 1};
  return {2, along / squared};
}

// A triangle's point nearest the origin: the simplex vertices (1 to 3)
// that support it and their weights.
struct triangle_nearest {
  int count;
  std::array<int, 3> which;
  std::array<real, 3> weight;
  vec3 point;
};
// A triangle whose corners are (within rounding) on one line: the nearest
// point of its three edges.
triangle_nearest nearest_on_edges(const std::array<simplex_vertex, 4>& v, int i, int j, int k) {
  triangle_nearest best{};
  real best_squared = std::numeric_limits<real>::infinity();
  for (const auto& [p, q] : {std::pair{i, j}, std::pair{j, k}, std::pair{k, i}}) {
    const segment_nearest n = nearest_on_segment(v[p].w, v[q].w);
    const vec3 point = v[p].w + n.t * (v[q].w - v[p].w);
    const real squared = dot(point, point);
    if (!(squared < best_squared)) continue;
    best_squared = squared;
    if (n.which == 0) {
      best = {1, {p}, {1}, point};
    } else if (n.which == 1) {
      best = {1, {q}, {1}, point};
    } else {
      best = {2, {p, q}, {1 - n.t, n.t}, point};
    }
  }
  return best;
}

// The origin's nearest point on triangle (i, j, k) of the simplex, by its
// Voronoi regions: a vertex when the origin is behind both edges leaving it,
// an edge when it is outside that edge and between its two ends, else the
// face.
triangle_nearest nearest_on_triangle(const std::array<simplex_vertex, 4>& v, int i, int j, int k) {
  const vec3 &a = v[i].w, &b = v[j].w, &c = v[k].w;
  const vec3 ab = b - a, ac = c - a;
  // p = origin: the offsets of p from each corner, dotted with the two edges.
  const real d1 = -dot(ab, a), d2 = -dot(ac, a);
  if (d1 <= 0 && d2 <= 0) return {1, {i}, {1}, a};
  const real d3 = -dot(ab, b), d4 = -dot(ac, b);
  if (d3 >= 0 && d4 <= d3) return {1, {j}, {1}, b};
  const real d5 = -dot(ab, c), d6 = -dot(ac, c);
  if (d6 >= 0 && d5 <= d6) return {1, {k}, {1}, c};
  // Edge regions: the edge's barycentric coordinate of the third corner
  // (its signed area with the origin) is <= 0 and the origin projects
  // inside the edge.
  const real area_c = d1 * d4 - d3 * d2;
  if (area_c <= 0 && d1 >= 0 && d3 <= 0) {
    const real t = d1 / (d1 - d3);
    return {2, {i, j}, {1 - t, t}, a + t * ab};
  }
  const real area_b = d5 * d2 - d1 * d6;
  if (area_b <= 0 && d2 >= 0 && d6 <= 0) {
    const real t = d2 / (d2 - d6);
    return {2, {i, k}, {1 - t, t}, a + t * ac};
  }
  const real area_a = d3 * d6 - d5 * d4;
  if (area_a <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const real t = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {2, {j, k}, {1 - t, t}, b + t * (c - b)};
  }
  // Inside: the projection of the origin on the plane, computed from the
  // normal (exact in its distance even for a sliver), weights by areas.
  const real total = area_a + area_b + area_c;
  const vec3 normal = cross(ab, ac);
  const real normal_squared = dot(normal, normal);
  if (!(total > 0) || !(normal_squared > 0)) return nearest_on_edges(v, i, j, k);
  const vec3 point = (dot(normal, a) / normal_squared) * normal;
  return {3, {i, j, k}, {area_a / total, area_b / total, area_c / total}, point};
}

// Moves s.nearest to the simplex's point nearest the origin and drops the
// vertices that do not support it. Returns false when the origin is inside
// the tetrahedron (the solids overlap).
bool reduce(simplex& s) {
  switch (s.count) {
    case 1:
      s.weight[0] = 1;
      s.nearest = s.vertex[0].w;
      return true;
    case 2: {
      const vec3 p = s.vertex[0].w, q = s.vertex[1].w;
      const segment_nearest n = nearest_on_segment(p, q);
      if (n.which == 0) {
        s.keep({0}, {1});
      } else if (n.which == 1) {
        s.keep({1}, {1});
      } else {
        s.weight = {1 - n.t, n.t};
      }
      s.nearest = n.which == 0 ? p : n.which == 1 ? q : p + n.t * (q - p);
      return true;
    }
    case 3: {
      const triangle_nearest n = nearest_on_triangle(s.vertex, 0, 1, 2);
      if (n.count == 1) {
        s.keep({n.which[0]}, {1});
      } else if (n.count == 2) {
        s.keep({n.which[0], n.which[1]}, {n.weight[0], n.weight[1]});
      } else {
        s.weight = {n.weight[0], n.weight[1], n.weight[2]};
      }
      s.nearest = n.point;
      return true;
    }
    default: {
      // The origin is outside the face opposite vertex x when the face's
      // plane has the origin and x on opposite sides. Inside every face:
      // overlap. Otherwise the nearest point lies on a face it is outside of.
      const vec3 &a = s.vertex[0].w, &b = s.vertex[1].w, &c = s.vertex[2].w, &d = s.vertex[3].w;
      constexpr std::array<std::array<int, 4>, 4> faces{
          {{1, 2, 3, 0}, {0, 2, 3, 1}, {0, 1, 3, 2}, {0, 1, 2, 3}}};
      const real volume = dot(b - a, cross(c - a, d - a));
      const real scale = std::max({dot(a, a), dot(b, b), dot(c, c), dot(d, d)});
      const bool flat = !(std::fabs(volume) > by_precision(1e-14, 5e-6) * scale * std::sqrt(scale));
      triangle_nearest best{};
      real best_squared = std::numeric_limits<real>::infinity();
      bool outside_any = false;
      for (const auto& f : faces) {
        const vec3& p = s.vertex[f[0]].w;
        const vec3 normal = cross(s.vertex[f[1]].w - p, s.vertex[f[2]].w - p);
        const real origin_side = -dot(normal, p);
        const real other_side = dot(normal, s.vertex[f[3]].w - p);
        if (!flat && !(origin_side * other_side < 0)) continue;
        outside_any = true;
        const triangle_nearest n = nearest_on_triangle(s.vertex, f[0], f[1], f[2]);
        const real squared = dot(n.point, n.point);
        if (squared < best_squared) best = n, best_squared = squared;
      }
      if (!outside_any) {
        // The origin's barycentric weights: each vertex's is the volume of
        // the tetrahedron with the origin in its place, over the whole.
        const vec3 o{};
        s.weight = {
            dot(b - o, cross(c - o, d - o)) / volume, dot(o - a, cross(c - a, d - a)) / volume,
            dot(b - a, cross(o - a, d - a)) / volume, dot(b - a, cross(c - a, o - a)) / volume};
        s.nearest = o;
        return false;
      }
      const std::array<simplex_vertex, 4> vertices = s.vertex;
      s.count = best.count;
      for (int i = 0; i < best.count; ++i) {
        s.vertex[i] = vertices[best.which[i]];
        s.weight[i] = best.weight[i];
      }
      s.nearest = best.point;
      return true;
    }
  }
}

gjk_result result_of(const simplex& s, bool overlap) {
  vec3 a, b;
  for (int i = 0; i < s.count; ++i) {
    a = a + s.weight[i] * s.vertex[i].a;
    b = b + s.weight[i] * s.vertex[i].b;
  }
  const real distance = overlap ? 0 : length(s.nearest);
  const vec3 normal = distance > 0 ? (1 / distance) * s.nearest : vec3{};
  return {distance, to_vector(a), to_vector(overlap ? a : b), to_vector(normal), overlap};
}

}  // namespace

support_function polyhedron_support(const placed_shape& placed) {
  return {&placed, +[](const void* context, const vector& direction) -> vector {
            const placed_shape& s = *static_cast<const placed_shape*>(context);
            const rigid_frame frame = frame_of(s.attitude, s.center);
            const vec3 local = frame.unrotate(to_vec3(direction));
            const auto& vertices = s.polyhedron->vertices;
            std::size_t best = 0;
            real best_height = -std::numeric_limits<real>::infinity();
            for (std::size_t i = 0; i < vertices.size(); ++i) {
              const real height = dot(to_vec3(vertices[i]), local);
              if (height > best_height) best = i, best_height = height;
            }
            return to_vector(frame.to_world(to_vec3(vertices[best])));
          }};
}

support_function segment_support(const segment& s) {
  return {&s, +[](const void* context, const vector& direction) -> vector {
            const segment& line = *static_cast<const segment*>(context);
            const vec3 d = to_vec3(direction);
            return dot(to_vec3(line.q) - to_vec3(line.p), d) > 0 ? line.q : line.p;
          }};
}

gjk_result gjk_distance(const support_function& a, const support_function& b,
                        const vector& first_direction) {
  constexpr int max_iterations = 128;
  // Converged when the support plane's lower bound v.w/|v| of the distance
  // is within a relative 1e-13 of the upper bound |v| (squared: 2e-13; in
  // float 5e-5 and 1e-4).
  const real relative_tolerance = by_precision(2e-13, 1e-4);

  auto support_of_difference = [&](const vec3& direction) {
    const vec3 pa = to_vec3(a(to_vector(direction)));
    const vec3 pb = to_vec3(b(to_vector(-direction)));
    return simplex_vertex{pa - pb, pa, pb};
  };

  vec3 start = to_vec3(first_direction);
  if (!(dot(start, start) > 0)) start = {1, 0, 0};
  simplex s;
  s.vertex[0] = support_of_difference(-start);
  s.count = 1;
  reduce(s);
  real scale = dot(s.vertex[0].w, s.vertex[0].w);

  simplex best = s;
  for (int iteration = 0; iteration < max_iterations; ++iteration) {
    const vec3 v = best.nearest;
    const real squared = dot(v, v);
    // The origin on the simplex: touching or overlapping within rounding.
    if (!(squared > by_precision(1e-30, 1e-13) * scale)) return result_of(best, true);
    const simplex_vertex w = support_of_difference(-v);
    scale = std::max(scale, dot(w.w, w.w));
    // No support point beyond the current nearest point's plane by more
    // than the tolerance: v is the nearest point of A - B.
    if (squared - dot(v, w.w) <= relative_tolerance * squared) break;
    bool repeated = false;
    for (int i = 0; i < best.count; ++i) {
      const vec3 step = best.vertex[i].w - w.w;
      repeated = repeated || !(dot(step, step) > 0);
    }
    if (repeated) break;

    s = best;
    s.vertex[s.count++] = w;
    if (!reduce(s)) return result_of(s, true);
    // Rounding can stall the descent: keep the best simplex seen.
    if (!(dot(s.nearest, s.nearest) < squared)) break;
    best = s;
  }
  return result_of(best, false);
}

}  // namespace gaphys::detail
