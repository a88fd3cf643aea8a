// The capsule's narrow phase against closed-form geometry: a capsule on a
// plane, against a sphere and a point, against another capsule, on a box's
// face, across its edge and through it; the margin; the symmetry of A and B;
// and capsule_separation against hand-computed distances and an independent
// segment-to-box distance (a ternary search of the closed-form point-to-box
// distance along the segment).
#include <algorithm>
#include <cmath>
#include <vector>

#include "capsule_contact.hpp"
#include "engine_test_support.hpp"
#include "placed_shape_test.hpp"

namespace gaphys::testing {
namespace {

using detail::capsule_separation;
using detail::collide_capsule;

const real closed_form_tolerance = tolerance(1e-12, 1e-5);  // closed forms a few operations deep
const real exact = tolerance(1e-9, 1e-5);  // capsule_separation against the independent distance

// The rotor turning the unit vector `from` onto the unit vector `to`:
// R = (1 + to from) / |1 + to from|, so that R from ~R = to; for opposite
// vectors (only e3 onto -e3 here) the half turn in the e1 e3 plane.
rotor turning(const vector& from, const vector& to) {
  if (e3ga::scp(from, to) < -0.999999) return rotor{0, 0, 1, 0};
  return e3ga::unit(identity + e3ga::gp(to, from));
}

class capsule_contact_test : public placed_shape_test {
 protected:
  // A capsule whose segment runs from centre - h axis (end 0) to centre + h
  // axis (end 1).
  static placed_shape capsule(const vector& centre, const vector& axis, real half_height,
                              real radius) {
    return place(shape::capsule(half_height, radius), centre, turning(e3, axis));
  }
  static contact_manifold collide(const placed_shape& a, const placed_shape& b, real margin = 0) {
    contact_manifold m;
    m.count = -1;  // collide_capsule must set it
    collide_capsule(a, b, margin, m);
    return m;
  }
  // The point of the manifold with this feature id (the test fails if none).
  static const contact_geometry& with_id(const contact_manifold& m, std::uint32_t id) {
    for (int i = 0; i < m.count; ++i) {
      if (m.points[i].feature == id) return m.points[i].geometry;
    }
    ADD_FAILURE() << "no point with feature id " << id;
    return m.points[0].geometry;
  }
  rotor random_attitude() {
    return e3ga::exp(uniform(-3.2, 3.2) * e3ga::dual(random_unit_vector()));
  }
  vector random_point(real extent) {
    return vector{uniform(-extent, extent), uniform(-extent, extent), uniform(-extent, extent)};
  }
};

// A pair and the same pair swapped: the same points and depths, the normals
// turned. With one capsule the ids name the same features too; two capsules
// swap roles (A's end 0 becomes B's), so their ids are not compared.
void expect_mirrored(const contact_manifold& ab, const contact_manifold& ba, bool same_ids = true) {
  ASSERT_EQ(ab.count, ba.count);
  for (int i = 0; i < ab.count; ++i) {
    const contact_geometry& g = ab.points[i].geometry;
    int match = -1;
    for (int j = 0; j < ba.count; ++j) {
      if (length(ba.points[j].geometry.point - g.point) <= closed_form_tolerance) match = j;
    }
    ASSERT_GE(match, 0) << "point " << i << " has no mirror";
    const contact_geometry& h = ba.points[match].geometry;
    if (same_ids) {
      EXPECT_EQ(ab.points[i].feature, ba.points[match].feature);
    }
    EXPECT_TRUE(near(g.normal, -h.normal, closed_form_tolerance));
    EXPECT_NEAR(g.depth, h.depth, closed_form_tolerance);
  }
}

// ---------------------------------------------------------------------------
// Planes. Each end's ball against the plane: depth r less the end's height,
// the point midway between the ball's surface and the plane's.

using CapsuleContactPlane = capsule_contact_test;

TEST_F(CapsuleContactPlane, lying_capsule_touches_at_both_ends) {
  const real h = 0.75, r = 0.3, sink = 0.01;
  const placed_shape lying = capsule({1, 2, r - sink}, e1, h, r);
  const contact_manifold m = collide(lying, floor());
  ASSERT_EQ(m.count, 2);
  const contact_geometry &end0 = with_id(m, 0), &end1 = with_id(m, 1);
  EXPECT_TRUE(near(end0.point, vector{1 - h, 2, -sink / 2}, closed_form_tolerance));
  EXPECT_TRUE(near(end1.point, vector{1 + h, 2, -sink / 2}, closed_form_tolerance));
  for (const contact_geometry* g : {&end0, &end1}) {
    EXPECT_TRUE(near(g->normal, e3, closed_form_tolerance));
    EXPECT_NEAR(g->depth, sink, closed_form_tolerance);
  }
}

TEST_F(CapsuleContactPlane, tilted_capsule_has_each_ends_own_depth) {
  // End 0 at height 0.2, end 1 at 0.2 + 2 h sin(tilt); radius 0.25.
  const real h = 0.5, r = 0.25, tilt = 0.05;
  const vector axis{std::cos(tilt), 0, std::sin(tilt)};
  const placed_shape c = capsule(vector{0, 0, 0.2} + h * axis, axis, h, r);
  const contact_manifold m = collide(c, floor(), 0.1);
  ASSERT_EQ(m.count, 2);
  EXPECT_NEAR(with_id(m, 0).depth, r - 0.2, closed_form_tolerance);
  EXPECT_NEAR(with_id(m, 1).depth, r - (0.2 + 2 * h * std::sin(tilt)), closed_form_tolerance);
  // Tilted further, end 1 is beyond the margin: end 0 alone.
  const real steep = 0.5;
  const vector up{std::cos(steep), 0, std::sin(steep)};
  const contact_manifold n = collide(capsule(vector{0, 0, 0.2} + h * up, up, h, r), floor(), 0.1);
  ASSERT_EQ(n.count, 1);
  EXPECT_EQ(n.points[0].feature, 0u);
  EXPECT_NEAR(n.points[0].geometry.depth, r - 0.2, closed_form_tolerance);
}

TEST_F(CapsuleContactPlane, standing_capsule_touches_at_its_lower_end) {
  const real h = 0.6, r = 0.2, sink = 0.03;
  const contact_manifold up = collide(capsule({3, -1, h + r - sink}, e3, h, r), floor(), 0.05);
  ASSERT_EQ(up.count, 1);
  EXPECT_EQ(up.points[0].feature, 0u);  // end 0 = centre - h axis, the lower one
  EXPECT_NEAR(up.points[0].geometry.depth, sink, closed_form_tolerance);
  EXPECT_TRUE(near(up.points[0].geometry.point, vector{3, -1, -sink / 2}, closed_form_tolerance));
  const contact_manifold down = collide(capsule({3, -1, h + r - sink}, -e3, h, r), floor(), 0.05);
  ASSERT_EQ(down.count, 1);
  EXPECT_EQ(down.points[0].feature, 1u);
}

TEST_F(CapsuleContactPlane, gap_within_margin_is_speculative_beyond_it_nothing) {
  const real r = 0.3, gap = 0.02;
  const placed_shape lying = capsule({0, 0, r + gap}, e2, 0.5, r);
  const contact_manifold within = collide(lying, floor(), 0.03);
  ASSERT_EQ(within.count, 2);
  for (int i = 0; i < 2; ++i) EXPECT_NEAR(within.points[i].geometry.depth, -gap, closed_form_tolerance);
  EXPECT_EQ(collide(lying, floor(), 0.01).count, 0);
  EXPECT_EQ(collide(lying, floor()).count, 0);
}

TEST_F(CapsuleContactPlane, swapping_a_and_b_turns_the_normal) {
  const placed_shape c = capsule({0, 0, 0.25}, vector{0.6, 0, 0.8}, 0.4, 0.5);
  const contact_manifold ab = collide(c, floor(), 0.2), ba = collide(floor(), c, 0.2);
  ASSERT_GT(ab.count, 0);
  expect_mirrored(ab, ba);
  EXPECT_TRUE(near(ba.points[0].geometry.normal, -e3, closed_form_tolerance));
}

// ---------------------------------------------------------------------------
// Spheres and points: the capsule's ball at the segment's nearest point meets
// the sphere; the closed form of two spheres: normal along the line of
// centres, depth rA + rB - d, the point midway between the two surfaces on
// that line, rB - depth / 2 from B's centre.

using CapsuleContactSphere = capsule_contact_test;

void expect_ball_and_sphere(const contact_manifold& m, const vector& ball, real ball_radius,
                            const vector& centre, real radius) {
  ASSERT_EQ(m.count, 1);
  const contact_geometry& g = m.points[0].geometry;
  const real d = length(ball - centre);
  const vector n = (ball - centre) / d;
  EXPECT_TRUE(near(g.normal, n, closed_form_tolerance));
  EXPECT_NEAR(g.depth, ball_radius + radius - d, closed_form_tolerance);
  EXPECT_TRUE(near(g.point, centre + (radius - g.depth / 2) * n, tolerance(1e-10, 1e-5)));
}

TEST_F(CapsuleContactSphere, beside_the_segment_the_nearest_ball_is_level_with_the_sphere) {
  const real h = 1, r = 0.3, radius = 0.5;
  const placed_shape c = capsule({0, 0, 0}, e3, h, r);
  const vector centre{0.7, 0.2, 0.4};  // beside the side, 0.728 from the axis
  const contact_manifold m = collide(c, place(shape::sphere(radius), centre, identity));
  expect_ball_and_sphere(m, vector{0, 0, 0.4}, r, centre, radius);
  EXPECT_TRUE(
      near(m.points[0].geometry.normal, vector{-0.7, -0.2, 0} / std::hypot(0.7, 0.2), closed_form_tolerance));
}

TEST_F(CapsuleContactSphere, beyond_an_end_the_cap_meets_it) {
  const real h = 1, r = 0.3, radius = 0.5;
  const placed_shape c = capsule({1, 1, 1}, e1, h, r);
  const vector centre{2.5, 1.3, 1.2};  // past end 1 at (2, 1, 1)
  expect_ball_and_sphere(collide(c, place(shape::sphere(radius), centre, identity)),
                         vector{2, 1, 1}, r, centre, radius);
}

TEST_F(CapsuleContactSphere, margin_and_symmetry) {
  const placed_shape c = capsule({0, 0, 0}, e2, 0.5, 0.25);
  const placed_shape s = place(shape::sphere(0.5), vector{0.8, 0.1, 0}, identity);  // gap 0.05
  EXPECT_EQ(collide(c, s).count, 0);
  EXPECT_EQ(collide(c, s, 0.04).count, 0);
  const contact_manifold ab = collide(c, s, 0.06);
  ASSERT_EQ(ab.count, 1);
  EXPECT_NEAR(ab.points[0].geometry.depth, -0.05, closed_form_tolerance);
  expect_mirrored(ab, collide(s, c, 0.06));
}

TEST_F(CapsuleContactSphere, a_point_is_met_midway_between_it_and_the_surface) {
  const placed_shape c = capsule({0, 0, 0}, e1, 1, 0.4);
  const vector p{0.3, 0.1, -0.25};
  const contact_manifold m = collide(c, place(shape::point(), p, identity));
  ASSERT_EQ(m.count, 1);
  const contact_geometry& g = m.points[0].geometry;
  EXPECT_NEAR(g.depth, 0.4 - std::hypot(0.1, 0.25), closed_form_tolerance);
  EXPECT_TRUE(near(g.normal, vector{0, -0.1, 0.25} / std::hypot(0.1, 0.25), closed_form_tolerance));
  EXPECT_TRUE(near(g.point, p - (g.depth / 2) * g.normal, tolerance(1e-10, 1e-5)));
  EXPECT_EQ(collide(c, place(shape::point(), vector{0, 0, 0.45}, identity)).count, 0);
  expect_mirrored(m, collide(place(shape::point(), p, identity), c));
}

// ---------------------------------------------------------------------------
// Two capsules.

using CapsuleContactCapsule = capsule_contact_test;

TEST_F(CapsuleContactCapsule, crossing_capsules_touch_at_the_common_perpendicular) {
  // A along x through the origin, B along y through (0, 0, d): the segments'
  // nearest points are (0, 0, 0) and (0, 0, d), the normal -e3.
  const real ra = 0.3, rb = 0.2, d = 0.45;
  const contact_manifold m = collide(capsule({0, 0, 0}, e1, 1, ra), capsule({0, 0, d}, e2, 1, rb));
  ASSERT_EQ(m.count, 1);
  const contact_geometry& g = m.points[0].geometry;
  EXPECT_TRUE(near(g.normal, -e3, closed_form_tolerance));
  EXPECT_NEAR(g.depth, ra + rb - d, closed_form_tolerance);
  EXPECT_TRUE(near(g.point, vector{0, 0, (ra + d - rb) / 2}, closed_form_tolerance));
  EXPECT_EQ(m.points[0].feature, 2u | (2u << 2));  // inside both segments
}

TEST_F(CapsuleContactCapsule, skew_capsules_meet_at_the_distance_of_their_lines) {
  // Random skew pairs whose nearest points are inside both segments: the
  // gap is |(cB - cA) . (dA x dB)| / |dA x dB| less the radii.
  for (int trial = 0; trial < 100; ++trial) {
    const vector da = random_unit_vector(), db = random_unit_vector();
    const vector across = e3ga::dual(e3ga::op(da, db));  // dA x dB up to sign
    const real sine = length(across);
    if (sine < 0.2) continue;
    const vector n = across / sine;
    const real ra = uniform(0.1, 0.5), rb = uniform(0.1, 0.5), d = uniform(0.05, 1.2);
    const vector ca = random_point(3);
    // B's line passes at distance d from A's, where A's and B's centres
    // are the nearest points, shifted along each line a little.
    const real sa = uniform(-0.5, 0.5), sb = uniform(-0.5, 0.5);
    const vector cb = ca + sa * da - d * n + sb * db;
    const placed_shape a = capsule(ca, da, 1, ra), b = capsule(cb, db, 1, rb);
    const contact_manifold m = collide(a, b, 2);
    ASSERT_EQ(m.count, 1) << "trial " << trial;
    EXPECT_NEAR(m.points[0].geometry.depth, ra + rb - d, closed_form_tolerance) << "trial " << trial;
    EXPECT_TRUE(near(m.points[0].geometry.normal, n, tolerance(1e-10, 1e-5))) << "trial " << trial;
    const detail::separation s = capsule_separation(a, b);
    EXPECT_NEAR(s.distance, d - ra - rb, closed_form_tolerance);
    EXPECT_TRUE(near(s.normal, n, tolerance(1e-10, 1e-5)));
    expect_mirrored(m, collide(b, a, 2), false);
  }
}

TEST_F(CapsuleContactCapsule, parallel_capsules_touch_at_both_ends_of_their_overlap) {
  // A from x = -1 to 1, B from 0.5 to 2.5, at height d above A: the overlap
  // is [0.5, 1], bounded by B's end 0 (id 16 + 2) and A's end 1 (16 + 1).
  const real ra = 0.25, rb = 0.35, d = 0.5;
  const placed_shape a = capsule({0, 0, 0}, e1, 1, ra);
  const contact_manifold m = collide(a, capsule({1.5, 0, d}, e1, 1, rb));
  ASSERT_EQ(m.count, 2);
  const contact_geometry &lower = with_id(m, 16 + 2), &upper = with_id(m, 16 + 1);
  for (const contact_geometry* g : {&lower, &upper}) {
    EXPECT_TRUE(near(g->normal, -e3, closed_form_tolerance));
    EXPECT_NEAR(g->depth, ra + rb - d, closed_form_tolerance);
  }
  const real midway = (ra + d - rb) / 2;
  EXPECT_TRUE(near(lower.point, vector{0.5, 0, midway}, closed_form_tolerance));
  EXPECT_TRUE(near(upper.point, vector{1, 0, midway}, closed_form_tolerance));
  // B turned end for end: its end 1 bounds the overlap now.
  const contact_manifold turned = collide(a, capsule({1.5, 0, d}, -e1, 1, rb));
  ASSERT_EQ(turned.count, 2);
  EXPECT_TRUE(near(with_id(turned, 16 + 3).point, vector{0.5, 0, midway}, closed_form_tolerance));
  expect_mirrored(m, collide(capsule({1.5, 0, d}, e1, 1, rb), a), false);
}

TEST_F(CapsuleContactCapsule, slightly_converging_capsules_have_each_ends_depth) {
  // B, longer than A, tilted by 0.005 rad in the x-z plane about (0, 0, d):
  // the overlap is all of A, and A's end 0 is nearest B, at A's end 0's
  // projection on B's line; the normal there is B's normal (sin, 0, -cos).
  const real ra = 0.25, rb = 0.25, d = 0.45, tilt = 0.005;
  const vector axis{std::cos(tilt), 0, std::sin(tilt)};
  const contact_manifold m =
      collide(capsule({0, 0, 0}, e1, 1, ra), capsule({0, 0, d}, axis, 2, rb), 0.1);
  ASSERT_EQ(m.count, 2);
  const vector n{std::sin(tilt), 0, -std::cos(tilt)};
  // Each end's depth along n, from its projection on B's line.
  for (const auto& [id, end] : {std::pair<std::uint32_t, real>{0, -1}, {1, 1}}) {
    const vector on_a{end, 0, 0};
    const vector on_b = vector{0, 0, d} + dot(on_a - vector{0, 0, d}, axis) * axis;
    const contact_geometry& g = with_id(m, 16 + id);
    EXPECT_TRUE(near(g.normal, n, tolerance(1e-12, 1e-6)));
    EXPECT_NEAR(g.depth, ra + rb - dot(n, on_a - on_b), tolerance(1e-12, 1e-6));
  }
  EXPECT_GT(with_id(m, 16).depth, with_id(m, 17).depth);
}

TEST_F(CapsuleContactCapsule, capsules_crossing_at_a_small_angle_rest_on_two_points) {
  // B 0.3 above A, turned by 0.004 rad about their common perpendicular e3:
  // along it the two lines are 0.3 apart everywhere, so both ends of the
  // overlap are as deep as the crossing, 0.4 - 0.3.
  const real tilt = 0.004;
  const vector axis{std::cos(tilt), std::sin(tilt), 0};
  const contact_manifold m =
      collide(capsule({0, 0, 0}, e1, 1, 0.2), capsule({0, 0, 0.3}, axis, 1, 0.2));
  ASSERT_EQ(m.count, 2);
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(m.points[i].geometry.depth, 0.4 - 0.3, closed_form_tolerance);
    EXPECT_TRUE(near(m.points[i].geometry.normal, -e3, closed_form_tolerance));
  }
  // Turned by 0.1 rad they cross: one point.
  const vector crossing{std::cos(0.1), std::sin(0.1), 0};
  EXPECT_EQ(collide(capsule({0, 0, 0}, e1, 1, 0.2), capsule({0, 0, 0.3}, crossing, 1, 0.2)).count,
            1);
}

TEST_F(CapsuleContactCapsule, collinear_capsules_end_to_end_touch_at_one_point) {
  const contact_manifold m =
      collide(capsule({0, 0, 0}, e1, 1, 0.3), capsule({2.5, 0, 0}, e1, 1, 0.3), 0.01);
  ASSERT_EQ(m.count, 1);
  EXPECT_TRUE(near(m.points[0].geometry.normal, -e1, closed_form_tolerance));
  EXPECT_NEAR(m.points[0].geometry.depth, 0.1, closed_form_tolerance);
  EXPECT_EQ(m.points[0].feature, 1u | (0u << 2));  // A's end 1, B's end 0
}

TEST_F(CapsuleContactCapsule, margin) {
  const placed_shape a = capsule({0, 0, 0}, e1, 1, 0.2), b = capsule({0, 0, 0.5}, e2, 1, 0.2);
  EXPECT_EQ(collide(a, b, 0.09).count, 0);
  const contact_manifold m = collide(a, b, 0.11);
  ASSERT_EQ(m.count, 1);
  EXPECT_NEAR(m.points[0].geometry.depth, -0.1, closed_form_tolerance);
}

// ---------------------------------------------------------------------------
// Boxes.

using CapsuleContactBox = capsule_contact_test;

TEST_F(CapsuleContactBox, capsule_lying_on_a_face_rests_on_two_points) {
  // Box [-1, 1] x [-0.5, 0.5] x [-0.25, 0.25]; capsule along x over its top,
  // sunk by 0.01. Each end: depth 0.01, point midway between the ball's
  // bottom and the face, z = 0.25 - 0.005.
  const real r = 0.1, sink = 0.01;
  const placed_shape b = box({0, 0, 0}, {1, 0.5, 0.25});
  const contact_manifold m = collide(capsule({0.2, 0.1, real(0.25) + r - sink}, e1, 0.5, r), b);
  ASSERT_EQ(m.count, 2);
  const real z = 0.25 - sink / 2;
  bool saw[2] = {false, false};
  for (int i = 0; i < 2; ++i) {
    const contact_geometry& g = m.points[i].geometry;
    EXPECT_TRUE(near(g.normal, e3, closed_form_tolerance));
    EXPECT_NEAR(g.depth, sink, closed_form_tolerance);
    const bool left = x(g.point) < 0.2;
    saw[left ? 0 : 1] = true;
    EXPECT_TRUE(near(g.point, vector{left ? real(-0.3) : real(0.7), 0.1, z}, closed_form_tolerance));
  }
  EXPECT_TRUE(saw[0] && saw[1]);
  EXPECT_NE(m.points[0].feature, m.points[1].feature);
  expect_mirrored(m, collide(b, capsule({0.2, 0.1, real(0.25) + r - sink}, e1, 0.5, r)));
}

TEST_F(CapsuleContactBox, capsule_across_a_face_rests_where_the_face_ends) {
  // Longer than the box: its stretch over the top face is x in [-1, 1].
  const real r = 0.1, sink = 0.02;
  const contact_manifold m =
      collide(capsule({0.3, 0, real(0.25) + r - sink}, e1, 2, r), box({0, 0, 0}, {1, 0.5, 0.25}));
  ASSERT_EQ(m.count, 2);
  std::vector<real> xs;
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(m.points[i].geometry.depth, sink, closed_form_tolerance);
    EXPECT_TRUE(near(m.points[i].geometry.normal, e3, closed_form_tolerance));
    xs.push_back(x(m.points[i].geometry.point));
  }
  std::sort(xs.begin(), xs.end());
  EXPECT_NEAR(xs[0], -1, closed_form_tolerance);
  EXPECT_NEAR(xs[1], 1, closed_form_tolerance);
}

