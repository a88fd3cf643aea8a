// The world's spatial queries against independent truth: ray casts at
// spheres and planes against the closed-form roots of |o + t d - c| = r and
// n . (o + t d) = offset, at boxes against the textbook slab test written
// here in the box's frame, at hulls against the box they span, at capsules
// against the distance from their segment; the grid's answers against
// every shape tested one by one; overlaps against centre distances and the
// narrow phase; rays that start inside, graze, or run along a face.
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "engine_test_support.hpp"
#include "ray_shape.hpp"

namespace gaphys::testing {
namespace {

constexpr real infinity = std::numeric_limits<real>::infinity();

class query_test : public engine_test {
 protected:
  rotor random_attitude() {
    return e3ga::exp(uniform(-3.2, 3.2) * e3ga::dual(random_unit_vector()));
  }
  vector random_point(real extent) {
    return vector{uniform(-extent, extent), uniform(-extent, extent), uniform(-extent, extent)};
  }

  static body_id add_static(world& w, const shape& s, const vector& position,
                            const rotor& attitude = identity) {
    body_definition d;
    d.is_static = true;
    d.position = position;
    d.attitude = attitude;
    d.shape = s;
    return w.create_body(d);
  }

  // A scene of every shape, a compound and a floor.
  world mixed_scene(int count) {
    world w;
    w.create_body([] {
      body_definition floor;
      floor.is_static = true;
      floor.shape = shape::plane(vector{0, 0, 1}, -10);
      return floor;
    }());
    for (int i = 0; i < count; ++i) {
      body_definition d;
      d.position = random_point(8);
      d.attitude = random_attitude();
      switch (i % 5) {
        case 0:
          d.shape = shape::sphere(uniform(0.1, 0.6));
          break;
        case 1:
          d.shape = shape::box(vector{uniform(0.1, 0.6), uniform(0.1, 0.6), uniform(0.1, 0.6)});
          break;
        case 2:
          d.shape = shape::capsule(uniform(0, 0.5), uniform(0.1, 0.4));
          break;
        case 3:
          d.shape = shape::convex_hull({random_point(0.5), random_point(0.5), random_point(0.5),
                                        random_point(0.5), random_point(0.5), random_point(0.5)});
          break;
        default:
          d.shapes = {
              attached_shape{shape::box(vector{0.4, 0.1, 0.1}), vector{0.3, 0, 0}, identity},
              attached_shape{shape::sphere(0.2), vector{-0.4, 0, 0}, identity}};
      }
      w.create_body(d);
    }
    return w;
  }

