// Shapes and their polyhedra. A hull is checked against what defines it:
// every given point inside or on every face plane, every corner one of the
// points, faces flat, convex and counter-clockwise from outside, each edge
// between the two faces that walk it, and Euler's V - E + F = 2. Known
// solids (cube, tetrahedron, icosahedron, dodecahedron) must come out with
// their known faces; degenerate inputs must be rejected with a reason.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "engine_test_support.hpp"

namespace gaphys::testing {
namespace {

// Plain arithmetic in the checks' inner loops: the instrumented algebra
// records every call, and these loops make millions.
real inner(const vector& a, const vector& b) { return x(a) * x(b) + y(a) * y(b) + z(a) * z(b); }

vector cross(const vector& a, const vector& b) {
  return {y(a) * z(b) - z(a) * y(b), z(a) * x(b) - x(a) * z(b), x(a) * y(b) - y(a) * x(b)};
}

std::vector<std::uint32_t> corners_of(const convex_polyhedron& p, const polyhedron_face& f) {
  return {p.vertex_indices.begin() + f.first, p.vertex_indices.begin() + f.first + f.count};
}

// Every structural promise of convex_polyhedron, to within `allowed`
// (a length): the faces' planes, winding and convexity, the edge list, the
// radius, Euler's formula, and every corner inside every face plane.
::testing::AssertionResult well_formed(const convex_polyhedron& p, real allowed) {
  const std::size_t v = p.vertices.size(), f = p.faces.size();
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> walked_by;
  std::vector<int> uses(v, 0);
  std::size_t corner_total = 0;
  for (std::uint32_t i = 0; i < f; ++i) {
    const polyhedron_face& face = p.faces[i];
    if (face.count < 3 || face.first + face.count > p.vertex_indices.size()) {
      return ::testing::AssertionFailure() << "face " << i << " has a bad corner range";
    }
    const auto corners = corners_of(p, face);
    if (std::set<std::uint32_t>(corners.begin(), corners.end()).size() != corners.size()) {
      return ::testing::AssertionFailure() << "face " << i << " repeats a corner";
    }
    corner_total += corners.size();
    if (std::fabs(length(face.normal) - 1) > tolerance(1e-12, 1e-6)) {
      return ::testing::AssertionFailure() << "face " << i << " normal is not unit";
    }
    // The polygon's own normal (its fan's summed cross products) must agree:
    // counter-clockwise seen from outside.
    vector newell{};
    const vector& origin = p.vertices.at(corners[0]);
    for (std::size_t k = 1; k + 1 < corners.size(); ++k) {
      newell = newell +
               cross(p.vertices.at(corners[k]) - origin, p.vertices.at(corners[k + 1]) - origin);
    }
    if (dot(newell / length(newell), face.normal) < 1 - tolerance(1e-9, 1e-5)) {
      return ::testing::AssertionFailure()
             << "face " << i << " is not counter-clockwise about its normal";
    }
    for (std::size_t k = 0; k < corners.size(); ++k) {
      const vector& a = p.vertices[corners[k]];
      const vector& b = p.vertices[corners[(k + 1) % corners.size()]];
      const vector& c = p.vertices[corners[(k + 2) % corners.size()]];
      if (std::fabs(dot(face.normal, a) - face.offset) > allowed) {
        return ::testing::AssertionFailure()
               << "face " << i << " corner off its plane by " << dot(face.normal, a) - face.offset;
      }
      if (dot(cross(b - a, c - b), face.normal) < -allowed * length(c - b)) {
        return ::testing::AssertionFailure() << "face " << i << " is not convex";
      }
      ++uses[corners[k]];
      if (!walked_by.emplace(std::pair{corners[k], corners[(k + 1) % corners.size()]}, i).second) {
        return ::testing::AssertionFailure() << "an edge is walked twice the same way";
      }
    }
    for (std::size_t k = 0; k < v; ++k) {
      if (inner(face.normal, p.vertices[k]) > face.offset + allowed) {
        return ::testing::AssertionFailure() << "corner " << k << " outside face " << i;
      }
    }
  }
  for (std::size_t k = 0; k < v; ++k) {
    if (uses[k] < 3)
      return ::testing::AssertionFailure() << "corner " << k << " is on fewer than 3 faces";
  }
  if (p.edges.size() * 2 != corner_total) {
    return ::testing::AssertionFailure()
           << p.edges.size() << " edges for " << corner_total << " face sides";
  }
  std::set<std::pair<std::uint32_t, std::uint32_t>> seen;
  for (const polyhedron_edge& e : p.edges) {
    const auto left = walked_by.find({e.tail, e.head});
    const auto right = walked_by.find({e.head, e.tail});
    if (left == walked_by.end() || right == walked_by.end() || left->second != e.left ||
        right->second != e.right) {
      return ::testing::AssertionFailure()
             << "edge " << e.tail << "-" << e.head << " has wrong faces";
    }
    if (!seen.insert({std::min(e.tail, e.head), std::max(e.tail, e.head)}).second) {
      return ::testing::AssertionFailure() << "edge " << e.tail << "-" << e.head << " listed twice";
    }
  }
  if (static_cast<long>(v) - static_cast<long>(p.edges.size()) + static_cast<long>(f) != 2) {
    return ::testing::AssertionFailure()
           << "V - E + F = " << v << " - " << p.edges.size() << " + " << f;
  }
  real radius = 0;
  for (const vector& c : p.vertices) radius = std::max(radius, length(c));
  if (p.bounding_radius != radius) {
    return ::testing::AssertionFailure()
           << "bounding radius " << p.bounding_radius << " != " << radius;
  }
  return ::testing::AssertionSuccess();
}

// The size of the points' bounding box, the scale of every tolerance here.
real size_of(const std::vector<vector>& points) {
  real size = 0;
  for (const vector& a : points) {
    for (const vector& b : points) {
      size =
          std::max({size, std::fabs(x(a) - x(b)), std::fabs(y(a) - y(b)), std::fabs(z(a) - z(b))});
    }
  }
  return size;
}

// The hull of `points`: the polyhedron contains them all and its corners are
// among them, exactly.
::testing::AssertionResult hull_of(const convex_polyhedron& p, const std::vector<vector>& points,
                                   real allowed) {
  for (const vector& c : p.vertices) {
    const bool given = std::any_of(points.begin(), points.end(), [&](const vector& q) {
      return x(q) == x(c) && y(q) == y(c) && z(q) == z(c);
    });
    if (!given)
      return ::testing::AssertionFailure()
             << "corner " << e3ga::basic_mv<real>(c) << " is not a given point";
  }
  for (std::size_t i = 0; i < points.size(); ++i) {
    for (const polyhedron_face& f : p.faces) {
      const real above = inner(f.normal, points[i]) - f.offset;
      if (above > allowed) {
        return ::testing::AssertionFailure()
               << "point " << i << " is " << above << " outside a face";
      }
    }
  }
  return ::testing::AssertionSuccess();
}

class HullTest : public engine_test {
 protected:
  std::vector<vector> box_corners(const vector& h) {
    std::vector<vector> corners;
    for (int i = 0; i < 8; ++i) {
      corners.push_back({i & 1 ? x(h) : -x(h), i & 2 ? y(h) : -y(h), i & 4 ? z(h) : -z(h)});
    }
    return corners;
  }