TEST_F(CapsuleContactBox, tilted_capsule_on_a_turned_box_has_each_ends_depth) {
  // The box turned and moved; the capsule placed in the box's frame, its
  // ends at heights 0.05 and 0.09 over the top face (radius 0.1, margin 0.02).
  const rotor attitude = random_attitude();
  const vector centre{1, -2, 0.5};
  const auto world = [&](const vector& local) { return centre + e3ga::apply(attitude, local); };
  const vector end0{-0.4, 0.1, 0.25 + 0.05}, end1{0.4, 0.1, 0.25 + 0.09};
  const vector axis = (end1 - end0) / length(end1 - end0);
  const placed_shape c = place(shape::capsule(length(end1 - end0) / 2, 0.1),
                               world((end0 + end1) / 2), e3ga::gp(attitude, turning(e3, axis)));
  const contact_manifold m = collide(c, box(centre, {1, 0.5, 0.25}, attitude), 0.02);
  ASSERT_EQ(m.count, 2);
  const vector up = e3ga::apply(attitude, e3);
  std::vector<real> depths;
  for (int i = 0; i < 2; ++i) {
    EXPECT_TRUE(near(m.points[i].geometry.normal, up, tolerance(1e-12, 1e-6)));
    depths.push_back(m.points[i].geometry.depth);
  }
  std::sort(depths.begin(), depths.end());
  EXPECT_NEAR(depths[0], 0.1 - 0.09, tolerance(1e-12, 1e-6));
  EXPECT_NEAR(depths[1], 0.1 - 0.05, tolerance(1e-12, 1e-6));
}

