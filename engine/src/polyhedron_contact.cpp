#include "polyhedron_contact.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "gjk.hpp"
#include "precision.hpp"
#include "vec3.hpp"

namespace gaphys::detail {

namespace {

// ---- Feature ids (the layout is in polyhedron_contact.hpp) -----------------

enum class feature_kind : std::uint32_t {
  incident_vertex = 0,
  edge_crossing = 1,
  reference_corner = 2,
  edge_pair = 3
};

std::uint32_t face_clip_feature(bool b_is_reference, feature_kind kind,
                                std::uint32_t reference_face, std::uint32_t side,
                                std::uint32_t incident) {
  return (std::uint32_t(b_is_reference) << 31) | (std::uint32_t(kind) << 29) |
         ((reference_face & 0x7ffu) << 18) | ((side & 0x3fu) << 12) | (incident & 0xfffu);
}

std::uint32_t edge_pair_feature(std::uint32_t edge_a, std::uint32_t edge_b) {
  return (std::uint32_t(feature_kind::edge_pair) << 29) | ((edge_a & 0x3fffu) << 14) |
         (edge_b & 0x3fffu);
}

// ---- The working frame ------------------------------------------------------

// An edge in the working frame, packed for the edge-pair loop: the normals
// of its left and right faces, their cross product (along the edge), its
// tail and its tail-to-head vector.
struct edge_data {
  vec3 n1, n2, normals_cross, tail, along;
};

// A polyhedron's vertices, face planes and edges in the frame the pair is
// tested in (B's). Moving A's data once per call costs O(V + F + E) and
// lets every test run on plain numbers.
struct polyhedron_data {
  const convex_polyhedron* shape = nullptr;
  std::vector<vec3> vertices;
  std::vector<vec3> normals;
  std::vector<real> offsets;
  std::vector<edge_data> edges;  // left empty by box pairs, which need none
  // The edges' normals_cross again, one array per coordinate, for the
  // edge-pair loop's first test, which runs over all of B's edges at once.
  std::vector<real> cross_x, cross_y, cross_z;

  // `to_working`: x_working = origin + M x_shape; none: the shape's own frame.
  void load(const convex_polyhedron& p, const rigid_frame* to_working, bool with_edges) {
    shape = &p;
    vertices.resize(p.vertices.size());
    normals.resize(p.faces.size());
    offsets.resize(p.faces.size());
    if (to_working) {
      for (std::size_t i = 0; i < p.vertices.size(); ++i) {
        vertices[i] = to_working->to_world(to_vec3(p.vertices[i]));
      }
      for (std::size_t f = 0; f < p.faces.size(); ++f) {
        normals[f] = to_working->rotate(to_vec3(p.faces[f].normal));
        offsets[f] = p.faces[f].offset + dot(normals[f], to_working->origin);
      }
    } else {
      for (std::size_t i = 0; i < p.vertices.size(); ++i) vertices[i] = to_vec3(p.vertices[i]);
      for (std::size_t f = 0; f < p.faces.size(); ++f) {
        normals[f] = to_vec3(p.faces[f].normal);
        offsets[f] = p.faces[f].offset;
      }
    }
    const std::size_t edge_count = with_edges ? p.edges.size() : 0;
    edges.resize(edge_count);
    cross_x.resize(edge_count), cross_y.resize(edge_count), cross_z.resize(edge_count);
    for (std::size_t e = 0; e < edge_count; ++e) {
      const polyhedron_edge& edge = p.edges[e];
      edge_data& d = edges[e];
      d.n1 = normals[edge.left], d.n2 = normals[edge.right];
      d.normals_cross = cross(d.n1, d.n2);
      d.tail = vertices[edge.tail];
      d.along = vertices[edge.head] - vertices[edge.tail];
      cross_x[e] = d.normals_cross.x, cross_y[e] = d.normals_cross.y,
      cross_z[e] = d.normals_cross.z;
    }
  }
};

// A point of the incident polygon while it is clipped. `along` names the
// feature the polygon's edge from this point to the next lies on: an
// incident edge (its tail vertex, >= 0) or a side of the reference face
// (-1 - side), so a crossing can say which two features made it.
struct clip_point {
  vec3 position;
  std::uint32_t feature;
  std::int32_t along;
};

struct candidate {
  vec3 position;  // on the incident surface (working frame)
  real gap;       // above the reference plane (< 0: below)
  std::uint32_t feature;
};

// A list kept at its largest size, with its own count: filling it is plain
// stores (clipping a convex polygon by a plane adds at most one corner, so
// the room needed is known before each pass).
template <class Item>
struct buffer {
  std::vector<Item> storage;
  std::size_t count = 0;

