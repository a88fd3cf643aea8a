// Snapshots: world::save_snapshot and world::restore_snapshot (docs/engine.md,
// "Snapshots"). A snapshot is everything a later step reads or a user can
// observe; a world restored from it steps on bit for bit as the saved one.
//
// Layout, little-endian throughout, reals as their bit patterns:
//
//   header    magic "gaphysSN" (8 bytes), format version (u32), sizeof(real)
//             (u8), the real -4/3 (byte order and real format), payload size
//             (u64)
//   payload   settings, time (a double whatever sizeof(real)), the next
//             island label, the polyhedra (each box or hull once, shared
//             by the shapes that share it), the
//             bodies with their shapes, the id tables, the contacts, the
//             sleeping contacts, the events, the sensor overlaps
//   checksum  FNV-1a 64 of every byte before it (u64)
//
// Counts and indices are u64. Boxes' polyhedra are rebuilt from their half
// extents (convex_polyhedron::box is exact and the narrow phase's box code
// relies on its layout); hulls' are stored whole, since the points they
// were built from are gone.
//
// Restoring trusts nothing: a fuzzer can re-seal the checksum, so every
// value the engine would later index with, divide by or loop over is checked
// against what the engine's own entry points guarantee (the checks of
// world_settings, body_definition and shape, and for hulls the convexity
// the narrow phase's clipping relies on). The result is built in a fresh
// world and moved into *this only when all of it is good.
#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <memory>
#include <new>
#include <optional>
#include <string>
#include <system_error>
#include <unordered_map>
#include <utility>
#include <vector>

#if defined(__unix__) || defined(__APPLE__)
#include <fcntl.h>     // open
#include <sys/stat.h>  // fstat
#include <unistd.h>    // fsync
#endif

#include "byte_stream.hpp"
#include "gaphys/world.hpp"
#include "precision.hpp"
#include "validate.hpp"