  // The box's corners among points inside it, on its faces and on its
  // edges, repeated, in a shuffled order.
  std::vector<vector> cluttered_box(const vector& h) {
    std::vector<vector> points = box_corners(h);
    for (int axis = 0; axis < 3; ++axis) {
      for (real side : {-1.0, 1.0}) {
        vector centre{};
        centre.c[axis] = side * h.c[axis];
        points.push_back(centre);      // face centre
        for (int k = 0; k < 5; ++k) {  // on the face
          vector q{uniform(-x(h), x(h)), uniform(-y(h), y(h)), uniform(-z(h), z(h))};
          q.c[axis] = side * h.c[axis];
          points.push_back(q);
        }
        for (real other : {-1.0, 1.0}) {  // edge midpoints and other points on edges
          vector m = centre;
          m.c[(axis + 1) % 3] = other * h.c[(axis + 1) % 3];
          points.push_back(m);
          m.c[(axis + 2) % 3] = uniform(-1, 1) * h.c[(axis + 2) % 3];
          points.push_back(m);
        }
      }
    }
    for (int k = 0; k < 40; ++k)
      points.push_back({uniform(-x(h), x(h)), uniform(-y(h), y(h)), uniform(-z(h), z(h))});
    const std::vector<vector> corners = box_corners(h);
    points.insert(points.end(), corners.begin(), corners.end());  // duplicates
    std::shuffle(points.begin(), points.end(), random);
    return points;
  }