  void reset(std::size_t room) {
    if (storage.size() < room) storage.resize(room);
    count = 0;
  }
  // The next item, to be filled in field by field (a whole temporary
  // copied in stalls on store forwarding).
  Item& append() { return storage[count++]; }
  const Item& operator[](std::size_t i) const { return storage[i]; }
};

// A contact point, set field by field for the same reason.
void set_point(contact_point& point, const vec3& position, const vec3& normal, real depth,
               std::uint32_t feature) {
  contact_geometry& g = point.geometry;
  g.point.c = {position.x, position.y, position.z};
  g.normal.c = {normal.x, normal.y, normal.z};
  g.depth = depth;
  g.squared_radius = 0;
  point.feature = feature;
}

// Scratch space per thread: it grows to the largest polyhedra seen and is
// reused, so a call allocates nothing once the scene's shapes have been met.
struct scratch_space {
  polyhedron_data a, b;
  buffer<clip_point> polygon, clipped;
  buffer<candidate> candidates;
  std::vector<real> straddle;  // the edge-pair loop's first test, per edge of B
};

// ---- Separating axes --------------------------------------------------------
//
// Two convex polyhedra are apart iff some axis separates them, and the
// axes to try are the face normals of their Minkowski difference A - B:
// A's face normals, B's (negated), and the cross products of an edge of A
// with an edge of B whose arcs cross on the Gauss map. Along an axis n
// (pointing from A towards B) the gap is min over B of n.x minus max over A
// of n.x; the largest gap over all axes is the distance between the solids
// when negative (minus the penetration depth, the least translation that
// separates them), and a lower bound of it when positive.

struct face_query {
  real gap = -infinity;
  int face = -1;
};

struct edge_query {
  real gap = -infinity;
  int edge_a = -1, edge_b = -1;
  vec3 axis;  // unit, from A towards B
  // Boxes: the axes a_i, e_j whose cross product it is (edges looked up
  // later), and the axis in A's frame.
  std::array<int, 2> box_axes{-1, -1};
  vec3 axis_in_a;
};

// The faces of `faces_of` against the vertices of `other`; stops early once
// a gap exceeds `cutoff` (the pair is then apart by more than it).
face_query query_faces(const polyhedron_data& faces_of, const polyhedron_data& other, real cutoff) {
  face_query best;
  for (std::size_t f = 0; f < faces_of.normals.size(); ++f) {
    const vec3& n = faces_of.normals[f];
    real lowest = infinity;
    for (const vec3& v : other.vertices) lowest = std::min(lowest, dot(n, v));
    const real gap = lowest - faces_of.offsets[f];
    if (gap > best.gap) best = {gap, int(f)};
    if (gap > cutoff) break;
  }
  return best;
}

// Edge pairs of A and B. The normals of an edge's two faces, n1 and n2, are
// the ends of an arc on the unit sphere (the edge's Gauss map); B's edge
// enters A - B negated, as the arc from c = -m1 to d = -m2. The two edges
// span a face of A - B iff the arcs cross:
//  - n1 and n2 lie on opposite sides of the plane of c and d (normal
//    w = c × d = m1 × m2): (n1.w)(n2.w) < 0;
//  - c and d lie on opposite sides of the plane of n1 and n2 (u = n1 × n2):
//    (c.u)(d.u) < 0;
//  - the crossings agree rather than being antipodal. Arc cd meets the
//    great circle of n1 n2 at q = sgn(c.u) ((c.u) d - (d.u) c) (q.u = 0,
//    and both weights are positive), and arc n1 n2 meets it at a positive
//    combination p of n1 and n2, so p.(n1 + n2) > 0; q is p, not -p,
//    iff q.(n1 + n2) > 0.
// The face's normal is then ±(edge A × edge B), the sign that points into
// A's arc, i.e. along n1 + n2.
edge_query query_edges(const polyhedron_data& a, const polyhedron_data& b, real cutoff,
                       std::vector<real>& straddle) {
  edge_query best;
  const std::size_t count_b = b.edges.size();
  straddle.resize(count_b);
  for (std::size_t i = 0; i < a.edges.size(); ++i) {
    const edge_data& ea = a.edges[i];
    const vec3& u = ea.normals_cross;
    const vec3 toward_a_arc = ea.n1 + ea.n2;
    // The first test for every edge of B in one branch-free pass (it
    // rejects most pairs; branching on it pair by pair costs more):
    // (n1.w)(n2.w), w = c × d.
    for (std::size_t j = 0; j < count_b; ++j) {
      const real n1w = ea.n1.x * b.cross_x[j] + ea.n1.y * b.cross_y[j] + ea.n1.z * b.cross_z[j];
      const real n2w = ea.n2.x * b.cross_x[j] + ea.n2.y * b.cross_y[j] + ea.n2.z * b.cross_z[j];
      straddle[j] = n1w * n2w;
    }
    for (std::size_t j = 0; j < count_b; ++j) {
      if (!(straddle[j] < 0)) continue;
      // c = -eb.n1, d = -eb.n2, and c × d = eb.normals_cross.
      const edge_data& eb = b.edges[j];
      const real cu = -dot(eb.n1, u), du = -dot(eb.n2, u);
      if (!(cu * du < 0)) continue;
      const real q_along = du * dot(eb.n1, toward_a_arc) - cu * dot(eb.n2, toward_a_arc);
      if (!((cu > 0 ? q_along : -q_along) > 0)) continue;

      // Parallel edges span no face of their own (their parallelogram
      // lies in a face already tried).
      vec3 axis = cross(ea.along, eb.along);
      const real axis_squared = dot(axis, axis);
      if (!(axis_squared >
            by_precision(1e-18, 1e-8) * dot(ea.along, ea.along) * dot(eb.along, eb.along)))
        continue;
      axis = (1 / std::sqrt(axis_squared)) * axis;
      if (dot(axis, toward_a_arc) < 0) axis = -axis;
      const real gap = dot(axis, eb.tail - ea.tail);
      if (gap > best.gap)
        best.gap = gap, best.edge_a = int(i), best.edge_b = int(j), best.axis = axis;
      if (gap > cutoff) return best;
    }
  }
  return best;
}

struct sat_result {
  face_query face_a, face_b;
  edge_query edge;
  bool apart = false;  // some gap exceeds the cutoff
};

sat_result separating_axes(const polyhedron_data& a, const polyhedron_data& b, real cutoff,
                           std::vector<real>& straddle) {
  sat_result r;
  r.face_a = query_faces(a, b, cutoff);
  if (r.face_a.gap > cutoff) return r.apart = true, r;
  r.face_b = query_faces(b, a, cutoff);
  if (r.face_b.gap > cutoff) return r.apart = true, r;
  r.edge = query_edges(a, b, cutoff, straddle);
  r.apart = r.edge.gap > cutoff;
  return r;
}

// ---- Boxes --------------------------------------------------------------------
//
// Two boxes have 15 candidate axes: the three face normals of each and the
// nine cross products of an edge direction of each (every such pair spans
// a face of A - B, the supports along the cross product being edges). Along
// each the gap has a closed form from the half extents (h of A, k of B),
// A's axes a_i and centre t in B's frame (e.g. a face of A:
// |t.a_i| - h_i - sum_j k_j |e_j.a_i|), the same
// numbers the general queries find by scanning corners, at a fraction of
// the cost. The features that made the best axes are then looked up in the
// boxes' polyhedra, so the manifold code and the feature ids are shared.

real component(const vec3& v, int k) { return k == 0 ? v.x : k == 1 ? v.y : v.z; }

// The box's face whose outward normal is `sign` times axis k: the faces of
// convex_polyhedron::box are -x, +x, -y, +y, -z, +z. (Scanning the faces'
// normals for it, a miss in the cache per box, was a fifth of the box pair
// test in a pile.)
int box_face(int k, real sign) { return 2 * k + (sign > 0 ? 1 : 0); }

// The box's edge along axis k whose other two coordinates have the signs of
// `side`'s (0 counts as +).
int box_edge(const convex_polyhedron& box, int k, const vec3& side) {
  for (std::size_t e = 0; e < box.edges.size(); ++e) {
    const vector& tail = box.vertices[box.edges[e].tail];
    const vector& head = box.vertices[box.edges[e].head];
    bool match = tail.c[k] != head.c[k];
    for (int m = 0; m < 3 && match; ++m) {
      if (m != k) match = (tail.c[m] > 0) == (component(side, m) >= 0);
    }
    if (match) return int(e);
  }
  return 0;
}

sat_result box_axes(const placed_shape& a, const placed_shape& b, const rigid_frame& a_in_b,
                    real cutoff) {
  sat_result r;
  const vec3& t = a_in_b.origin;  // A's centre from B's, in B's frame
  const vec3* axis = a_in_b.column;
  const vec3 ha = to_vec3(a.half_extents), hb = to_vec3(b.half_extents);
  const real h_a[3] = {ha.x, ha.y, ha.z}, h_b[3] = {hb.x, hb.y, hb.z};
  real abs_r[3][3];  // |e_j . a_i|
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) abs_r[j][i] = std::fabs(component(axis[i], j));
  }
  // B lies towards -t from A: A's face along a_i that faces it is -sgn(t.a_i) a_i.
  for (int i = 0; i < 3; ++i) {
    const real along = dot(t, axis[i]);
    const real gap = std::fabs(along) - h_a[i] -
                     (h_b[0] * abs_r[0][i] + h_b[1] * abs_r[1][i] + h_b[2] * abs_r[2][i]);
    if (gap > r.face_a.gap) r.face_a = {gap, box_face(i, along > 0 ? -1 : 1)};
    if (gap > cutoff) return r.apart = true, r;
  }
  for (int j = 0; j < 3; ++j) {
    const real along = component(t, j);
    const real gap = std::fabs(along) - h_b[j] -
                     (h_a[0] * abs_r[j][0] + h_a[1] * abs_r[j][1] + h_a[2] * abs_r[j][2]);
    if (gap > r.face_b.gap) r.face_b = {gap, box_face(j, along > 0 ? 1 : -1)};
    if (gap > cutoff) return r.apart = true, r;
  }