TEST_F(CapsuleContactBox, feature_ids_hold_while_the_capsule_slides_on_a_face) {
  const placed_shape b = box({0, 0, 0}, {1, 1, 0.5});
  const contact_manifold first = collide(capsule({0, 0, 0.59}, e1, 0.4, 0.1), b);
  ASSERT_EQ(first.count, 2);
  for (real shift : {0.01, 0.05, 0.2}) {
    const contact_manifold moved = collide(capsule({shift, -shift, 0.59}, e1, 0.4, 0.1), b);
    ASSERT_EQ(moved.count, 2);
    for (int i = 0; i < 2; ++i) EXPECT_EQ(moved.points[i].feature, first.points[i].feature);
  }
  // Over the edge at x = 1 the stretch is clipped there: a new id.
  const contact_manifold over = collide(capsule({0.9, 0, 0.59}, e1, 0.4, 0.1), b);
  ASSERT_EQ(over.count, 2);
  EXPECT_NE(over.points[1].feature, first.points[1].feature);
}

// A box of half extents (1, 0.5, 0.5) turned 45° about x: one of its edges
// along x is on top, at height sqrt(0.5) (y = 0), between the faces whose
// normals are (0, ±1, 1) / sqrt 2.
class CapsuleContactBoxEdge : public capsule_contact_test {
 protected:
  const real ridge = std::sqrt(0.5);
  const placed_shape ridged =
      box({0, 0, 0}, {1, 0.5, 0.5}, turning(e3, vector{0, -1, 1} / std::sqrt(2.0)));
};

