// Coulomb friction, rolling resistance and spinning friction against the
// closed forms of a solid sphere (I = 2/5 m r^2) on a plane, and against the
// exact discrete solution of the integrator where the closed form is a
// continuous one: semi-implicit Euler at h from rest under a constant
// acceleration a is at v_n = n a h, x_n = a h^2 n (n + 1) / 2, which is
// ½ a t^2 (1 + h / t): +0.21% from the continuous form after 2 s at 240 Hz.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "engine_test_support.hpp"
#include "impulse_row.hpp"

namespace gaphys::testing {
namespace {

constexpr real radius = 0.5;  // the scenes' sphere

class friction_test : public engine_test {
 protected:
  // The velocity over the floor of the ball's lowest point: v + r ⌋ Ω with
  // r = -radius e3. Zero when it rolls.
  static vector slip(const body& ball) { return ball.velocity_at(ball.position() - vector{0, 0, radius}); }

  static material with_friction(real mu) { return material{0, mu, 0, 0}; }

  // The ball's angular velocity about the world y axis (the e31 = -e13 plane),
  // positive when a ball moving along +x rolls forward.
  static real spin_about_y(const body& ball) { return -ball.angular_velocity().e13(); }
};

// Pushed at v0 without spin, the ball slides: friction μ m g slows it at
// μ g and spins it up at 5 μ g / (2 r), until the slip is gone at
// t* = 2 v0 / (7 μ g); then it rolls at 5/7 v0. Friction's impulse acts at
// the contact point, so the angular momentum about it is kept throughout,
// m v r + I ω = m v0 r: the final speed is 5/7 v0 exactly.
TEST_F(friction_test, a_sliding_ball_slows_at_mu_g_then_rolls_at_five_sevenths) {
  const real v0 = 5, mu = 0.3;
  world w = scenes::sphere_on_floor(vector{v0, 0, 0}, bivector{}, with_friction(mu));
  const body_id ball = 1;
  const real rolling_from = 2 * v0 / (7 * mu * g);
  int first_rolling_step = -1;
  simulate(w, 3 * 240, [&](int i) {
    const body& b = w.at(ball);
    const real t = (i + 1) * h;
    if (first_rolling_step < 0 && length(slip(b)) <= tolerance(1e-9, 1e-5)) first_rolling_step = i;
    if (t < rolling_from - h) {
      // Slipping: the exact discrete solution, v_n = v0 - n μ g h.
      ASSERT_NEAR(x(b.velocity()), v0 - (i + 1) * mu * g * h, tolerance(1e-9, 5e-5)) << "step " << i;
      ASSERT_NEAR(spin_about_y(b), (i + 1) * 5 * mu * g * h / (2 * radius), tolerance(1e-8, 1e-4)) << "step " << i;
    }
  });
  ASSERT_GE(first_rolling_step, 0);
  EXPECT_NEAR((first_rolling_step + 1) * h, rolling_from, h);
  const body& b = w.at(ball);
  EXPECT_NEAR(x(b.velocity()), 5.0 / 7 * v0, 1e-3 * 5.0 / 7 * v0);
  EXPECT_NEAR(x(b.velocity()), 5.0 / 7 * v0, tolerance(1e-12, 5e-5));
  EXPECT_NEAR(y(b.velocity()), 0, tolerance(1e-12, 1e-6));
  EXPECT_NEAR(z(b.velocity()), 0, tolerance(1e-9, 1e-5));
  EXPECT_LE(length(slip(b)), tolerance(1e-9, 1e-5));
  // The energy lost to sliding: ½ m v0² - ½ (m + I / r²) (5/7 v0)² = v0² / 7.
  EXPECT_NEAR(kinetic_energy(w), 0.5 * v0 * v0 - v0 * v0 / 7, tolerance(1e-9, 2e-4));
}

// With backspin ω0 (the lowest point moving forward at v0 + r ω0), the
// angular momentum about the contact, m v0 r - I ω0, is again all that is
// kept: the ball ends rolling at (5 v0 - 2 r ω0) / 7, backwards when
// 2 r ω0 > 5 v0.
TEST_F(friction_test, backspin_ends_at_five_v0_minus_two_r_omega0_over_seven) {
  const real v0 = 2;
  for (real backspin : {real(4), real(8), real(10), real(30)}) {  // 2 r ω0 (m/s)
    const real omega0 = backspin / (2 * radius);
    // Backspin turns the lowest point along +x: Ω = ω0 e13 (r ⌋ Ω = r ω0 e1).
    world w = scenes::sphere_on_floor(vector{v0, 0, 0}, bivector{0, omega0, 0}, with_friction(0.2));
    simulate(w, 5 * 240);
    const body& b = w.at(1);
    const real expected = (5 * v0 - backspin) / 7;
    EXPECT_NEAR(x(b.velocity()), expected, tolerance(1e-9, 2e-4)) << "2 r ω0 = " << backspin;
    EXPECT_LE(length(slip(b)), tolerance(1e-9, 1e-5)) << "2 r ω0 = " << backspin;
  }
}

// The slope falls towards -e1 by θ; `down` is the unit vector along it.
struct incline {
  real angle;
  vector down() const { return vector{-std::cos(angle), 0, -std::sin(angle)}; }
  vector normal() const { return vector{-std::sin(angle), 0, std::cos(angle)}; }
};

// On a 30° incline: with μ = 0.5 (more than the 2/7 tan θ = 0.165 rolling
// needs) the ball rolls without slipping at a = 5/7 g sin θ; with μ = 0.05 it
// slides at a = g (sin θ - μ cos θ) while friction spins it up at
// 5 μ g cos θ / (2 r). Both against the integrator's exact discrete
// solution; the continuous ½ a t² is 0.21% below it at 2 s.
TEST_F(friction_test, a_ball_on_an_incline_rolls_or_slides_as_mu_allows) {
  const incline slope{pi / 6};
  const int steps = 2 * 240;
  for (real mu : {real(0.5), real(0.05)}) {
    world w = scenes::sphere_on_incline(slope.angle, mu);
    const vector start = w.at(1).position();
    simulate(w, steps);
    const body& b = w.at(1);
    const bool rolls = mu > 2.0 / 7 * std::tan(slope.angle);
    const real s = std::sin(slope.angle), c = std::cos(slope.angle);
    const real a = rolls ? 5.0 / 7 * g * s : g * (s - mu * c);
    const real discrete = a * h * h * steps * (steps + 1) / 2;
    const real distance = dot(b.position() - start, slope.down());
    EXPECT_NEAR(distance, discrete, tolerance(1e-6, 1e-5) * discrete) << "μ = " << mu;
    EXPECT_NEAR(distance / (0.5 * a * 4) - 1, h / 2, tolerance(1e-6, 1e-5)) << "μ = " << mu;  // the O(h) offset
    EXPECT_NEAR(dot(b.position() - start, slope.normal()), 0, tolerance(1e-9, 1e-5)) << "μ = " << mu;
    // It turns only about the axis across the slope (e2, the e13 plane):
    // rolling ties the rate to the speed, sliding spins it up at
    // 5 μ g cos θ / (2 r).
    const bivector spin = b.angular_velocity();
    EXPECT_NEAR(std::fabs(spin.e12()) + std::fabs(spin.e23()), 0, tolerance(1e-12, 1e-6)) << "μ = " << mu;
    const real speed = dot(b.velocity(), slope.down());
    const real expected_spin = rolls ? speed / radius : steps * h * 5 * mu * g * c / (2 * radius);
    EXPECT_NEAR(std::fabs(spin.e13()), expected_spin, tolerance(1e-6, 1e-5) * expected_spin) << "μ = " << mu;
  }
}

// The contact reports the impulses that hold the rolling ball on the slope:
// per step the normal one carries m g cos θ h and friction m g sin θ h - m a h
// = 2/7 m g sin θ h up the slope, and the next step starts from them.
TEST_F(friction_test, a_rolling_contact_reports_its_normal_and_friction_impulses) {
  const incline slope{pi / 6};
  world w = scenes::sphere_on_incline(slope.angle, 0.5);
  simulate(w, 240);
  ASSERT_EQ(w.contacts().size(), 1u);
  const contact& c = w.contacts()[0];
  const real s = std::sin(slope.angle), co = std::cos(slope.angle);
  // Body A is the plane (index 0), so the impulses are the ones on it.
  EXPECT_NEAR(c.impulse.normal, g * co * h, tolerance(1e-12, 1e-6));
  EXPECT_TRUE(near(-c.impulse.tangent, (-2.0 / 7 * g * s * h) * slope.down(), tolerance(1e-12, 1e-6)));
  EXPECT_NEAR(c.resting.normal, c.impulse.normal, tolerance(1e-15, 1e-7));
  EXPECT_TRUE(near(c.resting.tangent, c.impulse.tangent, tolerance(1e-15, 1e-7)));
}

// Friction is a cone, not a pyramid aligned with some axes: a ball sliding
// in any direction over the floor slows at μ g. (ODE's pyramid gives √2 μ g
// at 45°.)
TEST_F(friction_test, sliding_friction_is_the_same_in_every_direction) {
  const real v0 = 5, mu = 0.3, t = 0.2;  // still slipping at t (t* = 0.49 s)
  for (real degrees : {real(0), real(30), real(45), real(60), real(137)}) {
    const real angle = degrees * pi / 180;
    const vector direction{std::cos(angle), std::sin(angle), 0};
    world w = scenes::sphere_on_floor(v0 * direction, bivector{}, with_friction(mu));
    simulate(w, static_cast<int>(t * 240));
    const vector v = w.at(1).velocity();
    const real deceleration = (v0 - dot(v, direction)) / t;
    EXPECT_NEAR(deceleration, mu * g, tolerance(1e-9, 2e-5) * mu * g) << degrees << "°";
    EXPECT_NEAR(length(v - dot(v, direction) * direction), 0, tolerance(1e-12, 2e-5)) << degrees << "°";
  }
}

// The impulsive law of a solid sphere striking a plane: the normal impulse
// J_n = (1 + e) m |v_n|; friction meets the slip u of the contact point
// (v + r ⌋ Ω, tangential) with at most μ J_n. Sticking, when the impulse
// that stops the slip, 2/7 m |u|, is within the bound: the ball leaves
// rolling; sliding otherwise: J_t = -μ J_n u / |u|.
TEST_F(friction_test, an_oblique_impact_with_friction_follows_the_impulsive_law) {
  for (int trial = 0; trial < 40; ++trial) {
    const real mu = trial % 2 == 0 ? uniform(0.8, 2) : uniform(0.01, 0.1);
    const real e = uniform(0, 1), m = uniform(0.5, 3), approach = uniform(1, 5);
    const vector tangential{uniform(-3, 3), uniform(-3, 3), 0};
    const bivector spin{uniform(-10, 10), uniform(-10, 10), uniform(-10, 10)};
    world w = make_world(vector{});
    add_floor(w, 0, e, mu);
    // Meets the floor 0.4 of the way into the first step.
    const vector start{0, 0, radius + real(0.4) * approach * h};
    body_definition d;
    d.mass = m;
    d.position = start;
    d.velocity = tangential - vector{0, 0, approach};
    d.angular_velocity = spin;
    d.shape = shape::sphere(radius).with_restitution(e).with_friction(mu);
    const body_id ball = w.create_body(d);
    const body before = w.at(ball);
    w.step(h);
    const body& after = w.at(ball);

    const vector r{0, 0, -radius};
    const vector u = before.velocity_at(before.position() + r) + vector{0, 0, approach};
    const real jn = (1 + e) * m * approach;
    const bool sticks = 2.0 / 7 * m * length(u) <= mu * jn;
    const vector jt = sticks ? (-2.0 / 7 * m) * u : (-mu * jn / length(u)) * u;
    const vector v = before.velocity() + (1 / m) * (jt + vector{0, 0, jn});
    const bivector omega = before.angular_velocity() + before.world_inverse_inertia(e3ga::op(r, jt));
    const real scale = length(before.velocity()) + radius * length(spin);
    EXPECT_TRUE(near(after.velocity(), v, tolerance(1e-9, 1e-5) * scale)) << "trial " << trial << (sticks ? " sticks" : " slides");
    EXPECT_TRUE(near(after.angular_velocity(), omega, tolerance(1e-9, 1e-5) * scale / radius))
        << "trial " << trial << (sticks ? " sticks" : " slides");
    if (sticks) {  // the lowest point leaves the floor without sliding over it
      const vector leaving = slip(after);
      EXPECT_LE(length(leaving - z(leaving) * vector{0, 0, 1}), tolerance(1e-9, 1e-5) * scale) << "trial " << trial;
    }
    // The contact reports the impulses it gave.
    ASSERT_EQ(w.contacts().size(), 1u);
    EXPECT_NEAR(w.contacts()[0].impulse.normal, jn, tolerance(1e-9, 1e-5) * jn);
    EXPECT_TRUE(near(-w.contacts()[0].impulse.tangent, jt, tolerance(1e-9, 1e-5) * jn)) << "trial " << trial;
  }
}

// Rolling resistance c: a resisting torque c r N against the rolling, and
// the friction that keeps the ball rolling, slow it at 5/7 c g until it
// stops, and it stays stopped.
TEST_F(friction_test, rolling_resistance_stops_a_rolling_ball) {
  const real v0 = 2, c = 0.05;
  const material m{0, 0.5, c, 0};
  world w = scenes::sphere_on_floor(vector{v0, 0, 0}, bivector{0, -v0 / radius, 0}, m);
  const real deceleration = 5.0 / 7 * c * g;
  const real stops_at = v0 / deceleration;  // 5.7 s
  const int steps_to_2_s = 2 * 240;
  simulate(w, steps_to_2_s);
  EXPECT_NEAR(x(w.at(1).velocity()), v0 - steps_to_2_s * deceleration * h, tolerance(1e-9, 1e-5));
  EXPECT_LE(length(slip(w.at(1))), tolerance(1e-9, 1e-5));
  simulate(w, static_cast<int>((stops_at - 2 + 1) * 240));
  const real x_stopped = x(w.at(1).position());
  // Travelled the discrete sum of v_n h, within a step's travel of v0² / (2 a).
  EXPECT_NEAR(x_stopped, v0 * v0 / (2 * deceleration), v0 * h);
  simulate(w, 240);
  EXPECT_LE(length(w.at(1).velocity()), tolerance(1e-9, 1e-5));
  EXPECT_LE(length(w.at(1).angular_velocity()), tolerance(1e-9, 1e-5));
  EXPECT_NEAR(x(w.at(1).position()), x_stopped, tolerance(1e-9, 1e-5));
}

// Spinning friction c: a ball spinning about the vertical slows by the
// torque c r N, at 5 c g / (2 r) rad/s², and stops.
TEST_F(friction_test, spinning_friction_stops_a_spinning_ball) {
  const real omega0 = 10, c = 0.1;
  const material m{0, 0.5, 0, c};
  world w = scenes::sphere_on_floor(vector{}, bivector{omega0, 0, 0}, m);
  const real rate = 5 * c * g / (2 * radius);
  simulate(w, 240);
  EXPECT_NEAR(w.at(1).angular_velocity().e12(), omega0 - 240 * rate * h, tolerance(1e-9, 2e-4));
  EXPECT_LE(length(w.at(1).velocity()), tolerance(1e-12, 1e-6));
  simulate(w, static_cast<int>((omega0 / rate) * 240));
  EXPECT_LE(length(w.at(1).angular_velocity()), tolerance(1e-9, 1e-5));
}

// A frictionless ball (μ = 0 on either surface, by the default geometric
// mean) slides for ever; the world's combine rules pick the contact's values.
TEST_F(friction_test, combine_rules_pick_each_contacts_values) {
  const material ball{0.9, 0.8, 0.02, 0.04}, floor{0.1, 0.2, 0.06, 0.01};
  const std::pair<combine_rule, std::array<real, 4>> cases[] = {
      {combine_rule::geometric_mean, {0.3, 0.4, std::sqrt(0.0012), std::sqrt(0.0004)}},
      {combine_rule::average, {0.5, 0.5, 0.04, 0.025}},
      {combine_rule::min, {0.1, 0.2, 0.02, 0.01}},
      {combine_rule::max, {0.9, 0.8, 0.06, 0.04}},
      {combine_rule::multiply, {0.09, 0.16, 0.0012, 0.0004}},
  };
  for (const auto& [rule, expected] : cases) {
    world_settings settings;
    settings.material_combine = {rule, rule, rule, rule};
    world w(settings);
    body_definition plane;
    plane.is_static = true;
    plane.shape = shape::plane(vector{0, 0, 1}, 0)
                      .with_restitution(floor.restitution)
                      .with_friction(floor.friction)
                      .with_rolling_resistance(floor.rolling_resistance)
                      .with_spinning_friction(floor.spinning_friction);
    w.create_body(plane);
    body_definition d;
    d.position = vector{0, 0, radius};
    d.shape = shape::sphere(radius)
                  .with_restitution(ball.restitution)
                  .with_friction(ball.friction)
                  .with_rolling_resistance(ball.rolling_resistance)
                  .with_spinning_friction(ball.spinning_friction);
    w.create_body(d);
    w.step(h);
    ASSERT_EQ(w.contacts().size(), 1u);
    const material& got = w.contacts()[0].material;
    EXPECT_NEAR(got.restitution, expected[0], tolerance(1e-15, 1e-7)) << static_cast<int>(rule);
    EXPECT_NEAR(got.friction, expected[1], tolerance(1e-15, 1e-7)) << static_cast<int>(rule);
    EXPECT_NEAR(got.rolling_resistance, expected[2], tolerance(1e-15, 1e-7)) << static_cast<int>(rule);
    EXPECT_NEAR(got.spinning_friction, expected[3], tolerance(1e-15, 1e-7)) << static_cast<int>(rule);
  }

  // The defaults: a bouncy ball on a dead floor still bounces (max), a
  // frictionless floor makes the contact frictionless (geometric mean); with
  // min, the dead floor wins.
  for (const bool dead_floor_wins : {false, true}) {
    world w = make_world();
    if (dead_floor_wins) w.set_material_combine({combine_rule::min, combine_rule::geometric_mean,
                                                 combine_rule::max, combine_rule::max});
    add_floor(w, 0, 0, 0);
    add_sphere(w, vector{0, 0, 1.5}, radius, 1, vector{2, 0, 0}, 1, 1);
    simulate(w, 240);
    EXPECT_NEAR(x(w.at(1).velocity()), 2, tolerance(1e-12, 1e-6));  // no friction: still sliding at 2 m/s
    real highest = 0;
    simulate(w, 240, [&](int) { highest = std::max(highest, z(w.at(1).position()) - radius); });
    if (dead_floor_wins) {
      EXPECT_LE(highest, tolerance(1e-6, 1e-5));
    } else {
      EXPECT_GT(highest, 0.5);
    }
  }
}

// Friction, rolling and spinning resistance only take energy away: in random
// scenes of spheres with random materials, spins and speeds, bouncing in a
// closed box without gravity (no external work), the kinetic energy never
// grows from one step to the next.
TEST_F(friction_test, friction_never_adds_kinetic_energy) {
  for (int scene = 0; scene < 4; ++scene) {
    world_settings settings;
    settings.gravity = vector{};
    settings.restitution_threshold = uniform(0, 1);
    world w(settings);
    const real half = 0.6;
    const std::array<vector, 6> normals{vector{1, 0, 0}, vector{-1, 0, 0}, vector{0, 1, 0},
                                        vector{0, -1, 0}, vector{0, 0, 1}, vector{0, 0, -1}};
    for (const vector& n : normals) {
      body_definition wall;
      wall.is_static = true;
      wall.shape = shape::plane(n, -half)
                       .with_restitution(uniform(0, 1))
                       .with_friction(uniform(0, 1.5))
                       .with_rolling_resistance(uniform(0, 0.1))
                       .with_spinning_friction(uniform(0, 0.1));
      w.create_body(wall);
    }
    for (int i = 0; i < 30; ++i) {
      body_definition d;
      const real r = uniform(0.05, 0.15);
      d.mass = uniform(0.2, 5);
      d.position = vector{uniform(-0.4, 0.4), uniform(-0.4, 0.4), uniform(-0.4, 0.4)};
      d.velocity = uniform(0, 3) * random_unit_vector();
      d.angular_velocity = bivector{uniform(-20, 20), uniform(-20, 20), uniform(-20, 20)};
      d.shape = shape::sphere(r)
                    .with_restitution(uniform(0, 1))
                    .with_friction(uniform(0, 1.5))
                    .with_rolling_resistance(uniform(0, 0.1))
                    .with_spinning_friction(uniform(0, 0.1));
      w.create_body(d);
    }
    const real e0 = kinetic_energy(w);
    for (int i = 0; i < 3 * 240; ++i) {
      const real before = kinetic_energy(w);
      w.step(h);
      ASSERT_LE(kinetic_energy(w), before + tolerance(1e-9, 1e-5) * e0) << "scene " << scene << ", step " << i;
    }
    EXPECT_LT(kinetic_energy(w), e0) << "scene " << scene;
  }
}

// A friction block of two linear rows (not turning, unit inverse masses)
// whose effective-mass matrix K is ((k00, k01), (k01, k11)), prepared.
detail::disk_block block_of_effective_mass(real k00, real k11, real k01) {
  detail::disk_block block;
  block.rows[0].linear = vector{1, 0, 0};
  block.rows[1].linear = vector{k01 / std::sqrt(k00 * k11), 0, 0};
  block.rows[1].linear =
      block.rows[1].linear +
      vector{0, std::sqrt(1 - x(block.rows[1].linear) * x(block.rows[1].linear)), 0};
  block.rows[0].linear = std::sqrt(k00) * block.rows[0].linear;
  block.rows[1].linear = std::sqrt(k11) * block.rows[1].linear;
  block.rows[0].turns = block.rows[1].turns = false;
  block.rows[0].mass_inverse = k00;
  block.rows[1].mass_inverse = k11;
  block.prepare(1);
  return block;
}

// A sliding contact's friction impulse is the point of the disk nearest to
// the sticking impulse λ* in the metric of the rows' effective mass K:
// on the circle, with the slip it leaves, K (λ - λ*), against it (Coulomb's
// most dissipation), and no point of the circle nearer in K's metric.
TEST_F(friction_test, a_sliding_impulse_is_the_disk_point_nearest_in_the_effective_mass_metric) {
  for (int trial = 0; trial < 2000; ++trial) {
    const real k00 = uniform(0.2, 3), k11 = uniform(0.2, 3);
    const real k01 = uniform(-0.9, 0.9) * std::sqrt(k00 * k11);
    detail::disk_block block = block_of_effective_mass(k00, k11, k01);
    ASSERT_NEAR(block.rows[0].coupling(block.rows[1], 1), k01, tolerance(1e-12, 1e-6));
    const std::array<real, 2> outside{uniform(-3, 3), uniform(-3, 3)};
    const real bound = 0.5;
    if (outside[0] * outside[0] + outside[1] * outside[1] <= bound * bound) continue;
    const std::array<real, 2> l = block.nearest_on_disk(outside, bound);
    ASSERT_NEAR(std::sqrt(l[0] * l[0] + l[1] * l[1]), bound, tolerance(1e-12, 1e-6));
    const std::array<real, 2> d{l[0] - outside[0], l[1] - outside[1]};
    const std::array<real, 2> slip{k00 * d[0] + k01 * d[1], k01 * d[0] + k11 * d[1]};
    // slip = -ν λ with ν >= 0: parallel to λ and opposite.
    EXPECT_NEAR(slip[0] * l[1] - slip[1] * l[0], 0, tolerance(1e-9, 1e-5) * (1 + std::fabs(slip[0]) + std::fabs(slip[1])));
    EXPECT_LE(slip[0] * l[0] + slip[1] * l[1], tolerance(1e-12, 1e-6));
    const auto energy = [&](real a0, real a1) {
      const real e0 = a0 - outside[0], e1 = a1 - outside[1];
      return k00 * e0 * e0 + 2 * k01 * e0 * e1 + k11 * e1 * e1;
    };
    for (int i = 0; i < 360; ++i) {
      const real angle = 2 * pi * i / 360;
      ASSERT_LE(energy(l[0], l[1]), energy(bound * std::cos(angle), bound * std::sin(angle)) + tolerance(1e-12, 2e-5));
    }
  }
}

// A sweep before a contact's last takes one Newton step towards the nearest
// point (nearest_on_disk, not exact) and puts λ on the circle; the next
// sweep starts from its root. Solved again and again from the same λ*, as
// a contact's sweeps converge, the steps reach the nearest point: its slip
// K (λ - λ*) against λ, as in the test above.
TEST_F(friction_test, single_newton_steps_land_on_the_circle_and_reach_the_nearest_point) {
  for (int trial = 0; trial < 2000; ++trial) {
    const real k00 = uniform(0.2, 3), k11 = uniform(0.2, 3);
    const real k01 = uniform(-0.9, 0.9) * std::sqrt(k00 * k11);
    detail::disk_block block = block_of_effective_mass(k00, k11, k01);
    const std::array<real, 2> outside{uniform(-3, 3), uniform(-3, 3)};
    const real bound = uniform(0.1, 1);
    if (outside[0] * outside[0] + outside[1] * outside[1] <= 1.01 * bound * bound) continue;
    std::array<real, 2> l{};
    for (int sweep = 0; sweep < 8; ++sweep) {
      l = detail::nearest_on_disk(outside, bound, block.eigen_ratio, block.eigenbasis,
                                  block.slip_rate, false);
      ASSERT_NEAR(std::hypot(l[0], l[1]), bound, tolerance(1e-12, 1e-6) * bound)
          << "trial " << trial << ", sweep " << sweep;
    }
    const std::array<real, 2> d{l[0] - outside[0], l[1] - outside[1]};
    const std::array<real, 2> slip{k00 * d[0] + k01 * d[1], k01 * d[0] + k11 * d[1]};
    EXPECT_NEAR(slip[0] * l[1] - slip[1] * l[0], 0,
                tolerance(1e-12, 1e-5) * (1 + std::fabs(slip[0]) + std::fabs(slip[1])))
        << "trial " << trial;
    EXPECT_LE(slip[0] * l[0] + slip[1] * l[1], tolerance(1e-12, 1e-6)) << "trial " << trial;
  }
}

// The normal impulse's clamp (detail::at_least_zero, SSE's max on x86) is
// std::max(x, 0) to the bit for every kind of x: the sweeps' results must
// not depend on which of the two a build uses.
TEST_F(friction_test, the_normal_impulses_clamp_is_std_max_with_zero_to_the_bit) {
  using limits = std::numeric_limits<real>;
  const std::vector<real> inputs = {-limits::infinity(), -limits::max(),        real(-1.5),
                                    -limits::min(),      -limits::denorm_min(), real(-0.0),
                                    real(0.0),           limits::denorm_min(),  limits::min(),
                                    real(2.25),          limits::max(),         limits::infinity(),
                                    limits::quiet_NaN(), -limits::quiet_NaN()};
  for (const real x : inputs) {
    const real clamped = detail::at_least_zero(x), expected = std::max(x, real(0));
    EXPECT_EQ(std::isnan(clamped), std::isnan(expected)) << x;
    if (std::isnan(expected)) continue;
    EXPECT_EQ(clamped, expected) << x;
    EXPECT_EQ(std::signbit(clamped), std::signbit(expected)) << x;
  }
}

// The sweeps apply a contact's normal impulse together with its friction
// impulse, friction reading its speeds from before the normal impulse plus
// what that changes them (the rows' coupling, disk_block::solve_after): the
// same, to rounding, as applying the normal impulse and then solving
// friction, sticking or sliding, for off-centre contacts on bodies of any
// inertia.
TEST_F(friction_test, friction_solved_after_the_normal_impulse_is_the_same_as_solved_behind_it) {
  int sliding = 0;
  for (int trial = 0; trial < 1000; ++trial) {
    std::array<detail::row_body, 2> bodies;
    for (detail::row_body& body : bodies) {
      body.inverse_mass = uniform(0.1, 2);
      body.is_static = false;
      body.isotropic = false;
      // A symmetric I⁻¹, positive definite by its dominant diagonal.
      const real m01 = uniform(-0.2, 0.2), m02 = uniform(-0.2, 0.2), m12 = uniform(-0.2, 0.2);
      body.columns = {bivector{uniform(0.5, 2), m01, m02}, bivector{m01, uniform(0.5, 2), m12},
                      bivector{m02, m12, uniform(0.5, 2)}};
    }
    const vector n = random_unit_vector();
    const vector v = random_unit_vector();
    const vector t1 = (v - dot(v, n) * n) / length(v - dot(v, n) * n);
    const vector t2{y(n) * z(t1) - z(n) * y(t1), z(n) * x(t1) - x(n) * z(t1),
                    x(n) * y(t1) - y(n) * x(t1)};
    const vector r_a = uniform(0.2, 1) * random_unit_vector();
    const vector r_b = uniform(0.2, 1) * random_unit_vector();
    detail::impulse_row normal;
    detail::set_linear_row(normal, n, r_a, r_b, bodies[0], bodies[1]);
    detail::disk_block block;
    detail::set_linear_row(block.rows[0], t1, r_a, r_b, bodies[0], bodies[1]);
    detail::set_linear_row(block.rows[1], t2, r_a, r_b, bodies[0], bodies[1]);
    const real inverse_masses = bodies[0].inverse_mass + bodies[1].inverse_mass;
    block.prepare(inverse_masses);
    block.accumulated = {uniform(-0.1, 0.1), uniform(-0.1, 0.1)};
    const std::array<real, 2> coupling{block.rows[0].coupling(normal, inverse_masses),
                                       block.rows[1].coupling(normal, inverse_masses)};
    const auto velocities = [&](const detail::row_body& body) {
      return detail::solver_body{uniform(-1, 1) * random_unit_vector(),
                                 bivector{uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)},
                                 body.inverse_mass};
    };
    const detail::solver_body a0 = velocities(bodies[0]), b0 = velocities(bodies[1]);
    const real normal_impulse = uniform(0, 1);
    const real bound = uniform(0.05, 0.5);

    detail::solver_body a = a0, b = b0;
    detail::disk_block behind = block;
    normal.apply(a, b, normal_impulse);
    const real change = behind.solve(a, b, bound);

    detail::solver_body a_with = a0, b_with = b0;
    detail::disk_block with = block;
    const real change_with = with.solve_after(a_with, b_with, bound, normal.linear, normal.arms(),
                                              normal_impulse, coupling, true);

    const real tolerance_ = tolerance(1e-12, 1e-5);
    ASSERT_TRUE(near(a_with.velocity, a.velocity, tolerance_)) << "trial " << trial;
    ASSERT_TRUE(near(b_with.velocity, b.velocity, tolerance_)) << "trial " << trial;
    ASSERT_TRUE(near(a_with.angular_velocity, a.angular_velocity, tolerance_)) << "trial " << trial;
    ASSERT_TRUE(near(b_with.angular_velocity, b.angular_velocity, tolerance_)) << "trial " << trial;
    ASSERT_NEAR(with.accumulated[0], behind.accumulated[0], tolerance_) << "trial " << trial;
    ASSERT_NEAR(with.accumulated[1], behind.accumulated[1], tolerance_) << "trial " << trial;
    ASSERT_NEAR(change_with, change, tolerance_) << "trial " << trial;
    const real held = std::hypot(behind.accumulated[0], behind.accumulated[1]);
    if (held > bound * (1 - tolerance_)) ++sliding;
  }
  // Both kinds of solve were met.
  EXPECT_GT(sliding, 100);
  EXPECT_LT(sliding, 900);
}

// The nearest point scales with λ* and the bound (the metric does not
// change), however small the impulses: a box settling into a corner of a
// float world had friction bounds of 3e-16 N s, whose squares times
// another impulse underflowed, and its impulses became NaN.
TEST_F(friction_test, a_sliding_impulse_scales_with_the_stopping_impulse_and_the_bound) {
  for (int trial = 0; trial < 500; ++trial) {
    detail::disk_block block;
    block.rows[0].linear = vector{uniform(0.4, 1.7), 0, 0};
    block.rows[1].linear = vector{uniform(-0.5, 0.5), uniform(0.4, 1.7), 0};
    block.rows[0].turns = block.rows[1].turns = false;
    block.rows[0].mass_inverse = e3ga::scp(block.rows[0].linear, block.rows[0].linear);
    block.rows[1].mass_inverse = e3ga::scp(block.rows[1].linear, block.rows[1].linear);
    block.prepare(1);
    const std::array<real, 2> outside{uniform(-3, 3), uniform(-3, 3)};
    const real bound = uniform(0.1, 0.5);
    if (outside[0] * outside[0] + outside[1] * outside[1] <= bound * bound) continue;
    const std::array<real, 2> unit = block.nearest_on_disk(outside, bound);
    for (const real scale : {real(1e-16), real(1e-12), real(1e-6), real(1e8)}) {
      block.slip_rate = -1;  // as a new contact starts
      const std::array<real, 2> l =
          block.nearest_on_disk({scale * outside[0], scale * outside[1]}, scale * bound);
      for (int i = 0; i < 2; ++i) {
        ASSERT_TRUE(std::isfinite(l[i])) << "scale " << scale;
        ASSERT_NEAR(l[i] / scale, unit[i], tolerance(1e-12, 1e-5)) << "scale " << scale;
      }
    }
  }
}

}  // namespace
}  // namespace gaphys::testing
