// Impacts that involve more than two bodies in one step: Newton's cradle and
// struck rows against the sequential (event-driven, vanishing gaps) closed
// form, and the energy of impacts that chain through a wall, checked on a
// gas of elastic spheres.
#include <algorithm>
#include <vector>

#include "engine_test_support.hpp"

namespace gaphys::testing {
namespace {

class impact_test : public engine_test {
 protected:
  // Steps the world for `seconds` in steps of `step`: the highest the ball
  // rises above `rest` (its centre's height when it touches what it falls
  // on) between its first bounce and its second.
  static real first_rebound_apex(world& w, body_id ball, real step, real seconds, real rest) {
    real apex = 0, last_speed = 0;
    int bounces = 0;
    for (int i = 0; i * step < seconds; ++i) {
      w.step(step);
      const real vz = z(w.at(ball).velocity());
      if (last_speed < 0 && vz > 0) ++bounces;
      if (bounces == 1) apex = std::max(apex, z(w.at(ball).position()) - rest);
      last_speed = vz;
    }
    return apex;
  }
  static vector momentum(const world& w) {
    vector p{};
    for (const body& b : w.bodies()) {
      if (!b.is_static()) p = p + b.mass() * b.velocity();
    }
    return p;
  }
};

// Sphere B bounces off a wall and, later in the same step, meets sphere A,
// from which it was moving away when the step began. In the exact event
// sequence B leaves the wall at 2 m/s, exchanges velocities with A (equal
// masses, e = 1) and returns to the wall at 1 m/s, which sends it back at
// 1 m/s: A ends at +2, B at +1, and the energy is what it was. (The solver
// used to give the wall a fixed bounce target and the pair a close-the-gap
// target, which together pushed out 42% more energy than came in here.)
TEST_F(impact_test, a_bounce_off_a_wall_into_a_second_sphere_creates_no_energy) {
  for (real threshold : {real(0), real(0.5)}) {
    world_settings settings;
    settings.gravity = vector{};
    settings.restitution_threshold = threshold;
    world w(settings);
    body_definition wall;
    wall.is_static = true;
    wall.shape = shape::plane(vector{1, 0, 0}, 0).with_restitution(1).with_friction(0);
    w.create_body(wall);  // the half-space x <= 0
    const real r = 0.1;
    const real wall_gap = 0.3 * 2 * h;  // B meets the wall 0.3 of the way into the step
    const body_id b = add_sphere(w, vector{r + wall_gap, 0, 0}, r, 1, vector{-2, 0, 0}, 1, 0);
    const body_id a =
        add_sphere(w, vector{3 * r + wall_gap + real(0.001), 0, 0}, r, 1, vector{-1, 0, 0}, 1, 0);
    const real e0 = kinetic_energy(w);
    for (int i = 0; i < 24; ++i) {  // 0.1 s
      const real before = kinetic_energy(w);
      w.step(h);
      EXPECT_LE(kinetic_energy(w), before * (1 + tolerance(1e-12, 1e-6))) << "step " << i << ", threshold " << threshold;
    }
    EXPECT_NEAR(kinetic_energy(w) / e0, 1, tolerance(1e-12, 1e-6)) << "threshold " << threshold;
    EXPECT_NEAR(x(w.at(a).velocity()), 2, tolerance(1e-12, 1e-6)) << "threshold " << threshold;
    EXPECT_NEAR(x(w.at(b).velocity()), 1, tolerance(1e-12, 1e-6)) << "threshold " << threshold;
  }
}

// 300 elastic spheres in a closed box, bouncing at any speed: every impact
// keeps the kinetic energy, so the gas does, step by step and over 20 s.
TEST_F(impact_test, a_gas_of_elastic_spheres_keeps_its_energy) {
  world w = scenes::sphere_gas(300, 1, 2);
  const real e0 = kinetic_energy(w);
  real largest_gain = 0;
  const int steps = 20 * 240;
  for (int i = 0; i < steps; ++i) {
    const real before = kinetic_energy(w);
    w.step(h);
    largest_gain = std::max(largest_gain, (kinetic_energy(w) - before) / e0);
  }
  EXPECT_LE(largest_gain, tolerance(1e-9, 1e-5));
  EXPECT_NEAR(kinetic_energy(w) / e0, 1, 1e-4);
  // And the balls stayed in the box.
  for (const body& b : w.bodies()) {
    if (b.is_static()) continue;
    for (real c : {x(b.position()), y(b.position())}) EXPECT_LE(std::fabs(c), 2);
    EXPECT_GE(z(b.position()), 0);
    EXPECT_LE(z(b.position()), 4);
  }
}

// Newton's cradle: k balls released at 1 m/s into a row of 5 - k touching
// balls. With vanishing gaps the impacts happen one after another, each an
// exchange of velocities between equal masses: k balls leave the far end at
// 1 m/s and the rest stop.
TEST_F(impact_test, newtons_cradle_sends_out_as_many_balls_as_came_in) {
  for (int released : {1, 2, 3}) {
    world w = scenes::newtons_cradle(released, 5, 1);
    const real e0 = kinetic_energy(w);
    const vector p0 = momentum(w);
    simulate(w, 240);
    for (body_id i = 0; i < 5; ++i) {
      const real expected = i >= 5 - static_cast<body_id>(released) ? 1 : 0;
      EXPECT_NEAR(x(w.at(i).velocity()), expected, tolerance(1e-9, 1e-5)) << released << " released, ball " << i;
    }
    EXPECT_NEAR(kinetic_energy(w), e0, tolerance(1e-12, 1e-6) * e0) << released << " released";
    EXPECT_TRUE(near(momentum(w), p0, tolerance(1e-12, 1e-6))) << released << " released";
  }
}

// The same row struck from the other end, so the sweeps meet the contacts
// against the impact's direction: the answer must not depend on the order.
TEST_F(impact_test, a_row_struck_against_the_contact_order_gives_the_same_answer) {
  world w = make_world(vector{});
  for (int i = 0; i < 4; ++i) add_sphere(w, vector{real(i), 0, 0}, 0.5, 1, vector{}, 1, 0);
  add_sphere(w, vector{4 + 1e-9, 0, 0}, 0.5, 1, vector{-1, 0, 0}, 1, 0);
  simulate(w, 240);
  EXPECT_NEAR(x(w.at(0).velocity()), -1, tolerance(1e-9, 1e-5));
  for (body_id i = 1; i < 5; ++i) EXPECT_NEAR(x(w.at(i).velocity()), 0, tolerance(1e-9, 1e-5)) << "ball " << i;
}

// A 1 kg ball at 1 m/s strikes a touching row of 2, 3 and 4 kg (e = 1).
// Sequential impacts: each ball meets the next with the 1-D elastic law,
// u' = (m1 - m2) / (m1 + m2) u, w' = 2 m1 / (m1 + m2) u. With the masses
// growing along the row every ball bounces back slower than the one behind
// it, so no pair meets again: striker -1/3, then -2/15, -8/105, and the last
// ball leaves at 48/105 m/s.
TEST_F(impact_test, a_struck_row_of_unequal_masses_follows_the_sequential_closed_form) {
  const std::vector<real> masses{1, 2, 3, 4};
  world w = make_world(vector{});
  add_sphere(w, vector{-1e-9, 0, 0}, 0.5, masses[0], vector{1, 0, 0}, 1, 0);
  for (std::size_t i = 1; i < masses.size(); ++i) {
    add_sphere(w, vector{real(i), 0, 0}, 0.5, masses[i], vector{}, 1, 0);
  }
  std::vector<real> expected(masses.size(), 0);
  real incoming = 1;
  for (std::size_t i = 0; i + 1 < masses.size(); ++i) {
    const real m1 = masses[i], m2 = masses[i + 1];
    expected[i] = (m1 - m2) / (m1 + m2) * incoming;
    incoming = 2 * m1 / (m1 + m2) * incoming;
  }
  expected.back() = incoming;
  EXPECT_NEAR(expected[0], -1.0 / 3, tolerance(1e-15, 1e-7));
  EXPECT_NEAR(expected[3], 48.0 / 105, tolerance(1e-15, 1e-7));
  const real e0 = kinetic_energy(w);
  simulate(w, 240);
  for (std::size_t i = 0; i < masses.size(); ++i) {
    EXPECT_NEAR(x(w.at(i).velocity()), expected[i], tolerance(1e-9, 1e-5)) << "ball " << i;
  }
  EXPECT_NEAR(kinetic_energy(w), e0, tolerance(1e-12, 1e-6) * e0);
  EXPECT_NEAR(x(momentum(w)), 1, tolerance(1e-12, 1e-6));
}

// A column of elastic balls resting on a floor is not an impact: gravity
// presses its contacts together by g h per step, far below the restitution
// threshold, so nothing bounces and the column stays as it was.
TEST_F(impact_test, a_resting_column_of_elastic_balls_stays_at_rest) {
  world w = make_world();
  add_floor(w, 0, 1);
  for (int i = 0; i < 4; ++i) add_sphere(w, vector{0, 0, real(0.5) + real(i)}, 0.5, 1, vector{}, 1);
  simulate(w, 240 * 5);
  for (body_id i = 1; i <= 4; ++i) {
    EXPECT_NEAR(z(w.at(i).position()), 0.5 + (i - 1), tolerance(1e-6, 1e-5)) << "ball " << i;
    EXPECT_LE(length(w.at(i).velocity()), tolerance(1e-9, 1e-5)) << "ball " << i;
  }
}

// A 1 g ball dropped 1 m onto a heavy ball or box (1e6 kg) resting on the
// floor rises to e^2 of its drop, as it does off a static one: what the
// struck body rests on holds its gravity through the step. (Timed as if the
// struck body fell freely, the ball struck it g t slower than it came and
// rose 7.5% too low at 240 Hz, 24% at 60 Hz.)
TEST_F(impact_test, a_ball_bounces_off_a_heavy_body_resting_on_the_floor_as_off_a_static_one) {
  const real e = 0.5;
  for (const real step : {real(1) / 240, real(1) / 60}) {
    for (const bool box : {false, true}) {
      for (const bool is_static : {true, false}) {
        world w = make_world();
        add_floor(w);
        body_definition struck;
        struck.is_static = is_static;
        struck.mass = 1e6;
        struck.position = vector{0, 0, 0.5};
        struck.shape =
            (box ? shape::box(vector{0.5, 0.5, 0.5}) : shape::sphere(0.5)).with_restitution(e);
        w.create_body(struck);
        const body_id ball =
            add_sphere(w, vector{box ? real(0.2) : real(0), 0, 2.01}, 0.01, 0.001, vector{}, e);
        const real apex = first_rebound_apex(w, ball, step, 2, real(1.01));
        EXPECT_NEAR(apex, e * e, 1e-3)
            << (box ? "box" : "ball") << (is_static ? ", static" : ", 1e6 kg") << ", 1/"
            << int(1 / step + real(0.5)) << " s";
      }
    }
  }
}

// The ball that strikes rests on nothing: dropped onto the floor beside a
// wall or a twin ball it touches, it bounces to e^2 of its drop as it does
// alone. (What a body touches beside it does not hold its gravity; taken
// for a support, it made the ball rise 24% low at 60 Hz.)
TEST_F(impact_test, a_ball_bouncing_beside_a_wall_or_a_twin_rises_to_e_squared) {
  const real e = 0.5, radius = 0.1;
  for (const real step : {real(1) / 240, real(1) / 60}) {
    for (const bool twin : {false, true}) {
      world w = make_world();
      add_floor(w, 0, e);
      if (twin) {
        add_sphere(w, vector{2 * radius, 0, 1 + radius}, radius, 1, vector{}, e, 0);
      } else {
        body_definition wall;
        wall.is_static = true;
        wall.shape = shape::plane(vector{-1, 0, 0}, -radius).with_restitution(e).with_friction(0);
        w.create_body(wall);
      }
      const body_id ball = add_sphere(w, vector{0, 0, 1 + radius}, radius, 1, vector{}, e, 0);
      const real apex = first_rebound_apex(w, ball, step, 1.5, radius);
      EXPECT_NEAR(apex, e * e, 1e-3) << (twin ? "beside a twin" : "beside a wall") << ", 1/"
                                     << int(1 / step + real(0.5)) << " s";
    }
  }
}

}  // namespace
}  // namespace gaphys::testing