TEST_F(CapsuleContactBoxEdge, capsule_across_an_edge_touches_it_at_one_point) {
  const real r = 0.2, sink = 0.03;
  ASSERT_TRUE(near(e3ga::apply(ridged.attitude, e3), vector{0, -1, 1} / std::sqrt(2.0), tolerance(1e-15, 1e-7)));
  const contact_manifold m = collide(capsule({0.3, 0.05, ridge + r - sink}, e2, 0.7, r), ridged);
  ASSERT_EQ(m.count, 1);
  const contact_geometry& g = m.points[0].geometry;
  EXPECT_TRUE(near(g.normal, e3, tolerance(1e-12, 1e-6)));
  EXPECT_NEAR(g.depth, sink, tolerance(1e-12, 1e-6));
  EXPECT_TRUE(near(g.point, vector{0.3, 0, ridge + (r - sink - r) / 2}, tolerance(1e-12, 1e-6)));
  EXPECT_EQ((m.points[0].feature >> 12) & 3u, 2u);  // an edge
  expect_mirrored(m, collide(ridged, capsule({0.3, 0.05, ridge + r - sink}, e2, 0.7, r)));
}

TEST_F(CapsuleContactBoxEdge, capsule_along_an_edge_rests_on_two_points) {
  // Along the ridge, its stretch beside the edge x in [-0.5, 0.7].
  const real r = 0.2, sink = 0.03;
  const contact_manifold m = collide(capsule({0.1, 0, ridge + r - sink}, e1, 0.6, r), ridged);
  ASSERT_EQ(m.count, 2);
  std::vector<real> xs;
  for (int i = 0; i < 2; ++i) {
    EXPECT_TRUE(near(m.points[i].geometry.normal, e3, tolerance(1e-12, 1e-6)));
    EXPECT_NEAR(m.points[i].geometry.depth, sink, tolerance(1e-12, 1e-6));
    xs.push_back(x(m.points[i].geometry.point));
  }
  std::sort(xs.begin(), xs.end());
  EXPECT_NEAR(xs[0], -0.5, tolerance(1e-12, 1e-6));
  EXPECT_NEAR(xs[1], 0.7, tolerance(1e-12, 1e-6));
}