  // Every shape of the world tested one by one: the truth the grid must give.
  static std::vector<ray_hit> every_hit(const world& w, const vector& origin,
                                        const vector& direction, real max_distance) {
    const vector d = (1 / length(direction)) * direction;
    std::vector<ray_hit> hits;
    for (body_id b = 0; b < w.body_count(); ++b) {
      const body& x = w.bodies()[b];
      for (std::size_t s = 0; s < x.shapes().size(); ++s) {
        const attached_shape& a = x.shapes()[s];
        const placed_shape p =
            place(a.shape, x.to_world(a.offset), e3ga::gp(x.attitude(), a.attitude));
        if (const auto hit = detail::cast_ray(p, origin, d, max_distance)) {
          hits.push_back({b, s, origin + hit->distance * d, hit->normal, hit->distance});
        }
      }
    }
    std::sort(hits.begin(), hits.end(), [](const ray_hit& a, const ray_hit& b) {
      return std::tie(a.distance, a.body, a.shape) < std::tie(b.distance, b.body, b.shape);
    });
    return hits;
  }
};

// The nearer root of |o + t d - c|² = r² with t >= 0, or 0 inside: the
// textbook quadratic in plain vector algebra.
std::optional<real> sphere_distance(const vector& o, const vector& d, const vector& c, real r) {
  const vector m = o - c;
  const real b = dot(m, d), q = dot(m, m) - r * r;
  if (q <= 0) return real(0);
  if (b > 0) return std::nullopt;
  const real discriminant = b * b - q;
  if (discriminant < 0) return std::nullopt;
  return -b - std::sqrt(discriminant);
}

TEST_F(query_test, a_ray_enters_a_sphere_at_the_nearer_root_of_the_quadratic) {
  int hits = 0, inside = 0;
  for (int trial = 0; trial < 10000; ++trial) {
    const vector c = random_point(5);
    const real r = uniform(0.1, 2);
    const vector o = random_point(6);
    // Half the rays aimed near the sphere, so that they hit often.
    const vector aim = trial % 2 ? c + uniform(0, 1.2 * r) * random_unit_vector() : random_point(6);
    if (length(aim - o) < 1e-3) continue;
    const vector d = (1 / length(aim - o)) * (aim - o);
    const placed_shape s = place(shape::sphere(r), c, identity);
    const auto expected = sphere_distance(o, d, c, r);
    const auto actual = detail::cast_ray(s, o, d, infinity);
    ASSERT_EQ(expected.has_value(), actual.has_value()) << "trial " << trial;
    if (!actual) continue;
    ++hits;
    EXPECT_NEAR(actual->distance, *expected, tolerance(1e-12, 2e-3) * (1 + *expected)) << "trial " << trial;
    if (*expected == 0) {
      ++inside;
      EXPECT_TRUE(near(actual->normal, -d, 0));
    } else {
      const vector p = o + actual->distance * d;
      EXPECT_TRUE(near(actual->normal, (1 / r) * (p - c), tolerance(1e-9, 1e-4)));
      EXPECT_NEAR(length(actual->normal), 1, tolerance(1e-14, 1e-6));
    }
  }
  EXPECT_GT(hits, 2500);
  EXPECT_GT(inside, 25);
}

TEST_F(query_test, a_ray_grazing_a_sphere_hits_it_at_the_tangent_point_and_a_hair_outside_misses) {
  const placed_shape s = place(shape::sphere(1), vector{0, 0, 0}, identity);
  const vector d{1, 0, 0};
  const auto tangent = detail::cast_ray(s, vector{-5, 1, 0}, d, infinity);
  ASSERT_TRUE(tangent);
  EXPECT_EQ(tangent->distance, 5);
  EXPECT_TRUE(near(tangent->normal, vector{0, 1, 0}, tolerance(1e-15, 1e-7)));
  const real hair = for_scalar(1e-9, 1e-5);
  EXPECT_FALSE(detail::cast_ray(s, vector{-5, 1 + hair, 0}, d, infinity));
  const auto inner = detail::cast_ray(s, vector{-5, 1 - hair, 0}, d, infinity);
  ASSERT_TRUE(inner);
  // 5 - sqrt(1 - (1 - hair)^2), to first order in hair (float: hair itself
  // rounds to 6e-8 of 1, so the root to a few 1e-6).
  EXPECT_NEAR(inner->distance, 5 - std::sqrt(2 * hair), tolerance(1e-12, 2e-5));
}

TEST_F(query_test, a_ray_meets_a_plane_where_its_height_above_it_runs_out) {
  for (int trial = 0; trial < 5000; ++trial) {
    const vector n = random_unit_vector();
    const real offset = uniform(-3, 3);
    const placed_shape s = place(shape::plane(n, offset), vector{}, identity);
    const vector o = random_point(6), d = random_unit_vector();
    const real height = dot(n, o) - offset, approach = dot(n, d);
    const auto actual = detail::cast_ray(s, o, d, 20);
    if (height <= 0) {
      ASSERT_TRUE(actual);
      EXPECT_EQ(actual->distance, 0);
      continue;
    }
    const real t = -height / approach;
    const bool hits = approach < 0 && t <= 20;
    ASSERT_EQ(hits, actual.has_value()) << "trial " << trial;
    if (!hits) continue;
    EXPECT_NEAR(actual->distance, t, tolerance(1e-12, 5e-5) * (1 + t));
    EXPECT_TRUE(near(actual->normal, n, tolerance(1e-15, 1e-6)));
  }
}

// The slab test as textbooks write it, in the box's frame: per axis the
// interval of t inside the slab |x_i| <= h_i.
std::optional<std::pair<real, int>> slab_distance(const vector& o, const vector& d,
                                                  const vector& h) {
  const real oc[3] = {o.e1(), o.e2(), o.e3()}, dc[3] = {d.e1(), d.e2(), d.e3()};
  const real hc[3] = {h.e1(), h.e2(), h.e3()};
  real near_t = -infinity, far_t = infinity;
  int face = -1;
  for (int i = 0; i < 3; ++i) {
    if (dc[i] == 0) {
      if (std::fabs(oc[i]) > hc[i]) return std::nullopt;
      continue;
    }
    real t1 = (-hc[i] - oc[i]) / dc[i], t2 = (hc[i] - oc[i]) / dc[i];
    if (t1 > t2) std::swap(t1, t2);
    if (t1 > near_t) near_t = t1, face = i;
    far_t = std::min(far_t, t2);
  }
  if (near_t > far_t || far_t < 0) return std::nullopt;
  if (near_t <= 0) return std::make_pair(real(0), -1);
  return std::make_pair(near_t, face);
}

TEST_F(query_test, a_ray_enters_a_box_where_the_slab_test_says) {
  int hits = 0;
  for (int trial = 0; trial < 10000; ++trial) {
    const vector h{uniform(0.1, 2), uniform(0.1, 2), uniform(0.1, 2)};
    const vector c = random_point(3);
    const rotor attitude = random_attitude();
    const vector o = random_point(6);
    const vector aim = trial % 2 ? c + random_point(2) : random_point(6);
    if (length(aim - o) < 1e-3) continue;
    const vector d = (1 / length(aim - o)) * (aim - o);
    const rotor back = e3ga::reverse(attitude);
    const auto expected = slab_distance(e3ga::apply(back, o - c), e3ga::apply(back, d), h);
    const auto actual = detail::cast_ray(place(shape::box(h), c, attitude), o, d, infinity);
    ASSERT_EQ(expected.has_value(), actual.has_value()) << "trial " << trial;
    if (!actual) continue;
    ++hits;
    EXPECT_NEAR(actual->distance, expected->first, tolerance(1e-12, 1e-4) * (1 + expected->first));
    if (expected->second < 0) {
      EXPECT_TRUE(near(actual->normal, -d, 0));
      continue;
    }
    // The normal: the entered face's axis, turned, against the ray.
    vector axis{};
    axis.c[expected->second] = 1;
    vector normal = e3ga::apply(attitude, axis);
    if (dot(normal, d) > 0) normal = -normal;
    EXPECT_TRUE(near(actual->normal, normal, tolerance(1e-12, 1e-6)));
  }
  EXPECT_GT(hits, 2500);
}

TEST_F(query_test, a_hull_of_a_boxs_corners_is_hit_where_the_box_is) {
  const vector h{0.7, 0.3, 1.1};
  std::vector<vector> corners;
  for (int i = 0; i < 8; ++i) {
    corners.push_back(
        vector{i & 1 ? h.e1() : -h.e1(), i & 2 ? h.e2() : -h.e2(), i & 4 ? h.e3() : -h.e3()});
  }
  const shape box = shape::box(h), hull = shape::convex_hull(corners);
  for (int trial = 0; trial < 5000; ++trial) {
    const vector c = random_point(2);
    const rotor attitude = random_attitude();
    const vector o = random_point(5), d = random_unit_vector();
    const auto a = detail::cast_ray(place(box, c, attitude), o, d, 8);
    const auto b = detail::cast_ray(place(hull, c, attitude), o, d, 8);
    ASSERT_EQ(a.has_value(), b.has_value()) << "trial " << trial;
    if (!a) continue;
    EXPECT_NEAR(a->distance, b->distance, tolerance(1e-12, 1e-6));
    EXPECT_TRUE(near(a->normal, b->normal, tolerance(1e-12, 1e-6)));
  }
}

// The distance from x to the segment c + s a, |s| <= h.
real segment_distance(const vector& x, const vector& c, const vector& a, real h) {
  const real s = std::clamp(dot(x - c, a), -h, h);
  return length(x - (c + s * a));
}

TEST_F(query_test, a_ray_enters_a_capsule_where_its_distance_from_the_segment_falls_to_the_radius) {
  int hits = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const real half_height = uniform(0, 1.5), r = uniform(0.1, 1);
    const vector c = random_point(2);
    const rotor attitude = random_attitude();
    const vector axis = e3ga::apply(attitude, vector{0, 0, 1});
    const vector o = random_point(5);
    const vector aim = trial % 2 ? c + uniform(-2, 2) * axis + random_point(1) : random_point(5);
    if (length(aim - o) < 1e-3) continue;
    const vector d = (1 / length(aim - o)) * (aim - o);
    const real max_distance = 12;
    const auto hit =
        detail::cast_ray(place(shape::capsule(half_height, r), c, attitude), o, d, max_distance);
    const auto distance_at = [&](real t) {
      return segment_distance(o + t * d, c, axis, half_height);
    };
    if (!hit) {
      // Missed: no point of the ray within reach comes within r.
      for (int i = 0; i <= 500; ++i) ASSERT_GT(distance_at(max_distance * i / 500), r) << trial;
      continue;
    }
    ++hits;
    if (hit->distance == 0) {
      EXPECT_LE(distance_at(0), r);
      continue;
    }
    const vector p = o + hit->distance * d;
    EXPECT_NEAR(distance_at(hit->distance), r, tolerance(1e-12, 1e-4)) << "trial " << trial;
    // Every point before it is outside.
    for (int i = 0; i < 200; ++i)
      ASSERT_GT(distance_at(hit->distance * i / 200), r - tolerance(1e-12, 1e-6)) << trial;
    // The normal points from the segment's nearest point to the hit.
    const real s = std::clamp(dot(p - c, axis), -half_height, half_height);
    EXPECT_TRUE(near(hit->normal, (1 / r) * (p - (c + s * axis)), tolerance(1e-9, 5e-4))) << "trial " << trial;
  }
  EXPECT_GT(hits, 400);
}

TEST_F(query_test, a_point_shape_is_never_hit) {
  EXPECT_FALSE(detail::cast_ray(place(shape::point(), vector{}, identity), vector{-1, 0, 0},
                                vector{1, 0, 0}, infinity));
}

TEST_F(query_test, the_grid_finds_the_hits_that_testing_every_shape_finds) {
  world w = mixed_scene(400);
  for (int trial = 0; trial < 1000; ++trial) {
    const vector o = random_point(12), d = random_unit_vector();
    const real max_distance = trial % 3 ? uniform(0, 30) : infinity;
    const std::vector<ray_hit> truth = every_hit(w, o, d, max_distance);
    const std::vector<ray_hit> all = w.ray_cast_all(o, d, max_distance);
    ASSERT_EQ(all.size(), truth.size()) << "trial " << trial;
    for (std::size_t i = 0; i < all.size(); ++i) {
      EXPECT_EQ(all[i].body, truth[i].body);
      EXPECT_EQ(all[i].shape, truth[i].shape);
      EXPECT_EQ(all[i].distance, truth[i].distance);
    }
    const std::optional<ray_hit> first = w.ray_cast(o, d, max_distance);
    ASSERT_EQ(first.has_value(), !truth.empty()) << "trial " << trial;
    if (!first) continue;
    EXPECT_EQ(first->body, truth.front().body);
    EXPECT_EQ(first->shape, truth.front().shape);
    EXPECT_EQ(first->distance, truth.front().distance);
    EXPECT_TRUE(near(first->point, o + first->distance * ((1 / length(d)) * d), 0));
  }
}

// Bodies strewn over kilometres leave most cells empty: the grid hashes its
// cells instead of laying them out in an array, and must find the same.
TEST_F(query_test, a_sparse_grid_finds_the_hits_that_testing_every_shape_finds) {
  world w = mixed_scene(100);
  for (int i = 0; i < 100; ++i) add_static(w, shape::sphere(uniform(0.2, 1)), random_point(3000));
  for (int trial = 0; trial < 1000; ++trial) {
    // From near a body, towards another one.
    const vector from = w.bodies()[1 + trial % (w.body_count() - 1)].position() + random_point(2);
    const vector to =
        w.bodies()[1 + (trial * 7) % (w.body_count() - 1)].position() + random_point(1);
    if (length(to - from) < 1e-3) continue;
    const vector d = to - from;
    const std::vector<ray_hit> truth = every_hit(w, from, d, infinity);
    const std::vector<ray_hit> all = w.ray_cast_all(from, d, infinity);
    ASSERT_EQ(all.size(), truth.size()) << "trial " << trial;
    for (std::size_t i = 0; i < all.size(); ++i) EXPECT_EQ(all[i].distance, truth[i].distance);
    const std::optional<ray_hit> first = w.ray_cast(from, d, infinity);
    ASSERT_EQ(first.has_value(), !truth.empty());
    if (first) {
      EXPECT_EQ(first->body, truth.front().body);
    }
  }
  // A far sphere above the floor (z >= -10) overlaps only itself.
  body_id far = 101;
  while (w.bodies()[far].position().e3() < 0) ++far;
  EXPECT_EQ(w.overlap_sphere(w.bodies()[far].position(), 0.01), std::vector<body_id>{far});
}

// Overlaps far larger than the cells of a sparse grid: tiny balls strewn
// over 100 m (cells of 2 mm) and one of 1 m. Each query finds what testing
// every shape finds. (Every cell of the query's bounds was looked up: a
// 2 m sphere took a minute, 10^10 lookups.)
TEST_F(query_test, a_large_overlap_in_a_sparse_grid_finds_every_shape_it_overlaps) {
  world w = make_world();
  for (int i = 0; i < 200; ++i) add_static(w, shape::sphere(0.001), random_point(50));
  add_static(w, shape::sphere(1), vector{0.5, 0, 0});
  for (int i = 0; i < 200; ++i) add_static(w, shape::sphere(0.001), random_point(3));
  for (const real size : {real(2), real(5), real(40)}) {
    std::vector<body_id> in_sphere, in_box;
    for (std::size_t i = 0; i < w.body_count(); ++i) {
      const vector c = w.bodies()[i].position();
      const real r = w.bodies()[i].shape()->bounding_radius();
      if (length(c) <= size + r) in_sphere.push_back(w.id_of(i));
      // The ball's centre from the cube [-size, size]^3.
      const vector outside{std::max(std::fabs(c.e1()) - size, real(0)),
                           std::max(std::fabs(c.e2()) - size, real(0)),
                           std::max(std::fabs(c.e3()) - size, real(0))};
      if (length(outside) <= r) in_box.push_back(w.id_of(i));
    }
    EXPECT_EQ(w.overlap_sphere(vector{}, size), in_sphere) << size;
    EXPECT_EQ(w.overlap_box(vector{}, vector{size, size, size}, rotor{1, 0, 0, 0}), in_box) << size;
  }
}

TEST_F(query_test, a_query_sees_the_bodies_where_they_are_now) {
  world w = make_world();
  const body_id ball = add_sphere(w, vector{0, 0, 5}, 0.5);
  const vector down{0, 0, -1};
  ASSERT_TRUE(w.ray_cast(vector{0, 0, 10}, down, 20));
  EXPECT_EQ(w.ray_cast(vector{0, 0, 10}, down, 20)->distance, 4.5);
  w.at(ball).set_position(vector{3, 0, 5});  // moved aside: the ray now misses it
  EXPECT_FALSE(w.ray_cast(vector{0, 0, 10}, down, 20));
  const auto moved = w.ray_cast(vector{3, 0, 10}, down, 20);
  ASSERT_TRUE(moved);
  EXPECT_EQ(moved->body, ball);
  w.step(h);  // falling: the hit moves with it
  const real z = w.bodies()[ball].position().e3();
  EXPECT_LT(z, 5);
  EXPECT_NEAR(w.ray_cast(vector{3, 0, 10}, down, 20)->distance, 10 - (z + 0.5), tolerance(1e-12, 1e-6));
  const body_id added = add_sphere(w, vector{3, 0, 8}, 0.5);
  EXPECT_EQ(w.ray_cast(vector{3, 0, 10}, down, 20)->body, added);
  // Moved through a reference kept from before the query.
  body& kept = w.at(added);
  ASSERT_EQ(w.ray_cast(vector{3, 0, 10}, down, 20)->body, added);
  kept.set_position(vector{-3, 0, 8});
  EXPECT_EQ(w.ray_cast(vector{-3, 0, 10}, down, 20)->body, added);
  EXPECT_NE(w.ray_cast(vector{3, 0, 10}, down, 20)->body, added);
  kept.set_attitude(rotor{0, 1, 0, 0});  // a turn counts too (a sphere looks the same)
  EXPECT_EQ(w.ray_cast(vector{-3, 0, 10}, down, 20)->body, added);
}

TEST_F(query_test, overlaps_are_the_bodies_whose_shapes_touch_the_query_shape) {
  world w = mixed_scene(300);
  for (int trial = 0; trial < 300; ++trial) {
    const vector c = random_point(9);
    const real r = uniform(0.1, 2);
    const std::vector<body_id> found = w.overlap_sphere(c, r);
    // Truth: the narrow phase against every shape; for spheres also the
    // distance of the centres.
    const placed_shape query = place(shape::sphere(r), c, identity);
    std::vector<body_id> expected;
    for (body_id b = 0; b < w.body_count(); ++b) {
      const body& x = w.bodies()[b];
      bool touches = false;
      for (const attached_shape& a : x.shapes()) {
        const placed_shape p =
            place(a.shape, x.to_world(a.offset), e3ga::gp(x.attitude(), a.attitude));
        if (a.shape.kind() == shape_kind::sphere) {
          touches = touches || length(p.center - c) <= r + a.shape.radius();
          continue;
        }
        contact_manifold m;
        find_contacts(query, p, 0, vector{}, vector{}, 0, m);
        for (int k = 0; k < m.count; ++k) touches = touches || m.points[k].geometry.depth >= 0;
      }
      if (touches) expected.push_back(b);
    }
    EXPECT_EQ(found, expected) << "trial " << trial;
  }
  // The floor z <= -10 under a box just touching it, and not a box above it.
  EXPECT_EQ(w.overlap_box(vector{0, 0, -9.5}, vector{1, 1, 0.5}).front(), 0u);
  const std::vector<body_id> above = w.overlap_box(vector{100, 0, -9.4}, vector{1, 1, 0.5});
  EXPECT_TRUE(above.empty());
}

// A direction need not be a unit vector, of any finite nonzero size: one of
// 1e155 (whose squared norm overflows) missed everything, one of 1e-170
// (whose squared norm underflows) was rejected as zero.
TEST_F(query_test, a_ray_direction_of_any_size_is_a_direction) {
  world w = make_world();
  add_floor(w);
  add_sphere(w, vector{0, 0, 1}, 0.5);
  const vector origin{0.3, 0, 4};
  const auto unit_hit = w.ray_cast(origin, vector{0, 0, -1}, 10);
  ASSERT_TRUE(unit_hit);
  for (real size : {for_scalar(1e155, 1e20), for_scalar(1e-170, 1e-23),
                    std::numeric_limits<real>::denorm_min()}) {
    const auto hit = w.ray_cast(origin, vector{0, 0, -size}, 10);
    ASSERT_TRUE(hit) << size;
    EXPECT_EQ(hit->body, unit_hit->body) << size;
    EXPECT_NEAR(hit->distance, unit_hit->distance, tolerance(1e-15, 1e-6)) << size;
  }
}

TEST_F(query_test, queries_reject_bad_input) {
  world w = mixed_scene(10);
  const real nan = std::numeric_limits<real>::quiet_NaN();
  EXPECT_TRUE(rejects(
      [&] {
        (void)w.ray_cast(vector{nan, 0, 0}, vector{1, 0, 0}, 1);
      },
      "ray origin"));
  EXPECT_TRUE(rejects([&] { (void)w.ray_cast(vector{}, vector{0, 0, 0}, 1); }, "ray direction"));
  EXPECT_TRUE(rejects(
      [&] {
        (void)w.ray_cast(vector{}, vector{infinity, 0, 0}, 1);
      },
      "ray direction"));
  EXPECT_TRUE(rejects([&] { (void)w.ray_cast(vector{}, vector{1, 0, 0}, -1); }, "max_distance"));
  EXPECT_TRUE(rejects(
      [&] {
        (void)w.ray_cast_all(vector{}, vector{1, 0, 0}, nan);
      },
      "max_distance"));
  EXPECT_TRUE(rejects([&] { (void)w.overlap_sphere(vector{}, 0); }, "radius"));
  EXPECT_TRUE(rejects([&] { (void)w.overlap_sphere(vector{0, nan, 0}, 1); }, "centre"));
  EXPECT_TRUE(rejects([&] { (void)w.overlap_box(vector{}, vector{1, -1, 1}); }, "half extent"));
  EXPECT_TRUE(rejects(
      [&] {
        (void)w.overlap_box(vector{}, vector{1, 1, 1}, rotor{0, 0, 0, 0});
      },
      "attitude"));
  // Points whose squared distances overflow: from 1e160 m a ray once "hit"
  // a sphere at an infinite distance, at a NaN point.
  const real far = for_scalar(1e160, 1e20);
  EXPECT_TRUE(rejects(
      [&] {
        (void)w.ray_cast(vector{-far, 0, 0}, vector{1, 0, 0}, infinity);
      },
      "ray origin is too far out"));
  EXPECT_TRUE(rejects([&] { (void)w.overlap_sphere(vector{0, far, 0}, 1); }, "too far out"));
  EXPECT_TRUE(rejects(
      [&] {
        (void)w.overlap_box(vector{0, 0, far}, vector{1, 1, 1});
      },
      "too far out"));
}

}  // namespace
}  // namespace gaphys::testing
