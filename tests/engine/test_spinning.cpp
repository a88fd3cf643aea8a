// Torque-free rotation. Without torque the world-frame angular momentum L is
// constant (Euler's equations), and so is the kinetic energy; the attitude
// rotor must stay a rotor. An asymmetric body (inertia 1:2:3) spun off its
// axes tumbles, so Ω changes all the time while L must not.
#include <algorithm>
#include <cmath>
#include <vector>

#include "engine_test_support.hpp"

namespace gaphys::testing {
namespace {

class spinning_test : public engine_test {
 protected:
  // |R ~R - 1|: zero for a unit rotor.
  static real rotor_defect(const rotor& r) {
    return e3ga::norm(e3ga::gp(r, e3ga::reverse(r)) - rotor{1, 0, 0, 0});
  }
};

TEST_F(spinning_test, an_asymmetric_body_keeps_its_angular_momentum_for_10000_steps) {
  world w = scenes::spinning_body();
  const body& b = w.at(0);
  const bivector l0 = b.angular_momentum();
  const real e0 = b.kinetic_energy();
  const bivector omega0 = b.angular_velocity();
  real max_drift = 0, max_defect = 0, max_energy_error = 0, max_turn_of_omega = 0;
  simulate(w, 10000, [&](int) {
    max_drift = std::max(max_drift, length(b.angular_momentum() - l0) / length(l0));
    max_defect = std::max(max_defect, rotor_defect(b.attitude()));
    max_energy_error = std::max(max_energy_error, std::fabs(b.kinetic_energy() - e0) / e0);
    max_turn_of_omega = std::max(max_turn_of_omega, length(b.angular_velocity() - omega0));
  });
  EXPECT_LT(max_drift, 0.01);
  EXPECT_LT(max_defect, tolerance(1e-6, 1e-5));
  EXPECT_LT(max_energy_error, 0.01);
  // The body does tumble: Ω wanders far from where it started (without the
  // gyroscopic term it would stay fixed and L would drift instead).
  EXPECT_GT(max_turn_of_omega, 0.5 * length(omega0));
  // Body-frame L = J Ω: (1, 2, 3) kg m^2 times (1, 2, 3) rad/s at the start.
  EXPECT_NEAR(length(l0), std::sqrt(real(1 + 16 + 81)), tolerance(1e-12, 1e-5));
}

// Spun about its axis of largest or smallest moment, a body turns steadily:
// Ω stays put, and after t seconds the attitude is the closed-form rotation.
TEST_F(spinning_test, a_spin_about_a_principal_axis_is_steady) {
  world w = make_world(vector{});
  body_definition d;
  d.inertia = inertia::principal(1, 2, 3);
  const real rate = 2;
  d.angular_velocity = bivector{rate, 0, 0};  // about z, the largest moment
  const body_id id = w.create_body(d);
  simulate(w, 2400);
  const real angle = rate * w.time();
  EXPECT_TRUE(near(w.at(id).angular_velocity(), bivector{rate, 0, 0}, tolerance(1e-12, 1e-3)));
  EXPECT_TRUE(near(w.at(id).to_world(vector{1, 0, 0}), vector{std::cos(angle), std::sin(angle), 0},
                   tolerance(1e-9, 3e-3)));
}

// The same tumbling body at a random starting attitude and a general
// (non-diagonal) inertia tensor conserves L just as well.
TEST_F(spinning_test, a_general_inertia_tensor_conserves_angular_momentum) {
  world w = make_world(vector{});
  body_definition d;
  d.inertia = inertia::tensor({2, 0.3, -0.2, 0.3, 1.5, 0.1, -0.2, 0.1, 1});
  d.attitude = e3ga::exp(bivector{0.3, -0.7, 0.2});
  d.angular_velocity = bivector{1, 3, -2};
  const body_id id = w.create_body(d);
  const bivector l0 = w.at(id).angular_momentum();
  const real e0 = w.at(id).kinetic_energy();
  simulate(w, 4800);
  EXPECT_LT(length(w.at(id).angular_momentum() - l0) / length(l0), tolerance(1e-6, 5e-4));
  EXPECT_NEAR(w.at(id).kinetic_energy(), e0, 0.01 * e0);
  EXPECT_LT(rotor_defect(w.at(id).attitude()), tolerance(1e-6, 1e-5));
}

// A top spinning on a frictionless floor: gravity acts at the centre of
// mass and the floor pushes straight up, so neither turns the top about the
// vertical through its centre: L_z, the vertical part of its angular
// momentum about the centre, is constant whatever the top does (precess,
// nutate, fall, rattle). The position correction's turns had kept Ω and
// so changed L = I(R) Ω of a top (inertia unlike about its axis and across
// it): L_z fell 3% in 2 s and 43% in 16 s, and the top fell over.
TEST_F(spinning_test, a_top_on_a_frictionless_floor_keeps_its_vertical_angular_momentum) {
  world w = make_world();
  add_floor(w, 0, 0, 0);
  // A disc (a 32-gon hull) on a stem (a capsule), standing on a small ball.
  std::vector<vector> rim;
  for (int i = 0; i < 32; ++i) {
    const real angle = 2 * real(3.14159265358979323846) * i / 32;
    for (const real z : {real(-0.015), real(0.015)}) {
      rim.push_back(vector{real(0.2) * std::cos(angle), real(0.2) * std::sin(angle), z});
    }
  }
  body_definition d;
  d.density = 1000;
  d.shapes = {{shape::convex_hull(rim).with_friction(0), vector{0, 0, real(0.25)}},
              {shape::sphere(real(0.01)).with_friction(0), vector{0, 0, real(0.01)}},
              {shape::capsule(real(0.12), real(0.008)).with_friction(0), vector{0, 0, real(0.14)}}};
  d.attitude = e3ga::exp(bivector{0, 0, real(-0.35) / 2});  // tilted 0.35 rad about x
  const body_id id = w.create_body(d);
  body& top = w.at(id);
  // The tip's ball touching the floor, the top spinning about its axis.
  const vector tip = top.to_world(top.shapes()[1].offset);
  top.set_position(top.position() + vector{0, 0, real(0.01) - z(tip)});
  top.set_angular_velocity(
      to_bivector(real(60) * (top.to_world(vector{0, 0, 1}) - top.position())));
  const real l0 = z(to_axial(top.angular_momentum()));
  real largest_change = 0, lowest_axis = 1;
  simulate(w, 960, [&](int) {
    largest_change = std::max(largest_change, std::fabs(z(to_axial(top.angular_momentum())) - l0));
    lowest_axis = std::min(lowest_axis, z(top.to_world(vector{0, 0, 1}) - top.position()));
  });
  EXPECT_LT(largest_change / l0, tolerance(1e-9, 1e-4));
  // It spins on, upright: tilted 0.35 rad (cos 0.94) at the start; it
  // nutates within a few hundredths.
  EXPECT_GT(lowest_axis, real(0.9));
}

}  // namespace
}  // namespace gaphys::testing