TEST_F(CapsuleContactBox, segment_piercing_a_face_is_pushed_out_through_it) {
  // Box [-1, 1]^3, a standing capsule whose lower end is 0.2 under the top
  // face at (0.2, 0.3): the separating axes by hand are +z: 0.2, +x: 0.8,
  // +y: 0.7, -x: 1.2, -y: 1.3, -z: 2 + 2h - 0.2, and the edges along x and
  // y give the same as +y and +x. Least: +z, 0.2; the capsule's depth 0.2 + r.
  const real h = 0.5, r = 0.1, under = 0.2;
  const placed_shape b = box({0, 0, 0}, {1, 1, 1});
  const placed_shape c = capsule({0.2, 0.3, 1 - under + h}, e3, h, r);
  const contact_manifold m = collide(c, b, 0.05);
  ASSERT_EQ(m.count, 1);
  const contact_geometry& g = m.points[0].geometry;
  EXPECT_TRUE(near(g.normal, e3, closed_form_tolerance));
  EXPECT_NEAR(g.depth, under + r, closed_form_tolerance);
  // Midway between the ball's bottom (z = 0.8 - r) and the face (z = 1).
  EXPECT_TRUE(near(g.point, vector{0.2, 0.3, (1 - under - r + 1) / 2}, closed_form_tolerance));
  EXPECT_EQ(m.points[0].feature & 3u, 0u);  // the segment's end 0
  const detail::separation s = capsule_separation(c, b);
  EXPECT_NEAR(s.distance, -(under + r), closed_form_tolerance);
  EXPECT_TRUE(near(s.normal, e3, closed_form_tolerance));
}

