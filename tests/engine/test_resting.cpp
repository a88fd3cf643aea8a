// Resting contact over 10 s of simulated time: bodies at rest on a floor or
// on each other must stay put. Penetration stays under 1% of the radius and
// does not creep: the mean depth in the last second equals the mean depth in
// the second after settling.
#include <algorithm>
#include <vector>

#include "engine_test_support.hpp"

namespace gaphys::testing {
namespace {

class resting_test : public engine_test {
 protected:
  static constexpr int steps_per_second = 240;

  // The deepest contact of the last step.
  static real deepest(const world& w) {
    real depth = 0;
    for (const contact& c : w.contacts()) depth = std::max(depth, c.geometry.depth);
    return depth;
  }
};

TEST_F(resting_test, a_sphere_rests_on_a_floor_without_sinking_or_jitter) {
  const real radius = 0.5;
  world w = make_world();
  add_floor(w);
  const body_id ball = add_sphere(w, vector{0.2, -0.1, radius + real(0.001)}, radius);
  real max_depth = 0, early_mean = 0, late_mean = 0, max_late_speed = 0;
  simulate(w, 10 * steps_per_second, [&](int i) {
    const real depth = radius - z(w.at(ball).position());
    max_depth = std::max(max_depth, depth);
    if (i >= steps_per_second && i < 2 * steps_per_second) early_mean += depth / steps_per_second;
    if (i >= 9 * steps_per_second) {
      late_mean += depth / steps_per_second;
      max_late_speed = std::max(max_late_speed, length(w.at(ball).velocity()));
    }
  });
  EXPECT_LT(max_depth, 0.01 * radius);
  EXPECT_NEAR(late_mean, early_mean, 1e-4 * radius);
  EXPECT_LT(max_late_speed, 1e-3);  // h g = 0.04 m/s would be a jitter
  // It stays where it was put, and upright.
  EXPECT_NEAR(x(w.at(ball).position()), 0.2, tolerance(1e-9, 1e-6));
  EXPECT_NEAR(y(w.at(ball).position()), -0.1, tolerance(1e-9, 1e-6));
  EXPECT_TRUE(near(w.at(ball).angular_velocity(), bivector{}, tolerance(1e-12, 1e-6)));
}

// Speculative contacts: a sphere (e = 0) landing at 0.44 m/s (dropped 1 cm)
// would sink up to h v = 1.8 mm into the floor before a contact at the end of
// the step noticed; found while still apart, it stops at the surface.
TEST_F(resting_test, a_landing_sphere_stops_at_the_surface) {
  const real radius = 0.5;
  for (real drop : {real(0.01), real(0.0123), real(0.02)}) {
    world w = make_world();
    add_floor(w);
    const body_id ball = add_sphere(w, vector{0, 0, radius + drop}, radius);
    real max_depth = 0;
    simulate(w, steps_per_second, [&](int) {
      max_depth = std::max(max_depth, radius - z(w.at(ball).position()));
    });
    EXPECT_LT(max_depth, tolerance(1e-9, 1e-5)) << "drop " << drop;
    EXPECT_NEAR(z(w.at(ball).position()), radius, tolerance(1e-9, 1e-5)) << "drop " << drop;
  }
}

// The shared column: five spheres of radius 0.5, 1 cm apart, drop into a
// tube of planes and land on each other. No contact gets deeper than 1e-4 of
// the radius, landing included: each ball is met speculatively even while it
// falls with the ball below it, which the floor stops (with only the relative
// speed counted, it fell g h^2 = 0.17 mm in and stayed there, below the slop).
// After two seconds every sphere keeps its height: the stack neither sinks
// nor grows. The same with friction on every ball and wall.
TEST_F(resting_test, a_column_of_five_spheres_stands_for_ten_seconds) {
  const real radius = 0.5;
  const int count = 5;
  for (real friction : {real(0), real(0.5)}) {
    world w = scenes::sphere_column(count, radius, friction);
    const std::size_t first_ball = w.body_count() - count;
    real max_depth = 0;
    std::vector<real> early(count, 0), late(count, 0);
    simulate(w, 10 * steps_per_second, [&](int i) {
      max_depth = std::max(max_depth, deepest(w));
      for (int k = 0; k < count; ++k) {
        const real height = z(w.at(first_ball + k).position());
        if (i >= 2 * steps_per_second && i < 3 * steps_per_second) early[k] += height / steps_per_second;
        if (i >= 9 * steps_per_second) late[k] += height / steps_per_second;
      }
    });
    EXPECT_LT(max_depth, 1e-4 * radius) << "friction " << friction;
    for (int k = 0; k < count; ++k) {
      // Stacked: each centre a diameter above the one below.
      EXPECT_NEAR(late[k], radius + 2 * radius * k, 1e-5 * radius * (k + 1))
          << "sphere " << k << ", friction " << friction;
      EXPECT_NEAR(late[k], early[k], 1e-4 * radius) << "sphere " << k << ", friction " << friction;
      EXPECT_LT(length(w.at(first_ball + k).velocity()), 1e-3) << "sphere " << k << ", friction " << friction;
      EXPECT_LT(length(w.at(first_ball + k).angular_velocity()), 1e-3)
          << "sphere " << k << ", friction " << friction;
    }
  }
}

// Many spheres piled in a box settle into a heap whose contacts stay shallow.
// Without friction the heap keeps rearranging for a while (spheres slide
// off each other and the kinetic energy rises and falls), so it is given 6 s;
// with friction the balls also stop rolling (a spin about the vertical, which
// only spinning friction would stop, is not rolling). With friction they
// also resist rolling (c_r = 0.01, a hard ball on a hard floor): without it
// nothing stops a ball knocked out of the heap rolling on across the floor,
// as nothing would.
TEST_F(resting_test, falling_spheres_settle_in_the_box) {
  for (real friction : {real(0), real(0.5)}) {
    world w = scenes::falling_spheres_in_box(40, 1, friction, friction > 0 ? real(0.01) : real(0));
    const real radius = 0.1;
    simulate(w, 6 * steps_per_second);
    real max_depth = 0, max_speed = 0, max_spin = 0;
    simulate(w, steps_per_second, [&](int) {
      max_depth = std::max(max_depth, deepest(w));
      for (const body& b : w.bodies()) {
        max_speed = std::max(max_speed, length(b.velocity()));
        // Turning in vertical planes only: a spin about the vertical, which
        // only spinning friction (none here) would stop, goes on.
        const bivector& turning = b.angular_velocity();
        const bivector rolling{0, turning.e13(), turning.e23()};
        max_spin = std::max(max_spin, length(rolling) * radius);
      }
    });
    EXPECT_LT(max_depth, 0.05 * radius) << "friction " << friction;
    EXPECT_LT(max_speed, 0.01) << "friction " << friction;
    if (friction > 0) {
      EXPECT_LT(max_spin, 0.01) << "friction " << friction;
    }
    for (const body& b : w.bodies()) {
      if (b.is_static()) continue;
      EXPECT_GT(z(b.position()), radius * 0.95) << "friction " << friction;  // none fell through
    }
  }
}

}  // namespace
}  // namespace gaphys::testing