  std::vector<vector> ball_points(int count) {
    std::vector<vector> points;
    while (points.size() < static_cast<std::size_t>(count)) {
      const vector q{uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)};
      if (length(q) <= 1) points.push_back(q);
    }
    return points;
  }
};

TEST_F(HullTest, of_a_cluttered_box_is_the_box) {
  const vector h{0.5, 1.5, 2};
  const std::vector<vector> points = cluttered_box(h);
  const convex_polyhedron p = convex_polyhedron::hull(points);
  ASSERT_TRUE(well_formed(p, tolerance(1e-12, 1e-6)));
  EXPECT_TRUE(hull_of(p, points, tolerance(1e-12, 1e-6)));
  EXPECT_EQ(p.vertices.size(), 8u);
  EXPECT_EQ(p.edges.size(), 12u);
  ASSERT_EQ(p.faces.size(), 6u);
  std::set<std::pair<int, real>> planes;  // (axis * sign, offset)
  for (const polyhedron_face& f : p.faces) {
    EXPECT_EQ(f.count, 4u);
    for (int axis = 0; axis < 3; ++axis) {
      if (std::fabs(f.normal.c[axis]) == 1)
        planes.insert({f.normal.c[axis] > 0 ? axis + 1 : -axis - 1, f.offset});
    }
  }
  const std::set<std::pair<int, real>> box_planes{{1, 0.5},  {-1, 0.5}, {2, 1.5},
                                                  {-2, 1.5}, {3, 2},    {-3, 2}};
  EXPECT_EQ(planes, box_planes);
  for (const vector& c : p.vertices) {
    EXPECT_EQ(std::fabs(x(c)), x(h));
    EXPECT_EQ(std::fabs(y(c)), y(h));
    EXPECT_EQ(std::fabs(z(c)), z(h));
  }
}

// Turned, the box's coplanar points are coplanar only to rounding: the
// faces must still merge to 6 quadrilaterals and the clutter drop out.
TEST_F(HullTest, of_a_turned_cluttered_box_merges_rounded_faces) {
  const rotor r = about(vector{1, 2, 3} / std::sqrt(real(14)), 0.7);
  std::vector<vector> points = cluttered_box(vector{1, 2, 3});
  for (vector& q : points) q = e3ga::apply(r, q) + vector{10, -20, 5};
  const convex_polyhedron p = convex_polyhedron::hull(points);
  const real size = size_of(points);
  ASSERT_TRUE(well_formed(p, tolerance(1e-9, 1e-5) * size));
  EXPECT_TRUE(hull_of(p, points, tolerance(1e-9, 1e-5) * size));
  EXPECT_EQ(p.vertices.size(), 8u);
  EXPECT_EQ(p.edges.size(), 12u);
  ASSERT_EQ(p.faces.size(), 6u);
  for (const polyhedron_face& f : p.faces) EXPECT_EQ(f.count, 4u);
}

TEST_F(HullTest, of_random_points_holds_them_all_and_is_made_of_them) {
  const std::vector<vector> points = ball_points(2000);
  const convex_polyhedron p = convex_polyhedron::hull(points);
  ASSERT_TRUE(well_formed(p, tolerance(1e-9, 5e-5)));
  EXPECT_TRUE(hull_of(p, points, tolerance(1e-9, 5e-5)));
  EXPECT_GT(p.vertices.size(), 50u);
  EXPECT_LT(p.vertices.size(), points.size());
}

// Points on a sphere are all corners; with a few thousand of them the hull
// is also quick.
TEST_F(HullTest, of_points_on_a_sphere_keeps_every_point) {
  std::vector<vector> points;
  for (int i = 0; i < 1000; ++i) points.push_back(2 * random_unit_vector());
  const convex_polyhedron p = convex_polyhedron::hull(points);
  ASSERT_TRUE(well_formed(p, tolerance(1e-9, 5e-5)));
  EXPECT_TRUE(hull_of(p, points, tolerance(1e-9, 5e-5)));
  EXPECT_EQ(p.vertices.size(), points.size());
}

TEST_F(HullTest, is_the_same_for_the_same_points_in_any_order) {
  std::vector<vector> points = ball_points(300);
  const convex_polyhedron first = convex_polyhedron::hull(points);
  const convex_polyhedron again = convex_polyhedron::hull(points);
  ASSERT_EQ(first.vertices.size(), again.vertices.size());
  for (std::size_t i = 0; i < first.vertices.size(); ++i) {
    EXPECT_EQ(first.vertices[i].c, again.vertices[i].c);
  }
  EXPECT_EQ(first.vertex_indices, again.vertex_indices);
  ASSERT_EQ(first.faces.size(), again.faces.size());
  for (std::size_t i = 0; i < first.faces.size(); ++i) {
    EXPECT_EQ(first.faces[i].offset, again.faces[i].offset);
    EXPECT_EQ(first.faces[i].first, again.faces[i].first);
  }
  ASSERT_EQ(first.edges.size(), again.edges.size());
  for (std::size_t i = 0; i < first.edges.size(); ++i) {
    EXPECT_EQ(first.edges[i].tail, again.edges[i].tail);
    EXPECT_EQ(first.edges[i].left, again.edges[i].left);
  }

  // Shuffled, the same faces as sets of corner positions.
  auto face_set = [](const convex_polyhedron& p) {
    std::set<std::set<std::array<real, 3>>> faces;
    for (const polyhedron_face& f : p.faces) {
      std::set<std::array<real, 3>> corners;
      for (std::uint32_t c : corners_of(p, f)) {
        corners.insert({x(p.vertices[c]), y(p.vertices[c]), z(p.vertices[c])});
      }
      faces.insert(corners);
    }
    return faces;
  };
  std::shuffle(points.begin(), points.end(), random);
  EXPECT_EQ(face_set(first), face_set(convex_polyhedron::hull(points)));
}

TEST_F(HullTest, of_a_tetrahedron_is_it) {
  const std::vector<vector> points{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const convex_polyhedron p = convex_polyhedron::hull(points);
  ASSERT_TRUE(well_formed(p, tolerance(1e-12, 1e-6)));
  EXPECT_EQ(p.vertices.size(), 4u);
  EXPECT_EQ(p.edges.size(), 6u);
  ASSERT_EQ(p.faces.size(), 4u);
  std::multiset<real> offsets;
  for (const polyhedron_face& f : p.faces) offsets.insert(f.offset);
  // Three faces through the origin, one at distance 1/sqrt(3).
  EXPECT_EQ(offsets.count(0), 3u);
  EXPECT_NEAR(*offsets.rbegin(), 1 / std::sqrt(real(3)), tolerance(1e-15, 1e-7));
}

// (0, +-1, +-phi) and its cyclic permutations: 20 equilateral triangles at
// the inradius phi^2 / sqrt(3) (edge 2).
TEST_F(HullTest, of_an_icosahedron_has_20_faces) {
  const real phi = (1 + std::sqrt(real(5))) / 2;
  std::vector<vector> points;
  for (real s : {-1.0, 1.0}) {
    for (real t : {-phi, phi}) {
      points.push_back({0, s, t});
      points.push_back({s, t, 0});
      points.push_back({t, 0, s});
    }
  }
  points.push_back({0, 0, 0});
  const convex_polyhedron p = convex_polyhedron::hull(points);
  ASSERT_TRUE(well_formed(p, tolerance(1e-12, 1e-6)));
  EXPECT_TRUE(hull_of(p, points, tolerance(1e-12, 1e-6)));
  EXPECT_EQ(p.vertices.size(), 12u);
  EXPECT_EQ(p.edges.size(), 30u);
  ASSERT_EQ(p.faces.size(), 20u);
  for (const polyhedron_face& f : p.faces) {
    EXPECT_EQ(f.count, 3u);
    EXPECT_NEAR(f.offset, phi * phi / std::sqrt(real(3)), tolerance(1e-14, 1e-6));
  }
  for (const polyhedron_edge& e : p.edges) {
    EXPECT_NEAR(length(p.vertices[e.head] - p.vertices[e.tail]), 2, tolerance(1e-14, 1e-6));
  }
}

// (+-1, +-1, +-1), (0, +-1/phi, +-phi) and cyclic: 12 regular pentagons,
// each triangulated by the hull's first stage and merged again.
TEST_F(HullTest, of_a_dodecahedron_has_12_pentagons) {
  const real phi = (1 + std::sqrt(real(5))) / 2;
  std::vector<vector> points;
  for (int i = 0; i < 8; ++i)
    points.push_back(
        {i & 1 ? real(1) : real(-1), i & 2 ? real(1) : real(-1), i & 4 ? real(1) : real(-1)});
  for (real s : {-1 / phi, 1 / phi}) {
    for (real t : {-phi, phi}) {
      points.push_back({0, s, t});
      points.push_back({s, t, 0});
      points.push_back({t, 0, s});
    }
  }
  const convex_polyhedron p = convex_polyhedron::hull(points);
  ASSERT_TRUE(well_formed(p, tolerance(1e-12, 1e-6)));
  EXPECT_EQ(p.vertices.size(), 20u);
  EXPECT_EQ(p.edges.size(), 30u);
  ASSERT_EQ(p.faces.size(), 12u);
  for (const polyhedron_face& f : p.faces) EXPECT_EQ(f.count, 5u);
}

TEST_F(HullTest, rejects_points_that_span_no_volume) {
  EXPECT_TRUE(rejects(
      [] {
        convex_polyhedron::hull({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
      },
      "at least 4 points"));
  EXPECT_TRUE(rejects([] { convex_polyhedron::hull({}); }, "at least 4 points"));
  std::vector<vector> flat;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) flat.push_back({real(i), real(j), 2});
  EXPECT_TRUE(rejects([&] { convex_polyhedron::hull(flat); }, "in one plane"));
  // Turned and lifted off the plane by far less than the tolerance.
  std::vector<vector> nearly_flat;
  const rotor r = about(vector{0, 0.6, 0.8}, 1);
  for (std::size_t i = 0; i < flat.size(); ++i) {
    nearly_flat.push_back(e3ga::apply(r, flat[i] + vector{0, 0, i % 2 ? real(1e-13) : real(0)}));
  }
  EXPECT_TRUE(rejects([&] { convex_polyhedron::hull(nearly_flat); }, "in one plane"));
  std::vector<vector> straight;
  for (int i = 0; i < 6; ++i) straight.push_back(real(i) * vector{1, 2, 3});
  EXPECT_TRUE(rejects([&] { convex_polyhedron::hull(straight); }, "on one line"));
  const std::vector<vector> same(5, vector{1, 2, 3});
  EXPECT_TRUE(rejects([&] { convex_polyhedron::hull(same); }, "coincide"));
}

TEST_F(HullTest, rejects_points_that_are_not_finite) {
  std::vector<vector> points{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, nan, 0}, {0, 0, 1}};
  EXPECT_TRUE(
      rejects([&] { convex_polyhedron::hull(points); }, "convex hull point 3 must be finite"));
  points[3] = vector{inf, 0, 0};
  EXPECT_TRUE(
      rejects([&] { convex_polyhedron::hull(points); }, "convex hull point 3 must be finite"));
  points[3] = vector{0, 0, 0};
  points[0] = vector{0, 0, -inf};
  EXPECT_TRUE(rejects([&] { shape::convex_hull(points); }, "convex hull point 0 must be finite"));
}

// Just enough points beyond a thin slab still make a (thin) solid.
TEST_F(HullTest, of_a_thin_plate_is_a_thin_box) {
  std::vector<vector> points = box_corners(vector{1, 1, for_scalar(1e-6, 1e-3)});
  const convex_polyhedron p = convex_polyhedron::hull(points);
  ASSERT_TRUE(well_formed(p, tolerance(1e-12, 1e-6)));
  EXPECT_EQ(p.faces.size(), 6u);
}

TEST(ShapeTest, box_polyhedron_is_the_box) {
  const vector h{0.5, 1, 2};
  const convex_polyhedron p = convex_polyhedron::box(h);
  ASSERT_TRUE(well_formed(p, 0));
  ASSERT_EQ(p.vertices.size(), 8u);
  ASSERT_EQ(p.faces.size(), 6u);
  EXPECT_EQ(p.edges.size(), 12u);
  EXPECT_EQ(p.bounding_radius, std::sqrt(real(0.25 + 1 + 4)));
  for (const vector& c : p.vertices) {
    EXPECT_EQ(std::fabs(x(c)), 0.5);
    EXPECT_EQ(std::fabs(y(c)), 1);
    EXPECT_EQ(std::fabs(z(c)), 2);
  }
  for (const polyhedron_face& f : p.faces) {
    EXPECT_EQ(f.count, 4u);
    int axis = -1;
    for (int k = 0; k < 3; ++k) {
      if (std::fabs(f.normal.c[k]) == 1) axis = k;
    }
    ASSERT_GE(axis, 0) << "normal " << e3ga::basic_mv<real>(f.normal) << " is not an axis";
    // In the documented order -x, +x, -y, +y, -z, +z (the box pair test
    // finds a face by its axis and side).
    EXPECT_EQ(&f - p.faces.data(), 2 * axis + (f.normal.c[axis] > 0 ? 1 : 0));
    EXPECT_EQ(f.offset, h.c[axis]);
    for (std::uint32_t c : corners_of(p, f))
      EXPECT_EQ(p.vertices[c].c[axis], f.normal.c[axis] * h.c[axis]);
  }
  for (const polyhedron_edge& e : p.edges) {
    const vector d = p.vertices[e.head] - p.vertices[e.tail];
    const int zeros = (x(d) == 0) + (y(d) == 0) + (z(d) == 0);
    EXPECT_EQ(zeros, 2);  // along an axis
    EXPECT_NE(e.left, e.right);
  }
}

TEST(ShapeTest, factories_keep_their_parameters) {
  const shape box = shape::box(vector{1, 2, 3}).with_friction(0.25);
  EXPECT_EQ(box.kind(), shape_kind::box);
  EXPECT_EQ(x(box.half_extents()), 1);
  EXPECT_EQ(z(box.half_extents()), 3);
  ASSERT_NE(box.polyhedron(), nullptr);
  EXPECT_EQ(box.polyhedron()->faces.size(), 6u);
  EXPECT_EQ(box.friction(), 0.25);
  EXPECT_DOUBLE_EQ(box.bounding_radius(), std::sqrt(real(14)));
  EXPECT_EQ(box.with_restitution(0.1).polyhedron(), box.polyhedron());  // shared, not copied

  const shape capsule = shape::capsule(0.75, 0.25);
  EXPECT_EQ(capsule.kind(), shape_kind::capsule);
  EXPECT_EQ(capsule.half_height(), 0.75);
  EXPECT_EQ(capsule.radius(), 0.25);
  EXPECT_EQ(capsule.polyhedron(), nullptr);
  EXPECT_EQ(capsule.bounding_radius(), 1);
  EXPECT_EQ(shape::capsule(0, 0.5).bounding_radius(), 0.5);

  const shape hull = shape::convex_hull({{0, 0, 0}, {2, 0, 0}, {0, 3, 0}, {0, 0, 1}});
  EXPECT_EQ(hull.kind(), shape_kind::convex_hull);
  ASSERT_NE(hull.polyhedron(), nullptr);
  EXPECT_EQ(hull.polyhedron()->faces.size(), 4u);
  EXPECT_EQ(hull.bounding_radius(), 3);

  EXPECT_EQ(shape::sphere(0.5).bounding_radius(), 0.5);
  EXPECT_EQ(shape::point().bounding_radius(), 0);
  EXPECT_EQ(shape::plane(vector{0, 0, 2}, 1).bounding_radius(), inf);
  EXPECT_EQ(z(shape::plane(vector{0, 0, 2}, 1).normal()), 1);
  // A normal of any finite nonzero size: its squared norm overflowed (the
  // normal was 0 and spheres fell through) or underflowed (rejected as zero).
  for (real size : {for_scalar(1e155, 1e20), for_scalar(1e-170, 1e-23),
                    std::numeric_limits<real>::denorm_min()}) {
    const vector n = shape::plane(vector{0, 3 * size, 4 * size}, 1).normal();
    EXPECT_NEAR(y(n), 0.6, tolerance(1e-15, 1e-7)) << size;
    EXPECT_NEAR(z(n), 0.8, tolerance(1e-15, 1e-7)) << size;
  }
  EXPECT_EQ(shape::sphere(0.5).polyhedron(), nullptr);
}

TEST(ShapeTest, factories_reject_bad_sizes) {
  EXPECT_TRUE(rejects([] { shape::box(vector{-1, 1, 1}); }, "box half extent x"));
  EXPECT_TRUE(rejects([] { shape::box(vector{1, 0, 1}); }, "box half extent y"));
  EXPECT_TRUE(rejects([] { shape::box(vector{1, 1, nan}); }, "box half extent z"));
  EXPECT_TRUE(rejects([] { shape::box(vector{1, inf, 1}); }, "box half extent y"));
  EXPECT_TRUE(rejects([] { shape::capsule(1, 0); }, "capsule radius"));
  EXPECT_TRUE(rejects([] { shape::capsule(1, -1); }, "capsule radius"));
  EXPECT_TRUE(rejects([] { shape::capsule(1, nan); }, "capsule radius"));
  EXPECT_TRUE(rejects([] { shape::capsule(-0.5, 1); }, "capsule half height"));
  EXPECT_TRUE(rejects([] { shape::capsule(inf, 1); }, "capsule half height"));
  EXPECT_TRUE(rejects([] { shape::capsule(nan, 1); }, "capsule half height"));
  EXPECT_TRUE(rejects([] { shape::sphere(0); }, "sphere radius"));
  EXPECT_TRUE(rejects([] { shape::convex_hull({{0, 0, 0}, {1, 1, 1}}); }, "at least 4 points"));
}

}  // namespace
}  // namespace gaphys::testing
