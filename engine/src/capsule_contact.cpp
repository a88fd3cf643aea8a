#include "capsule_contact.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "precision.hpp"
#include "round_meet.hpp"
#include "vec3.hpp"

namespace gaphys::detail {

namespace {

// Two segments within this sine of parallel lie alongside each other (about
// 0.6°): their contact is a line, held by two points at its ends.
constexpr real parallel_sine = real(0.01);
// A contact normal within this cosine of a face's normal (about 0.8°) is
// that face's: a capsule lying on it, or across it with both ends hanging
// over its edges, rests on two points.
constexpr real face_alignment = real(0.9999);
// Inside a polyhedron an edge's axis wins over the best face's only when it
// is clearly shallower, so that a capsule resting on a face near an edge
// does not flicker between the two.
constexpr real edge_preference = real(0.95);
// An edge within this sine of the segment's direction makes no axis: the
// face of the Minkowski difference it would bound is a sliver whose normal
// rounding cannot give (it errs by ~1e-16 / sine), and leaving it out errs
// by at most this sine times the segment's length.
const real edge_axis_sine = by_precision(1e-8, 3e-4);

real clamp01(real x) { return std::clamp(x, real(0), real(1)); }

// Any unit vector orthogonal to the unit vector u.
vec3 orthogonal_to(const vec3& u) {
  const vec3 other = std::fabs(u.x) < real(0.6) ? vec3{1, 0, 0} : vec3{0, 1, 0};
  const vec3 v = cross(u, other);
  return (1 / length(v)) * v;
}

// A capsule's core: the segment from `start` (its centre - h axis, end 0) to
// `end` (centre + h axis, end 1).
struct segment3 {
  vec3 start, end;
  vec3 delta() const { return end - start; }
  vec3 at(real s) const { return start + s * (end - start); }
};

segment3 core_of(const placed_shape& capsule) {
  const vec3 centre = to_vec3(capsule.center);
  const vec3 half = capsule.half_height * to_vec3(capsule.axis);
  return {centre - half, centre + half};
}

// Which part of a segment a parameter names: its end 0, its end 1, or a
// point inside it (feature ids).
std::uint32_t segment_part(real s) { return s <= 0 ? 0 : (s >= 1 ? 1 : 2); }

// The parameter s in [0, 1] of the point of p + s u nearest x.
real nearest_parameter(const vec3& p, const vec3& u, const vec3& x) {
  const real squared = dot(u, u);
  return squared > 0 ? clamp01(dot(x - p, u) / squared) : 0;
}

// The nearest points of the segments p + s u and q + t v, s and t in [0, 1].
// With w = p - q, |w + s u - t v|^2 is least on the lines where
// u . (w + s u - t v) = 0 and v . (w + s u - t v) = 0, at
//   s = (b e - c d) / (a c - b^2),  a = u.u, b = u.v, c = v.v, d = u.w, e = v.w,
// which Lagrange's identity ((x × y) . (z × t) = (x.z)(y.t) - (x.t)(y.z))
// turns into s = (u × v) . (v × w) / |u × v|^2: cross products keep their
// precision when the segments are nearly parallel, where a c - b^2 cancels.
// Clamped to [0, 1], s gives the nearest t = (b s + e) / c on the other;
// when that t is off its segment it clamps, and s becomes the point nearest
// that end. The squared distance is convex on the square, so this ends at
// its minimum.
struct parameter_pair {
  real s, t;
};
parameter_pair nearest_parameters(const vec3& p, const vec3& u, const vec3& q, const vec3& v) {
  const vec3 w = p - q;
  const real a = dot(u, u), b = dot(u, v), c = dot(v, v), d = dot(u, w), e = dot(v, w);
  if (!(a > 0)) return {0, c > 0 ? clamp01(e / c) : 0};
  if (!(c > 0)) return {clamp01(-d / a), 0};
  const vec3 normal = cross(u, v);
  const real sine_square = dot(normal, normal);  // |u|^2 |v|^2 sin^2
  // Parallel segments: every s is as near as any; take the first's start.
  real s = sine_square > real(1e-30) * a * c ? clamp01(dot(normal, cross(v, w)) / sine_square) : 0;
  real t = (b * s + e) / c;
  if (t < 0) {
    t = 0;
    s = clamp01(-d / a);
  } else if (t > 1) {
    t = 1;
    s = clamp01((b - d) / a);
  }
  return {s, t};
}

contact_point make_point(const vec3& point, const vec3& normal, real depth, std::uint32_t feature) {
  return contact_point{contact_geometry{to_vector(point), to_vector(normal), depth, 0}, feature};
}

// ---------------------------------------------------------------------------
// Round shapes: spheres, points, planes.

// A capsule and a sphere or a point: of the capsule's balls, the one centred
// at the segment's point nearest the other's centre is the first to touch,
// and the pair is that ball's and the other's meet (thesis 4.2.1, as
// find_contact does it), kept when they overlap, touch or are apart by at
// most `margin`. find_contact keeps an apart pair when the shapes' speeds
// close the gap within its lookahead; a gap of at most `margin` is one the
// ball closes within `margin` seconds coming at unit speed along the line of
// centres. The meet gives the normal and the depth; the point is then put
// midway between the two surfaces, as for every non-round pair, rather than
// at the centre of the meet's circle: the solver takes a capsule's lever
// arms from it, and a point sunk by the depth into the capsule would have it
// roll on a radius short by that depth.
void collide_round(const placed_shape& capsule, const placed_shape& round, real margin,
                   contact_manifold& out) {
  const segment3 core = core_of(capsule);
  const vec3 centre = to_vec3(round.center);
  const vec3 nearest = core.at(nearest_parameter(core.start, core.delta(), centre));
  const vec3 offset = nearest - centre;
  const real distance = length(offset);
  const vec3 towards_ball = distance > 0 ? (1 / distance) * offset : vec3{};
  const placed_shape ball =
      place(shape::sphere(capsule.radius), to_vector(nearest), rotor{1, 0, 0, 0});
  const auto met = find_contact(ball, round, margin, -to_vector(towards_ball), vector{});
  if (!met) return;
  const vec3 normal = to_vec3(met->normal);
  const vec3 midway = nearest - (capsule.radius - real(0.5) * met->depth) * normal;
  out.points[0] = make_point(midway, normal, met->depth, 0);
  out.points[0].geometry.squared_radius = met->squared_radius;
  out.count = 1;
}

// A capsule and a plane: the balls at its two ends. The plane's dual is
// Π = -(n + δ ni) (dual_of), so an end's conformal point X = no + x + x^2/2
// ni has X . Π = δ - n . x, its depth under the plane's surface, and its
// ball's depth is r + X . Π. Both ends when both are within the margin (a
// capsule lying on the plane), else the lower one; the point is midway
// between the ball's surface x - r n and the plane's. Feature id = which end.
void collide_plane(const placed_shape& capsule, const placed_shape& plane, real margin,
                   contact_manifold& out) {
  const segment3 core = core_of(capsule);
  // (A dual plane: its no coefficient is 0.)
  const conformal::dual_sphere dual(detail::dual_plane_of(plane, vector{}));
  const vec3 n = to_vec3(plane.normal);
  const int ends = capsule.half_height > 0 ? 2 : 1;
  for (int end = 0; end < ends; ++end) {
    const vec3& x = end == 0 ? core.start : core.end;
    const conformal::normalized_point point{x.x, x.y, x.z, real(0.5) * dot(x, x)};
    const real depth = capsule.radius + c3ga::scp(point, dual);
    if (!(depth >= -margin)) continue;
    const vec3 midway = x - (capsule.radius - real(0.5) * depth) * n;
    out.points[out.count++] = make_point(midway, n, depth, std::uint32_t(end));
  }
}

// ---------------------------------------------------------------------------
// Two capsules.

// Feature ids of capsule pairs: one point, segment_part(s) | segment_part(t)
// << 2 (0 to 10); two points alongside, 16 + which end bounds the overlap: 0
// or 1 A's own ends, 2 or 3 B's.
constexpr std::uint32_t alongside_id = 16;

// Whether two points at the ends of a stretch hold a line contact whose
// nearest points have depth `deepest`: both within the margin, and one as
// deep as the nearest points (segments that cross at a small angle are
// deepest between the ends, and take one point there instead).
bool hold_line(const contact_point (&points)[2], real deepest, real scale, real margin) {
  const real lower = std::min(points[0].geometry.depth, points[1].geometry.depth);
  const real upper = std::max(points[0].geometry.depth, points[1].geometry.depth);
  return lower >= -margin && upper >= deepest - by_precision(1e-9, 1e-4) * scale;
}

// Capsules alongside each other: the stretch of A's segment over which B's
// lies (B's ends projected on A's axis, clipped to A's), its two ends each a
// point with its own depth along the common normal. Fills `out` only when
// they hold the line (hold_line).
bool collide_alongside(const placed_shape& a, const placed_shape& b, const segment3& core_b,
                       const vec3& normal, real deepest, real margin, contact_manifold& out) {
  const vec3 centre = to_vec3(a.center), axis = to_vec3(a.axis);
  const real start_b = dot(core_b.start - centre, axis), end_b = dot(core_b.end - centre, axis);
  const bool b_ascends = start_b <= end_b;
  real lower = -a.half_height, upper = a.half_height;
  std::uint32_t lower_id = 0, upper_id = 1;
  if (std::min(start_b, end_b) > lower)
    lower = std::min(start_b, end_b), lower_id = b_ascends ? 2 : 3;
  if (std::max(start_b, end_b) < upper)
    upper = std::max(start_b, end_b), upper_id = b_ascends ? 3 : 2;
  if (!(upper - lower > by_precision(1e-9, 1e-4) * (a.half_height + b.half_height))) return false;

  const real reach = a.radius + b.radius;
  const real along[2] = {lower, upper};
  const std::uint32_t ids[2] = {lower_id, upper_id};
  contact_point points[2];
  for (int i = 0; i < 2; ++i) {
    const vec3 on_a = centre + along[i] * axis;
    const vec3 on_b = core_b.at(nearest_parameter(core_b.start, core_b.delta(), on_a));
    const real depth = reach - dot(normal, on_a - on_b);
    const vec3 midway = real(0.5) * ((on_a - a.radius * normal) + (on_b + b.radius * normal));
    points[i] = make_point(midway, normal, depth, alongside_id + ids[i]);
  }
  if (!hold_line(points, deepest, reach + a.half_height + b.half_height, margin)) return false;
  out.points[0] = points[0];
  out.points[1] = points[1];
  out.count = 2;
  return true;
}

// The nearest points of two capsules' segments and the normal between them
// (from B's to A's); for crossing segments the normal of the plane they span,
// for overlapping collinear ones any direction across A's axis.
struct segment_gap {
  vec3 on_a, on_b, normal;
  real s, t, distance;
};
segment_gap nearest_cores(const placed_shape& a, const segment3& core_a, const segment3& core_b) {
  const parameter_pair st =
      nearest_parameters(core_a.start, core_a.delta(), core_b.start, core_b.delta());
  segment_gap gap{core_a.at(st.s), core_b.at(st.t), {}, st.s, st.t, 0};
  const vec3 offset = gap.on_a - gap.on_b;
  gap.distance = length(offset);
  if (gap.distance > 0) {
    gap.normal = (1 / gap.distance) * offset;
    return gap;
  }
  const vec3 axis_a = to_vec3(a.axis);
  const vec3 across = cross(axis_a, core_b.delta());
  const real across_length = length(across);
  gap.normal = across_length > by_precision(1e-12, 1e-5) * length(core_b.delta())
                   ? (1 / across_length) * across
                   : orthogonal_to(axis_a);
  return gap;
}

void collide_capsules(const placed_shape& a, const placed_shape& b, real margin,
                      contact_manifold& out) {
  const segment3 core_a = core_of(a), core_b = core_of(b);
  const segment_gap gap = nearest_cores(a, core_a, core_b);
  const real depth = a.radius + b.radius - gap.distance;
  if (!(depth >= -margin)) return;
  const real sine = length(cross(to_vec3(a.axis), to_vec3(b.axis)));
  if (sine <= parallel_sine && a.half_height > 0 && b.half_height > 0 &&
      collide_alongside(a, b, core_b, gap.normal, depth, margin, out))
    return;
  const vec3 midway =
      real(0.5) * ((gap.on_a - a.radius * gap.normal) + (gap.on_b + b.radius * gap.normal));
  out.points[0] =
      make_point(midway, gap.normal, depth, segment_part(gap.s) | (segment_part(gap.t) << 2));
  out.count = 1;
}

// ---------------------------------------------------------------------------
// A capsule and a polyhedron (box or convex hull), in the polyhedron's frame.
//
// A face is the dual plane π = n + δ ni: a point's height above it is the
// inner product X . π = n . x - δ of its conformal point X with π, written
// out below on plain coordinates (as the other loops here; see vec3.hpp).

// Feature ids of capsule-polyhedron points:
//   bits 0-1   the capsule's part: 0 or 1 its end at -h or +h along its axis,
//              or the lower or upper end of the stretch of it that was
//              clipped; 2 a point inside the segment;
//   bits 2-11  what clipped it there: 0 nothing, 1 + k side k of the face,
//              for an edge 1 its tail, 2 its head;
//   bits 12-13 the polyhedron's feature: 1 a face, 2 an edge, 3 a corner;
//   bits 14-31 its index.
enum : std::uint32_t { face_feature = 1, edge_feature = 2, corner_feature = 3 };
std::uint32_t polyhedron_feature(std::uint32_t kind, std::uint32_t index) {
  return (kind << 12) | (index << 14);
}
std::uint32_t feature_id(std::uint32_t polyhedron, std::uint32_t clip, std::uint32_t part) {
  return polyhedron | ((clip & 0x3ffu) << 2) | part;
}

vec3 vertex(const convex_polyhedron& p, std::uint32_t index) { return to_vec3(p.vertices[index]); }
vec3 face_corner(const convex_polyhedron& p, const polyhedron_face& f, std::uint32_t k) {
  return vertex(p, p.vertex_indices[f.first + k % f.count]);
}
real height_above(const polyhedron_face& f, const vec3& x) {
  return dot(to_vec3(f.normal), x) - f.offset;
}

// Whether x lies within the face's side planes (the planes through its
// sides, orthogonal to it): side k from corner k to k + 1 keeps the points
// x with (n x (v[k+1] - v[k])) . (x - v[k]) >= 0, the corners running
// counter-clockwise about n.
bool over_face(const convex_polyhedron& p, const polyhedron_face& f, const vec3& x) {
  const vec3 n = to_vec3(f.normal);
  for (std::uint32_t k = 0; k < f.count; ++k) {
    const vec3 corner = face_corner(p, f, k);
    if (dot(cross(n, face_corner(p, f, k + 1) - corner), x - corner) < 0) return false;
  }
  return true;
}

// The separating-axis test of the segment against the polyhedron. Along a
// unit axis u, the segment runs into the polyhedron by
//   overlap(u) = max over P of u . x - min over the segment of u . x,
// which is the support of the Minkowski difference D = P - segment along u.
// The segment and P are apart exactly when some face of D has overlap < 0,
// and when they meet, the least overlap over D's faces is how far the
// segment must move to leave P (its penetration depth). D's faces are P's
// faces and, for each edge of P, the parallelogram of that edge and the
// segment, with normal ±(edge x segment direction) when that direction lies
// in the edge's normal cone (between its two faces' normals), where the
// edge is P's support.
struct axis_overlap {
  real overlap = infinity;
  vec3 axis{};              // unit, outward of P
  std::uint32_t index = 0;  // the face or the edge
};
struct segment_axes {
  axis_overlap face, edge;
  const axis_overlap& least() const { return edge.overlap < face.overlap ? edge : face; }
};

segment_axes overlap_axes(const convex_polyhedron& p, const segment3& core, const vec3& direction) {
  segment_axes best;
  for (std::uint32_t i = 0; i < p.faces.size(); ++i) {
    const polyhedron_face& f = p.faces[i];
    const vec3 n = to_vec3(f.normal);
    const real overlap = f.offset - std::min(dot(n, core.start), dot(n, core.end));
    if (overlap < best.face.overlap) best.face = {overlap, n, i};
  }
  for (std::uint32_t i = 0; i < p.edges.size(); ++i) {
    const polyhedron_edge& e = p.edges[i];
    const vec3 tail = vertex(p, e.tail), head = vertex(p, e.head);
    vec3 axis = cross(head - tail, direction);
    const real axis_length = length(axis);  // |edge| sin(angle to the segment)
    if (!(axis_length > edge_axis_sine * length(head - tail))) continue;
    axis = (1 / axis_length) * axis;
    // In the cone between the unit normals l and r, whose bisector is l + r:
    // at an angle from the bisector at most half theirs, u . (l + r) >= 1 + l . r.
    const vec3 left = to_vec3(p.faces[e.left].normal), right = to_vec3(p.faces[e.right].normal);
    const vec3 bisector = left + right;
    if (dot(axis, bisector) < 0) axis = -axis;
    if (dot(axis, bisector) < 1 + dot(left, right) - by_precision(1e-12, 1e-5)) continue;
    const real overlap = std::max(dot(axis, tail), dot(axis, head)) -
                         std::min(dot(axis, core.start), dot(axis, core.end));
    if (overlap < best.edge.overlap) best.edge = {overlap, axis, i};
  }
  return best;
}

// The nearest points of a segment and a polyhedron that it does not meet.
// They pair an end of the segment with a face it stands over, or the
// segment with an edge or a corner (when the segment's nearest point is
// inside it and P's inside a face, the segment is parallel to that face and
// an end or an edge is as near). The nearest edge within parallel_sine of
// the segment's direction is kept too, for a capsule lying along an edge.
struct polyhedron_gap {
  real distance = infinity;
  vec3 on_segment{}, on_polyhedron{};
  real s = 0;  // the point's parameter on the segment
  std::uint32_t feature = 0;
  real parallel_distance = infinity;
  std::uint32_t parallel_edge = 0;
};

polyhedron_gap nearest_to_polyhedron(const convex_polyhedron& p, const segment3& core) {
  polyhedron_gap gap;
  const auto consider = [&gap](const vec3& x, real s, const vec3& y, std::uint32_t feature) {
    const real distance = length(x - y);
    if (distance < gap.distance) {
      gap.distance = distance, gap.on_segment = x, gap.on_polyhedron = y;
      gap.s = s, gap.feature = feature;
    }
    return distance;
  };
  for (int end = 0; end < 2; ++end) {
    const vec3& x = end == 0 ? core.start : core.end;
    for (std::uint32_t i = 0; i < p.faces.size(); ++i) {
      const polyhedron_face& f = p.faces[i];
      const real height = height_above(f, x);
      if (height > 0 && over_face(p, f, x))
        consider(x, real(end), x - height * to_vec3(f.normal), polyhedron_feature(face_feature, i));
    }
  }
  const vec3 delta = core.delta();
  const real segment_length = length(delta);
  for (std::uint32_t i = 0; i < p.edges.size(); ++i) {
    const polyhedron_edge& e = p.edges[i];
    const vec3 tail = vertex(p, e.tail), edge = vertex(p, e.head) - tail;
    const parameter_pair st = nearest_parameters(core.start, delta, tail, edge);
    const std::uint32_t feature = st.t <= 0   ? polyhedron_feature(corner_feature, e.tail)
                                  : st.t >= 1 ? polyhedron_feature(corner_feature, e.head)
                                              : polyhedron_feature(edge_feature, i);
    const real distance = consider(core.at(st.s), st.s, tail + st.t * edge, feature);
    if (distance < gap.parallel_distance &&
        length(cross(edge, delta)) <= parallel_sine * length(edge) * segment_length)
      gap.parallel_distance = distance, gap.parallel_edge = i;
  }
  return gap;
}

// The stretch of the segment over face f (inside all its side planes, as in
// over_face; parameters s in [lower, upper]) and the sides that cut it.
struct clipped_stretch {
  real lower = 0, upper = 1;
  std::uint32_t lower_side = 0, upper_side = 0;  // 0 the segment's own end, 1 + k side k
  bool empty = false;
};

clipped_stretch clip_to_face(const convex_polyhedron& p, const polyhedron_face& f,
                             const segment3& core) {
  clipped_stretch stretch;
  const vec3 n = to_vec3(f.normal);
  for (std::uint32_t k = 0; k < f.count; ++k) {
    const vec3 corner = face_corner(p, f, k);
    const vec3 inward = cross(n, face_corner(p, f, k + 1) - corner);
    const real at_start = dot(inward, core.start - corner), at_end = dot(inward, core.end - corner);
    if (at_start < 0 && at_end < 0) {
      stretch.empty = true;
      return stretch;
    }
    if (at_start < 0) {
      const real s = at_start / (at_start - at_end);
      if (s > stretch.lower) stretch.lower = s, stretch.lower_side = 1 + k;
    } else if (at_end < 0) {
      const real s = at_start / (at_start - at_end);
      if (s < stretch.upper) stretch.upper = s, stretch.upper_side = 1 + k;
    }
  }
  stretch.empty = stretch.lower > stretch.upper;
  return stretch;
}

// The contact point of the capsule's ball at x with face f, along its
// normal n: depth r - height, midway between the ball's surface x - r n and
// the face's x - height n.
contact_point face_point(const polyhedron_face& f, std::uint32_t face, const vec3& x, real radius,
                         std::uint32_t clip, std::uint32_t part) {
  const vec3 n = to_vec3(f.normal);
  const real height = height_above(f, x);
  return make_point(x - real(0.5) * (radius + height) * n, n, radius - height,
                    feature_id(polyhedron_feature(face_feature, face), clip, part));
}

// A capsule on face f: the ends of its stretch over the face, those within
// the margin (one end when the segment is a point). Returns how many (0 to 2).
int face_contacts(const convex_polyhedron& p, std::uint32_t face, const segment3& core, real radius,
                  bool has_length, real margin, contact_manifold& out) {
  const polyhedron_face& f = p.faces[face];
  const clipped_stretch stretch = clip_to_face(p, f, core);
  out.count = 0;
  if (stretch.empty) return 0;
  const bool two_ends = has_length && stretch.upper - stretch.lower > by_precision(1e-9, 1e-4);
  const contact_point lower =
      face_point(f, face, core.at(stretch.lower), radius, stretch.lower_side, 0);
  const contact_point upper =
      face_point(f, face, core.at(stretch.upper), radius, stretch.upper_side, 1);
  if (lower.geometry.depth >= -margin) out.points[out.count++] = lower;
  if (two_ends && upper.geometry.depth >= -margin) out.points[out.count++] = upper;
  return out.count;
}

// A capsule lying along edge i (parallel within parallel_sine): the ends of
// the stretch of the segment beside the edge, each paired with its nearest
// point of the edge, depth along the normal. Fills `out` only when they hold
// the line (hold_line).
bool edge_contacts(const convex_polyhedron& p, std::uint32_t i, const segment3& core, real radius,
                   const vec3& normal, real deepest, real margin, contact_manifold& out) {
  const polyhedron_edge& e = p.edges[i];
  const vec3 tail = vertex(p, e.tail), edge = vertex(p, e.head) - tail;
  const vec3 delta = core.delta();
  const real squared = dot(delta, delta);
  const real at_tail = dot(tail - core.start, delta) / squared;
  const real at_head = dot(tail + edge - core.start, delta) / squared;
  real lower = 0, upper = 1;
  std::uint32_t lower_clip = 0, upper_clip = 0;  // 0 the segment's end, 1 the tail, 2 the head
  if (std::min(at_tail, at_head) > lower)
    lower = std::min(at_tail, at_head), lower_clip = at_tail <= at_head ? 1 : 2;
  if (std::max(at_tail, at_head) < upper)
    upper = std::max(at_tail, at_head), upper_clip = at_tail <= at_head ? 2 : 1;
  if (!(upper - lower > by_precision(1e-9, 1e-4))) return false;
  const real along[2] = {lower, upper};
  const std::uint32_t clips[2] = {lower_clip, upper_clip};
  contact_point points[2];
  for (std::uint32_t k = 0; k < 2; ++k) {
    const vec3 x = core.at(along[k]);
    const vec3 y = tail + nearest_parameter(tail, edge, x) * edge;
    points[k] =
        make_point(real(0.5) * ((x - radius * normal) + y), normal, radius - dot(normal, x - y),
                   feature_id(polyhedron_feature(edge_feature, i), clips[k], k));
  }
  if (!hold_line(points, deepest, radius + std::sqrt(squared), margin)) return false;
  out.points[0] = points[0];
  out.points[1] = points[1];
  out.count = 2;
  return true;
}

// The outward normal of P between its nearest point and the segment's;
// when they coincide (touching), the axis that separates them best.
vec3 gap_normal(const polyhedron_gap& gap, const segment_axes& axes) {
  if (gap.distance > 0) return (1 / gap.distance) * (gap.on_segment - gap.on_polyhedron);
  return axes.least().axis;
}

// The face whose outward normal is nearest `normal`.
std::uint32_t most_aligned_face(const convex_polyhedron& p, const vec3& normal, real& cosine) {
  std::uint32_t best = 0;
  cosine = -infinity;
  for (std::uint32_t i = 0; i < p.faces.size(); ++i) {
    const real c = dot(to_vec3(p.faces[i].normal), normal);
    if (c > cosine) cosine = c, best = i;
  }
  return best;
}

// The segment outside P, the capsule within the margin of it: two points
// when the capsule lies on a face (the normal is the face's) or along an
// edge, else one at the nearest points.
void collide_outside(const convex_polyhedron& p, const segment3& core, real radius, bool has_length,
                     const polyhedron_gap& gap, const segment_axes& axes, real margin,
                     contact_manifold& out) {
  const vec3 normal = gap_normal(gap, axes);
  if (has_length) {
    real cosine;
    const std::uint32_t face = most_aligned_face(p, normal, cosine);
    if (cosine >= face_alignment &&
        face_contacts(p, face, core, radius, has_length, margin, out) == 2)
      return;
    const real tie =
        gap.distance * by_precision(1e-9, 1e-4) + by_precision(1e-12, 1e-5) * p.bounding_radius;
    if (gap.parallel_distance <= gap.distance + tie &&
        edge_contacts(p, gap.parallel_edge, core, radius, normal, radius - gap.distance, margin,
                      out))
      return;
  }
  const vec3 midway = real(0.5) * ((gap.on_segment - radius * normal) + gap.on_polyhedron);
  out.points[0] = make_point(midway, normal, radius - gap.distance,
                             feature_id(gap.feature, 0, segment_part(gap.s)));
  out.count = 1;
}

// The segment inside P: the least-overlap axis, a face's unless an edge's is
// clearly shallower. On a face, the ends of the segment's stretch over it
// (those within the margin; a segment piercing the face leaves its deep end);
// across an edge, one point where the segment passes it.
void collide_inside(const convex_polyhedron& p, const segment3& core, real radius, bool has_length,
                    const segment_axes& axes, real margin, contact_manifold& out) {
  if (!(axes.edge.overlap < edge_preference * axes.face.overlap)) {
    const std::uint32_t face = axes.face.index;
    if (face_contacts(p, face, core, radius, has_length, margin, out) > 0) return;
    // Rounding left no stretch over the face: the deeper end alone.
    const vec3 n = axes.face.axis;
    const vec3& deeper = dot(n, core.start) <= dot(n, core.end) ? core.start : core.end;
    out.points[0] =
        face_point(p.faces[face], face, deeper, radius, 0, &deeper == &core.start ? 0 : 1);
    out.count = 1;
    return;
  }
  const polyhedron_edge& e = p.edges[axes.edge.index];
  const vec3 tail = vertex(p, e.tail), edge = vertex(p, e.head) - tail;
  const parameter_pair st = nearest_parameters(core.start, core.delta(), tail, edge);
  const vec3 n = axes.edge.axis;
  const vec3 midway = real(0.5) * ((core.at(st.s) - radius * n) + (tail + st.t * edge));
  out.points[0] = make_point(
      midway, n, radius + axes.edge.overlap,
      feature_id(polyhedron_feature(edge_feature, axes.edge.index), 0, segment_part(st.s)));
  out.count = 1;
}

// Whether the capsule is farther from the polyhedron than `margin` can
// bridge, by their bounding spheres.
bool beyond_reach(const placed_shape& capsule, const placed_shape& solid, real margin) {
  const vec3 offset = to_vec3(capsule.center) - to_vec3(solid.center);
  const real reach =
      capsule.half_height + capsule.radius + solid.polyhedron->bounding_radius + margin;
  return dot(offset, offset) > reach * reach;
}

segment3 to_local(const rigid_frame& frame, const segment3& s) {
  return {frame.to_local(s.start), frame.to_local(s.end)};
}

void collide_polyhedron(const placed_shape& capsule, const placed_shape& solid, real margin,
                        contact_manifold& out) {
  if (beyond_reach(capsule, solid, margin)) return;
  const convex_polyhedron& p = *solid.polyhedron;
  const rigid_frame frame = frame_of(solid.attitude, solid.center);
  const segment3 core = to_local(frame, core_of(capsule));
  const vec3 direction = frame.unrotate(to_vec3(capsule.axis));
  const bool has_length = capsule.half_height > 0;
  const segment_axes axes = overlap_axes(p, core, direction);
  if (axes.least().overlap > 0) {
    collide_inside(p, core, capsule.radius, has_length, axes, margin, out);
  } else {
    const polyhedron_gap gap = nearest_to_polyhedron(p, core);
    if (!(gap.distance <= capsule.radius + margin)) return;
    collide_outside(p, core, capsule.radius, has_length, gap, axes, margin, out);
  }
  for (int i = 0; i < out.count; ++i) {
    contact_geometry& g = out.points[i].geometry;
    g.point = to_vector(frame.to_world(to_vec3(g.point)));
    g.normal = to_vector(frame.rotate(to_vec3(g.normal)));
  }
}

separation polyhedron_separation(const placed_shape& capsule, const placed_shape& solid) {
  const convex_polyhedron& p = *solid.polyhedron;
  const rigid_frame frame = frame_of(solid.attitude, solid.center);
  const segment3 core = to_local(frame, core_of(capsule));
  const segment_axes axes = overlap_axes(p, core, frame.unrotate(to_vec3(capsule.axis)));
  const axis_overlap& least = axes.least();
  if (least.overlap > 0)
    return {-(least.overlap + capsule.radius), to_vector(frame.rotate(least.axis))};
  const polyhedron_gap gap = nearest_to_polyhedron(p, core);
  return {gap.distance - capsule.radius, to_vector(frame.rotate(gap_normal(gap, axes)))};
}

// ---------------------------------------------------------------------------

// The capsule's contacts with the other shape, normal towards the capsule.
void collide_with(const placed_shape& capsule, const placed_shape& other, real margin,
                  contact_manifold& out) {
  switch (other.kind) {
    case shape_kind::sphere:
    case shape_kind::point:
      collide_round(capsule, other, margin, out);
      return;
    case shape_kind::plane:
      collide_plane(capsule, other, margin, out);
      return;
    case shape_kind::capsule:
      collide_capsules(capsule, other, margin, out);
      return;
    case shape_kind::box:
    case shape_kind::convex_hull:
      collide_polyhedron(capsule, other, margin, out);
      return;
  }
}

// The separation of the capsule and the other shape, normal towards the
// capsule: the distance from its segment less the radii, or the depth of
// its lowest end below a plane, or the polyhedron's exact value.
separation separation_from(const placed_shape& capsule, const placed_shape& other) {
  const segment3 core = core_of(capsule);
  switch (other.kind) {
    case shape_kind::sphere:
    case shape_kind::point: {
      const vec3 centre = to_vec3(other.center);
      const vec3 offset = core.at(nearest_parameter(core.start, core.delta(), centre)) - centre;
      const real distance = length(offset);
      const vec3 normal =
          distance > 0 ? (1 / distance) * offset : orthogonal_to(to_vec3(capsule.axis));
      const real other_radius = other.kind == shape_kind::sphere ? other.radius : 0;
      return {distance - capsule.radius - other_radius, to_vector(normal)};
    }
    case shape_kind::plane: {
      const vec3 n = to_vec3(other.normal);
      const real lowest = std::min(dot(n, core.start), dot(n, core.end)) - other.offset;
      return {lowest - capsule.radius, other.normal};
    }
    case shape_kind::capsule: {
      const segment_gap gap = nearest_cores(capsule, core, core_of(other));
      return {gap.distance - capsule.radius - other.radius, to_vector(gap.normal)};
    }
    case shape_kind::box:
    case shape_kind::convex_hull:
      return polyhedron_separation(capsule, other);
  }
  return {infinity, vector{0, 0, 1}};
}

}  // namespace

void collide_capsule(const placed_shape& a, const placed_shape& b, real margin,
                     contact_manifold& out) {
  out.count = 0;
  if (a.kind == shape_kind::capsule) {
    collide_with(a, b, margin, out);
    return;
  }
  // B is the capsule: its contacts with A, the normal turned to point at A.
  collide_with(b, a, margin, out);
  for (int i = 0; i < out.count; ++i)
    out.points[i].geometry.normal = -out.points[i].geometry.normal;
}

separation capsule_separation(const placed_shape& a, const placed_shape& b) {
  if (a.kind == shape_kind::capsule) return separation_from(a, b);
  separation s = separation_from(b, a);
  s.normal = -s.normal;
  return s;
}

}  // namespace gaphys::detail