namespace gaphys {

namespace {

constexpr char magic[8] = {'g', 'a', 'p', 'h', 'y', 's', 'S', 'N'};
constexpr std::uint32_t format_version = 2;
constexpr std::size_t header_size = 8 + 4 + 1 + sizeof(real) + 8;
constexpr std::size_t checksum_size = 8;
constexpr std::uint64_t no_stored_index = std::numeric_limits<std::uint64_t>::max();
constexpr std::size_t no_slot = std::numeric_limits<std::size_t>::max();
using detail::pi;

// Its bytes (55 55 55 55 55 55 f5 bf as binary64) read otherwise in another
// byte or word order, or real format: such a snapshot fails this check.
real byte_order_check() { return real(-4) / 3; }

// Attitudes are unit rotors to rounding; a restored one must be within this.
const real unit_tolerance = detail::by_precision(1e-6, 1e-5);

// Lower bounds on the bytes of one item, for the counts' checks.
constexpr std::size_t body_bytes = 24 * sizeof(real);
constexpr std::size_t shape_bytes = 14 * sizeof(real);
constexpr std::size_t contact_bytes = 16 + 12 + 27 * sizeof(real);
constexpr std::size_t event_bytes = 16 + 8 * sizeof(real);

bool same_bits(real a, real b) { return std::memcmp(&a, &b, sizeof(real)) == 0; }

template <class Named>
bool same_bits(const Named& a, const Named& b) {
  for (std::size_t i = 0; i < a.c.size(); ++i) {
    if (!same_bits(a.c[i], b.c[i])) return false;
  }
  return true;
}

template <class Named>
bool all_finite(const Named& value) {
  return std::all_of(value.c.begin(), value.c.end(), [](real x) { return std::isfinite(x); });
}

using detail::is_zero;

// Plain coordinates for the hull checks' loops, as convex_polyhedron.cpp
// has them (the instrumented build would count every algebra call).
real dot(const vector& a, const vector& b) {
  return a.c[0] * b.c[0] + a.c[1] * b.c[1] + a.c[2] * b.c[2];
}
vector cross(const vector& a, const vector& b) {
  return vector{a.c[1] * b.c[2] - a.c[2] * b.c[1], a.c[2] * b.c[0] - a.c[0] * b.c[2],
                a.c[0] * b.c[1] - a.c[1] * b.c[0]};
}
vector minus(const vector& a, const vector& b) {
  return vector{a.c[0] - b.c[0], a.c[1] - b.c[1], a.c[2] - b.c[2]};
}
real length(const vector& v) { return std::sqrt(dot(v, v)); }

// --- Reading checked values ---------------------------------------------------

real finite(detail::byte_reader& in, const char* what) {
  const real x = in.number(what);
  if (!std::isfinite(x)) in.fail(what, " must be finite (got ", x, ")");
  return x;
}

real non_negative(detail::byte_reader& in, const char* what) {
  const real x = in.number(what);
  if (!(std::isfinite(x) && x >= 0)) in.fail(what, " must be finite and >= 0 (got ", x, ")");
  return x;
}

// A shape's size as the shape factories take it (validate.hpp,
// smallest_length): a static sphere of radius 1e300 restored moved a ball
// by 2e299 m, and a capsule of radius 1e-300 made every step throw.
void require_shape_length(detail::byte_reader& in, std::size_t at, real value, const char* what) {
  if (!(value >= detail::smallest_length && value <= detail::largest_length)) {
    in.fail_at(at, what, " must be between ", detail::smallest_length, " and ",
               detail::largest_length, " m (got ", value, ")");
  }
}

// A speed the step can use, as body::set_velocity asks: its square finite.
template <class Named>
Named steppable_numbers(detail::byte_reader& in, const char* what) {
  const Named value = in.numbers<Named>(what);
  if (!std::isfinite(e3ga::norm2(value))) {
    in.fail(what, " must be finite, its square too (got ", e3ga::basic_mv<real>(value), ")");
  }
  return value;
}

template <class Named>
Named finite_numbers(detail::byte_reader& in, const char* what) {
  const Named value = in.numbers<Named>(what);
  if (!all_finite(value)) in.fail(what, " must be finite (got ", e3ga::basic_mv<real>(value), ")");
  return value;
}

rotor read_unit_rotor(detail::byte_reader& in, const char* what) {
  const rotor r = finite_numbers<rotor>(in, what);
  const real norm =
      std::sqrt(r.c[0] * r.c[0] + r.c[1] * r.c[1] + r.c[2] * r.c[2] + r.c[3] * r.c[3]);
  if (!(std::fabs(norm - 1) <= unit_tolerance)) {
    in.fail(what, " must be a unit rotor (its norm is ", norm, ")");
  }
  return r;
}

std::size_t index_below(detail::byte_reader& in, std::size_t end, const char* what) {
  const std::uint64_t i = in.u64(what);
  if (i >= end) in.fail(what, " is ", i, ", out of range (there are ", end, ")");
  return static_cast<std::size_t>(i);
}

// --- Aggregates: structured bindings name every field, so a field added to
// one of these structs fails to compile here until the snapshot holds it. --

void write_material(detail::byte_writer& out, const material& m) {
  const auto& [restitution, friction, rolling_resistance, spinning_friction] = m;
  for (real x : {restitution, friction, rolling_resistance, spinning_friction}) out.number(x);
}

material read_material(detail::byte_reader& in) {
  material m;
  m.restitution = in.number("restitution");
  if (!(m.restitution >= 0 && m.restitution <= 1)) {
    in.fail("restitution must be in [0, 1] (got ", m.restitution, ")");
  }
  m.friction = non_negative(in, "friction");
  m.rolling_resistance = non_negative(in, "rolling resistance");
  m.spinning_friction = non_negative(in, "spinning friction");
  return m;
}

void write_impulse(detail::byte_writer& out, const contact_impulse& i) {
  const auto& [normal, tangent, angular] = i;
  out.number(normal);
  out.numbers(tangent);
  out.numbers(angular);
}

contact_impulse read_impulse(detail::byte_reader& in) {
  contact_impulse i;
  // (The solver's contacts push, never pull.)
  i.normal = non_negative(in, "normal impulse");
  i.tangent = finite_numbers<vector>(in, "tangent impulse");
  i.angular = finite_numbers<bivector>(in, "angular impulse");
  return i;
}

void write_contact(detail::byte_writer& out, const contact& c) {
  const auto& [body_a, body_b, geometry, shape_a, shape_b, feature, m, impulse, resting,
               approach_speed] = c;
  const auto& [point, normal, depth, squared_radius] = geometry;
  out.u64(body_a);
  out.u64(body_b);
  out.numbers(point);
  out.numbers(normal);
  out.number(depth);
  out.number(squared_radius);
  out.u32(shape_a);
  out.u32(shape_b);
  out.u32(feature);
  write_material(out, m);
  write_impulse(out, impulse);
  write_impulse(out, resting);
  out.number(approach_speed);
}

// Contacts in pair order, body_a < body_b, naming shapes their bodies have:
// what the solver's warm start and the events' merge of two steps rely on.
std::vector<contact> read_contacts(detail::byte_reader& in, const std::vector<body>& bodies,
                                   const char* list, const char* item) {
  in.within(list);
  const std::size_t count = in.count("the count", contact_bytes);
  std::vector<contact> contacts(count);
  for (std::size_t k = 0; k < count; ++k) {
    in.within(item, k);
    contact& c = contacts[k];
    c.body_a = index_below(in, bodies.size(), "body_a");
    c.body_b = index_below(in, bodies.size(), "body_b");
    if (!(c.body_a < c.body_b)) in.fail("body_a must be below body_b");
    if (k > 0 && std::make_pair(c.body_a, c.body_b) <
                     std::make_pair(contacts[k - 1].body_a, contacts[k - 1].body_b)) {
      in.fail("contacts must be sorted by body pair");
    }
    c.geometry.point = finite_numbers<vector>(in, "point");
    c.geometry.normal = finite_numbers<vector>(in, "normal");
    c.geometry.depth = finite(in, "depth");
    c.geometry.squared_radius = finite(in, "squared radius");
    c.shape_a = in.u32("shape_a");
    if (c.shape_a >= bodies[c.body_a].shapes().size()) in.fail("shape_a is out of range");
    c.shape_b = in.u32("shape_b");
    if (c.shape_b >= bodies[c.body_b].shapes().size()) in.fail("shape_b is out of range");
    c.feature = in.u32("feature");
    c.material = read_material(in);
    c.impulse = read_impulse(in);
    c.resting = read_impulse(in);
    // The next step's warm start gives the bodies this impulse again: a
    // change of velocity it can use, as body::set_velocity asks of a
    // velocity (a fuzzed 1e306 overflowed the step).
    const real change =
        c.resting.normal * (bodies[c.body_a].inverse_mass() + bodies[c.body_b].inverse_mass());
    if (!std::isfinite(change * change)) {
      in.fail("resting normal impulse ", c.resting.normal,
              " is too large to step: the velocity change it gives overflows when squared");
    }
    c.approach_speed = finite(in, "approach speed");
  }
  in.within(nullptr);
  return contacts;
}

void write_events(detail::byte_writer& out, const std::vector<contact_event>& events) {
  out.u64(events.size());
  for (const contact_event& e : events) {
    const auto& [body_a, body_b, point, normal, impulse, approach_speed] = e;
    out.u64(body_a);
    out.u64(body_b);
    out.numbers(point);
    out.numbers(normal);
    out.number(impulse);
    out.number(approach_speed);
  }
}

void write_settings(detail::byte_writer& out, const world_settings& s) {
  const auto& [gravity, linear_damping, angular_damping, solver_iterations, turning_iterations,
               solver_tolerance, solver_relaxation, restitution_threshold, impact_iterations,
               material_combine, position_correction, linear_slop, contact_margin, broad_phase,
               sleeping, sleep_linear_speed, sleep_angular_speed, time_to_sleep, threads,
               batch_contacts] = s;
  // Not written: how many threads step the world, and whether its sweeps
  // run on batches, change nothing it computes, and the state hash must not
  // depend on them.
  static_cast<void>(threads);
  static_cast<void>(batch_contacts);
  const auto& [restitution_rule, friction_rule, rolling_rule, spinning_rule] = material_combine;
  out.numbers(gravity);
  out.number(linear_damping);
  out.number(angular_damping);
  out.i32(solver_iterations);
  out.i32(turning_iterations);
  out.number(solver_tolerance);
  out.number(solver_relaxation);
  out.number(restitution_threshold);
  out.i32(impact_iterations);
  for (combine_rule rule : {restitution_rule, friction_rule, rolling_rule, spinning_rule}) {
    out.u8(static_cast<std::uint8_t>(rule));
  }
  out.number(position_correction);
  out.number(linear_slop);
  out.number(contact_margin);
  out.u8(static_cast<std::uint8_t>(broad_phase));
  out.boolean(sleeping);
  out.number(sleep_linear_speed);
  out.number(sleep_angular_speed);
  out.number(time_to_sleep);
}

combine_rule read_rule(detail::byte_reader& in, const char* what) {
  const std::uint8_t x = in.u8(what);
  if (x > static_cast<std::uint8_t>(combine_rule::multiply)) {
    in.fail(what, " is ", int(x), ", not a combine rule");
  }
  return static_cast<combine_rule>(x);
}

// The ranges are the world constructor's to check (read_world builds one
// from these); here only what it cannot see: enum values out of range.
world_settings read_settings(detail::byte_reader& in) {
  in.within("settings");
  world_settings s;
  s.gravity = in.numbers<vector>("gravity");
  s.linear_damping = in.number("linear damping");
  s.angular_damping = in.number("angular damping");
  s.solver_iterations = in.i32("solver iterations");
  s.turning_iterations = in.i32("turning iterations");
  s.solver_tolerance = in.number("solver tolerance");
  s.solver_relaxation = in.number("solver relaxation");
  s.restitution_threshold = in.number("restitution threshold");
  s.impact_iterations = in.i32("impact iterations");
  s.material_combine.restitution = read_rule(in, "restitution combine rule");
  s.material_combine.friction = read_rule(in, "friction combine rule");
  s.material_combine.rolling_resistance = read_rule(in, "rolling resistance combine rule");
  s.material_combine.spinning_friction = read_rule(in, "spinning friction combine rule");
  s.position_correction = in.number("position correction");
  s.linear_slop = in.number("linear slop");
  s.contact_margin = in.number("contact margin");
  const std::uint8_t broad_phase = in.u8("broad phase");
  if (broad_phase > static_cast<std::uint8_t>(broad_phase_kind::all_pairs)) {
    in.fail("broad phase is ", int(broad_phase), ", not uniform_grid (0) or all_pairs (1)");
  }
  s.broad_phase = static_cast<broad_phase_kind>(broad_phase);
  s.sleeping = in.boolean("sleeping");
  s.sleep_linear_speed = in.number("sleep linear speed");
  s.sleep_angular_speed = in.number("sleep angular speed");
  s.time_to_sleep = in.number("time to sleep");
  in.within(nullptr);
  return s;
}

// --- Polyhedra ----------------------------------------------------------------

void write_hull(detail::byte_writer& out, const convex_polyhedron& p) {
  const auto& [vertices, faces, vertex_indices, edges, bounding_radius] = p;
  out.u64(vertices.size());
  for (const vector& v : vertices) out.numbers(v);
  out.u64(faces.size());
  for (const polyhedron_face& f : faces) {
    const auto& [normal, offset, first, count] = f;
    out.numbers(normal);
    out.number(offset);
    out.u32(first);
    out.u32(count);
  }
  out.u64(vertex_indices.size());
  for (std::uint32_t i : vertex_indices) out.u32(i);
  out.u64(edges.size());
  for (const polyhedron_edge& e : edges) {
    const auto& [tail, head, left, right] = e;
    for (std::uint32_t x : {tail, head, left, right}) out.u32(x);
  }
  out.number(bounding_radius);
}

// What the narrow phase relies on, beyond indices in range: every face a
// strictly convex polygon, counter-clockwise about its unit normal, its
// corners on its plane and every vertex behind it (to within 1e-6 of the
// hull's size: convex_polyhedron::hull merges faces flat to 1e-9), and each
// edge the two faces that walk it. A face clipped against another would
// otherwise outgrow the clipping buffer, which holds one corner more than
// a convex polygon can gain. Testing every vertex against every face costs
// O(F V), what one separating-axis test of the hull against itself costs.
void check_hull(detail::byte_reader& in, std::size_t at, const convex_polyhedron& p) {
  const auto fail = [&](const auto&... parts) { in.fail_at(at, parts...); };
  if (p.vertices.size() < 4 || p.faces.size() < 4 || p.edges.size() < 6) {
    fail("a hull needs at least 4 vertices, 4 faces and 6 edges");
  }
  real radius = 0;
  vector low = p.vertices[0], high = p.vertices[0];
  for (const vector& v : p.vertices) {
    radius = std::max(radius, length(v));
    for (int i = 0; i < 3; ++i) {
      low.c[i] = std::min(low.c[i], v.c[i]);
      high.c[i] = std::max(high.c[i], v.c[i]);
    }
  }
  if (!(radius > 0 && std::isfinite(radius))) fail("the hull's size must be finite and > 0");
  // The sizes convex_polyhedron::hull accepts.
  if (radius > detail::largest_length) {
    fail("the hull's vertices must lie within ", detail::largest_length,
         " m of its origin (got one ", radius, " m from it)");
  }
  const real span = std::max({high.c[0] - low.c[0], high.c[1] - low.c[1], high.c[2] - low.c[2]});
  if (span < detail::smallest_length) {
    fail("the hull must span at least ", detail::smallest_length, " m (got ", span, ")");
  }
  if (!(std::fabs(p.bounding_radius - radius) <= detail::by_precision(1e-9, 1e-5) * radius)) {
    fail("the hull's bounding radius is ", p.bounding_radius, ", its farthest vertex ", radius);
  }
  // The faces' corner lists tile vertex_indices in order, as hull() lays
  // them out: the work below is then bounded by the bytes read.
  std::uint64_t corners = 0;
  for (std::size_t f = 0; f < p.faces.size(); ++f) {
    const polyhedron_face& face = p.faces[f];
    if (face.first != corners || face.count < 3) {
      fail("face ", f, " has corners [", face.first, ", +", face.count, "), not from ", corners,
           " and at least 3");
    }
    corners += face.count;
  }
  if (corners != p.vertex_indices.size()) {
    fail("the faces have ", corners, " corners, the vertex indices ", p.vertex_indices.size());
  }
  if (corners != 2 * std::uint64_t(p.edges.size())) {
    fail("the hull has ", p.edges.size(), " edges for ", corners, " face sides");
  }
  // Each face side (tail, head), found by binary search, used by one edge.
  struct side {
    std::uint32_t tail, head, face;
    bool operator<(const side& o) const { return tail != o.tail ? tail < o.tail : head < o.head; }
  };
  std::vector<side> sides;
  sides.reserve(corners);
  for (std::uint32_t f = 0; f < p.faces.size(); ++f) {
    const polyhedron_face& face = p.faces[f];
    for (std::uint32_t k = 0; k < face.count; ++k) {
      sides.push_back({p.vertex_indices[face.first + k],
                       p.vertex_indices[face.first + (k + 1) % face.count], f});
    }
  }
  std::sort(sides.begin(), sides.end());
  for (std::size_t i = 1; i < sides.size(); ++i) {
    if (!(sides[i - 1] < sides[i])) fail("two faces walk one edge the same way");
  }
  std::vector<char> used(sides.size(), 0);
  const auto claim = [&](std::uint32_t tail, std::uint32_t head, std::uint32_t face,
                         std::size_t e) {
    const auto it = std::lower_bound(sides.begin(), sides.end(), side{tail, head, 0});
    if (it == sides.end() || it->tail != tail || it->head != head || it->face != face ||
        used[std::size_t(it - sides.begin())]) {
      fail("edge ", e, " is not a side of its faces");
    }
    used[std::size_t(it - sides.begin())] = 1;
  };
  for (std::size_t e = 0; e < p.edges.size(); ++e) {
    const polyhedron_edge& edge = p.edges[e];
    claim(edge.tail, edge.head, edge.left, e);
    claim(edge.head, edge.tail, edge.right, e);
  }
  // The geometry last, as it costs O(F V): a hull of one face repeated
  // 40,000 times took 12 s to be refused for its edges.
  const real tolerance = detail::by_precision(1e-6, 1e-4) * radius;
  for (std::size_t f = 0; f < p.faces.size(); ++f) {
    const polyhedron_face& face = p.faces[f];
    const vector& n = face.normal;
    const auto corner = [&](std::uint32_t k) {
      return p.vertices[p.vertex_indices[face.first + k % face.count]];
    };
    real turning = 0;
    for (std::uint32_t k = 0; k < face.count; ++k) {
      const vector v = corner(k);
      const real height = dot(n, v) - face.offset;
      if (!(std::fabs(height) <= tolerance)) fail("face ", f, ": corner ", k, " is off its plane");
      const vector in_edge = minus(v, corner(k + face.count - 1));
      const vector out_edge = minus(corner(k + 1), v);
      const real left = dot(n, cross(in_edge, out_edge));
      if (!(left > 0)) fail("face ", f, " is not strictly convex at corner ", k);
      turning += std::atan2(left, dot(in_edge, out_edge));
    }
    // Left turns all the way round, once: a convex polygon (a star would
    // wind twice).
    if (!(std::fabs(turning - 2 * pi) < 1e-3)) fail("face ", f, " winds more than once");
    for (const vector& v : p.vertices) {
      if (!(dot(n, v) - face.offset <= tolerance)) {
        fail("the hull is not convex: a vertex is in front of face ", f);
      }
    }
  }
}

std::shared_ptr<const convex_polyhedron> read_hull(detail::byte_reader& in) {
  const std::size_t at = in.offset();
  auto p = std::make_shared<convex_polyhedron>();
  const std::size_t vertex_count = in.count("the hull's vertex count", 3 * sizeof(real));
  p->vertices.resize(vertex_count);
  for (vector& v : p->vertices) v = finite_numbers<vector>(in, "hull vertex");
  const std::size_t face_count = in.count("the hull's face count", 4 * sizeof(real) + 8);
  p->faces.resize(face_count);
  for (polyhedron_face& f : p->faces) {
    f.normal = finite_numbers<vector>(in, "hull face normal");
    if (!(std::fabs(length(f.normal) - 1) <= unit_tolerance)) {
      in.fail("hull face normal must be unit");
    }
    f.offset = finite(in, "hull face offset");
    f.first = in.u32("hull face first corner");
    f.count = in.u32("hull face corner count");
  }
  const std::size_t index_count = in.count("the hull's vertex index count", 4);
  p->vertex_indices.resize(index_count);
  for (std::uint32_t& i : p->vertex_indices) {
    i = in.u32("hull vertex index");
    if (i >= vertex_count) in.fail("hull vertex index ", i, " is out of range");
  }
  const std::size_t edge_count = in.count("the hull's edge count", 16);
  p->edges.resize(edge_count);
  for (polyhedron_edge& e : p->edges) {
    e.tail = in.u32("hull edge tail");
    e.head = in.u32("hull edge head");
    e.left = in.u32("hull edge left face");
    e.right = in.u32("hull edge right face");
    if (e.tail >= vertex_count || e.head >= vertex_count || e.tail == e.head) {
      in.fail("hull edge ends out of range");
    }
    if (e.left >= face_count || e.right >= face_count || e.left == e.right) {
      in.fail("hull edge faces out of range");
    }
  }
  p->bounding_radius = in.number("hull bounding radius");
  check_hull(in, at, *p);
  return p;
}

}  // namespace

// --- The private fields -----------------------------------------------------------

namespace detail {

// A new field in one of these classes must be saved and restored here (and
// this size updated): the bit-identical continuation depends on it. The
// sizes are those of 64-bit libstdc++ with double reals.
#if defined(__GLIBCXX__) && defined(__x86_64__)
constexpr bool sizes_known = sizeof(real) == 8;
static_assert(!sizes_known || sizeof(inertia) == 152,
              "a new inertia field: add it to the snapshot");
static_assert(!sizes_known || sizeof(shape) == 144, "a new shape field: add it to the snapshot");
static_assert(!sizes_known || sizeof(body) == 424, "a new body field: add it to the snapshot");
#endif

// How a polyhedron is stored: a box's half extents, or a hull whole.
enum class polyhedron_entry : std::uint8_t { box = 0, hull = 1 };

struct snapshot_access {
  // The polyhedra shapes share: a box's (rebuilt from its half extents)
  // or a hull's (stored whole).
  struct polyhedron_ref {
    std::shared_ptr<const convex_polyhedron> polyhedron;
    polyhedron_entry kind;
    vector half_extents;  // of a box
  };
  using polyhedra = std::vector<polyhedron_ref>;