  // The nine cross-product axes n = a_i × e_j, unnormalized: the gap along
  // n/|n| is (|t.n| - reach) / |n|, and its sign times its square,
  // s|s| / |n|^2, orders the axes as well without a square root; only the
  // best is normalized.
  int edge_i = -1, edge_j = -1;
  real best_numerator = 0, best_squared = 1;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      const vec3 e_j{real(j == 0), real(j == 1), real(j == 2)};
      const vec3 n = cross(axis[i], e_j);
      const real squared = dot(n, n);
      if (!(squared > by_precision(1e-18, 1e-8)))
        continue;  // parallel edges span no face of their own
      const real reach = h_a[0] * std::fabs(dot(axis[0], n)) + h_a[1] * std::fabs(dot(axis[1], n)) +
                         h_a[2] * std::fabs(dot(axis[2], n)) + h_b[0] * std::fabs(n.x) +
                         h_b[1] * std::fabs(n.y) + h_b[2] * std::fabs(n.z);
      const real numerator = std::fabs(dot(t, n)) - reach;
      if (edge_i < 0 || numerator * std::fabs(numerator) * best_squared >
                            best_numerator * std::fabs(best_numerator) * squared) {
        edge_i = i, edge_j = j, best_numerator = numerator, best_squared = squared;
      }
    }
  }
  if (edge_i < 0) return r;
  const vec3 e_j{real(edge_j == 0), real(edge_j == 1), real(edge_j == 2)};
  const vec3 n = cross(axis[edge_i], e_j);
  const real length = std::sqrt(best_squared);
  r.edge.gap = best_numerator / length;
  r.edge.axis = ((dot(t, n) > 0 ? -1 : 1) / length) * n;  // from A towards B
  r.edge.box_axes = {edge_i, edge_j};
  r.edge.axis_in_a = a_in_b.unrotate(r.edge.axis);
  r.apart = r.edge.gap > cutoff;
  return r;
}

