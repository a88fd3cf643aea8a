// Torque-free rotation. Without torque the world-frame angular momentum L is
// constant (Euler's equations), and so is the kinetic energy; the attitude
// rotor must stay a rotor. An asymmetric body (inertia 1:2:3) spun off its
// axes tumbles, so Ω changes all the time while L must not.
#include <algorithm>

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

}  // namespace
}  // namespace gaphys::testing
