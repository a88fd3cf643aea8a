// The convex narrow phase of boxes and hulls against closed-form geometry: a
// box on a plane (its corners, their exact depths and ids), a box on a box
// (the overlap polygon's corners), crossing edges, the margin's speculative
// contacts, the direction of the normal, hulls, a sphere against a box's
// face, edge, corner and inside, and convex_separation and GJK distances
// against hand-computed ones. libccd checks the same code on random pairs
// (oracle/test_libccd_oracle.cpp).
#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

#include "convex_contact.hpp"
#include "engine_test_support.hpp"
#include "gjk.hpp"
#include "placed_shape_test.hpp"
#include "vec3.hpp"

namespace gaphys::testing {
namespace {

using detail::collide_convex;
using detail::convex_separation;
using detail::separation;

const real convex_closed_form_tolerance =
    tolerance(1e-12, 1e-6);  // closed forms a few operations deep

class convex_contact_test : public placed_shape_test {
 protected:
  static contact_manifold collide(const placed_shape& a, const placed_shape& b, real margin = 0) {
    contact_manifold m;
    m.count = -1;  // collide_convex must set it
    collide_convex(a, b, margin, m);
    return m;
  }
  // The box's corner with signs (sx, sy, sz) in the world.
  static vector corner(const vector& centre, const vector& h, const rotor& attitude, int sx, int sy,
                       int sz) {
    return centre + e3ga::apply(attitude, vector{sx * h.e1(), sy * h.e2(), sz * h.e3()});
  }
  static std::set<std::uint32_t> ids(const contact_manifold& m) {
    std::set<std::uint32_t> s;
    for (int i = 0; i < m.count; ++i) s.insert(m.points[i].feature);
    return s;
  }
};

// The suites, by the pair of features they meet.
using ConvexContactEdges = convex_contact_test;
using ConvexContactFaces = convex_contact_test;
using ConvexContactFrame = convex_contact_test;
using ConvexContactGjk = convex_contact_test;
using ConvexContactHulls = convex_contact_test;
using ConvexContactPlane = convex_contact_test;
using ConvexContactSeparation = convex_contact_test;
using ConvexContactSpeculative = convex_contact_test;
using ConvexContactSphere = convex_contact_test;

// Is `p` within `tol` of one of the points?
::testing::AssertionResult among(const vector& p, const std::vector<vector>& points, real tol) {
  for (const vector& q : points) {
    if (length(p - q) <= tol) return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure()
         << e3ga::basic_mv<real>(p) << " is none of the " << points.size() << " expected points";
}

// ---- Planes -------------------------------------------------------------------

// A box sunk 4 mm into the floor, turned about the vertical: its four lower
// corners, each 4 mm deep, the contact point midway between the corner and
// the floor, normal +z, four distinct ids; moved by a hair, the same ids.
TEST_F(ConvexContactPlane, box_on_plane_gives_its_four_corners) {
  const vector h{0.3, 0.2, 0.1};
  const rotor turn = about(e3, 0.7);
  const vector centre{0.5, -0.2, 0.1 - 0.004};
  const contact_manifold m = collide(box(centre, h, turn), floor(), 0.001);
  ASSERT_EQ(m.count, 4);
  std::vector<vector> expected;
  for (int sx : {-1, 1}) {
    for (int sy : {-1, 1}) expected.push_back(corner(centre, h, turn, sx, sy, -1) + 0.002 * e3);
  }
  for (int i = 0; i < 4; ++i) {
    const contact_geometry& g = m.points[i].geometry;
    EXPECT_NEAR(g.depth, 0.004, convex_closed_form_tolerance);
    EXPECT_TRUE(near(g.normal, e3, convex_closed_form_tolerance));
    EXPECT_TRUE(among(g.point, expected, convex_closed_form_tolerance));
    EXPECT_EQ(g.squared_radius, 0);
  }
  EXPECT_EQ(ids(m).size(), 4u);

  const contact_manifold moved =
      collide(box(centre + vector{1e-4, -2e-4, 1e-5}, h, about(e3, 0.7001)), floor(), 0.001);
  ASSERT_EQ(moved.count, 4);
  EXPECT_EQ(ids(moved), ids(m));
}

// Tilted about a horizontal axis, the corners sit at different depths: each
// is -z of the corner (the floor is z = 0), for the corners within the margin.
TEST_F(ConvexContactPlane, tilted_box_has_each_corner_at_its_own_depth) {
  const vector h{0.5, 0.3, 0.2};
  const rotor tilt = about(vector{1, 1, 0} / std::sqrt(real(2)), 0.05);
  const vector centre{0, 0, 0.2};
  const real margin = 0.1;
  const contact_manifold m = collide(box(centre, h, tilt), floor(), margin);
  std::vector<real> depths;
  for (int sx : {-1, 1}) {
    for (int sy : {-1, 1}) {
      for (int sz : {-1, 1}) {
        const vector c = corner(centre, h, tilt, sx, sy, sz);
        if (c.e3() <= margin) depths.push_back(-c.e3());
      }
    }
  }
  ASSERT_EQ(depths.size(), 4u);
  ASSERT_EQ(m.count, 4);
  for (int i = 0; i < 4; ++i) {
    const real d = m.points[i].geometry.depth;
    EXPECT_TRUE(
        std::any_of(depths.begin(), depths.end(),
                    [&](real x) { return std::fabs(x - d) <= convex_closed_form_tolerance; }))
        << "depth " << d;
    // Midway between the corner (z = -depth) and the floor.
    EXPECT_NEAR(m.points[i].geometry.point.e3(), -0.5 * d, convex_closed_form_tolerance);
  }
}

// The same pair given the other way round: the normal turns, nothing else.
TEST_F(ConvexContactPlane, plane_as_a_turns_the_normal) {
  const placed_shape b = box({0, 0, 0.09}, {0.1, 0.1, 0.1}, about(e2, 0.3));
  const contact_manifold m = collide(b, floor(), 0.01);
  const contact_manifold swapped = collide(floor(), b, 0.01);
  ASSERT_EQ(m.count, swapped.count);
  ASSERT_GT(m.count, 0);
  for (int i = 0; i < m.count; ++i) {
    EXPECT_TRUE(near(swapped.points[i].geometry.normal, -m.points[i].geometry.normal, 0));
    EXPECT_TRUE(near(swapped.points[i].geometry.point, m.points[i].geometry.point, 0));
    EXPECT_EQ(swapped.points[i].geometry.depth, m.points[i].geometry.depth);
  }
}

// A plate thinner than the margin (0.8 mm, margin 1 mm) lying on the floor,
// flat or tilted a little, and a coin (a 12-sided prism 0.6 mm thick): every
// corner is within the margin, but only the lower face's touch the floor.
// The manifold's points are those, at depth 0 (to the tilt's share), never
// an upper corner standing above one of them.
TEST_F(ConvexContactPlane, a_body_thinner_than_the_margin_touches_with_its_lower_face) {
  const real margin = 0.001;
  for (const real tilt : {real(0), real(0.004)}) {
    const vector h{0.05, 0.05, 0.0004};
    const rotor attitude = about(e1, tilt);
    // Lowest corner on the floor: the centre at h_z cos + h_y sin.
    const vector centre{0, 0, h.e3() * std::cos(tilt) + h.e2() * std::sin(tilt)};
    const contact_manifold m = collide(box(centre, h, attitude), floor(), margin);
    ASSERT_EQ(m.count, 4) << "tilt " << tilt;
    for (int i = 0; i < m.count; ++i) {
      EXPECT_EQ(m.points[i].feature & 4u, 0u) << "an upper corner, tilt " << tilt;  // bit 2: +z
      EXPECT_LE(-m.points[i].geometry.depth,
                2 * h.e2() * std::sin(tilt) + convex_closed_form_tolerance);
    }
  }
  std::vector<vector> coin;
  for (int k = 0; k < 12; ++k) {
    const real angle = real(2 * 3.14159265358979323846 / 12) * k;
    for (const real z : {real(-0.0003), real(0.0003)}) {
      coin.push_back(vector{real(0.01) * std::cos(angle), real(0.01) * std::sin(angle), z});
    }
  }
  const contact_manifold m = collide(hull(coin, vector{0, 0, 0.0003}), floor(), margin);
  ASSERT_GT(m.count, 2);
  for (int i = 0; i < m.count; ++i) {
    EXPECT_NEAR(m.points[i].geometry.depth, 0, convex_closed_form_tolerance) << "point " << i;
  }
}

// A box above the floor within the margin: speculative, depth = -gap; beyond
// it, nothing.
TEST_F(ConvexContactSpeculative, box_above_plane) {
  const vector h{0.2, 0.2, 0.2};
  const contact_manifold near_floor = collide(box({0, 0, 0.203}, h), floor(), 0.01);
  ASSERT_EQ(near_floor.count, 4);
  for (int i = 0; i < 4; ++i)
    EXPECT_NEAR(near_floor.points[i].geometry.depth, -0.003, convex_closed_form_tolerance);
  EXPECT_EQ(collide(box({0, 0, 0.211}, h), floor(), 0.01).count, 0);
}

// ---- Faces on faces ------------------------------------------------------------

// A 1 m cube sunk 1 cm into the top of a 2 x 2 x 1 m slab, offset so that
// part of it overhangs: the contact is the overlap square [0.3, 1] x [0.2, 1]
// of its bottom face with the slab's top, every corner 1 cm deep, contact
// points 5 mm below the slab's top (midway), normal +z.
TEST_F(ConvexContactFaces, overhanging_box_gives_the_overlap_square) {
  const placed_shape slab = box({0, 0, 0}, {1, 1, 0.5});
  const placed_shape cube = box({0.8, 0.7, 0.99}, {0.5, 0.5, 0.5});
  const contact_manifold m = collide(cube, slab, 0.001);
  ASSERT_EQ(m.count, 4);
  const std::vector<vector> overlap{
      {0.3, 0.2, 0.495}, {1, 0.2, 0.495}, {1, 1, 0.495}, {0.3, 1, 0.495}};
  for (int i = 0; i < 4; ++i) {
    EXPECT_TRUE(among(m.points[i].geometry.point, overlap, convex_closed_form_tolerance));
    EXPECT_NEAR(m.points[i].geometry.depth, 0.01, convex_closed_form_tolerance);
    EXPECT_TRUE(near(m.points[i].geometry.normal, e3, convex_closed_form_tolerance));
  }
  EXPECT_EQ(ids(m).size(), 4u);
}

// The cube turned 30 degrees about the vertical, wholly over the slab: its
// own four bottom corners. Turned 45 degrees and pushed over the slab's
// corner, its bottom square is cut to a pentagon by x <= 1 and y <= 1; the
// manifold keeps four of its five corners.
TEST_F(ConvexContactFaces, turned_box_gives_its_corners_or_the_cut_polygon) {
  const placed_shape slab = box({0, 0, 0}, {1, 1, 0.5});
  const vector h{0.5, 0.5, 0.5};
  const rotor turn = about(e3, M_PI / 6);
  const vector centre{0.1, -0.2, 0.99};
  const contact_manifold inside = collide(box(centre, h, turn), slab, 0.001);
  ASSERT_EQ(inside.count, 4);
  std::vector<vector> corners;
  for (int sx : {-1, 1}) {
    for (int sy : {-1, 1}) corners.push_back(corner(centre, h, turn, sx, sy, -1) + 0.005 * e3);
  }
  for (int i = 0; i < 4; ++i) {
    EXPECT_TRUE(among(inside.points[i].geometry.point, corners, convex_closed_form_tolerance));
  }
  EXPECT_EQ(ids(inside).size(), 4u);

  // The diamond |x - 0.9| + |y - 0.9| <= r, r = 0.5 sqrt 2, cut by x <= 1 and
  // y <= 1: corners (0.9 - r, 0.9), (0.9, 0.9 - r), (1, 0.9 - r + 0.1),
  // (1, 1), (0.9 - r + 0.1, 1).
  const real r = 0.5 * std::sqrt(real(2));
  const contact_manifold cut = collide(box({0.9, 0.9, 0.99}, h, about(e3, M_PI / 4)), slab, 0.001);
  const std::vector<vector> pentagon{{real(0.9) - r, 0.9, 0.495},
                                     {0.9, real(0.9) - r, 0.495},
                                     {1, 1 - r, 0.495},
                                     {1, 1, 0.495},
                                     {1 - r, 1, 0.495}};
  ASSERT_EQ(cut.count, 4);
  for (int i = 0; i < 4; ++i) {
    EXPECT_TRUE(among(cut.points[i].geometry.point, pentagon, tolerance(1e-12, 1e-6)));
    EXPECT_NEAR(cut.points[i].geometry.depth, 0.01, convex_closed_form_tolerance);
  }
  EXPECT_EQ(ids(cut).size(), 4u);
}

// A box resting on a box keeps its four ids while it slides and sinks by
// hairs (nothing changes topologically), and swapping A and B turns the
// normal and keeps the points.
TEST_F(ConvexContactFaces, resting_box_keeps_its_ids_and_swaps_cleanly) {
  const vector h{0.4, 0.3, 0.2};
  const placed_shape lower = box({0, 0, 0}, {1, 1, 0.2}, about(e3, 0.2));
  std::set<std::uint32_t> first;
  for (int step = 0; step < 20; ++step) {
    const vector centre{real(0.01 * step), real(-0.005 * step),
                        real(0.4 - 0.001 - 1e-5 * (step % 3))};
    const placed_shape upper = box(centre, h, about(e3, 0.5 + 1e-3 * step));
    const contact_manifold m = collide(upper, lower, 0.002);
    ASSERT_EQ(m.count, 4) << "step " << step;
    if (step == 0) first = ids(m);
    EXPECT_EQ(ids(m), first) << "step " << step;

    const contact_manifold swapped = collide(lower, upper, 0.002);
    ASSERT_EQ(swapped.count, 4);
    for (int i = 0; i < 4; ++i) {
      EXPECT_TRUE(near(m.points[i].geometry.normal, e3, convex_closed_form_tolerance));
      EXPECT_TRUE(near(swapped.points[i].geometry.normal, -e3, convex_closed_form_tolerance));
      std::vector<vector> points;
      for (int k = 0; k < 4; ++k) points.push_back(m.points[k].geometry.point);
      EXPECT_TRUE(among(swapped.points[i].geometry.point, points, convex_closed_form_tolerance));
    }
  }
}

// ---- Edges ---------------------------------------------------------------------

// Two unit cubes stood on edge, A's top-to-bottom edge along x, B's along
// y, crossing 1 cm deep: one point midway between the two edges (on the
// vertical through both), normal +z, depth 1 cm; raised 5 mm apart, the
// same point with depth -5 mm within the margin, nothing beyond it.
TEST_F(ConvexContactEdges, crossing_edges_give_one_point) {
  const vector h{0.5, 0.5, 0.5};
  const real reach = 0.5 * std::sqrt(real(2));  // centre to edge of a cube on its edge
  const rotor on_edge_x = about(e1, M_PI / 4), on_edge_y = about(e2, M_PI / 4);
  const placed_shape b = box({0, 0, 0}, h, on_edge_y);
  for (real gap : {-0.01, 0.005}) {
    const placed_shape a = box({0, 0, 2 * reach + gap}, h, on_edge_x);
    const contact_manifold m = collide(a, b, 0.01);
    ASSERT_EQ(m.count, 1) << "gap " << gap;
    EXPECT_NEAR(m.points[0].geometry.depth, -gap, convex_closed_form_tolerance);
    EXPECT_TRUE(near(m.points[0].geometry.normal, e3, convex_closed_form_tolerance));
    EXPECT_TRUE(near(m.points[0].geometry.point, vector{0, 0, reach + real(0.5) * gap},
                     convex_closed_form_tolerance));

    const contact_manifold swapped = collide(b, a, 0.01);
    ASSERT_EQ(swapped.count, 1);
    EXPECT_TRUE(near(swapped.points[0].geometry.normal, -e3, convex_closed_form_tolerance));
    EXPECT_NEAR(swapped.points[0].geometry.depth, -gap, convex_closed_form_tolerance);
  }
  EXPECT_EQ(collide(box({0, 0, 2 * reach + real(0.011)}, h, on_edge_x), b, 0.01).count, 0);
}

// Box against box apart by 5 mm face to face: speculative within a 1 cm
// margin, nothing within 4 mm.
TEST_F(ConvexContactSpeculative, boxes_apart) {
  const placed_shape b = box({0, 0, 0}, {1, 1, 0.5});
  const placed_shape a = box({0.2, 0.1, 1.005}, {0.5, 0.5, 0.5}, about(e3, 0.3));
  const contact_manifold m = collide(a, b, 0.01);
  ASSERT_EQ(m.count, 4);
  for (int i = 0; i < 4; ++i)
    EXPECT_NEAR(m.points[i].geometry.depth, -0.005, convex_closed_form_tolerance);
  EXPECT_EQ(collide(a, b, 0.004).count, 0);
}

// ---- Hulls ---------------------------------------------------------------------

// The hull of a box's corners behaves as the box: same points and depths.
TEST_F(ConvexContactHulls, hull_of_box_corners_matches_the_box) {
  const vector h{0.3, 0.4, 0.25};
  std::vector<vector> corners;
  for (int i = 0; i < 8; ++i) {
    corners.push_back(
        {(i & 1) ? h.e1() : -h.e1(), (i & 2) ? h.e2() : -h.e2(), (i & 4) ? h.e3() : -h.e3()});
  }
  const placed_shape slab = box({0, 0, 0}, {1, 1, 0.2});
  const vector centre{0.1, 0.2, 0.2 + 0.25 - 0.003};
  const rotor turn = about(e3, 0.4);
  const contact_manifold as_box = collide(box(centre, h, turn), slab, 0.001);
  const contact_manifold as_hull = collide(hull(corners, centre, turn), slab, 0.001);
  ASSERT_EQ(as_box.count, 4);
  ASSERT_EQ(as_hull.count, 4);
  std::vector<vector> box_points;
  for (int i = 0; i < 4; ++i) box_points.push_back(as_box.points[i].geometry.point);
  for (int i = 0; i < 4; ++i) {
    EXPECT_TRUE(among(as_hull.points[i].geometry.point, box_points, convex_closed_form_tolerance));
    EXPECT_NEAR(as_hull.points[i].geometry.depth, 0.003, convex_closed_form_tolerance);
  }
}

// An octahedron standing on a vertex, sunk 2 mm into a hull of a slab: one
// point, at the vertex, 2 mm deep; and on a plane, the same.
TEST_F(ConvexContactHulls, octahedron_on_its_vertex) {
  const std::vector<vector> octahedron{{0.3, 0, 0},  {-0.3, 0, 0}, {0, 0.3, 0},
                                       {0, -0.3, 0}, {0, 0, 0.3},  {0, 0, -0.3}};
  const std::vector<vector> slab{{-1, -1, -0.5}, {1, -1, -0.5}, {-1, 1, -0.5}, {1, 1, -0.5},
                                 {-1, -1, 0},    {1, -1, 0},    {-1, 1, 0},    {1, 1, 0}};
  const placed_shape a = hull(octahedron, {0.1, -0.2, 0.298}, about(e3, 0.3));
  for (const placed_shape& b : {hull(slab, {}), floor()}) {
    const contact_manifold m = collide(a, b, 0.001);
    ASSERT_EQ(m.count, 1);
    EXPECT_NEAR(m.points[0].geometry.depth, 0.002, convex_closed_form_tolerance);
    EXPECT_TRUE(near(m.points[0].geometry.normal, e3, convex_closed_form_tolerance));
    EXPECT_TRUE(
        near(m.points[0].geometry.point, vector{0.1, -0.2, -0.001}, convex_closed_form_tolerance));
  }
}

// A wheel of 64 sides (a prism along y, radius 0.5 m, 1 m wide) lying on
// the floor on the corners at its bottom, 1.5 mm deep, one end 1 mm lower,
// with the wide margin of a wheel rolling at 60 Hz: of the corners
// within it, the four kept hold both touching corners, one at each end. (The
// corner farthest from the deepest was one 4 cm up at the other end, and the
// wheel, left on one touching corner, sank 3 cm rolling at 60 Hz.)
TEST_F(ConvexContactHulls, a_wheel_on_its_bottom_edge_keeps_a_corner_at_each_end) {
  std::vector<vector> wheel;
  const int sides = 64;
  for (int i = 0; i < sides; ++i) {
    const real angle = 2 * real(M_PI) * i / sides;
    for (const real y : {real(-0.5), real(0.5)}) {
      wheel.push_back({real(0.5) * std::cos(angle), y, real(0.5) * std::sin(angle)});
    }
  }
  const real camber = 0.001;  // rad, about the rolling direction x
  const placed_shape w = hull(wheel, {0.2, 0.1, real(0.5) - real(0.0015)}, about(e1, camber));
  const contact_manifold m = collide(w, floor(), 0.06);
  ASSERT_EQ(m.count, 4);
  int touching_low_end = 0, touching_high_end = 0;
  for (int i = 0; i < m.count; ++i) {
    const contact_geometry& g = m.points[i].geometry;
    if (g.depth <= 0) continue;
    EXPECT_NEAR(x(g.point), 0.2, convex_closed_form_tolerance);
    (y(g.point) < 0.1 ? touching_low_end : touching_high_end) += 1;
  }
  EXPECT_EQ(touching_low_end, 1);
  EXPECT_EQ(touching_high_end, 1);
}

// A random hull sunk into the floor: its deepest contact is its lowest
// point, whatever the hull.
TEST_F(ConvexContactHulls, random_hull_on_plane_reaches_its_lowest_point) {
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<vector> points;
    for (int i = 0; i < 16; ++i) points.push_back({uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)});
    const rotor attitude = about(random_unit_vector(), uniform(-3, 3));
    const vector centre{uniform(-1, 1), uniform(-1, 1), uniform(0.2, 1)};
    real lowest = INFINITY;
    for (const vector& p : points)
      lowest = std::min(lowest, (centre + e3ga::apply(attitude, p)).e3());
    const contact_manifold m = collide(hull(points, centre, attitude), floor(), 0);
    if (lowest > 0) {
      EXPECT_EQ(m.count, 0);
      continue;
    }
    ASSERT_GT(m.count, 0);
    real deepest = 0;
    for (int i = 0; i < m.count; ++i) deepest = std::max(deepest, m.points[i].geometry.depth);
    EXPECT_NEAR(deepest, -lowest, convex_closed_form_tolerance) << "trial " << trial;
  }
}

// ---- Spheres and points ----------------------------------------------------------

// A sphere over a box's face, edge and corner (the nearest point of the box
// is the centre clamped to it), and with its centre inside (the face it is
// least deep under).
TEST_F(ConvexContactSphere, face_edge_corner_and_inside) {
  const vector h{0.5, 0.4, 0.3};
  const rotor turn = about(vector{1, 2, 3} / std::sqrt(real(14)), 0.8);
  const vector centre{0.2, -0.1, 0.4};
  const placed_shape b = box(centre, h, turn);
  const real radius = 0.2;
  struct region {
    vector local_centre;  // the sphere's centre in the box's frame
    real margin;
  };
  for (const region& r : {region{{0.1, 0.2, 0.45}, 0}, region{{0.6, 0.1, 0.4}, 0.1},
                          region{{0.62, 0.5, -0.4}, 0.1}, region{{-0.4, 0.1, 0.55}, 0.1}}) {
    const vector c = r.local_centre;
    const vector clamped{std::clamp(c.e1(), -h.e1(), h.e1()), std::clamp(c.e2(), -h.e2(), h.e2()),
                         std::clamp(c.e3(), -h.e3(), h.e3())};
    const real distance = length(c - clamped);
    const vector world_centre = centre + e3ga::apply(turn, c);
    const vector n = e3ga::apply(turn, (c - clamped) / distance);  // from the box to the sphere
    for (bool sphere_first : {true, false}) {
      const placed_shape s = sphere(world_centre, radius);
      const contact_manifold m = sphere_first ? collide(s, b, r.margin) : collide(b, s, r.margin);
      ASSERT_EQ(m.count, 1);
      const contact_geometry& g = m.points[0].geometry;
      EXPECT_NEAR(g.depth, radius - distance, convex_closed_form_tolerance);
      EXPECT_TRUE(near(g.normal, sphere_first ? n : -n, convex_closed_form_tolerance));
      const vector on_box = centre + e3ga::apply(turn, clamped);
      EXPECT_TRUE(
          near(g.point, 0.5 * (on_box + world_centre - radius * n), convex_closed_form_tolerance));
    }
  }
  // Centre inside, nearest the +y face (0.05 below it): depth r + 0.05.
  const vector inside = centre + e3ga::apply(turn, vector{0.1, 0.35, 0.1});
  const contact_manifold m = collide(sphere(inside, radius), b);
  ASSERT_EQ(m.count, 1);
  EXPECT_NEAR(m.points[0].geometry.depth, radius + 0.05, convex_closed_form_tolerance);
  EXPECT_TRUE(
      near(m.points[0].geometry.normal, e3ga::apply(turn, e2), convex_closed_form_tolerance));
}

// A point shape is a sphere of radius 0.
TEST_F(ConvexContactSphere, point_on_box) {
  const placed_shape b = box({0, 0, 0}, {1, 1, 1});
  const placed_shape p = place(shape::point(), vector{0.3, 0.2, 0.99}, identity);
  const contact_manifold m = collide(p, b);
  ASSERT_EQ(m.count, 1);
  EXPECT_NEAR(m.points[0].geometry.depth, 0.01, convex_closed_form_tolerance);
  EXPECT_TRUE(near(m.points[0].geometry.normal, e3, convex_closed_form_tolerance));
  EXPECT_EQ(collide(place(shape::point(), vector{0.3, 0.2, 1.01}, identity), b).count, 0);
}

// ---- Separation ---------------------------------------------------------------------

// Two axis-aligned boxes apart diagonally: the distance is the length of the
// per-axis gaps; overlapping along one axis least: minus that overlap, along
// it; and turned 45 degrees about z, a corner against a face.
TEST_F(ConvexContactSeparation, boxes_against_closed_forms) {
  const vector ha{0.5, 0.4, 0.3}, hb{0.2, 0.3, 0.4};
  const placed_shape b = box({0, 0, 0}, hb);
  const vector gaps{0.1, 0.05, 0.2};
  const separation apart = convex_separation(
      box(vector{ha.e1() + hb.e1(), ha.e2() + hb.e2(), ha.e3() + hb.e3()} + gaps, ha), b);
  EXPECT_NEAR(apart.distance, length(gaps), convex_closed_form_tolerance);
  EXPECT_TRUE(near(apart.normal, gaps / length(gaps), tolerance(1e-9, 1e-5)));

  const separation overlapping = convex_separation(box({0.69, 0.1, 0.05}, ha), b);
  EXPECT_NEAR(overlapping.distance, -0.01, convex_closed_form_tolerance);
  EXPECT_TRUE(near(overlapping.normal, e1, convex_closed_form_tolerance));
  const separation reversed = convex_separation(b, box({0.69, 0.1, 0.05}, ha));
  EXPECT_NEAR(reversed.distance, -0.01, convex_closed_form_tolerance);
  EXPECT_TRUE(near(reversed.normal, -e1, convex_closed_form_tolerance));

  // A's corner (its half diagonal in x: 0.5 sqrt 2 for a 0.5 x 0.5 square)
  // 3 mm from B's +x face.
  const real reach = 0.5 * std::sqrt(real(2));
  const separation corner_to_face = convex_separation(
      box({hb.e1() + reach + real(0.003), 0, 0}, {0.5, 0.5, 0.1}, about(e3, M_PI / 4)), b);
  EXPECT_NEAR(corner_to_face.distance, 0.003, convex_closed_form_tolerance);
  EXPECT_TRUE(near(corner_to_face.normal, e1, tolerance(1e-9, 1e-5)));
}

TEST_F(ConvexContactSeparation, sphere_and_plane) {
  const placed_shape b = box({0, 0, 0}, {0.5, 0.5, 0.5}, about(e3, 0.3));
  const separation s = convex_separation(sphere({0, 0, 1}, 0.25), b);
  EXPECT_NEAR(s.distance, 0.25, convex_closed_form_tolerance);
  EXPECT_TRUE(near(s.normal, e3, convex_closed_form_tolerance));
  const separation p = convex_separation(floor(-0.6), b);
  EXPECT_NEAR(p.distance, 0.1, convex_closed_form_tolerance);
  EXPECT_TRUE(near(p.normal, -e3, convex_closed_form_tolerance));
}

// ---- GJK ------------------------------------------------------------------------------

// GJK between a point and a box against the clamped closed form, and
// between two segments against their hand-computed distance.
TEST_F(ConvexContactGjk, distances_against_closed_forms) {
  for (int trial = 0; trial < 500; ++trial) {
    const vector h{uniform(0.1, 1), uniform(0.1, 1), uniform(0.1, 1)};
    const vector p{uniform(-3, 3), uniform(-3, 3), uniform(-3, 3)};
    auto box_support = [&](const vector& d) {
      return vector{d.e1() >= 0 ? h.e1() : -h.e1(), d.e2() >= 0 ? h.e2() : -h.e2(),
                    d.e3() >= 0 ? h.e3() : -h.e3()};
    };
    auto point_support = [&](const vector&) { return p; };
    const detail::gjk_result r = detail::gjk_distance(detail::make_support(point_support),
                                                      detail::make_support(box_support));
    const vector clamped{std::clamp(p.e1(), -h.e1(), h.e1()), std::clamp(p.e2(), -h.e2(), h.e2()),
                         std::clamp(p.e3(), -h.e3(), h.e3())};
    const real exact = length(p - clamped);
    if (exact == 0) {
      EXPECT_TRUE(r.overlap);
      continue;
    }
    ASSERT_FALSE(r.overlap) << "trial " << trial;
    EXPECT_NEAR(r.distance, exact, convex_closed_form_tolerance) << "trial " << trial;
    EXPECT_TRUE(near(r.point_b, clamped, tolerance(1e-12, 1e-6)));
    EXPECT_TRUE(near(r.normal, (p - clamped) / exact, tolerance(1e-9, 1e-5)));
  }
  // Skew segments: x axis and the line y, at height z.
  const detail::segment x_axis{{-1, 0, 0}, {1, 0, 0}};
  for (real z : {0.0, 0.3, 1.2}) {
    const detail::segment other{{0.2, -1, z}, {0.2, 1, z}};
    const detail::gjk_result r =
        detail::gjk_distance(detail::segment_support(x_axis), detail::segment_support(other));
    EXPECT_NEAR(r.distance, z, convex_closed_form_tolerance);
    EXPECT_EQ(r.overlap, z == 0);
  }
}

// ---- The plain frame the narrow phase computes in --------------------------------------

// frame_of's matrix, written out from the rotor's coefficients, turns
// vectors as the algebra's sandwich R x ~R does, and unrotate undoes it.
TEST_F(ConvexContactFrame, rigid_frame_matches_the_rotor) {
  for (int trial = 0; trial < 200; ++trial) {
    const rotor r = about(random_unit_vector(), uniform(-3.2, 3.2));
    const vector origin{uniform(-2, 2), uniform(-2, 2), uniform(-2, 2)};
    const vector x{uniform(-2, 2), uniform(-2, 2), uniform(-2, 2)};
    const detail::rigid_frame f = detail::frame_of(r, origin);
    const vector turned = detail::to_vector(f.to_world(detail::to_vec3(x)));
    EXPECT_TRUE(near(turned, origin + e3ga::apply(r, x), tolerance(1e-14, 1e-6)));
    EXPECT_TRUE(near(detail::to_vector(f.to_local(detail::to_vec3(turned))), x, tolerance(1e-14, 5e-6)));
  }
}

}  // namespace
}  // namespace gaphys::testing