// The edges that made a box pair's best edge axis, found only when the
// contact is made from them: A's edge along a_i that leads along the axis,
// B's along e_j that leads against it. Their other coordinates have the
// signs of the axis's (A) and of minus the axis's (B), in each box's frame.
void find_box_edges(const placed_shape& a, const placed_shape& b, edge_query& q) {
  if (q.box_axes[0] < 0 || q.edge_a >= 0) return;
  q.edge_a = box_edge(*a.polyhedron, q.box_axes[0], q.axis_in_a);
  q.edge_b = box_edge(*b.polyhedron, q.box_axes[1], -q.axis);
}

// The separating axes tested, and A's data moved into B's frame, B's in
// its own (for two boxes, only where the axes do not find them apart);
// `world` maps B's frame to the world. Returns false when the bounding
// spheres are apart by more than `cutoff` (nothing tested).
bool test_pair(const placed_shape& a, const placed_shape& b, real cutoff, scratch_space& s,
               rigid_frame& world, sat_result& sat) {
  const rigid_frame frame_a = frame_of(a.attitude, a.center);
  world = frame_of(b.attitude, b.center);
  const vec3 offset = world.to_local(frame_a.origin);
  const real reach = a.polyhedron->bounding_radius + b.polyhedron->bounding_radius + cutoff;
  if (dot(offset, offset) > reach * reach) return false;
  rigid_frame a_in_b;
  for (int i = 0; i < 3; ++i) a_in_b.column[i] = world.unrotate(frame_a.column[i]);
  a_in_b.origin = offset;
  if (a.kind == shape_kind::box && b.kind == shape_kind::box) {
    // (Box pairs' axes need no loaded data: boxes found apart load none.)
    sat = box_axes(a, b, a_in_b, cutoff);
    if (sat.apart) return true;
    s.a.load(*a.polyhedron, &a_in_b, false);
    s.b.load(*b.polyhedron, nullptr, false);
    return true;
  }
  s.a.load(*a.polyhedron, &a_in_b, true);
  s.b.load(*b.polyhedron, nullptr, true);
  sat = separating_axes(s.a, s.b, cutoff, s.straddle);
  return true;
}

scratch_space& scratch() {
  thread_local scratch_space space;
  return space;
}

// ---- Manifolds --------------------------------------------------------------

// Sutherland–Hodgman against one side plane (side_normal . x <= side_offset
// is inside). A point where an edge of the polygon crosses the plane is the
// meet of the edge's line with the plane, a flat point in c3ga; written out
// it is p + t (q - p), t = dp / (dp - dq) from the signed distances dp, dq
// of p and q, the plane's inner products with them.
void clip_by_side(const buffer<clip_point>& polygon, const vec3& side_normal, real side_offset,
                  std::uint32_t side, bool b_is_reference, std::uint32_t reference_face,
                  buffer<clip_point>& out) {
  const std::size_t n = polygon.count;
  out.reset(n + 1);
  auto add_crossing = [&](const clip_point& p, const clip_point& q, real dp, real dq,
                          std::int32_t along) {
    clip_point& x = out.append();
    x.position = p.position + (dp / (dp - dq)) * (q.position - p.position);
    x.feature = p.along >= 0 ? face_clip_feature(b_is_reference, feature_kind::edge_crossing,
                                                 reference_face, side, std::uint32_t(p.along))
                             : face_clip_feature(b_is_reference, feature_kind::reference_corner,
                                                 reference_face, side, std::uint32_t(-1 - p.along));
    x.along = along;
  };
  for (std::size_t i = 0; i < n; ++i) {
    const clip_point& p = polygon[i];
    const clip_point& q = polygon[i + 1 == n ? 0 : i + 1];
    const real dp = dot(side_normal, p.position) - side_offset;
    const real dq = dot(side_normal, q.position) - side_offset;
    if (dp <= 0) {
      out.append() = p;
      // Leaving: the polygon goes on along the side plane.
      if (dp < 0 && dq > 0) add_crossing(p, q, dp, dq, -1 - std::int32_t(side));
    } else if (dq < 0) {
      // Entering: it goes on along p's edge to q.
      add_crossing(p, q, dp, dq, p.along);
    }
  }
}