  // --- Writing ---

  // Each box's or hull's polyhedron once, in the order the shapes first
  // name it; `index` maps each to its place.
  static void write_polyhedra(byte_writer& out, const world& w,
                              std::unordered_map<const convex_polyhedron*, std::size_t>& index) {
    std::vector<const shape*> first_user;
    for (const body& b : w.bodies_) {
      for (const attached_shape& a : b.shapes_) {
        const convex_polyhedron* p = a.shape.polyhedron_.get();
        if (p && index.emplace(p, first_user.size()).second) first_user.push_back(&a.shape);
      }
    }
    out.u64(first_user.size());
    for (const shape* s : first_user) {
      if (s->kind_ == shape_kind::box) {
        out.u8(static_cast<std::uint8_t>(polyhedron_entry::box));
        out.numbers(s->half_extents_);
      } else {
        out.u8(static_cast<std::uint8_t>(polyhedron_entry::hull));
        write_hull(out, *s->polyhedron_);
      }
    }
  }

  static void write_shape(byte_writer& out, const shape& s,
                          const std::unordered_map<const convex_polyhedron*, std::size_t>& index) {
    out.u8(static_cast<std::uint8_t>(s.kind_));
    out.number(s.radius_);
    out.numbers(s.normal_);
    out.number(s.offset_);
    out.numbers(s.half_extents_);
    out.number(s.half_height_);
    write_material(out, s.material_);
    const auto& [category, mask] = s.filter_;
    out.u32(category);
    out.u32(mask);
    out.boolean(s.sensor_);
    if (s.polyhedron_) out.u64(index.at(s.polyhedron_.get()));
  }

