// Contact generation: through the conformal meet (thesis 4.2.1), one code
// path for every pair of round shapes (spheres, points, planes); boxes,
// capsules and hulls through the convex narrow phase (convex_contact.hpp).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>

#include "gaphys/algebra.hpp"
#include "gaphys/material.hpp"
#include "gaphys/shape.hpp"

namespace gaphys {

// A shape at its body's pose, in the form the contact test needs.
// (Its conformal dual is dual_of's: each meet makes it in a frame at the
// pair. Kept here as a 32-coefficient multivector, written for every body
// in every step and never read, it took 0.6 ms of a 10,000-sphere step.)
struct placed_shape {
  shape_kind kind;
  vector center{};  // the shape frame's origin in the world (a sphere's centre)
  vector normal{};  // world-frame outward normal (planes)
  real radius = 0;
  real offset = 0;  // world-frame: the plane is normal . x = offset
  // Boxes, capsules and hulls: `center` is the shape frame's origin in the
  // world and `attitude` its turn (x_world = center + R x_shape ~R).
  rotor attitude{1, 0, 0, 0};
  vector half_extents{};  // box
  real half_height = 0;   // capsule: its segment is center +- half_height axis
  vector axis{};          // capsule: R e3 ~R
  const convex_polyhedron* polyhedron = nullptr;  // box and hull, in the shape frame
};

// The shape at the pose of its frame in the world.
placed_shape place(const shape& s, const vector& position, const rotor& attitude);

// The shape's dual in c3ga, in the world frame: a sphere is c - r^2/2 ni
// (c the conformal centre), a plane -(n + d ni) (the limit of a sphere
// containing its solid side, so spheres and planes orient alike), a point
// the dual of the flat point x ^ ni; zero for the shapes the convex narrow
// phase meets (boxes, capsules, hulls).
conformal::mv dual_of(const placed_shape& s);

struct contact_geometry {
  // Round pairs, thesis eq. 4.10: C ni C, normalized: the centre of the
  // meet's round (other pairs: midway between the two surfaces). Two
  // spheres: the centre of their intersection circle; a sphere and a plane:
  // the sphere's centre projected on the plane; a point: the point. When one
  // solid holds the other whole the circle is imaginary and its centre is on
  // the radical plane (for a plane, still the projected centre).
  vector point;
  vector normal;  // unit, from B towards A
  real depth;     // overlap along the normal; < 0 (minus the gap) for a speculative contact
  // Of the meet's round: > 0 the surfaces cross, 0 they touch, < 0 one solid
  // holds the other whole (a sphere inside a sphere or below a plane).
  real squared_radius;
};

// The contact between A and B, or nothing when they are apart. Shapes apart
// by a gap that A's and B's velocities may close within `lookahead` seconds
// make a speculative contact: the same geometry (the meet's round is
// imaginary, its centre and carrier still real), with depth = -gap < 0.
// Each body's own speed towards the other counts, not only their relative
// speed: either may be stopped by its other contacts while the other goes
// on (two touching balls of a stack both falling under gravity). The meet
// is computed in a frame at the pair, so a pair far from the world's origin
// meets as it would near it (docs/engine.md, "Contacts through the meet").
std::optional<contact_geometry> find_contact(const placed_shape& a, const placed_shape& b,
                                             real lookahead = 0,
                                             const vector& velocity_a = vector{},
                                             const vector& velocity_b = vector{});

// Up to four contact points between two shapes, all with one normal: one for
// round shapes (spheres, points, planes, a capsule's cap), two for a
// capsule's side lying on a face, up to four for a face lying on a face.
// Each point's feature id names the features that made it (a corner, an
// edge crossing a side of a face) so that the same point of a resting box
// has the same id step after step, and the solver warm starts it.
struct contact_point {
  contact_geometry geometry;
  std::uint32_t feature = 0;
};

struct contact_manifold {
  std::array<contact_point, 4> points;
  int count = 0;
};

// Every pair of shapes: A and B overlapping, touching, or apart by at most
// `margin` (a speculative contact, depth = -gap). Round pairs (spheres,
// points, planes) are met as find_contact above, with the margin their
// velocities close within the lookahead; the others by the convex narrow
// phase. Fills `out` (count 0: no contact).
void find_contacts(const placed_shape& a, const placed_shape& b, real lookahead,
                   const vector& velocity_a, const vector& velocity_b, real margin,
                   contact_manifold& out);

// Whether A and B overlap or touch: find_contacts at no margin, some point
// at depth >= 0 (`scratch` holds the manifold). Sensors and the overlap
// queries use it.
bool touching(const placed_shape& a, const placed_shape& b, contact_manifold& scratch);

// The impulses of one contact over a step, all acting on A (B gets their
// opposites): along the normal, in the tangent plane (friction), and the
// angular impulse of rolling resistance and spinning friction.
struct contact_impulse {
  real normal = 0;    // N s, >= 0
  vector tangent{};   // N s, orthogonal to the normal, |tangent| <= μ normal
  bivector angular{};  // N m s: rolling (planes holding the normal) and spin (the tangent plane)
};

// A contact between two bodies, as the solver uses it.
struct contact {
  // Indices into world::bodies() (world::id_of gives their ids; without
  // removals the two are equal), body_a < body_b.
  std::size_t body_a;
  std::size_t body_b;
  contact_geometry geometry;
  // Which of each body's shapes touch (indices into body::shapes()), and
  // the point's feature id within their manifold.
  std::uint32_t shape_a = 0;
  std::uint32_t shape_b = 0;
  std::uint32_t feature = 0;
  gaphys::material material;  // the two shapes' values, combined by world_settings' rules
  // What the solver gave this contact in its step; impulse.normal / h is the
  // mean normal force. Of it, `resting` is what the contact solve (not the
  // step's bounces) gave: the next step starts from it when the two bodies
  // still touch (warm starting), so a resting stack is held up at once
  // instead of sinking while the sweeps converge.
  contact_impulse impulse{};
  contact_impulse resting{};
  // m/s: how fast the point was closing along the normal as the step began,
  // -n . (v_A(p) - v_B(p)) with the bodies' velocities then (> 0 closing).
  real approach_speed = 0;
};

}  // namespace gaphys