// Up to four of the candidates (indices into `chosen`), spread to keep the
// support polygon wide: the deepest, the farthest from it, the one making
// the largest triangle with those two, and the one adding the most area
// outside that triangle. Each is chosen first among the candidates level
// with the deepest (touching, or as deep as the deepest when none touch,
// give or take a thousandth of their spread over the plane, which keeps
// rounding from splitting a resting face), and among all only when none of
// those serves. A wheel of many sides lying on its bottom edge, with the
// wide margin of a rolling wheel, has corners a few centimetres up that are
// farther from the deepest than the touching corner at the edge's other
// end: chosen instead of it, they left the wheel on one corner, and it
// rolled 2-3 cm deep at 60 Hz. Returns how many.
int choose_four(const buffer<candidate>& c, const vec3& normal, std::array<int, 4>& chosen) {
  const int n = int(c.count);
  if (n <= 4) {
    for (int i = 0; i < n; ++i) chosen[i] = i;
    return n;
  }
  int first = 0;
  for (int i = 1; i < n; ++i) {
    if (c[i].gap < c[first].gap) first = i;
  }
  real spread = 0;
  for (int i = 0; i < n; ++i) {
    const vec3 apart = c[i].position - c[first].position;
    const vec3 beside = apart - dot(apart, normal) * normal;
    spread = std::max(spread, dot(beside, beside));
  }
  const real level_gap = std::max(c[first].gap, real(0)) + real(1e-3) * std::sqrt(spread);
  const auto level = [&](int i) { return c[i].gap <= level_gap; };
  // The candidate with the largest positive score, the level ones tried
  // first; -1 when no score is positive.
  const auto best = [&](const auto& score) {
    for (const bool level_only : {true, false}) {
      int found = -1;
      real most = 0;
      for (int i = 0; i < n; ++i) {
        if (level_only && !level(i)) continue;
        const real value = score(i);
        if (value > most) most = value, found = i;
      }
      if (found >= 0) return found;
    }
    return -1;
  };
  const int second = best([&](int i) {
    const vec3 d = c[i].position - c[first].position;
    return dot(d, d);
  });
  chosen = {first, second, -1, -1};
  if (second < 0) return 1;
  const vec3 base = c[second].position - c[first].position;
  const auto area = [&](int i) {
    return dot(cross(base, c[i].position - c[first].position), normal);
  };
  const int third = best([&](int i) { return std::fabs(area(i)); });
  if (third < 0) return 2;
  chosen[2] = third;
  // Orient the triangle counter-clockwise about the normal; a point outside
  // edge (p, q) has a negative area with it.
  const std::array<int, 3> corner = area(third) > 0 ? std::array<int, 3>{first, second, third}
                                                    : std::array<int, 3>{first, third, second};
  const int fourth = best([&](int i) {
    real outside = 0;
    for (int k = 0; k < 3; ++k) {
      const vec3& p = c[corner[k]].position;
      const vec3& q = c[corner[(k + 1) % 3]].position;
      outside = std::min(outside, dot(cross(q - p, c[i].position - p), normal));
    }
    return -outside;
  });
  if (fourth < 0) return 3;
  chosen[3] = fourth;
  return 4;
}

// Leaves out the candidates that stand above a deeper one, within 45° of the
// plane's normal (unit, working frame): more above it than beside it. A body
// thinner than the contact margin (a card, a coin) has all its corners
// within the margin; its upper corners hold nothing the lower ones below
// them do not, and choose_four, which spreads the points over the plane,
// took them as readily as the lower ones (a plate 0.8 mm thick sank through
// the plane, turning, its contacts on its top face).
void drop_shadowed(buffer<candidate>& c, const vec3& normal) {
  // (Compacted in place. A candidate overwritten before the later ones are
  // tested was shadowed by a deeper one, which shadows whatever it did: the
  // cones above the candidates nest.)
  std::size_t kept = 0;
  for (std::size_t i = 0; i < c.count; ++i) {
    const candidate& k = c[i];
    bool shadowed = false;
    for (std::size_t j = 0; j < c.count && !shadowed; ++j) {
      const real above = k.gap - c[j].gap;
      if (!(above > 0)) continue;
      const vec3 apart = k.position - c[j].position;
      const vec3 beside = apart - dot(apart, normal) * normal;
      shadowed = dot(beside, beside) < above * above;
    }
    if (!shadowed) c.storage[kept++] = k;
  }
  c.count = kept;
}

// The candidates' chosen points as contacts: each midway between its
// incident point and that point's projection on the reference plane
// (normal `reference_normal`, working frame), depth = -gap. `normal` is
// the manifold's world normal, from B towards A.
void emit(const buffer<candidate>& c, const vec3& reference_normal, const vec3& normal,
          const rigid_frame& world, contact_manifold& out) {
  std::array<int, 4> chosen;
  const int count = choose_four(c, reference_normal, chosen);
  for (int i = 0; i < count; ++i) {
    const candidate& k = c[chosen[i]];
    const vec3 midway = k.position - (real(0.5) * k.gap) * reference_normal;
    set_point(out.points[i], world.to_world(midway), normal, -k.gap, k.feature);
  }
  out.count = count;
}