  static void write_body(byte_writer& out, const body& b,
                         const std::unordered_map<const convex_polyhedron*, std::size_t>& index) {
    out.boolean(b.is_static_);
    out.boolean(b.is_kinematic_);
    out.number(b.inverse_mass_);
    for (real x : b.inertia_.tensor_) out.number(x);
    for (real x : b.inertia_.inverse_) out.number(x);
    out.boolean(b.inertia_.isotropic_);
    out.u64(b.shapes_.size());
    for (const attached_shape& a : b.shapes_) {
      const auto& [s, offset, attitude] = a;
      out.numbers(offset);
      out.numbers(attitude);
      write_shape(out, s, index);
    }
    out.number(b.bounding_radius_);
    out.numbers(b.position_);
    out.numbers(b.velocity_);
    out.numbers(b.attitude_);
    out.numbers(b.angular_velocity_);
    out.numbers(b.force_);
    out.numbers(b.torque_);
    out.number(b.gravity_scale_);
    for (const std::optional<real>* rate : {&b.linear_damping_, &b.angular_damping_}) {
      out.boolean(rate->has_value());
      if (*rate) out.number(**rate);
    }
    out.boolean(b.can_sleep_);
    out.boolean(b.asleep_);
    out.number(b.still_time_);
    out.u64(b.island_);
    out.boolean(b.woken_);
  }