TEST_F(CapsuleContactBox, segment_inside_under_a_face_is_pushed_out_at_both_ends) {
  const real r = 0.1, under = 0.15;
  const placed_shape b = box({0, 0, 0}, {1, 1, 1});
  const contact_manifold m = collide(capsule({0, 0.2, 1 - under}, e1, 0.5, r), b);
  ASSERT_EQ(m.count, 2);
  for (int i = 0; i < 2; ++i) {
    EXPECT_TRUE(near(m.points[i].geometry.normal, e3, closed_form_tolerance));
    EXPECT_NEAR(m.points[i].geometry.depth, under + r, closed_form_tolerance);
  }
}

TEST_F(CapsuleContactBox, segment_cutting_an_edge_is_pushed_out_across_it) {
  // Box [-1, 1]^3; the segment in the plane x = 0.1 along (0, 1, -1) / sqrt 2
  // through (0.1, 1 - e, 1 - e), half height 0.5. Along the edge axis
  // (0, 1, 1) / sqrt 2 it runs in by sqrt 2 e; along +y and +z by e + 0.5 /
  // sqrt 2; along ±x by 0.9 and 1.1. Least: the edge's, sqrt 2 e.
  const real e = 0.1, r = 0.05;
  const vector along = vector{0, 1, -1} / std::sqrt(2.0), n = vector{0, 1, 1} / std::sqrt(2.0);
  const placed_shape b = box({0, 0, 0}, {1, 1, 1});
  const placed_shape c = capsule({0.1, 1 - e, 1 - e}, along, 0.5, r);
  const contact_manifold m = collide(c, b);
  ASSERT_EQ(m.count, 1);
  const contact_geometry& g = m.points[0].geometry;
  EXPECT_TRUE(near(g.normal, n, closed_form_tolerance));
  EXPECT_NEAR(g.depth, std::sqrt(2.0) * e + r, closed_form_tolerance);
  // Between the segment's point nearest the edge, less r n, and the edge's.
  const vector expected = (vector{0.1, 1 - e, 1 - e} - r * n + vector{0.1, 1, 1}) / 2;
  EXPECT_TRUE(near(g.point, expected, closed_form_tolerance));
  EXPECT_EQ((m.points[0].feature >> 12) & 3u, 2u);
  const detail::separation s = capsule_separation(c, b);
  EXPECT_NEAR(s.distance, -(std::sqrt(2.0) * e + r), closed_form_tolerance);
  EXPECT_TRUE(near(s.normal, n, closed_form_tolerance));
}