// A face of `reference` against the most anti-parallel face of `incident`:
// the incident face clipped to the reference face's side planes, the
// points within `margin` above the reference plane kept.
void face_contact(const polyhedron_data& reference, const polyhedron_data& incident,
                  int reference_face, bool b_is_reference, real margin, const rigid_frame& world,
                  scratch_space& s, contact_manifold& out) {
  const vec3& n = reference.normals[reference_face];
  const real offset = reference.offsets[reference_face];

  int incident_face = 0;
  real most_opposed = infinity;
  for (std::size_t f = 0; f < incident.normals.size(); ++f) {
    const real alignment = dot(incident.normals[f], n);
    if (alignment < most_opposed) most_opposed = alignment, incident_face = int(f);
  }

  const auto& inc_face = incident.shape->faces[incident_face];
  const auto& inc_indices = incident.shape->vertex_indices;
  s.polygon.reset(inc_face.count);
  for (std::uint32_t k = 0; k < inc_face.count; ++k) {
    const std::uint32_t v = inc_indices[inc_face.first + k];
    clip_point& p = s.polygon.append();
    p.position = incident.vertices[v];
    p.feature = face_clip_feature(b_is_reference, feature_kind::incident_vertex,
                                  std::uint32_t(reference_face), 0, v);
    p.along = std::int32_t(v);
  }

  // The side planes: through each edge of the reference face, normal
  // (edge × n) pointing out of the face (its corners run counter-clockwise
  // about n). Unnormalized: clipping needs only the ratio of distances.
  const auto& ref_face = reference.shape->faces[reference_face];
  const auto& ref_indices = reference.shape->vertex_indices;
  for (std::uint32_t k = 0; k < ref_face.count && s.polygon.count > 0; ++k) {
    const vec3& p = reference.vertices[ref_indices[ref_face.first + k]];
    const vec3& q = reference.vertices[ref_indices[ref_face.first + (k + 1) % ref_face.count]];
    const vec3 side_normal = cross(q - p, n);
    clip_by_side(s.polygon, side_normal, dot(side_normal, p), k, b_is_reference,
                 std::uint32_t(reference_face), s.clipped);
    std::swap(s.polygon, s.clipped);
  }

  s.candidates.reset(s.polygon.count);
  for (std::size_t i = 0; i < s.polygon.count; ++i) {
    const clip_point& p = s.polygon[i];
    const real gap = dot(n, p.position) - offset;
    if (gap > margin) continue;
    candidate& k = s.candidates.append();
    k.position = p.position, k.gap = gap, k.feature = p.feature;
  }
  if (s.candidates.count == 0) return;
  // n is the reference body's outward normal: from A towards B when A's
  // face is the reference.
  emit(s.candidates, n, world.rotate(b_is_reference ? n : -n), world, out);
}

// One point: the incident body's corner deepest under the reference face.
void deepest_corner_contact(const polyhedron_data& reference, const polyhedron_data& incident,
                            int reference_face, bool b_is_reference, const rigid_frame& world,
                            contact_manifold& out) {
  const vec3& n = reference.normals[reference_face];
  std::size_t deepest = 0;
  for (std::size_t v = 1; v < incident.vertices.size(); ++v) {
    if (dot(n, incident.vertices[v]) < dot(n, incident.vertices[deepest])) deepest = v;
  }
  const real gap = dot(n, incident.vertices[deepest]) - reference.offsets[reference_face];
  set_point(out.points[0], world.to_world(incident.vertices[deepest] - (real(0.5) * gap) * n),
            world.rotate(b_is_reference ? n : -n), -gap,
            face_clip_feature(b_is_reference, feature_kind::incident_vertex,
                              std::uint32_t(reference_face), 0, std::uint32_t(deepest)));
  out.count = 1;
}

// The nearest points of segments p1 q1 and p2 q2 as parameters (s, t): the
// nearest points of the two lines, then clamped to the segments, each
// clamp followed by the other segment's best answer to it.
std::array<real, 2> nearest_on_segments(const vec3& p1, const vec3& q1, const vec3& p2,
                                        const vec3& q2) {
  const vec3 d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
  const real a = dot(d1, d1), e = dot(d2, d2), b = dot(d1, d2);
  const real c = dot(d1, r), f = dot(d2, r);
  const real denominator = a * e - b * b;
  auto clamp01 = [](real x) { return std::clamp(x, real(0), real(1)); };
  real s = denominator > 0 ? clamp01((b * f - c * e) / denominator) : 0;
  real t = e > 0 ? (b * s + f) / e : 0;
  if (t < 0) {
    t = 0;
    s = a > 0 ? clamp01(-c / a) : 0;
  } else if (t > 1) {
    t = 1;
    s = a > 0 ? clamp01((b - c) / a) : 0;
  }
  return {s, t};
}

// Edge of A against edge of B: one point, midway between their nearest
// points; the normal is the axis (from A towards B) reversed.
void edge_contact(const polyhedron_data& a, const polyhedron_data& b, const edge_query& q,
                  const rigid_frame& world, contact_manifold& out) {
  const polyhedron_edge& ea = a.shape->edges[q.edge_a];
  const polyhedron_edge& eb = b.shape->edges[q.edge_b];
  const vec3 &pa = a.vertices[ea.tail], &qa = a.vertices[ea.head];
  const vec3 &pb = b.vertices[eb.tail], &qb = b.vertices[eb.head];
  const auto [s, t] = nearest_on_segments(pa, qa, pb, qb);
  const vec3 on_a = pa + s * (qa - pa), on_b = pb + t * (qb - pb);
  const vec3 midway = real(0.5) * (on_a + on_b);
  set_point(out.points[0], world.to_world(midway), world.rotate(-q.axis), -q.gap,
            edge_pair_feature(std::uint32_t(q.edge_a), std::uint32_t(q.edge_b)));
  out.count = 1;
}