  static std::vector<std::uint8_t> save(const world& w) {
    byte_writer out;
    out.raw(magic, sizeof magic);
    out.u32(format_version);
    out.u8(static_cast<std::uint8_t>(sizeof(real)));
    out.number(byte_order_check());
    const std::size_t payload_size_at = out.size();
    out.u64(0);  // the payload's size, patched below

    write_settings(out, w.settings_);
    out.float64(w.time_);
    out.u64(w.next_island_);
    std::unordered_map<const convex_polyhedron*, std::size_t> index;
    write_polyhedra(out, w, index);
    out.u64(w.bodies_.size());
    for (const body& b : w.bodies_) write_body(out, b, index);
    const auto write_indices = [&out](const std::vector<std::size_t>& list) {
      out.u64(list.size());
      for (std::size_t i : list) out.u64(i == no_slot ? no_stored_index : i);
    };
    write_indices(w.slot_of_index_);
    write_indices(w.index_of_slot_);
    out.u64(w.generation_of_slot_.size());
    for (std::uint32_t g : w.generation_of_slot_) out.u32(g);
    write_indices(w.free_slots_);
    for (const std::vector<contact>* list : {&w.contacts_, &w.sleeping_contacts_}) {
      out.u64(list->size());
      for (const contact& c : *list) write_contact(out, c);
    }
    w.settle_events();
    const auto& [began, persisted, ended] = w.events_;
    for (const std::vector<contact_event>* list : {&began, &persisted, &ended}) {
      write_events(out, *list);
    }
    out.u64(w.sensor_overlaps_.size());
    for (const sensor_overlap& o : w.sensor_overlaps_) {
      const auto& [sensor, sensor_shape, other, other_shape] = o;
      for (std::size_t x : {sensor, sensor_shape, other, other_shape}) out.u64(x);
    }

    out.patch_u64(payload_size_at, out.size() - header_size);
    out.u64(fnv1a(out.bytes().data(), out.size()));
    return out.take();
  }

  // --- Reading ---

  static polyhedra read_polyhedra(byte_reader& in) {
    in.within("polyhedra");
    const std::size_t count = in.count("the count", 1 + 3 * sizeof(real));
    polyhedra table;
    table.reserve(count);
    for (std::size_t i = 0; i < count; ++i) {
      in.within("polyhedron", i);
      const std::uint8_t kind = in.u8("polyhedron kind");
      if (kind == static_cast<std::uint8_t>(polyhedron_entry::box)) {
        const vector h = in.numbers<vector>("box half extents");
        const std::size_t at = in.last_offset();
        for (real x : h.c) require_shape_length(in, at, x, "a box's half extents");
        table.push_back({std::make_shared<const convex_polyhedron>(convex_polyhedron::box(h)),
                         polyhedron_entry::box, h});
      } else if (kind == static_cast<std::uint8_t>(polyhedron_entry::hull)) {
        table.push_back({read_hull(in), polyhedron_entry::hull, vector{}});
      } else {
        in.fail("polyhedron kind is ", int(kind), ", not box (0) or hull (1)");
      }
    }
    in.within(nullptr);
    return table;
  }

  static shape read_shape(byte_reader& in, const polyhedra& table) {
    const std::uint8_t kind_value = in.u8("shape kind");
    if (kind_value > static_cast<std::uint8_t>(shape_kind::convex_hull)) {
      in.fail("shape kind is ", int(kind_value), ", not one of the 6 kinds");
    }
    shape s(static_cast<shape_kind>(kind_value));
    s.radius_ = finite(in, "shape radius");
    const std::size_t radius_at = in.last_offset();
    s.normal_ = finite_numbers<vector>(in, "shape normal");
    s.offset_ = finite(in, "shape offset");
    s.half_extents_ = finite_numbers<vector>(in, "shape half extents");
    s.half_height_ = finite(in, "shape half height");
    s.material_ = read_material(in);
    s.filter_.category = in.u32("shape filter category");
    s.filter_.mask = in.u32("shape filter mask");
    s.sensor_ = in.boolean("shape sensor flag");
    const auto fail = [&](const auto&... parts) { in.fail_at(radius_at, parts...); };
    switch (s.kind_) {
      case shape_kind::sphere:
        require_shape_length(in, radius_at, s.radius_, "a sphere's radius");
        break;
      case shape_kind::plane:
        if (!(std::fabs(gaphys::length(s.normal_) - 1) <= unit_tolerance)) {
          fail("a plane's normal must be unit");
        }
        if (!(std::fabs(s.offset_) <= detail::largest_length)) {
          fail("a plane's offset must be at most ", detail::largest_length,
               " m from the origin (got ", s.offset_, ")");
        }
        break;
      case shape_kind::point:
        break;
      case shape_kind::capsule:
        require_shape_length(in, radius_at, s.radius_, "a capsule's radius");
        if (s.half_height_ != 0)
          require_shape_length(in, radius_at, s.half_height_, "a capsule's half height");
        break;
      case shape_kind::box:
      case shape_kind::convex_hull: {
        const polyhedron_ref& entry = table[index_below(in, table.size(), "shape polyhedron")];
        const bool box = s.kind_ == shape_kind::box;
        if (box ? entry.kind != polyhedron_entry::box ||
                      !same_bits(entry.half_extents, s.half_extents_)
                : entry.kind != polyhedron_entry::hull) {
          in.fail(box ? "a box's polyhedron must be the box of its half extents"
                      : "a hull's polyhedron must be a hull");
        }
        s.polyhedron_ = entry.polyhedron;
        break;
      }
    }
    if (s.sensor_ && (s.kind_ == shape_kind::plane || s.kind_ == shape_kind::point)) {
      fail("a plane or a point cannot be a sensor");
    }
    return s;
  }

