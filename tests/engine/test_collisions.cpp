// Collision response against the laws of impact for smooth (frictionless)
// spheres: the
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

  // Two smooth spheres placed overlapping by 1e-9 m, so the first step
  // meets them exactly where the closed form assumes contact, without gravity.
  world two_balls(const ball& a, const ball& b, real restitution) {
    world w = make_world(vector{});
    add_sphere(w, a.position, a.radius, a.mass, a.velocity, restitution, 0);
    add_sphere(w, b.position, b.radius, b.mass, b.velocity, restitution, 0);
    return w;
  }

  static vector momentum(const world& w) {
    vector p{};
    for (const body& b : w.bodies()) {
      if (!b.is_static()) p = p + b.mass() * b.velocity();
    }
    return p;
  }
  static real energy(const world& w) { return kinetic_energy(w); }

  // When the spheres first touch, moving uniformly, and the unit normal (from
  // B to A) then: |p + t u| = rA + rB for their relative position and
  // velocity, on the approaching branch (t < 0 if they already overlap).
  struct touch {
    real time;
    vector normal;
  };
  static touch first_touch(const ball& a, const ball& b) {
    const vector p = a.position - b.position, u = a.velocity - b.velocity;
    const real distance = a.radius + b.radius;
    const real uu = dot(u, u), pu = dot(p, u), pp = dot(p, p) - distance * distance;
    const real t = (-pu - std::sqrt(pu * pu - uu * pp)) / uu;
    return {t, (p + t * u) / length(p + t * u)};
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
  EXPECT_TRUE(near(w.at(0).velocity(), vector{-7.0 / 3, 0, 0}, tolerance(1e-12, 1e-5)));
  EXPECT_TRUE(near(w.at(1).velocity(), vector{5.0 / 3, 0, 0}, tolerance(1e-12, 1e-5)));
  simulate(w, 240);
  EXPECT_LE(length(momentum(w) - p0), 1e-5 * length(p0));
  EXPECT_NEAR(energy(w), e0, tolerance(1e-12, 1e-5) * e0);
  EXPECT_TRUE(w.contacts().empty());
  // No spin from a central impact.
  EXPECT_TRUE(near(w.at(0).angular_velocity(), bivector{}, tolerance(1e-15, 1e-7)));
}

TEST_F(collision_test, elastic_oblique_impacts_follow_the_law_of_impact) {
  for (int trial = 0; trial < 50; ++trial) {
    const vector n = random_unit_vector();
    const ball b{uniform(0.2, 5), uniform(0.1, 1), vector{uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)},
                 vector{uniform(-2, 2), uniform(-2, 2), uniform(-2, 2)}};
    const real ra = uniform(0.1, 1);
    // A approaches B along -n at 1 to 5 m/s relative to it, plus a random
    // tangential slide, from a gap it closes within the step (or overlapping
    // a little, as if found a step late). The spheres turn while they close
    // it: the impact is along the normal at first touch.
    vector slide = vector{uniform(-2, 2), uniform(-2, 2), uniform(-2, 2)};
    slide = slide - dot(slide, n) * n;
    const real approach = uniform(1, 5);
    const real gap = uniform(-0.5, 1) * approach * h;
    const ball a{uniform(0.2, 5), ra, b.position + (ra + b.radius + gap) * n,
                 b.velocity - approach * n + slide};
    world w = two_balls(a, b, 1);
    const vector p0 = momentum(w);
    const real e0 = energy(w);
    w.step(h);
    const auto [t, touch] = first_touch(a, b);
    const auto [va, vb] = after_impact(a, b, touch, 1);
    const real scale = length(a.velocity) + length(b.velocity);
    EXPECT_TRUE(near(w.at(0).velocity(), va, tolerance(1e-9, 1e-4) * scale)) << "trial " << trial;
    EXPECT_TRUE(near(w.at(1).velocity(), vb, tolerance(1e-9, 1e-4) * scale)) << "trial " << trial;
    EXPECT_LE(length(momentum(w) - p0), 1e-5 * length(p0)) << "trial " << trial;
    EXPECT_NEAR(energy(w), e0, tolerance(1e-9, 1e-4) * e0) << "trial " << trial;
    // The tangential velocities are untouched (smooth spheres).
    const vector ta = w.at(0).velocity() - dot(w.at(0).velocity(), touch) * touch;
    EXPECT_TRUE(near(ta, a.velocity - dot(a.velocity, touch) * touch, tolerance(1e-9, 1e-4) * scale))
        << "trial " << trial;
    // Impact at first touch, then the new velocities: the step ends where
    // the two motions take the spheres.
    EXPECT_TRUE(near(w.at(0).position(), a.position + t * a.velocity + (h - t) * va, tolerance(1e-9, 1e-5)))
        << "trial " << trial;
    EXPECT_TRUE(near(w.at(1).position(), b.position + t * b.velocity + (h - t) * vb, tolerance(1e-9, 1e-5)))
        << "trial " << trial;
  }
}