// How much deeper an edge pair's axis must be than the best face axis
// before the contact is made from the edges, and B's face than A's before
// B's face becomes the reference: a small bias, so that a face resting on
// a face does not flicker between face and edge contacts (or between its
// two reference faces) with rounding. 0.2% of the smaller shape.
real axis_bias(const placed_shape& a, const placed_shape& b) {
  return real(0.002) * std::min(a.polyhedron->bounding_radius, b.polyhedron->bounding_radius);
}

// The inverse of a shape's pose x -> c + R x ~R as a c3ga motor, ~R ~T with
// T = 1 - c ni / 2: it moves world objects into the shape's frame.
conformal::motor world_to_shape(const placed_shape& s) {
  const rotor& r = s.attitude;
  const conformal::rotor undo_turn{r.c[0], -r.c[1], -r.c[2], -r.c[3]};
  const conformal::translator undo_shift{1, real(0.5) * s.center.c[0], real(0.5) * s.center.c[1],
                                         real(0.5) * s.center.c[2]};
  return c3ga::gp(undo_turn, undo_shift);
}

// A plane shape as the dual plane n + d ni in the polyhedron's frame: the
// signed height of a point x over it is the inner product of x's
// normalized conformal point with it, n.x - d.
struct local_plane {
  vec3 normal;
  real offset;
};
local_plane plane_in_frame_of(const placed_shape& polyhedron, const placed_shape& plane) {
  const conformal::dual_plane world{plane.normal.c[0], plane.normal.c[1], plane.normal.c[2],
                                    plane.offset};
  const conformal::dual_plane local = c3ga::apply(world_to_shape(polyhedron), world);
  return {{local.c[0], local.c[1], local.c[2]}, local.c[3]};
}

// The nearest point of a polyhedron (its own frame) to a point x: outside,
// on the faces x is above of (the nearest point lies on one of them); inside,
// x's projection on the face it is least deep under.
struct nearest_point {
  vec3 point;
  vec3 normal;      // unit, from the polyhedron towards x
  real signed_gap;  // |x - point| outside, minus the depth inside
};
nearest_point nearest_on_polyhedron(const convex_polyhedron& p, const vec3& x) {
  int shallowest = 0;
  real highest = -infinity;
  for (std::size_t f = 0; f < p.faces.size(); ++f) {
    const real height = dot(to_vec3(p.faces[f].normal), x) - p.faces[f].offset;
    if (height > highest) highest = height, shallowest = int(f);
  }
  if (!(highest > 0)) {
    const vec3 n = to_vec3(p.faces[shallowest].normal);
    return {x - highest * n, n, highest};
  }
  vec3 nearest;
  real nearest_squared = infinity;
  for (const polyhedron_face& face : p.faces) {
    const vec3 n = to_vec3(face.normal);
    const real height = dot(n, x) - face.offset;
    if (!(height > 0)) continue;
    const vec3 projected = x - height * n;
    bool inside = true;
    for (std::uint32_t k = 0; k < face.count && inside; ++k) {
      const vec3 v = to_vec3(p.vertices[p.vertex_indices[face.first + k]]);
      const vec3 w = to_vec3(p.vertices[p.vertex_indices[face.first + (k + 1) % face.count]]);
      inside = dot(cross(w - v, n), projected - v) <= 0;
    }
    if (inside) {
      if (height * height < nearest_squared) nearest_squared = height * height, nearest = projected;
      continue;
    }
    for (std::uint32_t k = 0; k < face.count; ++k) {
      const vec3 v = to_vec3(p.vertices[p.vertex_indices[face.first + k]]);
      const vec3 w = to_vec3(p.vertices[p.vertex_indices[face.first + (k + 1) % face.count]]);
      const vec3 edge = w - v;
      const real t = std::clamp(dot(x - v, edge) / dot(edge, edge), real(0), real(1));
      const vec3 on_edge = v + t * edge;
      const vec3 d = x - on_edge;
      if (dot(d, d) < nearest_squared) nearest_squared = dot(d, d), nearest = on_edge;
    }
  }
  const real distance = std::sqrt(nearest_squared);
  return {nearest, (1 / distance) * (x - nearest), distance};
}

// The sphere's centre in the polyhedron's frame, moved as a conformal point
// by the motor, and the sphere's radius (0 for a point shape).
nearest_point sphere_against_polyhedron(const placed_shape& polyhedron, const placed_shape& sphere,
                                        real& radius) {
  const vec3 c = to_vec3(sphere.center);
  const conformal::normalized_point world{c.x, c.y, c.z, real(0.5) * dot(c, c)};
  const conformal::normalized_point local = c3ga::apply(world_to_shape(polyhedron), world);
  radius = sphere.kind == shape_kind::sphere ? sphere.radius : 0;
  return nearest_on_polyhedron(*polyhedron.polyhedron, {local.c[0], local.c[1], local.c[2]});
}

}  // namespace