  // The rules body's constructor enforces, on the restored fields.
  static body read_body(byte_reader& in, const polyhedra& table, std::uint64_t next_island) {
    body_definition placeholder;  // a valid body to overwrite field by field
    placeholder.is_static = true;
    body b(placeholder);
    b.is_static_ = in.boolean("static flag");
    b.is_kinematic_ = in.boolean("kinematic flag");
    if (b.is_static_ && b.is_kinematic_) in.fail("a body cannot be both static and kinematic");
    b.inverse_mass_ = in.number("inverse mass");
    if (b.is_dynamic() ? !(std::isfinite(b.inverse_mass_) && b.inverse_mass_ > 0)
                       : b.inverse_mass_ != 0) {
      in.fail("inverse mass must be finite and > 0 (dynamic) or 0 (got ", b.inverse_mass_, ")");
    }
    read_inertia(in, b.inertia_);

    const std::size_t shape_count = in.count("the shape count", shape_bytes);
    b.shapes_.reserve(shape_count);
    for (std::size_t i = 0; i < shape_count; ++i) {
      const vector offset = finite_numbers<vector>(in, "shape offset");
      if (!(e3ga::norm(offset) <= detail::largest_length)) {
        in.fail_at(in.last_offset(), "a shape's offset must be at most ", detail::largest_length,
                   " m from its body's origin (got ", e3ga::basic_mv<real>(offset), ")");
      }
      const rotor attitude = read_unit_rotor(in, "shape attitude");
      const std::size_t shape_at = in.offset();
      b.shapes_.push_back(attached_shape{read_shape(in, table), offset, attitude});
      if (b.shapes_.back().shape.kind_ == shape_kind::plane) {
        const bool posed =
            !is_zero(offset) || attitude.c[1] != 0 || attitude.c[2] != 0 || attitude.c[3] != 0;
        if (!b.is_static_ || shape_count != 1 || posed) {
          in.fail_at(shape_at, "a plane must be a static body's only shape, unposed");
        }
      }
    }
    b.bounding_radius_ = in.number("bounding radius");
    real reach = 0;
    for (const attached_shape& a : b.shapes_) {
      reach = std::max(reach, e3ga::norm(a.offset) + a.shape.bounding_radius());
    }
    const bool infinite = std::isinf(reach) && b.bounding_radius_ == reach;
    if (!infinite && !(std::fabs(b.bounding_radius_ - reach) <=
                       detail::by_precision(1e-9, 1e-5) * (1 + reach))) {
      in.fail("bounding radius is ", b.bounding_radius_, ", its shapes reach ", reach);
    }

    b.position_ = finite_numbers<vector>(in, "position");
    b.velocity_ = steppable_numbers<vector>(in, "velocity");
    b.attitude_ = read_unit_rotor(in, "attitude");
    b.angular_velocity_ = steppable_numbers<bivector>(in, "angular velocity");
    if (b.is_static_ && !(is_zero(b.velocity_) && is_zero(b.angular_velocity_))) {
      in.fail("a static body must be at rest");
    }
    b.force_ = finite_numbers<vector>(in, "force");
    b.torque_ = finite_numbers<bivector>(in, "torque");
    b.gravity_scale_ = finite(in, "gravity scale");
    for (std::optional<real>* rate : {&b.linear_damping_, &b.angular_damping_}) {
      *rate = std::nullopt;
      if (in.boolean("damping flag")) *rate = non_negative(in, "damping");
    }
    b.can_sleep_ = in.boolean("can_sleep flag");
    b.asleep_ = in.boolean("asleep flag");
    const std::size_t asleep_at = in.last_offset();
    b.still_time_ = non_negative(in, "still time");
    b.island_ = in.u64("island");
    if (b.island_ >= next_island) {
      in.fail("island ", b.island_, " is not below the next island label ", next_island);
    }
    b.woken_ = in.boolean("woken flag");
    // As the world puts a body to sleep: only dynamic ones, in an island.
    if (b.asleep_ && (!b.is_dynamic() || b.island_ == 0)) {
      in.fail_at(asleep_at, "only a dynamic body in an island (label > 0) can be asleep");
    }
    return b;
  }

  // The tensor as inertia::tensor checks it (finite, symmetric, positive
  // definite, invertible), and the inverse and the isotropic flag as it
  // makes them, to the bit: every body's inertia comes from it (or is the
  // default, its identity), so a saved inverse is the one it gives again.
  // (Checked against a bound alone, a resealed snapshot with a tensor entry
  // pushed up, or an inverse entry of 1e245, restored and overflowed in its
  // first step.)
  static void read_inertia(byte_reader& in, inertia& out) {
    const std::size_t at = in.offset();
    for (real& x : out.tensor_) x = finite(in, "inertia tensor entry");
    for (real& x : out.inverse_) x = finite(in, "inverse inertia entry");
    out.isotropic_ = in.boolean("isotropic flag");
    inertia made;
    try {
      made = inertia::tensor(out.tensor_);
    } catch (const invalid_input&) {
      in.fail_at(at, "the inertia tensor must be symmetric and positive definite");
    }
    if (std::memcmp(made.inverse_.data(), out.inverse_.data(), sizeof(out.inverse_)) != 0) {
      in.fail_at(at, "the inverse inertia is not the inertia tensor's inverse");
    }
    if (out.isotropic_ != made.isotropic_) in.fail("the isotropic flag does not match the tensor");
  }

  static std::vector<std::size_t> read_indices(byte_reader& in, const char* what) {
    const std::size_t count = in.count(what, 8);
    std::vector<std::size_t> list(count);
    for (std::size_t& i : list) {
      const std::uint64_t x = in.u64(what);
      i = x == no_stored_index ? no_slot : static_cast<std::size_t>(x);
    }
    return list;
  }

  // The id tables (world.hpp): each body has a slot, each slot its body or
  // none; a slot without a body is free for reuse or retired (its
  // generation at the largest value), never both.
  static void read_ids(byte_reader& in, world& w) {
    in.within("id tables");
    const std::size_t at = in.offset();
    const std::size_t n = w.bodies_.size();
    w.slot_of_index_ = read_indices(in, "slots of the bodies");
    w.index_of_slot_ = read_indices(in, "bodies of the slots");
    const std::size_t slots = w.index_of_slot_.size();
    const std::size_t generations = in.count("the generation count", 4);
    w.generation_of_slot_.resize(generations);
    for (std::uint32_t& g : w.generation_of_slot_) g = in.u32("generation");
    w.free_slots_ = read_indices(in, "free slots");
    const auto fail = [&](const auto&... parts) { in.fail_at(at, parts...); };
    if (w.slot_of_index_.size() != n) {
      fail("there are ", n, " bodies but ", w.slot_of_index_.size(), " slots of bodies");
    }
    if (generations != slots) fail(slots, " slots but ", generations, " generations");
    if (slots > (std::size_t{1} << 32)) fail("more slots than 32-bit slot numbers");
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t slot = w.slot_of_index_[i];
      if (slot >= slots || w.index_of_slot_[slot] != i) {
        fail("body ", i, "'s slot does not name it");
      }
    }
    std::size_t named = 0;
    for (std::size_t slot = 0; slot < slots; ++slot) {
      if (w.index_of_slot_[slot] == no_slot) continue;
      if (w.index_of_slot_[slot] >= n) fail("slot ", slot, " names no body");
      ++named;
    }
    if (named != n) fail("slots name ", named, " bodies, not ", n);
    std::vector<char> free(slots, 0);
    for (std::size_t slot : w.free_slots_) {
      if (slot >= slots || w.index_of_slot_[slot] != no_slot || free[slot]) {
        fail("free slot ", slot, " is out of range, taken or listed twice");
      }
      if (w.generation_of_slot_[slot] == std::numeric_limits<std::uint32_t>::max()) {
        fail("free slot ", slot, " is retired");
      }
      free[slot] = 1;
    }
    for (std::size_t slot = 0; slot < slots; ++slot) {
      const bool retired = w.generation_of_slot_[slot] == std::numeric_limits<std::uint32_t>::max();
      if (w.index_of_slot_[slot] == no_slot && !free[slot] && !retired) {
        fail("slot ", slot, " has no body and is neither free nor retired");
      }
    }
    in.within(nullptr);
  }