TEST_F(CapsuleContactBox, margin) {
  const placed_shape b = box({0, 0, 0}, {1, 1, 1});
  const placed_shape lying = capsule({0, 0, 1.25}, e2, 0.5, 0.2);  // gap 0.05
  EXPECT_EQ(collide(lying, b).count, 0);
  EXPECT_EQ(collide(lying, b, 0.049).count, 0);
  const contact_manifold m = collide(lying, b, 0.051);
  ASSERT_EQ(m.count, 2);
  for (int i = 0; i < 2; ++i) EXPECT_NEAR(m.points[i].geometry.depth, -0.05, closed_form_tolerance);
  // Beside a corner, apart by sqrt(0.1^2 + 0.1^2 + 0.1^2) - r.
  const placed_shape corner = capsule({1.1, 1.1, 1.1 + 0.5}, e3, 0.5, 0.1);
  const real gap = std::sqrt(0.03) - 0.1;
  EXPECT_EQ(collide(corner, b, gap - tolerance(1e-6, 1e-5)).count, 0);
  const contact_manifold c = collide(corner, b, gap + tolerance(1e-6, 1e-5));
  ASSERT_EQ(c.count, 1);
  EXPECT_NEAR(c.points[0].geometry.depth, -gap, closed_form_tolerance);
  EXPECT_TRUE(near(c.points[0].geometry.normal, vector{1, 1, 1} / std::sqrt(3.0), closed_form_tolerance));
  EXPECT_EQ((c.points[0].feature >> 12) & 3u, 3u);  // a corner
}

// ---------------------------------------------------------------------------
// capsule_separation.

using CapsuleContactSeparation = capsule_contact_test;

TEST_F(CapsuleContactSeparation, hand_computed_distances) {
  const placed_shape c = capsule({0, 0, 0}, e3, 1, 0.25);
  const auto expect = [&](const placed_shape& other, real distance, const vector& normal) {
    const detail::separation ab = capsule_separation(c, other), ba = capsule_separation(other, c);
    EXPECT_NEAR(ab.distance, distance, closed_form_tolerance);
    EXPECT_TRUE(near(ab.normal, normal, closed_form_tolerance));
    EXPECT_NEAR(ba.distance, distance, closed_form_tolerance);
    EXPECT_TRUE(near(ba.normal, -normal, closed_form_tolerance));
  };
  expect(place(shape::sphere(0.5), vector{3, 4, 0.5}, identity), 5 - 0.75, vector{-0.6, -0.8, 0});
  expect(place(shape::sphere(0.5), vector{0, 0.3, 1.4}, identity), 0.5 - 0.75,
         vector{0, -0.6, -0.8});
  expect(place(shape::point(), vector{0, 0, -2}, identity), 1 - 0.25, e3);
  expect(floor(-3), 2 - 0.25, e3);
  expect(floor(-0.5), -0.75, e3);  // end 0 under the floor by 0.5
  expect(capsule({2, 0, 0.5}, e2, 3, 0.5), 2 - 0.75, -e1);
  expect(box({2, 0, 3}, {0.5, 0.5, 0.5}), std::hypot(1.5, 1.5) - 0.25,
         vector{-1, 0, -1} / std::sqrt(2.0));            // beyond an edge of the box
  expect(box({0, 0, -2}, {2, 2, 0.5}), 0.5 - 0.25, e3);  // above its top face
  expect(box({0.5, 0, 0}, {0.5, 2, 0.5}), -0.25, -e1);   // the axis lies on its -x face
}

// The distance from the point (x, y, z) of the box's frame to the box
// [-h, h], closed form.
real box_distance(const real (&x)[3], const vector& h) {
  real squared = 0;
  for (int k = 0; k < 3; ++k) {
    const real outside = std::max(std::fabs(x[k]) - h.c[k], real(0));
    squared += outside * outside;
  }
  return std::sqrt(squared);
}

// The distance from the segment p q to the box: the point-to-box distance
// is convex along the segment (a convex function of an affine map), so a
// ternary search finds its least value, to rounding. (Plain arithmetic in
// the loop: the instrumented algebra counts every call.)
real segment_box_distance(const vector& p, const vector& q, const placed_shape& b) {
  const rotor back = e3ga::reverse(b.attitude);
  const vector lp = e3ga::apply(back, p - b.center), lq = e3ga::apply(back, q - b.center);
  const auto f = [&](real s) {
    real x[3];
    for (int k = 0; k < 3; ++k) x[k] = lp.c[k] + s * (lq.c[k] - lp.c[k]);
    return box_distance(x, b.half_extents);
  };
  real low = 0, high = 1;
  for (int i = 0; i < 64; ++i) {
    const real m1 = low + (high - low) / 3, m2 = high - (high - low) / 3;
    if (f(m1) <= f(m2)) {
      high = m2;
    } else {
      low = m1;
    }
  }
  return std::min({f(low), f(0), f(1)});
}