void collide_polyhedra(const placed_shape& a, const placed_shape& b, real margin,
                       contact_manifold& out) {
  out.count = 0;
  scratch_space& s = scratch();
  rigid_frame world;
  sat_result sat;
  if (!test_pair(a, b, margin, s, world, sat) || sat.apart) return;
  // No face was chosen only when every gap is NaN: a pose gone NaN (a
  // finite but huge angular velocity overflows the attitude) meets nothing.
  if (sat.face_a.face < 0 || sat.face_b.face < 0) return;

  const real bias = axis_bias(a, b);
  const bool b_is_reference = sat.face_b.gap > sat.face_a.gap + bias;
  const real face_gap = std::max(sat.face_a.gap, sat.face_b.gap);
  // Faces are the rule; the edges only when clearly deeper, or when the
  // face's clipped polygon holds no point within the margin (then the
  // edges' axis, within the bias of the face's, is the one that separates).
  const polyhedron_data& reference = b_is_reference ? s.b : s.a;
  const polyhedron_data& incident = b_is_reference ? s.a : s.b;
  const int reference_face = b_is_reference ? sat.face_b.face : sat.face_a.face;
  if (!(sat.edge.gap > face_gap + bias)) {
    face_contact(reference, incident, reference_face, b_is_reference, margin, world, s, out);
  }
  if (out.count > 0) return;
  if (sat.edge.gap > face_gap - bias) {
    find_box_edges(a, b, sat.edge);
    edge_contact(s.a, s.b, sat.edge, world, out);
  } else if (!(face_gap > 0)) {
    // Overlapping, yet the clipped face kept nothing (a face chosen within
    // the bias of a better axis can miss): the incident body's deepest
    // corner under the reference face, rather than no contact.
    deepest_corner_contact(reference, incident, reference_face, b_is_reference, world, out);
  }
}

void collide_polyhedron_plane(const placed_shape& polyhedron, const placed_shape& plane,
                              real margin, contact_manifold& out) {
  out.count = 0;
  const local_plane p = plane_in_frame_of(polyhedron, plane);
  const auto& vertices = polyhedron.polyhedron->vertices;
  scratch_space& s = scratch();
  s.candidates.reset(vertices.size());
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    const vec3 v = to_vec3(vertices[i]);
    const real gap = dot(p.normal, v) - p.offset;
    if (gap > margin) continue;
    candidate& k = s.candidates.append();
    k.position = v, k.gap = gap, k.feature = std::uint32_t(i);
  }
  if (s.candidates.count == 0) return;
  drop_shadowed(s.candidates, p.normal);
  // The plane is B; its normal points out of its solid, towards A.
  emit(s.candidates, p.normal, to_vec3(plane.normal),
       frame_of(polyhedron.attitude, polyhedron.center), out);
}

void collide_polyhedron_sphere(const placed_shape& polyhedron, const placed_shape& sphere,
                               real margin, contact_manifold& out) {
  out.count = 0;
  real radius = 0;
  const nearest_point n = sphere_against_polyhedron(polyhedron, sphere, radius);
  const real gap = n.signed_gap - radius;
  if (gap > margin) return;
  const rigid_frame frame = frame_of(polyhedron.attitude, polyhedron.center);
  // Midway between the polyhedron's nearest point and the sphere's deepest.
  const vec3 sphere_side = n.point + (n.signed_gap - radius) * n.normal;
  const vec3 midway = real(0.5) * (n.point + sphere_side);
  set_point(out.points[0], frame.to_world(midway), frame.rotate(-n.normal), -gap, 0);
  out.count = 1;
}

separation polyhedra_separation(const placed_shape& a, const placed_shape& b) {
  scratch_space& s = scratch();
  rigid_frame world;
  sat_result sat;
  // Overlapping or touching: the deepest axis, unbiased, is the exact least
  // translation (every face of A - B was tried).
  if (test_pair(a, b, 0, s, world, sat) && !sat.apart) {
    vec3 axis = -s.a.normals[sat.face_a.face];  // from B towards A
    real gap = sat.face_a.gap;
    if (sat.face_b.gap > gap) gap = sat.face_b.gap, axis = s.b.normals[sat.face_b.face];
    if (sat.edge.gap > gap) gap = sat.edge.gap, axis = -sat.edge.axis;
    return {gap, to_vector(world.rotate(axis))};
  }
  const gjk_result r =
      gjk_distance(polyhedron_support(a), polyhedron_support(b), a.center - b.center);
  // Apart by an axis yet touching to GJK: rounding; the centres' line will do.
  if (!(r.distance > 0)) return {0, e3ga::unit(a.center - b.center)};
  return {r.distance, r.normal};
}

separation polyhedron_plane_separation(const placed_shape& polyhedron, const placed_shape& plane) {
  const local_plane p = plane_in_frame_of(polyhedron, plane);
  real lowest = infinity;
  for (const vector& v : polyhedron.polyhedron->vertices) {
    lowest = std::min(lowest, dot(p.normal, to_vec3(v)) - p.offset);
  }
  return {lowest, plane.normal};
}

separation polyhedron_sphere_separation(const placed_shape& polyhedron,
                                        const placed_shape& sphere) {
  real radius = 0;
  const nearest_point n = sphere_against_polyhedron(polyhedron, sphere, radius);
  const rigid_frame frame = frame_of(polyhedron.attitude, polyhedron.center);
  return {n.signed_gap - radius, to_vector(frame.rotate(-n.normal))};
}

}  // namespace gaphys::detail