  static std::vector<contact_event> read_events(byte_reader& in, const world& w, const char* list,
                                                const char* item) {
    in.within(list);
    const std::size_t count = in.count("the count", event_bytes);
    std::vector<contact_event> events(count);
    for (std::size_t k = 0; k < count; ++k) {
      in.within(item, k);
      contact_event& e = events[k];
      e.body_a = in.u64("body_a");
      if (!w.contains(e.body_a)) in.fail("body_a is no live body's id");
      e.body_b = in.u64("body_b");
      if (!w.contains(e.body_b)) in.fail("body_b is no live body's id");
      if (!(w.index_of(e.body_a) < w.index_of(e.body_b))) {
        in.fail("body_a must be created before body_b");
      }
      e.point = finite_numbers<vector>(in, "point");
      e.normal = finite_numbers<vector>(in, "normal");
      e.impulse = finite(in, "impulse");
      e.approach_speed = finite(in, "approach speed");
    }
    in.within(nullptr);
    return events;
  }

  static std::vector<sensor_overlap> read_sensor_overlaps(byte_reader& in, const world& w) {
    in.within("sensor overlaps");
    const std::size_t count = in.count("the count", 32);
    std::vector<sensor_overlap> overlaps(count);
    for (std::size_t k = 0; k < count; ++k) {
      in.within("sensor overlap", k);
      sensor_overlap& o = overlaps[k];
      o.sensor = in.u64("sensor");
      if (!w.contains(o.sensor)) in.fail("sensor is no live body's id");
      const body& sensor = w.bodies_[w.index_of(o.sensor)];
      o.sensor_shape = index_below(in, sensor.shapes_.size(), "sensor shape");
      if (!sensor.shapes_[o.sensor_shape].shape.sensor_) in.fail("sensor shape is no sensor");
      o.other = in.u64("other");
      if (!w.contains(o.other) || o.other == o.sensor) in.fail("other is no other live body's id");
      o.other_shape = index_below(in, w.bodies_[w.index_of(o.other)].shapes_.size(), "other shape");
    }
    in.within(nullptr);
    return overlaps;
  }

  static world read(byte_reader& in) {
    const std::size_t settings_at = in.offset();
    const world_settings settings = read_settings(in);
    std::optional<world> restored;
    try {
      restored.emplace(settings);  // the constructor checks the ranges
    } catch (const invalid_input& e) {
      in.fail_at(settings_at, "settings: ", e.what() + std::strlen("gaphys: "));
    }
    world& w = *restored;
    w.time_ = in.float64("time");
    if (!(std::isfinite(w.time_) && w.time_ >= 0)) {
      in.fail("time must be finite and >= 0 (got ", w.time_, ")");
    }
    w.next_island_ = in.u64("next island label");
    if (w.next_island_ == 0) in.fail("the next island label must be >= 1");
    const polyhedra table = read_polyhedra(in);

    in.within("bodies");
    const std::size_t body_count = in.count("the count", body_bytes);
    w.bodies_.reserve(body_count);
    for (std::size_t i = 0; i < body_count; ++i) {
      in.within("body", i);
      w.bodies_.push_back(read_body(in, table, w.next_island_));
    }
    in.within(nullptr);
    read_ids(in, w);
    w.contacts_ = read_contacts(in, w.bodies_, "contacts", "contact");
    w.sleeping_contacts_ = read_contacts(in, w.bodies_, "sleeping contacts", "sleeping contact");
    w.events_.began = read_events(in, w, "began events", "began event");
    w.events_.persisted = read_events(in, w, "persisted events", "persisted event");
    w.events_.ended = read_events(in, w, "ended events", "ended event");
    w.sensor_overlaps_ = read_sensor_overlaps(in, w);
    if (in.left() != 0) {
      in.fail_at(in.offset(), "the payload has ", in.left(), " bytes after its last item");
    }
    // The space knows which bodies have shapes, in index order, as
    // create_body adds them; the rest of it is scratch for each step.
    for (std::size_t i = 0; i < w.bodies_.size(); ++i) {
      if (w.bodies_[i].shape()) w.space_.add(i);
    }
    return std::move(w);
  }

  static world restore(const std::vector<std::uint8_t>& bytes) {
    const std::uint8_t* data = bytes.data();
    const std::size_t size = bytes.size();
    if (size == 0) reject("snapshot: not a gaphys snapshot (no bytes at all)");
    if (std::memcmp(data, magic, std::min(size, sizeof magic)) != 0) {
      reject("snapshot: not a gaphys snapshot (wrong magic at byte 0)");
    }
    byte_reader header(data, 0, size);
    for (std::size_t i = 0; i < sizeof magic; ++i) header.u8("the magic");
    const std::uint32_t version = header.u32("the format version");
    if (version != format_version) {
      header.fail("made by another build: format version ", version, " (this build reads ",
                  format_version, ")");
    }
    const std::uint8_t real_size = header.u8("the size of a real");
    if (real_size != sizeof(real)) {
      header.fail("made by another build: reals of ", int(real_size), " bytes (this build's have ",
                  sizeof(real), ")");
    }
    if (!same_bits(header.number("the byte order check"), byte_order_check())) {
      header.fail("made by another build: another byte order or real format");
    }
    const std::uint64_t payload_size = header.u64("the payload size");
    if (payload_size > size - header_size) {
      reject("snapshot: truncated at byte ", size, " reading the payload (", payload_size,
             " bytes from byte ", header_size, ")");
    }
    const std::size_t payload_end = header_size + static_cast<std::size_t>(payload_size);
    if (size - payload_end < checksum_size) {
      reject("snapshot: truncated at byte ", size, " reading the checksum");
    }
    if (size - payload_end > checksum_size) {
      reject("snapshot: ", size - payload_end - checksum_size, " trailing bytes at byte ",
             payload_end + checksum_size);
    }
    byte_reader trailer(data, payload_end, size);
    if (trailer.u64("the checksum") != fnv1a(data, payload_end)) {
      reject("snapshot: corrupt: checksum at byte ", payload_end,
             " does not match the bytes before it");
    }
    byte_reader payload(data, header_size, payload_end);
    return read(payload);
  }
};

}  // namespace detail

std::vector<std::uint8_t> world::save_snapshot() const {
  return detail::snapshot_access::save(*this);
}

