// The convex polyhedra behind shape::box and shape::convex_hull.
//
// hull() is quickhull (Barber, Dobkin & Huhdanpaa 1996) in two stages, on
// the points less those within the tolerance of an earlier one:
//
// 1. Topology. The points are snapped to an integer grid of 2^40 cells across
//    their bounding box and triangulated with exact orientation tests in
//    128-bit integers. Exact tests never contradict each other, so the
//    triangles always close into a convex surface whatever the coplanar,
//    collinear or repeated points; a point on the surface is never taken in.
//    Snapping moves a point by at most 5e-13 of the hull's size, and only the
//    choice of triangles uses it: the vertices keep their given coordinates.
// 2. Faces. Neighbouring polygons merge while the merged polygon stays flat
//    to within the tolerance (1e-9 of the hull's size), so a cube has 6
//    square faces, not 12 triangles; then corners left in the middle of a
//    straight edge are dropped. Should a merged face come out concave (a
//    flat patch notched by points a hair more than the tolerance below it),
//    the merging is redone allowing only convex steps.
//
// Everything is ordered by point index, so the same points give the same
// polyhedron. The inner loops use plain coordinates, not the algebra's
// calls, which the instrumented build would count thousands of times.
#include "gaphys/convex_polyhedron.hpp"

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <unordered_map>
#include <utility>

#include "precision.hpp"
#include "validate.hpp"