TEST_F(CapsuleContactSeparation, apart_matches_the_segment_to_box_distance) {
  int apart = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const vector half{uniform(0.2, 1.5), uniform(0.2, 1.5), uniform(0.2, 1.5)};
    const placed_shape b = box(random_point(1), half, random_attitude());
    const real h = uniform(0, 1.5), r = uniform(0.05, 0.5);
    const vector axis = random_unit_vector(), centre = random_point(3.5);
    const placed_shape c = capsule(centre, axis, h, r);
    const vector p = c.center - h * c.axis, q = c.center + h * c.axis;
    const real truth = segment_box_distance(p, q, b);
    if (!(truth > r)) continue;
    ++apart;
    const detail::separation s = capsule_separation(c, b);
    EXPECT_NEAR(s.distance, truth - r, exact) << "trial " << trial;
    // Moved back along the normal by the distance, it touches.
    const vector back = -s.distance * s.normal;
    EXPECT_NEAR(segment_box_distance(p + back, q + back, b), r, exact) << "trial " << trial;
    const detail::separation t = capsule_separation(b, c);
    EXPECT_NEAR(t.distance, s.distance, closed_form_tolerance);
    EXPECT_TRUE(near(t.normal, -s.normal, closed_form_tolerance));
    // A contact within the margin: one point at the nearest points, or two
    // on a face, the nearer at the distance.
    const contact_manifold m = collide(c, b, s.distance + tolerance(1e-6, 1e-5));
    ASSERT_GE(m.count, 1) << "trial " << trial;
    if (m.count == 1) {
      EXPECT_NEAR(m.points[0].geometry.depth, -s.distance, exact) << "trial " << trial;
      EXPECT_TRUE(near(m.points[0].geometry.normal, s.normal, tolerance(1e-9, 1e-5))) << "trial " << trial;
    } else {
      // Lying on a face (its normal within a degree of the nearest points'):
      // each end's depth is measured from the face's plane.
      const contact_geometry &g = m.points[0].geometry, &k = m.points[1].geometry;
      EXPECT_GE(std::max(g.depth, k.depth), -s.distance - exact) << "trial " << trial;
      EXPECT_GE(dot(g.normal, s.normal), 0.9999) << "trial " << trial;
    }
    EXPECT_EQ(collide(c, b, s.distance - tolerance(1e-6, 1e-5)).count, 0) << "trial " << trial;
  }
  EXPECT_GT(apart, 150);
}

// Overlapping pairs: translating the capsule by the depth along the normal
// leaves it touching, and no direction frees it with a shorter translation
// (each found by bisection with the independent distance).
TEST_F(CapsuleContactSeparation, overlapping_depth_is_the_shortest_way_out) {
  int overlapping = 0;
  for (int trial = 0; trial < 60 && overlapping < 20; ++trial) {
    const vector half{uniform(0.3, 1.2), uniform(0.3, 1.2), uniform(0.3, 1.2)};
    const placed_shape b = box(random_point(0.5), half, random_attitude());
    const real h = uniform(0, 1.2), r = uniform(0.05, 0.4);
    const placed_shape c = capsule(b.center + random_point(1.3), random_unit_vector(), h, r);
    const vector p = c.center - h * c.axis, q = c.center + h * c.axis;
    if (!(segment_box_distance(p, q, b) < r)) continue;
    ++overlapping;
    const detail::separation s = capsule_separation(c, b);
    ASSERT_LT(s.distance, 0) << "trial " << trial;
    const vector out = -s.distance * s.normal;
    EXPECT_NEAR(segment_box_distance(p + out, q + out, b), r, exact) << "trial " << trial;
    const auto way_out = [&](const vector& u) {
      real low = 0, high = 8;
      for (int i = 0; i < 45; ++i) {
        const real mid = (low + high) / 2;
        (segment_box_distance(p + mid * u, q + mid * u, b) < r ? low : high) = mid;
      }
      return high;
    };
    for (int k = 0; k < 40; ++k) {
      vector u = random_unit_vector();
      if (k % 2) u = (s.normal + 0.2 * u) / length(s.normal + 0.2 * u);  // near the normal
      EXPECT_GE(way_out(u), -s.distance - tolerance(1e-9, 1e-5)) << "trial " << trial << " direction " << k;
    }
    // Overlapping, they are in contact, with no margin.
    EXPECT_GE(collide(c, b).count, 1) << "trial " << trial;
  }
  EXPECT_EQ(overlapping, 20);
}

TEST_F(CapsuleContactSeparation, a_hull_of_a_boxs_corners_is_that_box) {
  for (int trial = 0; trial < 100; ++trial) {
    const vector half{uniform(0.2, 1.5), uniform(0.2, 1.5), uniform(0.2, 1.5)};
    std::vector<vector> corners;
    for (int i = 0; i < 8; ++i)
      corners.push_back({i & 1 ? half.e1() : -half.e1(), i & 2 ? half.e2() : -half.e2(),
                         i & 4 ? half.e3() : -half.e3()});
    const vector centre = random_point(1);
    const rotor attitude = random_attitude();
    const placed_shape b = box(centre, half, attitude);
    const placed_shape hull = keep_placed(shape::convex_hull(corners), centre, attitude);
    const placed_shape c =
        capsule(random_point(2.5), random_unit_vector(), uniform(0, 1.5), uniform(0.05, 0.5));
    const detail::separation sb = capsule_separation(c, b), sh = capsule_separation(c, hull);
    EXPECT_NEAR(sb.distance, sh.distance, closed_form_tolerance) << "trial " << trial;
    EXPECT_TRUE(near(sb.normal, sh.normal, tolerance(1e-9, 1e-5))) << "trial " << trial;
    const contact_manifold mb = collide(c, b, 0.1), mh = collide(c, hull, 0.1);
    ASSERT_EQ(mb.count, mh.count) << "trial " << trial;
    std::vector<real> depths_b, depths_h;
    for (int i = 0; i < mb.count; ++i) {
      depths_b.push_back(mb.points[i].geometry.depth);
      depths_h.push_back(mh.points[i].geometry.depth);
    }
    std::sort(depths_b.begin(), depths_b.end());
    std::sort(depths_h.begin(), depths_h.end());
    for (int i = 0; i < mb.count; ++i) EXPECT_NEAR(depths_b[i], depths_h[i], tolerance(1e-9, 1e-5));
  }
}

}  // namespace
}  // namespace gaphys::testing