void world::restore_snapshot(const std::vector<std::uint8_t>& bytes) {
  world restored = detail::snapshot_access::restore(bytes);
  // A later query must not take the old index for the new bodies.
  restored.geometry_version_ = geometry_version_ + 1;
  // This machine's, not the snapshot's.
  restored.settings_.threads = settings_.threads;
  restored.settings_.batch_contacts = settings_.batch_contacts;
  *this = std::move(restored);
}

// --- Files ---------------------------------------------------------------------

namespace {

std::string system_error_text(int error) {
  return std::error_code(error, std::generic_category()).message();
}

// A name in the target's folder that no other writer is using: the target's
// name, the process's clock and a counter.
std::filesystem::path temporary_beside(const std::filesystem::path& target, int attempt) {
  static std::atomic<std::uint64_t> counter{0};
  const auto ticks = std::chrono::steady_clock::now().time_since_epoch().count();
  // The target's name cut to 100 bytes: a name of 255 bytes, the most most
  // file systems take, left no room for the suffix.
  std::string name = target.filename().string().substr(0, 100);
  name += ".tmp-" + std::to_string(ticks) + "-" + std::to_string(counter.fetch_add(1)) + "-" +
          std::to_string(attempt);
  return target.parent_path() / name;
}

// The file a path names once its symbolic links are followed, link by link
// (a link to a file not made yet leads to it too): saving replaces that
// file and leaves the link a link.
std::filesystem::path followed_links(const std::string& path) {
  std::filesystem::path followed = path;
  std::error_code error;
  for (int links = 0; std::filesystem::is_symlink(std::filesystem::symlink_status(followed, error));
       ++links) {
    const std::filesystem::path next = std::filesystem::read_symlink(followed, error);
    if (error) {
      detail::reject("snapshot file ", path, ": cannot follow its link (", error.message(), ")");
    }
    if (links == 40) detail::reject("snapshot file ", path, ": too many levels of links");
    followed = next.is_absolute() ? next : followed.parent_path() / next;
  }
  return followed;
}

// The file at `path`, opened for reading if it is a regular file: a device
// can have no end (/dev/zero filled memory until std::bad_alloc) and a named
// pipe blocks until something writes to it. (Its type is read from the
// file opened, not from the path, which might name another by then; it is
// opened without waiting, for a pipe.)
std::FILE* open_regular_file(const std::string& path) {
#if defined(__unix__) || defined(__APPLE__)
  const int descriptor = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (descriptor < 0) {
    detail::reject("snapshot file ", path, ": cannot open (", system_error_text(errno), ")");
  }
  struct stat status {};
  const bool regular = ::fstat(descriptor, &status) == 0 && S_ISREG(status.st_mode);
  std::FILE* file = regular ? ::fdopen(descriptor, "rb") : nullptr;
  if (!file) {
    const int error = errno;
    ::close(descriptor);
    if (!regular) detail::reject("snapshot file ", path, ": is not a regular file");
    detail::reject("snapshot file ", path, ": cannot open (", system_error_text(error), ")");
  }
  return file;
#else
  std::error_code status_error;
  if (!std::filesystem::is_regular_file(std::filesystem::status(path, status_error))) {
    detail::reject("snapshot file ", path, ": is not a regular file");
  }
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) {
    detail::reject("snapshot file ", path, ": cannot open (", system_error_text(errno), ")");
  }
  return file;
#endif
}

}  // namespace

void world::save_snapshot_file(const std::string& path) const {
  if (path.empty()) detail::reject("snapshot file: the path is empty");
  const std::vector<std::uint8_t> bytes = save_snapshot();
  const std::filesystem::path target = followed_links(path);
  // Only a regular file is replaced: the rename below would put the
  // snapshot in place of a device or a named pipe (as root, of /dev/full).
  std::error_code status_error;
  const std::filesystem::file_status status = std::filesystem::status(target, status_error);
  if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status)) {
    detail::reject("snapshot file ", path, ": exists and is not a regular file");
  }
  std::filesystem::path temporary;
  std::FILE* file = nullptr;
  int error = 0;
  for (int attempt = 0; attempt < 8 && !file; ++attempt) {
    temporary = temporary_beside(target, attempt);
    file = std::fopen(temporary.string().c_str(), "wbx");  // x: never an existing file
    error = errno;
    if (!file && error != EEXIST) break;
  }
  if (!file) {
    detail::reject("snapshot file ", path, ": cannot write beside it (", system_error_text(error),
                   ")");
  }
  // A file replaced keeps its permissions (a private 600 save stays private).
  std::error_code ignored;
  if (std::filesystem::is_regular_file(status)) {
    std::filesystem::permissions(temporary, status.permissions(), ignored);
  }
  bool written = std::fwrite(bytes.data(), 1, bytes.size(), file) == bytes.size();
  written = std::fflush(file) == 0 && written;
#if defined(__unix__) || defined(__APPLE__)
  // On the disk before the rename makes it the snapshot, so a power cut
  // leaves the old file or the whole new one.
  written = ::fsync(::fileno(file)) == 0 && written;
#endif
  error = errno;
  written = std::fclose(file) == 0 && written;
  if (!written) {
    std::filesystem::remove(temporary, ignored);
    detail::reject("snapshot file ", path, ": cannot write (", system_error_text(error), ")");
  }
  std::error_code renamed;
  std::filesystem::rename(temporary, target, renamed);
  if (renamed) {
    std::filesystem::remove(temporary, ignored);
    detail::reject("snapshot file ", path, ": cannot replace it (", renamed.message(), ")");
  }
}

void world::restore_snapshot_file(const std::string& path) {
  if (path.empty()) detail::reject("snapshot file: the path is empty");
  std::FILE* file = open_regular_file(path);
  std::vector<std::uint8_t> bytes;
  std::uint8_t chunk[65536];
  std::size_t got;
  bool failed = false, too_large = false;
  try {
    while ((got = std::fread(chunk, 1, sizeof chunk, file)) > 0) {
      bytes.insert(bytes.end(), chunk, chunk + got);
    }
    failed = std::ferror(file) != 0;
  } catch (const std::bad_alloc&) {
    too_large = true;
  }
  const int error = errno;
  std::fclose(file);
  if (too_large) {
    detail::reject("snapshot file ", path, ": too large to read into memory (over ", bytes.size(),
                   " bytes)");
  }
  if (failed) {
    detail::reject("snapshot file ", path, ": cannot read (", system_error_text(error), ")");
  }
  try {
    restore_snapshot(bytes);
  } catch (const invalid_input& e) {
    // "gaphys: snapshot: <what>" becomes "gaphys: snapshot file <path>: <what>".
    const std::string message = e.what();
    const std::string prefix = "gaphys: snapshot: ";
    const bool ours = message.compare(0, prefix.size(), prefix) == 0;
    detail::reject("snapshot file ", path, ": ", ours ? message.substr(prefix.size()) : message);
  }
}

}  // namespace gaphys