namespace gaphys {

namespace {

using index = std::uint32_t;
using loop = std::vector<index>;  // a face's corners, counter-clockwise from outside
constexpr index none = std::numeric_limits<index>::max();

// Two points closer than this fraction of the hull's size (plus a rounding
// allowance for points far from the origin) to a common plane or line count
// as lying on it: flat faces merge, straight-edge corners drop, and inputs
// this thin are rejected as having no volume.
const real relative_tolerance = detail::by_precision(1e-9, 1e-5);

struct xyz {
  real x, y, z;
};
xyz operator+(const xyz& a, const xyz& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
xyz operator-(const xyz& a, const xyz& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
xyz operator*(real s, const xyz& a) { return {s * a.x, s * a.y, s * a.z}; }
real dot(const xyz& a, const xyz& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
xyz cross(const xyz& a, const xyz& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
real length(const xyz& a) { return std::sqrt(dot(a, a)); }

// ---------------------------------------------------------------------------
// Faces to polyhedron: planes, edges and radius from the corner loops.

// The polygon's normal times its area, summed over the fan from its first
// corner (for a slightly warped polygon, the area-weighted mean normal).
xyz area_vector(const std::vector<xyz>& points, const loop& corners) {
  xyz sum{0, 0, 0};
  const xyz& origin = points[corners[0]];
  for (std::size_t i = 1; i + 1 < corners.size(); ++i) {
    sum = sum + cross(points[corners[i]] - origin, points[corners[i + 1]] - origin);
  }
  return real(0.5) * sum;
}

// Each loop starts at its smallest vertex index, so equal polyhedra print
// equally. The face plane is the supporting plane of its corners: n . x <=
// offset holds for each of them.
convex_polyhedron assemble(const std::vector<xyz>& points, std::vector<loop> loops) {
  convex_polyhedron p;
  for (const xyz& v : points) {
    p.vertices.push_back(vector{v.x, v.y, v.z});
    p.bounding_radius = std::max(p.bounding_radius, length(v));
  }
  struct side {
    index tail, head, face;
    bool operator<(const side& o) const { return tail != o.tail ? tail < o.tail : head < o.head; }
  };
  std::vector<side> sides;  // every face's directed edges, to find each edge's other face
  for (loop& corners : loops) {
    std::rotate(corners.begin(), std::min_element(corners.begin(), corners.end()), corners.end());
    const index f = static_cast<index>(p.faces.size());
    const xyz area = area_vector(points, corners);
    const xyz normal = (1 / length(area)) * area;
    real offset = -std::numeric_limits<real>::infinity();
    for (index v : corners) offset = std::max(offset, dot(normal, points[v]));
    p.faces.push_back(polyhedron_face{vector{normal.x, normal.y, normal.z}, offset,
                                      static_cast<index>(p.vertex_indices.size()),
                                      static_cast<index>(corners.size())});
    for (std::size_t i = 0; i < corners.size(); ++i) {
      sides.push_back({corners[i], corners[(i + 1) % corners.size()], f});
    }
    p.vertex_indices.insert(p.vertex_indices.end(), corners.begin(), corners.end());
  }
  std::sort(sides.begin(), sides.end());
  // Each edge once, from the face that walks it from the lower index up.
  for (index f = 0; f < p.faces.size(); ++f) {
    const loop& corners = loops[f];
    for (std::size_t i = 0; i < corners.size(); ++i) {
      const index tail = corners[i], head = corners[(i + 1) % corners.size()];
      if (tail > head) continue;
      const auto back = std::lower_bound(sides.begin(), sides.end(), side{head, tail, 0});
      if (back == sides.end() || back->tail != head || back->head != tail) {
        throw std::logic_error("gaphys: convex polyhedron edge has one face");
      }
      p.edges.push_back(polyhedron_edge{tail, head, f, back->face});
    }
  }
  return p;
}

// ---------------------------------------------------------------------------
// Stage 1: the exact triangulated hull on the grid.

__extension__ typedef __int128 wide;  // exact products of grid coordinates

// 2^40 cells across the widest side: differences of grid coordinates stay
// within 2^40, cross products within 2^81 and orientation determinants within
// 3 * 2^121, well inside a signed 128-bit integer.
constexpr real grid_cells = 1099511627776.0;

struct grid_point {
  std::int64_t x, y, z;
};
grid_point operator-(const grid_point& a, const grid_point& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}

struct wide_vector {
  wide x, y, z;
};
wide_vector cross(const grid_point& a, const grid_point& b) {
  return {wide(a.y) * b.z - wide(a.z) * b.y, wide(a.z) * b.x - wide(a.x) * b.z,
          wide(a.x) * b.y - wide(a.y) * b.x};
}
wide dot(const wide_vector& n, const grid_point& d) { return n.x * d.x + n.y * d.y + n.z * d.z; }

// Six times the signed volume of the tetrahedron: > 0 when d is above the
// triangle a, b, c (counter-clockwise seen from d).
wide orientation(const grid_point& a, const grid_point& b, const grid_point& c,
                 const grid_point& d) {
  return dot(cross(b - a, c - a), d - a);
}

struct triangle {
  std::array<index, 3> corners;     // counter-clockwise from outside
  std::array<index, 3> neighbours;  // across the edge corners[i] -> corners[i + 1]
  wide_vector normal;               // (b - a) x (c - a), outward, on the grid
  std::vector<index> outside;       // points above it not yet in the hull
  index seen_by = none;             // the last eye point it was visible from
  bool alive = true;
};

class triangle_hull {
 public:
  // The tetrahedron's corners must not be coplanar on the grid.
  triangle_hull(const std::vector<grid_point>& grid, std::array<index, 4> tetrahedron)
      : grid_(grid), horizon_from_(grid.size(), none) {
    auto& [a, b, c, d] = tetrahedron;
    // With d below the triangle a, b, c, these four triangles each have the
    // remaining corner below them: their normals point outwards.
    if (orientation(grid[a], grid[b], grid[c], grid[d]) > 0) std::swap(b, c);
    add_triangle(a, b, c);
    add_triangle(a, d, b);
    add_triangle(b, d, c);
    add_triangle(a, c, d);
    for (index t = 0; t < 4; ++t) {
      for (int i = 0; i < 3; ++i) {
        const index from = triangles_[t].corners[i], to = triangles_[t].corners[(i + 1) % 3];
        for (index u = 0; u < 4; ++u) {
          if (u != t && slot_of(u, to, from) < 3) triangles_[t].neighbours[i] = u;
        }
      }
    }
    std::vector<index> rest;
    for (index p = 0; p < grid.size(); ++p) {
      if (p != a && p != b && p != c && p != d) rest.push_back(p);
    }
    assign(rest, 0);
    // New triangles are appended, so one pass meets them all.
    for (index t = 0; t < triangles_.size(); ++t) {
      if (triangles_[t].alive && !triangles_[t].outside.empty()) add_farthest_point(t);
    }
  }

  const std::vector<triangle>& triangles() const { return triangles_; }

 private:
  wide height(index t, index p) const {
    const triangle& tri = triangles_[t];
    return dot(tri.normal, grid_[p] - grid_[tri.corners[0]]);
  }

  index add_triangle(index a, index b, index c) {
    triangle t;
    t.corners = {a, b, c};
    t.neighbours = {none, none, none};
    t.normal = cross(grid_[b] - grid_[a], grid_[c] - grid_[a]);
    triangles_.push_back(std::move(t));
    return static_cast<index>(triangles_.size() - 1);
  }

  // Which of t's edges runs from -> to (3 if none does).
  int slot_of(index t, index from, index to) const {
    const auto& c = triangles_[t].corners;
    for (int i = 0; i < 3; ++i) {
      if (c[i] == from && c[(i + 1) % 3] == to) return i;
    }
    return 3;
  }

  // Each point goes to the first triangle from `first` on that it is strictly
  // above; a point above none is inside the hull or on it, and is dropped.
  void assign(const std::vector<index>& points, index first) {
    for (index p : points) {
      for (index t = first; t < triangles_.size(); ++t) {
        if (height(t, p) > 0) {
          triangles_[t].outside.push_back(p);
          break;
        }
      }
    }
  }

  struct horizon_edge {
    index from, to;  // as the visible triangle walks it
    index beyond;    // the triangle on the other side, which stays
  };

  // Adds the point of t's outside set farthest above t: every triangle it
  // sees goes, and a fan of triangles joins it to the horizon around them.
  void add_farthest_point(index start) {
    const std::vector<index>& candidates = triangles_[start].outside;
    index eye = candidates[0];
    wide best = height(start, eye);
    for (index p : candidates) {
      const wide h = height(start, p);
      if (h > best || (h == best && p < eye)) best = h, eye = p;
    }

    // The triangles the eye sees form a disc (exact tests): grow it from start.
    std::vector<index> visible{start};
    triangles_[start].seen_by = eye;
    for (std::size_t k = 0; k < visible.size(); ++k) {
      for (index n : triangles_[visible[k]].neighbours) {
        if (triangles_[n].seen_by != eye && height(n, eye) > 0) {
          triangles_[n].seen_by = eye;
          visible.push_back(n);
        }
      }
    }
    std::vector<horizon_edge> edges;
    for (index t : visible) {
      const triangle& tri = triangles_[t];
      for (int i = 0; i < 3; ++i) {
        if (triangles_[tri.neighbours[i]].seen_by != eye) {
          edges.push_back({tri.corners[i], tri.corners[(i + 1) % 3], tri.neighbours[i]});
        }
      }
    }

    // The horizon is one cycle: chain its edges head to tail.
    for (index e = 0; e < edges.size(); ++e) horizon_from_[edges[e].from] = e;
    std::vector<horizon_edge> horizon{edges[0]};
    while (horizon.size() < edges.size() && horizon.back().to != edges[0].from) {
      const index e = horizon_from_[horizon.back().to];
      if (e == none) break;
      horizon.push_back(edges[e]);
    }
    for (const horizon_edge& e : edges) horizon_from_[e.from] = none;
    if (horizon.size() != edges.size() || horizon.back().to != edges[0].from) {
      throw std::logic_error("gaphys: convex hull horizon is not one cycle");
    }

    const index first = static_cast<index>(triangles_.size());
    const index count = static_cast<index>(horizon.size());
    for (index k = 0; k < count; ++k) {
      const horizon_edge& e = horizon[k];
      const index t = add_triangle(e.from, e.to, eye);
      triangles_[t].neighbours = {e.beyond, first + (k + 1) % count,
                                  first + (k + count - 1) % count};
      triangles_[e.beyond].neighbours[slot_of(e.beyond, e.to, e.from)] = t;
    }
    std::vector<index> orphans;
    for (index t : visible) {
      triangle& tri = triangles_[t];
      for (index p : tri.outside) {
        if (p != eye) orphans.push_back(p);
      }
      tri.outside = {};
      tri.alive = false;
    }
    assign(orphans, first);
  }

  const std::vector<grid_point>& grid_;
  std::vector<triangle> triangles_;
  std::vector<index> horizon_from_;  // per point: the horizon edge leaving it
};

// ---------------------------------------------------------------------------
// Stage 2: merging flat neighbours on a half-edge mesh of the triangles.

class face_mesh {
 public:
  face_mesh(const std::vector<xyz>& points, const std::vector<triangle>& triangles, real tolerance)
      : points_(&points), tolerance_(tolerance), seen_at_(points.size(), 0) {
    std::vector<index> renumbered(triangles.size(), none);
    for (index t = 0; t < triangles.size(); ++t) {
      if (!triangles[t].alive) continue;
      renumbered[t] = static_cast<index>(face_edge_.size());
      face_edge_.push_back(3 * renumbered[t]);
    }
    origin_.resize(3 * face_edge_.size());
    next_.resize(origin_.size());
    twin_.resize(origin_.size());
    face_.resize(origin_.size());
    for (index t = 0; t < triangles.size(); ++t) {
      if (renumbered[t] == none) continue;
      const triangle& tri = triangles[t];
      const index f = renumbered[t];
      for (index i = 0; i < 3; ++i) {
        const index h = 3 * f + i;
        const index n = tri.neighbours[i];
        const auto& nc = triangles[n].corners;
        const index to = tri.corners[(i + 1) % 3];
        index j = 0;
        while (!(nc[j] == to && nc[(j + 1) % 3] == tri.corners[i])) ++j;
        origin_[h] = tri.corners[i];
        next_[h] = 3 * f + (i + 1) % 3;
        twin_[h] = 3 * renumbered[n] + j;
        face_[h] = f;
      }
    }
  }

  // Merges neighbouring faces while the merged polygon is flat to within the
  // tolerance, until no pair is. The polygons around a corner inside a flat
  // face only become convex when the last of them joins, so a merge may make
  // a concave polygon on the way, unless `convex_steps` forbids it.
  void merge_flat_neighbours(bool convex_steps) {
    for (bool merged = true; merged;) {
      merged = false;
      for (index f = 0; f < face_edge_.size(); ++f) {
        for (bool again = true; again && face_edge_[f] != none;) {
          again = false;
          const index start = face_edge_[f];
          index h = start;
          do {
            const index g = face_[twin_[h]];
            if (g != f && try_merge(f, g, convex_steps)) {
              again = merged = true;
              break;
            }
            h = next_[h];
          } while (h != start);
        }
      }
    }
  }

  // A corner where only two faces meet lies on their common edge (else they
  // would be one face): when it is on the straight line through its
  // neighbours, its two edges become one.
  void drop_straight_corners() {
    std::vector<index> leaving(points_->size(), none), degree(points_->size(), 0);
    for (index h = 0; h < origin_.size(); ++h) {
      if (face_[h] == none) continue;
      leaving[origin_[h]] = h;
      ++degree[origin_[h]];
    }
    for (index v = 0; v < points_->size(); ++v) {
      if (degree[v] != 2) continue;
      const index out_a = leaving[v];   // v -> w, in face a
      const index in_c = twin_[out_a];  // w -> v, in face c
      const index out_c = next_[in_c];  // v -> u, in face c
      const index in_a = twin_[out_c];  // u -> v, in face a
      const index a = face_[out_a], c = face_[out_c];
      if (a == c || corner_count(a) < 4 || corner_count(c) < 4) continue;
      const xyz& u = (*points_)[origin_[in_a]];
      const xyz& w = (*points_)[origin_[in_c]];
      const xyz along = w - u;
      const real gap = length(cross((*points_)[v] - u, along)) / length(along);
      if (!(gap <= tolerance_)) continue;
      // u -> v -> w becomes u -> w in a, and w -> v -> u becomes w -> u in c.
      next_[in_a] = next_[out_a];
      next_[in_c] = next_[out_c];
      twin_[in_a] = in_c;
      twin_[in_c] = in_a;
      face_[out_a] = face_[out_c] = none;
      face_edge_[a] = in_a;
      face_edge_[c] = in_c;
    }
  }

  bool faces_convex() const {
    for (const loop& corners : loops()) {
      if (!is_convex(corners)) return false;
    }
    return true;
  }

  // The faces' corner loops.
  std::vector<loop> loops() const {
    std::vector<loop> result;
    for (index start : face_edge_) {
      if (start == none) continue;
      loop corners;
      index h = start;
      do {
        corners.push_back(origin_[h]);
        h = next_[h];
      } while (h != start);
      result.push_back(std::move(corners));
    }
    return result;
  }

 private:
  index corner_count(index f) const {
    index count = 0;
    index h = face_edge_[f];
    do {
      ++count;
      h = next_[h];
    } while (h != face_edge_[f]);
    return count;
  }

  // Merges g into f when they share one unbroken run of edges and the merged
  // polygon is flat (and convex, if asked); false (nothing changed) otherwise.
  bool try_merge(index f, index g, bool convex_steps) {
    // f's half-edges in order, and where the run shared with g starts.
    std::vector<index>& ring = ring_;
    ring.clear();
    index h = face_edge_[f];
    do {
      ring.push_back(h);
      h = next_[h];
    } while (h != face_edge_[f]);
    const std::size_t n = ring.size();
    auto shared = [&](std::size_t i) { return face_[twin_[ring[i % n]]] == g; };
    std::size_t runs = 0, run_start = 0;
    for (std::size_t i = 0; i < n; ++i) {
      if (shared(i) && !shared(i + n - 1)) ++runs, run_start = i;
    }
    if (runs != 1) return false;
    std::size_t run_length = 0;
    while (shared(run_start + run_length)) ++run_length;
    const index first_shared = ring[run_start];
    const index last_shared = ring[(run_start + run_length - 1) % n];

    // The merged ring: f's edges after the run, then g's edges around it.
    std::vector<index>& merged = merged_;
    merged.clear();
    for (std::size_t i = run_length; i < n; ++i) merged.push_back(ring[(run_start + i) % n]);
    const std::size_t from_f = merged.size();
    for (h = next_[twin_[first_shared]]; h != twin_[last_shared]; h = next_[h]) {
      if (face_[twin_[h]] == f) return false;  // g would touch f twice
      merged.push_back(h);
    }
    if (from_f == 0 || merged.size() == from_f) return false;
    loop& corners = corners_;
    corners.clear();
    for (index e : merged) corners.push_back(origin_[e]);
    if (!is_flat(corners) || !is_simple(corners) || (convex_steps && !is_convex(corners))) {
      return false;
    }

    for (std::size_t i = 0; i < merged.size(); ++i) {
      next_[merged[i]] = merged[(i + 1) % merged.size()];
      face_[merged[i]] = f;
    }
    for (std::size_t i = 0; i < run_length; ++i) {
      const index gone = ring[(run_start + i) % n];
      face_[twin_[gone]] = none;
      face_[gone] = none;
    }
    face_edge_[f] = merged[0];
    face_edge_[g] = none;
    return true;
  }

  // All corners within the tolerance of one plane.
  bool is_flat(const loop& corners) const {
    const xyz area = area_vector(*points_, corners);
    const real area_length = length(area);
    if (!(area_length > 0)) return false;
    const xyz normal = (1 / area_length) * area;
    real low = std::numeric_limits<real>::infinity(), high = -low;
    for (index v : corners) {
      low = std::min(low, dot(normal, (*points_)[v]));
      high = std::max(high, dot(normal, (*points_)[v]));
    }
    return high - low <= tolerance_;
  }

  // No corner twice (two faces touching at a corner besides their common
  // edges would merge into a ring).
  bool is_simple(const loop& corners) {
    ++stamp_;
    for (index v : corners) {
      if (seen_at_[v] == stamp_) return false;
      seen_at_[v] = stamp_;
    }
    return true;
  }

  // No corner more than the tolerance inside the chord of its neighbours,
  // and the turns add up to one turn, not two (no spike folding back).
  bool is_convex(const loop& corners) const {
    const xyz area = area_vector(*points_, corners);
    const xyz normal = (1 / length(area)) * area;
    const std::size_t n = corners.size();
    real turning = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const xyz& u = (*points_)[corners[i]];
      const xyz& v = (*points_)[corners[(i + 1) % n]];
      const xyz& w = (*points_)[corners[(i + 2) % n]];
      const xyz in = v - u, out = w - v;
      // (v - u) x (w - v) = (v - u) x (w - u): the turn is v's distance
      // outside the chord u -> w times the chord's length.
      const real turn = dot(cross(in, out), normal);
      if (turn < -tolerance_ * length(w - u)) return false;
      turning += std::atan2(turn, dot(in, out));
    }
    return turning < 3 * detail::pi;
  }

  const std::vector<xyz>* points_;  // a pointer, so that a mesh can be reassigned
  real tolerance_;
  std::vector<index> origin_, next_, twin_, face_;  // per half-edge; face none: gone
  std::vector<index> face_edge_;                    // per face: a half-edge, none: merged away
  std::vector<index> ring_, merged_, corners_;      // try_merge's scratch
  std::vector<index> seen_at_;                      // per point: is_simple's last stamp
  index stamp_ = 0;
};

// ---------------------------------------------------------------------------

// The points in order, less each within `distance` of one kept before it:
// corners closer than the tolerance would only make faces too small for
// their normals to be more than rounding noise.
std::vector<xyz> welded(const std::vector<xyz>& points, real distance) {
  using cell = std::array<std::int64_t, 3>;
  struct cell_hash {
    std::size_t operator()(const cell& c) const {  // splitmix64's finalizer over the three
      std::uint64_t h = 0;
      for (std::int64_t k : c) {
        h = (h ^ static_cast<std::uint64_t>(k)) * 0x9e3779b97f4a7c15u;
        h ^= h >> 31;
      }
      return static_cast<std::size_t>(h);
    }
  };
  // Cells twice the welding distance wide: the points within it of p are in
  // the cells holding the corners of the cube p +- distance, at most 8. Cell
  // numbers stay within 1 / (16 DBL_EPSILON), as the tolerance grows with the
  // points' magnitude.
  const real width = 2 * distance;
  auto cell_of = [&](real x, real y, real z) {
    return cell{static_cast<std::int64_t>(std::floor(x / width)),
                static_cast<std::int64_t>(std::floor(y / width)),
                static_cast<std::int64_t>(std::floor(z / width))};
  };
  std::unordered_map<cell, index, cell_hash> first_in;  // a cell's last kept point
  first_in.reserve(2 * points.size());
  std::vector<index> next_in;  // per kept point: the one before in its cell
  std::vector<xyz> kept;
  for (const xyz& p : points) {
    const cell low = cell_of(p.x - distance, p.y - distance, p.z - distance);
    const cell high = cell_of(p.x + distance, p.y + distance, p.z + distance);
    bool near = false;
    for (std::int64_t i = low[0]; i <= high[0] && !near; ++i) {
      for (std::int64_t j = low[1]; j <= high[1] && !near; ++j) {
        for (std::int64_t k = low[2]; k <= high[2] && !near; ++k) {
          const auto found = first_in.find({i, j, k});
          if (found == first_in.end()) continue;
          for (index q = found->second; q != none && !near; q = next_in[q]) {
            near = length(kept[q] - p) <= distance;
          }
        }
      }
    }
    if (near) continue;
    const auto [slot, added] = first_in.try_emplace(cell_of(p.x, p.y, p.z), none);
    (void)added;
    next_in.push_back(slot->second);
    slot->second = static_cast<index>(kept.size());
    kept.push_back(p);
  }
  return kept;
}

// The index of the point that maximizes score (the lowest index on ties).
template <class Score>
index best_point(std::size_t count, Score score) {
  index best = 0;
  real best_score = score(0);
  for (index i = 1; i < count; ++i) {
    const real s = score(i);
    if (s > best_score) best_score = s, best = i;
  }
  return best;
}

}  // namespace

convex_polyhedron convex_polyhedron::box(const vector& half_extents) {
  detail::require_length(half_extents.e1(), "box half extent x");
  detail::require_length(half_extents.e2(), "box half extent y");
  detail::require_length(half_extents.e3(), "box half extent z");
  const std::array<real, 3> h{half_extents.e1(), half_extents.e2(), half_extents.e3()};
  // Corner i is on the + side of axis k when bit k of i is set.
  std::vector<xyz> corners;
  for (index i = 0; i < 8; ++i) {
    corners.push_back({i & 1 ? h[0] : -h[0], i & 2 ? h[1] : -h[1], i & 4 ? h[2] : -h[2]});
  }
  // Faces -x, +x, -y, +y, -z, +z. With (k, u, v) a cyclic order of the axes,
  // e_u x e_v = e_k, so (-u-v, +u-v, +u+v, -u+v) runs counter-clockwise about
  // +e_k; the - face walks it backwards.
  std::vector<loop> faces;
  for (index k = 0; k < 3; ++k) {
    const index u = 1u << ((k + 1) % 3), v = 1u << ((k + 2) % 3);
    for (const index side : {0u, 1u << k}) {
      loop q{side, side | u, side | u | v, side | v};
      if (side == 0) std::reverse(q.begin(), q.end());
      faces.push_back(q);
    }
  }
  return assemble(corners, faces);
}

convex_polyhedron convex_polyhedron::hull(const std::vector<vector>& input) {
  for (std::size_t i = 0; i < input.size(); ++i) {
    for (real x : input[i].c) {
      if (!std::isfinite(x)) {
        detail::reject("convex hull point ", i, " must be finite (got ",
                       e3ga::basic_mv<real>(input[i]), ")");
      }
    }
  }
  if (input.size() < 4)
    detail::reject("convex hull needs at least 4 points (got ", input.size(), ")");
  if (input.size() >= none) detail::reject("convex hull has too many points (", input.size(), ")");

  std::vector<xyz> given;
  for (const vector& v : input) given.push_back({v.e1(), v.e2(), v.e3()});
  xyz low = given[0], high = given[0];
  real magnitude = 0;
  for (const xyz& p : given) {
    low = {std::min(low.x, p.x), std::min(low.y, p.y), std::min(low.z, p.z)};
    high = {std::max(high.x, p.x), std::max(high.y, p.y), std::max(high.z, p.z)};
    magnitude = std::max({magnitude, std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
  }
  const xyz extent = high - low;
  const real size = std::max({extent.x, extent.y, extent.z});
  if (!std::isfinite(size)) detail::reject("convex hull points must span a finite range");
  // The lengths every shape keeps to (validate.hpp, smallest_length); each
  // coordinate within them first, so that the distances squared are finite.
  real farthest = magnitude;
  if (magnitude <= detail::largest_length) {
    for (const xyz& p : given) farthest = std::max(farthest, length(p));
  }
  if (farthest > detail::largest_length) {
    detail::reject("convex hull points must lie within ", detail::largest_length,
                   " m of the origin (got one ", farthest, " m from it)");
  }
  const real tolerance = relative_tolerance * size + 8 * DBL_EPSILON * magnitude;
  if (!(size > tolerance)) detail::reject("convex hull points all (nearly) coincide");
  if (size < detail::smallest_length) {
    detail::reject("convex hull points must span at least ", detail::smallest_length, " m (got ",
                   size, ")");
  }
  const std::vector<xyz> points = welded(given, tolerance);

  // A first tetrahedron as large as cheaply found: the extremes along the
  // widest axis, the point farthest from their line, the one farthest from
  // the plane of those three.
  const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
  auto along = [&](index i) {
    return axis == 0 ? points[i].x : axis == 1 ? points[i].y : points[i].z;
  };
  const index a = best_point(points.size(), [&](index i) { return -along(i); });
  const index b = best_point(points.size(), along);
  const xyz ab = points[b] - points[a];
  const index c =
      best_point(points.size(), [&](index i) { return length(cross(points[i] - points[a], ab)); });
  if (!(length(cross(points[c] - points[a], ab)) / length(ab) > tolerance)) {
    detail::reject("convex hull points all lie (nearly) on one line: they span no volume");
  }
  const xyz abc = cross(ab, points[c] - points[a]);
  const xyz up = (1 / length(abc)) * abc;
  const index d =
      best_point(points.size(), [&](index i) { return std::fabs(dot(up, points[i] - points[a])); });
  if (!(std::fabs(dot(up, points[d] - points[a])) > tolerance)) {
    detail::reject("convex hull points all lie (nearly) in one plane: they span no volume");
  }

  const real cell = size / grid_cells;
  std::vector<grid_point> grid;
  for (const xyz& p : points) {
    grid.push_back({std::llround((p.x - low.x) / cell), std::llround((p.y - low.y) / cell),
                    std::llround((p.z - low.z) / cell)});
  }
  if (orientation(grid[a], grid[b], grid[c], grid[d]) == 0) {
    detail::reject("convex hull points all lie (nearly) in one plane: they span no volume");
  }

  const triangle_hull triangles(grid, {a, b, c, d});
  face_mesh mesh(points, triangles.triangles(), tolerance);
  mesh.merge_flat_neighbours(false);
  if (!mesh.faces_convex()) {
    // A flat patch with a notch (points a hair more than the tolerance below
    // a face): merge only while the faces stay convex.
    mesh = face_mesh(points, triangles.triangles(), tolerance);
    mesh.merge_flat_neighbours(true);
  }
  mesh.drop_straight_corners();

  // Keep only the corners, in input order.
  std::vector<loop> faces = mesh.loops();
  std::vector<index> renumbered(points.size(), none);
  for (const loop& corners : faces) {
    for (index v : corners) renumbered[v] = 0;
  }
  std::vector<xyz> corners;
  for (index v = 0; v < points.size(); ++v) {
    if (renumbered[v] == none) continue;
    renumbered[v] = static_cast<index>(corners.size());
    corners.push_back(points[v]);
  }
  for (loop& face : faces) {
    for (index& v : face) v = renumbered[v];
  }
  return assemble(corners, std::move(faces));
}

}  // namespace gaphys
