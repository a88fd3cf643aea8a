// Collision response against the laws of impact for smooth spheres: the
// impulse acts along the line of centres, momentum is conserved, kinetic
// energy scales the normal approach speed by e, and a dropped ball rebounds
// to e^2 of its drop height.
#include <vector>

#include "engine_test_support.hpp"

namespace gaphys::testing {
namespace {

class collision_test : public engine_test {
 protected:
  struct ball {
    real mass, radius;
    vector position, velocity;
  };

  // Two spheres placed overlapping by 1e-9 m, so the first step meets them
  // exactly where the closed form assumes contact, without gravity.
  world two_balls(const ball& a, const ball& b, real restitution) {
    world w = make_world(vector{});
    add_sphere(w, a.position, a.radius, a.mass, a.velocity, restitution);
    add_sphere(w, b.position, b.radius, b.mass, b.velocity, restitution);
    return w;
  }

  static vector momentum(const world& w) {
    vector p{};
    for (const body& b : w.bodies()) {
      if (!b.is_static()) p = p + b.mass() * b.velocity();
    }
    return p;
  }
  static real energy(const world& w) {
    real e = 0;
    for (const body& b : w.bodies()) e += b.kinetic_energy();
    return e;
  }

  // Newton's law of impact for smooth spheres meeting with unit normal n
  // (from B to A): j = -(1 + e) (uA - uB) . n / (1/mA + 1/mB).
  static std::pair<vector, vector> after_impact(const ball& a, const ball& b, const vector& n,
                                                real e) {
    const real approach = dot(a.velocity - b.velocity, n);
    const real j = -(1 + e) * approach / (1 / a.mass + 1 / b.mass);
    return {a.velocity + (j / a.mass) * n, b.velocity - (j / b.mass) * n};
  }
};

TEST_F(collision_test, elastic_head_on_impact_of_unequal_masses) {
  // 1 kg at 3 m/s meets 2 kg at -1 m/s: v1' = -7/3, v2' = 5/3.
  const ball a{1, 0.5, vector{-0.5 + 0.5e-9, 0, 0}, vector{3, 0, 0}};
  const ball b{2, 0.5, vector{0.5 - 0.5e-9, 0, 0}, vector{-1, 0, 0}};
  world w = two_balls(a, b, 1);
  const vector p0 = momentum(w);
  const real e0 = energy(w);
  w.step(h);
  EXPECT_TRUE(near(w.at(0).velocity(), vector{-7.0 / 3, 0, 0}, 1e-12));
  EXPECT_TRUE(near(w.at(1).velocity(), vector{5.0 / 3, 0, 0}, 1e-12));
  simulate(w, 240);
  EXPECT_LE(length(momentum(w) - p0), 1e-5 * length(p0));
  EXPECT_NEAR(energy(w), e0, 1e-12 * e0);
  EXPECT_TRUE(w.contacts().empty());
  // No spin from a central impact.
  EXPECT_TRUE(near(w.at(0).angular_velocity(), bivector{}, 1e-15));
}

TEST_F(collision_test, a_struck_row_of_touching_balls_gets_the_simultaneous_impulse_solution) {
  // A 1 kg ball at 1 m/s strikes the first of four touching 1 kg balls (e = 1).
  // The resting contacts approach at 0 and do not bounce, so the impulses
  // solve: striker and row separate at 1 m/s, the row moves as one, momentum
  // is kept: s + 4 u = 1, u - s = 1, so s = -0.6, u = 0.4, and the kinetic
  // energy (0.36 + 4 * 0.16) / 2 is the striker's 1/2. Plain Gauss-Seidel
  // sweeps converge along the row by a factor 0.65 per sweep (3e-4 of the
  // energy lost after 20); over-relaxation meets the solution.
  world w = make_world(vector{});
  add_sphere(w, vector{-1 - 0.5e-9, 0, 0}, 0.5, 1, vector{1, 0, 0}, 1);
  for (int i = 0; i < 4; ++i) add_sphere(w, vector{real(i), 0, 0}, 0.5, 1, vector{}, 1);
  const real e0 = energy(w);
  simulate(w, 240);
  EXPECT_NEAR(x(w.at(0).velocity()), -0.6, 1e-9);
  for (body_id i = 1; i < 5; ++i) EXPECT_NEAR(x(w.at(i).velocity()), 0.4, 1e-9) << "ball " << i;
  EXPECT_NEAR(x(momentum(w)), 1, 1e-12);
  EXPECT_NEAR(energy(w), e0, 1e-9 * e0);
}

TEST_F(collision_test, elastic_oblique_impacts_follow_the_law_of_impact) {
  for (int trial = 0; trial < 50; ++trial) {
    const vector n = random_unit_vector();
    const ball b{uniform(0.2, 5), uniform(0.1, 1), vector{uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)},
                 vector{uniform(-2, 2), uniform(-2, 2), uniform(-2, 2)}};
    const real ra = uniform(0.1, 1);
    // A approaches B along -n at 1 to 5 m/s relative to it, plus a random
    // tangential slide.
    vector slide = vector{uniform(-2, 2), uniform(-2, 2), uniform(-2, 2)};
    slide = slide - dot(slide, n) * n;
    const ball a{uniform(0.2, 5), ra, b.position + (ra + b.radius - 1e-9) * n,
                 b.velocity + uniform(-5, -1) * n + slide};
    world w = two_balls(a, b, 1);
    const vector p0 = momentum(w);
    const real e0 = energy(w);
    w.step(h);
    const auto [va, vb] = after_impact(a, b, n, 1);
    const real scale = length(a.velocity) + length(b.velocity);
    EXPECT_TRUE(near(w.at(0).velocity(), va, 1e-9 * scale)) << "trial " << trial;
    EXPECT_TRUE(near(w.at(1).velocity(), vb, 1e-9 * scale)) << "trial " << trial;
    EXPECT_LE(length(momentum(w) - p0), 1e-5 * length(p0)) << "trial " << trial;
    EXPECT_NEAR(energy(w), e0, 1e-9 * e0) << "trial " << trial;
    // The tangential velocities are untouched (smooth spheres).
    const vector ta = w.at(0).velocity() - dot(w.at(0).velocity(), n) * n;
    EXPECT_TRUE(near(ta, a.velocity - dot(a.velocity, n) * n, 1e-9 * scale)) << "trial " << trial;
  }
}

TEST_F(collision_test, inelastic_impacts_lose_the_normal_approach_energy) {
  for (real e : {real(0), real(0.5)}) {
    const ball a{1, 0.5, vector{-0.5 + 0.5e-9, 0, 0}, vector{3, 1, 0}};
    const ball b{3, 0.5, vector{0.5 - 0.5e-9, 0, 0}, vector{-1, 0, 0}};
    world w = two_balls(a, b, e);
    const vector p0 = momentum(w);
    w.step(h);
    const auto [va, vb] = after_impact(a, b, vector{-1, 0, 0}, e);
    EXPECT_TRUE(near(w.at(0).velocity(), va, 1e-12)) << "e = " << e;
    EXPECT_TRUE(near(w.at(1).velocity(), vb, 1e-12)) << "e = " << e;
    EXPECT_LE(length(momentum(w) - p0), 1e-12 * length(p0));
    // The separation speed is e times the approach speed of 4 m/s.
    EXPECT_NEAR(x(w.at(1).velocity()) - x(w.at(0).velocity()), 4 * e, 1e-12);
  }
}

// The shared scene: the spheres fly in from 4 m apart and meet off-centre.
// The narrow phase sees them only once they overlap, up to h |uA - uB|
// = 1.7 cm deep, so its normal is within a few milliradians of the normal at
// first touch, which the closed form uses; momentum and energy stay exact.
TEST_F(collision_test, the_elastic_collision_scene_conserves_momentum_and_energy) {
  const real offset = 0.3;
  world w = scenes::elastic_collision(offset);
  const ball a{1, 0.5, w.at(0).position(), w.at(0).velocity()};
  const ball b{2, 0.5, w.at(1).position(), w.at(1).velocity()};
  const vector p0 = momentum(w);
  const real e0 = energy(w);
  simulate(w, 480);  // 2 s: they meet after about 0.76 s
  EXPECT_LE(length(momentum(w) - p0), 1e-5 * length(p0));
  EXPECT_NEAR(energy(w), e0, 1e-5 * e0);
  // First touch: |p0 + t u| = rA + rB for the relative position and velocity.
  const vector p = a.position - b.position, u = a.velocity - b.velocity;
  const real uu = dot(u, u), pu = dot(p, u), pp = dot(p, p) - 1;
  const real t = (-pu - std::sqrt(pu * pu - uu * pp)) / uu;
  const vector n = (p + t * u) / length(p + t * u);
  const auto [va, vb] = after_impact(a, b, n, 1);
  EXPECT_TRUE(near(w.at(0).velocity(), va, 0.05));
  EXPECT_TRUE(near(w.at(1).velocity(), vb, 0.05));
  // The light sphere is deflected away from the heavy one (towards -e2).
  EXPECT_LT(y(w.at(0).velocity()), -0.5);
}

// Dropped from 2 m onto a floor with restitution e, the sphere leaves the
// floor at e times its impact speed and so climbs back to e^2 of the drop.
TEST_F(collision_test, a_dropped_sphere_rebounds_to_e_squared_of_its_height) {
  for (real e : {real(0), real(0.3), real(0.5), real(0.8), real(0.95)}) {
    const real drop = 2, radius = 0.5;
    world w = scenes::bouncing_sphere(e, drop);
    const body_id ball = 1;
    bool bounced = false;
    real apex = 0;
    for (int i = 0; i < 240 * 4; ++i) {
      w.step(h);
      const real height = z(w.at(ball).position()) - radius;
      for (const contact& c : w.contacts()) bounced = bounced || c.geometry.depth >= 0;
      if (bounced) {
        apex = std::max(apex, height);
        if (z(w.at(ball).velocity()) < 0) break;  // past the first apex
      }
    }
    ASSERT_TRUE(bounced) << "e = " << e;
    EXPECT_NEAR(apex / drop, e * e, 0.05) << "e = " << e;
  }
}

// e = 1: every bounce returns the ball to its drop height. Restitution acts
// on the approach speed the ball had before the step's gravity, so the
// bounces neither gain h g each (1.3% height per bounce) nor lose it.
TEST_F(collision_test, an_elastic_ball_keeps_its_height_over_20_bounces) {
  const real drop = 2, radius = 0.5;
  world w = scenes::bouncing_sphere(1, drop);
  const body_id ball = 1;
  std::vector<real> apexes;
  real previous_vz = 0;
  while (apexes.size() < 20 && w.time() < 40) {
    w.step(h);
    const real vz = z(w.at(ball).velocity());
    if (previous_vz > 0 && vz <= 0) apexes.push_back(z(w.at(ball).position()) - radius);
    previous_vz = vz;
  }
  ASSERT_EQ(apexes.size(), 20u);
  for (std::size_t i = 0; i < apexes.size(); ++i) {
    EXPECT_NEAR(apexes[i] / drop, 1, 0.01) << "bounce " << i + 1;
  }
  EXPECT_NEAR(apexes.back() / apexes.front(), 1, 0.005);
}

}  // namespace
}  // namespace gaphys::testing