TEST_F(collision_test, inelastic_impacts_lose_the_normal_approach_energy) {
  for (real e : {real(0), real(0.5)}) {
    const ball a{1, 0.5, vector{-0.5 + 0.5e-9, 0, 0}, vector{3, 1, 0}};
    const ball b{3, 0.5, vector{0.5 - 0.5e-9, 0, 0}, vector{-1, 0, 0}};
    world w = two_balls(a, b, e);
    const vector p0 = momentum(w);
    w.step(h);
    // A bounce (e > 0) is timed to the first touch; a contact that does not
    // bounce is met along the normal the step found (1e-9 m deep here).
    const vector n = e > 0 ? first_touch(a, b).normal : vector{-1, 0, 0};
    const auto [va, vb] = after_impact(a, b, n, e);
    EXPECT_TRUE(near(w.at(0).velocity(), va, tolerance(1e-12, 1e-5))) << "e = " << e;
    EXPECT_TRUE(near(w.at(1).velocity(), vb, tolerance(1e-12, 1e-5))) << "e = " << e;
    EXPECT_LE(length(momentum(w) - p0), tolerance(1e-12, 1e-6) * length(p0));
    // The separation speed is e times the approach speed (4 m/s).
    EXPECT_NEAR(dot(w.at(0).velocity() - w.at(1).velocity(), n),
                -e * dot(a.velocity - b.velocity, n), tolerance(1e-12, 1e-5));
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
  const auto [va, vb] = after_impact(a, b, first_touch(a, b).normal, 1);
  EXPECT_TRUE(near(w.at(0).velocity(), va, 0.05));
  EXPECT_TRUE(near(w.at(1).velocity(), vb, 0.05));
  // The light sphere is deflected away from the heavy one (towards -e2).
  EXPECT_LT(y(w.at(0).velocity()), -0.5);
}

// How far a sampled apex may be from e^2 of the drop with an exactly timed
// bounce: semi-implicit Euler starting from rest moves as if dropped from
// g h^2 / 8 higher, and the highest sample may miss the apex by that again.
constexpr real apex_sampling = real(9.81) * scenes::time_step * scenes::time_step / 4;

// The highest sample of the sphere's bottom between the bounce (vertical
// velocity turning up) and the first step it goes down again; also the lowest
// it was before.
struct rebound {
  real apex = 0;
  real lowest;
  bool seen = false;
};

rebound next_rebound(world& w, body_id ball, real radius, real seconds) {
  rebound r;
  r.lowest = z(w.at(ball).position()) - radius;
  real previous_vz = z(w.at(ball).velocity());
  const real h = scenes::time_step;
  for (int i = 0; i < seconds / h; ++i) {
    w.step(h);
    const real height = z(w.at(ball).position()) - radius;
    const real vz = z(w.at(ball).velocity());
    r.lowest = std::min(r.lowest, height);
    r.seen = r.seen || (previous_vz < 0 && vz >= 0);
    if (r.seen) {
      r.apex = std::max(r.apex, height);
      if (vz < 0) break;
    }
    previous_vz = vz;
  }
  return r;
}

// Dropped onto a floor with restitution e, the sphere leaves the floor at e
// times its impact speed and so climbs back to e^2 of the drop. The bounce is
// timed inside the step, so this holds to the sampling whatever fraction of a
// step the contact falls at: the drops below put it at different phases.
// Nor does the ball sink into the floor on the way.
TEST_F(collision_test, a_dropped_sphere_rebounds_to_e_squared_of_its_height) {
  for (real drop : {real(2), real(1.37), real(0.83)}) {
    for (real e : {real(0.3), real(0.5), real(0.8), real(0.95), real(1)}) {
      world w = scenes::bouncing_sphere(e, drop);
      const rebound r = next_rebound(w, 1, 0.5, 4);
      ASSERT_TRUE(r.seen) << "drop " << drop << ", e = " << e;
      EXPECT_NEAR(r.apex, e * e * drop, apex_sampling) << "drop " << drop << ", e = " << e;
      EXPECT_GE(r.lowest, -tolerance(1e-12, 1e-6)) << "drop " << drop << ", e = " << e;
    }
  }
}

// A ball fired at a small static sphere covers up to 21 radii per step, so it
// would pass through between two steps; it is met speculatively and bounced
// at the moment of first touch: back along the line of centres at e times its
// speed, from where the bounce takes it within the step.
TEST_F(collision_test, a_fast_ball_bounces_off_a_small_sphere_instead_of_passing_through) {
  for (real speed : {real(10), real(60), real(200), real(500)}) {
    const real radius = 0.1, e = 0.5;
    world w = make_world(vector{});
    body_definition target;
    target.is_static = true;
    target.shape = shape::sphere(radius).with_restitution(e);
    w.create_body(target);
    // Started 1 m away, plus a fraction of a step so the touch falls mid-step.
    const real start = 2 * radius + 1 + real(0.37) * speed * h;
    const body_id ball = add_sphere(w, vector{0, 0, start}, radius, 1, vector{0, 0, -speed}, e);
    const int steps_to_touch = static_cast<int>((start - 2 * radius) / (speed * h));
    simulate(w, steps_to_touch + 1);
    const real touch = (start - 2 * radius) / speed;  // s after the start
    const real after = (steps_to_touch + 1) * h - touch;
    EXPECT_NEAR(z(w.at(ball).velocity()), e * speed, tolerance(1e-9, 1e-5) * speed) << "speed " << speed;
    EXPECT_NEAR(z(w.at(ball).position()), 2 * radius + e * speed * after, tolerance(1e-9, 1e-5) * start)
        << "speed " << speed;
  }
}

// e = 0: the sphere lands and stays, touching the floor.
TEST_F(collision_test, a_dropped_sphere_without_restitution_stays_down) {
  const real drop = 2, radius = 0.5;
  world w = scenes::bouncing_sphere(0, drop);
  simulate(w, 240 * 2);
  EXPECT_NEAR(z(w.at(1).position()) - radius, 0, tolerance(1e-9, 1e-5));
  EXPECT_NEAR(z(w.at(1).velocity()), 0, tolerance(1e-9, 1e-5));
}

// e = 1: every bounce returns the ball to its drop height. The bounce takes
// the impact speed from the step's motion before and after gravity, so the
// bounces neither gain h g each (1.3% height per bounce) nor lose it.
TEST_F(collision_test, an_elastic_ball_keeps_its_height_over_20_bounces) {
  const real drop = 2;
  world w = scenes::bouncing_sphere(1, drop);
  for (int bounce = 1; bounce <= 20; ++bounce) {
    const rebound r = next_rebound(w, 1, 0.5, 2);
    ASSERT_TRUE(r.seen) << "bounce " << bounce;
    EXPECT_NEAR(r.apex, drop, apex_sampling) << "bounce " << bounce;
  }
}

}  // namespace
}  // namespace gaphys::testing
