// The narrow phase against closed-form geometry: for random sphere-sphere,
// sphere-plane and point-sphere configurations (apart, touching, overlapping,
// deep, nested) the conformal meet's contact point, normal and depth must be
// the ones elementary geometry gives.
#include <cstring>
#include <limits>

#include "engine_test_support.hpp"

namespace gaphys::testing {
namespace {

// (In float, coordinates 5 m out round to 5e-7 m: over the shortest
// distances below, 1 mm, a normal turns by up to 5e-4.)
const real geometry_tolerance = tolerance(1e-9, 5e-4);

bool same_bits(real a, real b) { return std::memcmp(&a, &b, sizeof(real)) == 0; }
bool same_bits(const vector& a, const vector& b) {
  return same_bits(a.e1(), b.e1()) && same_bits(a.e2(), b.e2()) && same_bits(a.e3(), b.e3());
}

class contact_test : public engine_test {
 protected:
  placed_shape sphere_at(const vector& centre, real radius) {
    return place(shape::sphere(radius), centre, identity);
  }
  vector random_point(real extent) {
    return vector{uniform(-extent, extent), uniform(-extent, extent), uniform(-extent, extent)};
  }
  rotor random_attitude() {
    const vector axis = random_unit_vector();
    return e3ga::exp(uniform(-3, 3) * e3ga::dual(axis));
  }
};

// Two spheres whose centres are `distance` apart along a random direction.
struct sphere_pair {
  vector centre_a, centre_b;
  real radius_a, radius_b;
};

// The closed form for two spheres: the normal is the line of centres from B
// to A, the depth is rA + rB - d, and the point is where the radical plane
// (the plane of the intersection circle, real or imaginary) crosses the line
// of centres: at t = (d^2 + rB^2 - rA^2) / 2d from B's centre.
void expect_sphere_sphere_geometry(const sphere_pair& s, const contact_geometry& g) {
  const vector offset = s.centre_a - s.centre_b;
  const real d = length(offset);
  const vector n = offset / d;
  const real t = (d * d + s.radius_b * s.radius_b - s.radius_a * s.radius_a) / (2 * d);
  EXPECT_TRUE(near(g.normal, n, geometry_tolerance));
  EXPECT_NEAR(g.depth, s.radius_a + s.radius_b - d, geometry_tolerance);
  EXPECT_TRUE(near(g.point, s.centre_b + t * n, geometry_tolerance * (1 + d)));
}

TEST_F(contact_test, spheres_apart_have_no_contact) {
  for (int trial = 0; trial < 200; ++trial) {
    const real ra = uniform(0.05, 2), rb = uniform(0.05, 2);
    const vector b = random_point(5);
    const vector a = b + (ra + rb + uniform(1e-6, 5)) * random_unit_vector();
    EXPECT_FALSE(find_contact(sphere_at(a, ra), sphere_at(b, rb))) << "trial " << trial;
    EXPECT_FALSE(find_contact(sphere_at(b, rb), sphere_at(a, ra))) << "trial " << trial;
  }
}

// Speculative contacts: spheres apart by a gap their closing speed covers
// within the lookahead still meet, in an imaginary circle whose centre and
// carrier give the same closed form, with depth = -gap.
TEST_F(contact_test, spheres_within_the_gap_asked_for_are_speculative_contacts) {
  for (int trial = 0; trial < 200; ++trial) {
    const real ra = uniform(0.05, 2), rb = uniform(0.05, 2);
    const vector b = random_point(5);
    const real gap = uniform(1e-6, 0.5);
    const vector n = random_unit_vector();
    const sphere_pair s{b + (ra + rb + gap) * n, b, ra, rb};
    const placed_shape a_shape = sphere_at(s.centre_a, ra), b_shape = sphere_at(s.centre_b, rb);
    // A closes on B at speed u along -n plus a sideways slide: the gap is
    // closed within h exactly when u h >= gap.
    vector slide = random_unit_vector();
    slide = slide - dot(slide, n) * n;
    const auto closing = [&](real u) { return -u * n + uniform(0, 3) * slide; };
    const auto within = find_contact(a_shape, b_shape, h, closing(gap * 1.01 / h));
    ASSERT_TRUE(within) << "trial " << trial;
    EXPECT_LT(within->squared_radius, 0);
    expect_sphere_sphere_geometry(s, *within);
    EXPECT_FALSE(find_contact(a_shape, b_shape, h, closing(gap * 0.99 / h))) << "trial " << trial;
    // B moving with A (a stack falling together) does not hide A's approach:
    // B may be stopped by another contact within the step.
    const vector together = closing(gap * 1.01 / h);
    EXPECT_TRUE(find_contact(a_shape, b_shape, h, together, together)) << "trial " << trial;
    // Nor does it matter which of the two approaches.
    EXPECT_TRUE(find_contact(a_shape, b_shape, h, vector{}, -closing(gap * 1.01 / h)))
        << "trial " << trial;
    EXPECT_FALSE(find_contact(a_shape, b_shape, h, -closing(gap * 2 / h))) << "trial " << trial;
    EXPECT_FALSE(find_contact(a_shape, b_shape)) << "trial " << trial;
  }
}

TEST_F(contact_test, overlapping_spheres_match_the_closed_form) {
  for (int trial = 0; trial < 200; ++trial) {
    const real ra = uniform(0.05, 2), rb = uniform(0.05, 2);
    const vector b = random_point(5);
    // From barely overlapping to one centre nearly on the other's surface
    // and beyond, but the surfaces still crossing: |rA - rB| < d < rA + rB.
    const real d = uniform(std::fabs(ra - rb) + 1e-3, ra + rb - 1e-6);
    const sphere_pair s{b + d * random_unit_vector(), b, ra, rb};
    const auto g = find_contact(sphere_at(s.centre_a, ra), sphere_at(s.centre_b, rb));
    ASSERT_TRUE(g) << "trial " << trial;
    EXPECT_GT(g->squared_radius, 0);
    expect_sphere_sphere_geometry(s, *g);
    // The intersection circle's radius, by Pythagoras from the point.
    const real t = length(g->point - s.centre_b);
    EXPECT_NEAR(g->squared_radius, rb * rb - t * t, tolerance(1e-8, 1e-4) * (1 + rb * rb));
  }
}

TEST_F(contact_test, touching_spheres_are_in_contact_at_the_touching_point) {
  for (int trial = 0; trial < 100; ++trial) {
    const real ra = uniform(0.05, 2), rb = uniform(0.05, 2);
    const vector b = random_point(5);
    const vector n = random_unit_vector();
    // Overlapping by far less than the sizes, and in float by 20 times the
    // rounding of coordinates 5 m out. (When the meet was computed in the
    // world frame, its terms |x|^2 / 2 rounded to 1e-5 m^2 there, and float
    // needed 1 mm: 0.1 mm left a 5 cm sphere's contact unseen.)
    const real overlap = for_scalar(1e-7, 1e-5);
    const sphere_pair s{b + (ra + rb - overlap) * n, b, ra, rb};
    const auto g = find_contact(sphere_at(s.centre_a, ra), sphere_at(s.centre_b, rb));
    ASSERT_TRUE(g) << "trial " << trial;
    expect_sphere_sphere_geometry(s, *g);
    EXPECT_TRUE(near(g->point, b + rb * n, tolerance(1e-6, 1e-3)));
    // The circle's squared radius rB^2 - t^2, nearly 0.
    const real d = ra + rb - overlap;
    const real t = (d * d + rb * rb - ra * ra) / (2 * d);
    EXPECT_NEAR(g->squared_radius, rb * rb - t * t, tolerance(1e-6, 1e-4));
  }
}

// The meet is computed at the pair (detail::meet_origin), so a pair met far
// from the world's origin gives the contact it gives near it: the same
// normal, depth and squared radius to the bit, and the point moved with it.
// Centres, radii and shifts on a grid of 2^-8 m, and shifts by powers of two
// up to 2^30 m (float: 2^15): every coordinate and every difference is then
// exact, and only the point's final shift rounds. (Met in the world frame,
// the terms carried |x|^2 / 2: two spheres 10 km out, or 100 m out in float,
// that overlapped by 1 mm met nothing.)
TEST_F(contact_test, a_pair_meets_alike_wherever_it_is) {
  const auto on_grid = [&](real low, real high) {
    return std::round(uniform(low, high) * 256) / 256;
  };
  const auto grid_point = [&] { return vector{on_grid(-4, 4), on_grid(-4, 4), on_grid(-4, 4)}; };
  const int largest_power = sizeof(real) == 8 ? 30 : 15;
  int met = 0;
  for (int trial = 0; trial < 300; ++trial) {
    // A sphere and a sphere, plane (an axis-aligned one: its offset then
    // moves exactly) or point, overlapping or not.
    const real ra = on_grid(0.05, 2), rb = on_grid(0.05, 2);
    const vector a = grid_point();
    const int kind = trial % 3;
    const vector b = kind == 0 ? a + vector{on_grid(0, real(1.2) * (ra + rb)), on_grid(-0.5, 0.5),
                                            on_grid(-0.5, 0.5)}
                               : grid_point();
    const shape other = kind == 0   ? shape::sphere(rb)
                        : kind == 1 ? shape::plane(vector{0, 0, 1}, on_grid(-1, 1))
                                    : shape::point();
    const auto meet_shifted = [&](const vector& shift) {
      return find_contact(place(shape::sphere(ra), a + shift, identity),
                          place(other, b + shift, identity));
    };
    const auto here = meet_shifted(vector{});
    for (int power = 4; power <= largest_power; power += 2) {
      const real far = std::ldexp(real(1), power);
      const vector shift{far, -far / 2, far / 4};
      const auto there = meet_shifted(shift);
      ASSERT_EQ(bool(here), bool(there)) << "trial " << trial << ", 2^" << power << " m out";
      if (!here) continue;
      EXPECT_TRUE(same_bits(here->normal, there->normal)) << "trial " << trial;
      EXPECT_TRUE(same_bits(here->depth, there->depth)) << "trial " << trial;
      EXPECT_TRUE(same_bits(here->squared_radius, there->squared_radius)) << "trial " << trial;
      // (The shift adds at most half a unit in the last place of |far|.)
      EXPECT_TRUE(
          near(there->point - shift, here->point, far * std::numeric_limits<real>::epsilon()))
          << "trial " << trial;
    }
    met += here ? 1 : 0;
  }
  // Both outcomes were tried.
  EXPECT_GT(met, 50);
  EXPECT_LT(met, 250);
}

TEST_F(contact_test, a_sphere_inside_another_is_a_deep_contact) {
  for (int trial = 0; trial < 200; ++trial) {
    const real rb = uniform(0.5, 2), ra = uniform(0.05, rb / 2);
    const vector b = random_point(5);
    // Centre distance below rB - rA: A lies wholly inside B.
    const real d = uniform(1e-3, rb - ra - 1e-3);
    const sphere_pair inner{b + d * random_unit_vector(), b, ra, rb};
    const auto g = find_contact(sphere_at(inner.centre_a, ra), sphere_at(inner.centre_b, rb));
    ASSERT_TRUE(g) << "trial " << trial;
    EXPECT_LT(g->squared_radius, 0);
    expect_sphere_sphere_geometry(inner, *g);
    // The same pair the other way round: B inside... A holds B.
    const sphere_pair outer{b, inner.centre_a, rb, ra};
    const auto h = find_contact(sphere_at(outer.centre_a, rb), sphere_at(outer.centre_b, ra));
    ASSERT_TRUE(h) << "trial " << trial;
    expect_sphere_sphere_geometry(outer, *h);
  }
}

// Bodies placed exactly on top of each other: identical spheres (whose meet
// is zero) and concentric ones (no line of centres) still make a contact
// with a unit normal and the full overlap as depth, never NaN.
TEST_F(contact_test, coincident_and_concentric_spheres_are_deep_contacts) {
  for (int trial = 0; trial < 50; ++trial) {
    const vector c = random_point(5);
    const real ra = uniform(0.05, 2), rb = uniform(0.05, 2);
    for (const real other : {ra, rb}) {
      const auto g = find_contact(sphere_at(c, ra), sphere_at(c, other));
      ASSERT_TRUE(g) << "trial " << trial << " radii " << ra << ", " << other;
      EXPECT_NEAR(length(g->normal), 1, tolerance(1e-12, 1e-6));
      EXPECT_NEAR(g->depth, ra + other, tolerance(1e-9, 1e-4));
      EXPECT_TRUE(near(g->point, c, tolerance(1e-9, 1e-4) * (1 + length(c))));
    }
  }
}

TEST_F(contact_test, swapping_the_spheres_flips_the_normal_only) {
  for (int trial = 0; trial < 100; ++trial) {
    const real ra = uniform(0.05, 2), rb = uniform(0.05, 2);
    const vector b = random_point(5);
    const vector a = b + uniform(std::fabs(ra - rb) + 1e-3, ra + rb) * random_unit_vector();
    const auto ab = find_contact(sphere_at(a, ra), sphere_at(b, rb));
    const auto ba = find_contact(sphere_at(b, rb), sphere_at(a, ra));
    ASSERT_TRUE(ab && ba);
    EXPECT_TRUE(near(ab->normal, -ba->normal, geometry_tolerance));
    EXPECT_TRUE(near(ab->point, ba->point, geometry_tolerance));
    EXPECT_NEAR(ab->depth, ba->depth, geometry_tolerance);
  }
}

// A plane {n . x <= offset} on a body at a random pose, against a sphere at
// signed height s above it: apart (s > r), touching, overlapping, the centre
// below the surface, and the sphere sunk wholly below it (s < -r).
TEST_F(contact_test, sphere_and_plane_match_the_closed_form) {
  for (int trial = 0; trial < 300; ++trial) {
    const vector body_normal = random_unit_vector();
    const real body_offset = uniform(-3, 3);
    const vector plane_position = random_point(4);
    const rotor attitude = random_attitude();
    const placed_shape plane = place(shape::plane(body_normal, body_offset), plane_position, attitude);

    // The plane in the world frame, computed independently of place().
    const vector n = e3ga::apply(attitude, body_normal);
    const real offset = body_offset + dot(n, plane_position);

    const real r = uniform(0.05, 2);
    const real height = uniform(-3 * r, 3 * r);  // of the centre above the plane
    const vector foot = random_point(4);
    const vector on_plane = foot + (offset - dot(n, foot)) * n;
    const vector centre = on_plane + height * n;
    const placed_shape sphere = sphere_at(centre, r);

    const auto sp = find_contact(sphere, plane);
    const auto ps = find_contact(plane, sphere);
    if (height > r) {
      EXPECT_FALSE(sp) << "trial " << trial << " height " << height << " radius " << r;
      EXPECT_FALSE(ps) << "trial " << trial;
      continue;
    }
    ASSERT_TRUE(sp) << "trial " << trial << " height " << height << " radius " << r;
    ASSERT_TRUE(ps) << "trial " << trial;
    EXPECT_TRUE(near(sp->normal, n, geometry_tolerance));
    EXPECT_TRUE(near(ps->normal, -n, geometry_tolerance));
    EXPECT_NEAR(sp->depth, r - height, geometry_tolerance * 10);
    EXPECT_NEAR(ps->depth, r - height, geometry_tolerance * 10);
    EXPECT_TRUE(near(sp->point, on_plane, geometry_tolerance * 10));
    EXPECT_TRUE(near(ps->point, on_plane, geometry_tolerance * 10));
    EXPECT_NEAR(sp->squared_radius, r * r - height * height, tolerance(1e-8, 1e-4) * (1 + r * r));
  }
}

// A point (a flat point in c3ga) inside a sphere is in contact along the line
// of centres at the point itself, with depth r - |x - c|; outside it is not.
TEST_F(contact_test, point_and_sphere_match_the_closed_form) {
  for (int trial = 0; trial < 300; ++trial) {
    const real r = uniform(0.05, 2);
    const vector c = random_point(5);
    const vector direction = random_unit_vector();
    const real distance = uniform(1e-3, 3 * r);
    const vector x = c + distance * direction;
    const placed_shape point = place(shape::point(), x, random_attitude());
    const placed_shape sphere = sphere_at(c, r);

    const auto ps = find_contact(point, sphere);
    const auto sp = find_contact(sphere, point);
    if (distance > r + 1e-9) {
      EXPECT_FALSE(ps) << "trial " << trial;
      EXPECT_FALSE(sp) << "trial " << trial;
      continue;
    }
    ASSERT_TRUE(ps) << "trial " << trial << " distance " << distance << " radius " << r;
    ASSERT_TRUE(sp) << "trial " << trial;
    EXPECT_TRUE(near(ps->point, x, geometry_tolerance * 10));
    EXPECT_TRUE(near(sp->point, x, geometry_tolerance * 10));
    EXPECT_TRUE(near(ps->normal, direction, geometry_tolerance));
    EXPECT_TRUE(near(sp->normal, -direction, geometry_tolerance));
    EXPECT_NEAR(ps->depth, r - distance, geometry_tolerance * 10);
    EXPECT_NEAR(sp->depth, r - distance, geometry_tolerance * 10);
  }
}

// dual_of against the incidence it stands for: a conformal point X = no +
// x + x^2/2 ni has X . σ = (r^2 - |x - c|^2) / 2 with a sphere's dual (zero
// on the surface), X . Π = d - n . x with a plane's (its depth below the
// surface), and X ⌋ D = 0 with a point's D exactly at X; a box has none.
TEST_F(contact_test, the_dual_of_a_placed_shape_is_the_one_its_points_are_on) {
  const auto conformal_point = [](const vector& x) {
    return conformal::mv(conformal::normalized_point{x.e1(), x.e2(), x.e3(), dot(x, x) / 2});
  };
  const real incidence_tolerance = tolerance(1e-12, 1e-4);
  for (int trial = 0; trial < 100; ++trial) {
    const real r = uniform(0.05, 2);
    const vector c = random_point(5);
    const conformal::mv sphere = dual_of(sphere_at(c, r));
    const vector x = c + uniform(0, 3 * r) * random_unit_vector();
    const real inside = (r * r - dot(x - c, x - c)) / 2;
    EXPECT_NEAR(c3ga::scp(conformal_point(x), sphere), inside,
                incidence_tolerance * (1 + 100 * r * r))
        << "trial " << trial;

    const vector body_normal = random_unit_vector();
    const real body_offset = uniform(-3, 3);
    const vector position = random_point(4);
    const rotor attitude = random_attitude();
    const conformal::mv plane =
        dual_of(place(shape::plane(body_normal, body_offset), position, attitude));
    const vector n = e3ga::apply(attitude, body_normal);
    const real offset = body_offset + dot(n, position);
    EXPECT_NEAR(c3ga::scp(conformal_point(x), plane), offset - dot(n, x), incidence_tolerance * 100)
        << "trial " << trial;

    const conformal::mv point = dual_of(place(shape::point(), x, attitude));
    EXPECT_LE(c3ga::norm(c3ga::lc(conformal_point(x), point)), incidence_tolerance * 1000)
        << "trial " << trial;
    const vector elsewhere = x + random_unit_vector();
    EXPECT_GT(c3ga::norm(c3ga::lc(conformal_point(elsewhere), point)), 0.1) << "trial " << trial;
  }
  const conformal::mv box = dual_of(place(shape::box(vector{1, 2, 3}), vector{1, 1, 1}, identity));
  EXPECT_EQ(c3ga::norm(box), 0);
}

// Contacts the meet does not define: parallel planes never pair (both are
// static), and a point meets a plane nowhere in the thesis's sense.
TEST_F(contact_test, a_point_and_a_plane_do_not_collide) {
  const placed_shape floor = place(shape::plane(vector{0, 0, 1}, 0), vector{}, identity);
  for (real z : {real(-1), real(-1e-3), real(1e-3), real(1)}) {
    EXPECT_FALSE(find_contact(place(shape::point(), vector{0.3, -0.2, z}, identity), floor)) << z;
  }
}

// The world forms contacts with the same geometry, between body ids.
TEST_F(contact_test, the_world_reports_contacts_between_its_bodies) {
  world w = make_world(vector{});
  const body_id floor = add_floor(w, 0);
  const body_id low = add_sphere(w, vector{0, 0, 0.49}, 0.5);
  const body_id high = add_sphere(w, vector{0, 0, 1.4}, 0.5);
  const body_id apart = add_sphere(w, vector{5, 0, 0.6}, 0.5);
  w.step(h);
  ASSERT_EQ(w.contacts().size(), 2u);
  const contact& ground = w.contacts()[0];
  EXPECT_EQ(ground.body_a, floor);
  EXPECT_EQ(ground.body_b, low);
  EXPECT_TRUE(near(ground.geometry.normal, vector{0, 0, -1}, geometry_tolerance));
  EXPECT_NEAR(ground.geometry.depth, 0.01, geometry_tolerance);
  const contact& stack = w.contacts()[1];
  EXPECT_EQ(stack.body_a, low);
  EXPECT_EQ(stack.body_b, high);
  EXPECT_TRUE(near(stack.geometry.normal, vector{0, 0, -1}, geometry_tolerance));
  EXPECT_NEAR(stack.geometry.depth, 0.09, geometry_tolerance);
  EXPECT_TRUE(near(stack.geometry.point, vector{0, 0, 0.945}, geometry_tolerance));
  for (const contact& c : w.contacts()) EXPECT_NE(c.body_b, apart);
}

}  // namespace
}  // namespace gaphys::testing
