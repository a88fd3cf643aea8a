// Bodies without contacts against the exact solution of the discrete scheme:
// semi-implicit Euler, v_n = v_{n-1} + h a, then x_n = x_{n-1} + h v_n, so
//   v_n = v_0 + n h a,   x_n = x_0 + n h v_0 + h^2 a n (n + 1) / 2.
// The engine must reproduce that to rounding, not merely approximate the
// continuous parabola.
#include "engine_test_support.hpp"

namespace gaphys::testing {
namespace {

class free_motion_test : public engine_test {};

TEST_F(free_motion_test, free_fall_is_the_exact_discrete_solution) {
  const vector g{0, 0, -9.81};
  world w = make_world(g);
  const vector x0{0, 0, 100};
  const body_id id = add_sphere(w, x0, 0.5);
  simulate(w, 2400, [&](int i) {
    const real n = i + 1;
    const vector v = n * h * g;
    const vector x = x0 + (h * h * n * (n + 1) / 2) * g;
    ASSERT_TRUE(near(w.at(id).velocity(), v, tolerance(1e-12, 1e-6) * n)) << "step " << n;
    ASSERT_TRUE(near(w.at(id).position(), x, tolerance(1e-12, 1e-5) * n)) << "step " << n;
  });
  // And within h |g| t / 2 of the continuous parabola after 10 s.
  const real t = w.time();
  EXPECT_NEAR(t, 10, tolerance(1e-9, 1e-3));
  EXPECT_NEAR(z(w.at(id).position()), 100 - 9.81 * t * t / 2, 9.81 * h * t / 2 + tolerance(1e-9, 3e-2));
}

TEST_F(free_motion_test, a_projectile_is_the_exact_discrete_solution) {
  const vector g{0, 0, -9.81};
  world w = make_world(g);
  const vector x0{-3, 2, 1}, v0{4, -1, 12};
  const body_id id = add_sphere(w, x0, 0.1, 0.3, v0);
  simulate(w, 600, [&](int i) {
    const real n = i + 1;
    const vector x = x0 + (n * h) * v0 + (h * h * n * (n + 1) / 2) * g;
    ASSERT_TRUE(near(w.at(id).position(), x, tolerance(1e-12, 1e-6) * n)) << "step " << n;
  });
  // The horizontal motion is untouched by gravity.
  EXPECT_NEAR(x(w.at(id).velocity()), 4, tolerance(1e-12, 1e-6));
  EXPECT_NEAR(y(w.at(id).velocity()), -1, tolerance(1e-12, 1e-6));
}

// With linear damping c each step is v_n = d (v_{n-1} + h g), d = 1/(1 + h c):
// v_n = d^n v_0 + h g d (1 - d^n) / (1 - d), a geometric series.
TEST_F(free_motion_test, linear_damping_is_the_exact_discrete_solution) {
  const vector g{0, 0, -9.81}, v0{5, 0, 3};
  world w = make_world(g);
  const real c = 1;
  w.set_damping(c, 0);
  const body_id id = add_sphere(w, vector{}, 0.2, 1, v0);
  const real d = 1 / (1 + h * c);
  real dn = 1;
  vector x{};
  simulate(w, 2400, [&](int i) {
    dn *= d;
    const vector v = dn * v0 + (h * d * (1 - dn) / (1 - d)) * g;
    x = x + h * v;
    ASSERT_TRUE(near(w.at(id).velocity(), v, tolerance(1e-11, 3e-4))) << "step " << i + 1;
    ASSERT_TRUE(near(w.at(id).position(), x, tolerance(1e-10, 1e-3))) << "step " << i + 1;
  });
  // After 10 s the fall approaches the terminal speed |g| / c (the discrete
  // scheme's fixed point is exactly that).
  EXPECT_NEAR(z(w.at(id).velocity()), -9.81 / c, 1e-3);
}

TEST_F(free_motion_test, a_constant_force_accelerates_by_f_over_m) {
  world w = make_world(vector{});
  const real mass = 4;
  const vector f{2, -6, 1};
  const body_id id = add_sphere(w, vector{}, 0.3, mass);
  simulate(w, 480, [&](int i) {
    w.at(id).apply_force(f);  // after the step: acts on the next one
    const real n = i + 1;
    const vector a = (1 / mass) * f;
    // The force applied after step n acts on steps 2 .. n+1.
    const vector v = ((n - 1) * h) * a;
    ASSERT_TRUE(near(w.at(id).velocity(), v, tolerance(1e-12, 1e-6) * n)) << "step " << n;
  });
}

// A constant torque τ on a sphere (isotropic inertia I) spins it up at τ / I
// about a fixed axis: ω_n = n h τ / I and the angle θ_n = h Σ ω_k =
// h^2 τ n (n + 1) / 2I. The body's e1 then points along (cos θ, sin θ, 0).
TEST_F(free_motion_test, a_constant_torque_spins_a_sphere_up_about_a_fixed_axis) {
  world w = make_world(vector{});
  const real mass = 2, radius = 0.5, torque = 0.3;
  const real moment = real(0.4) * mass * radius * radius;
  const body_id id = add_sphere(w, vector{}, radius, mass);
  for (int i = 0; i < 960; ++i) {
    w.at(id).apply_torque(bivector{torque, 0, 0});  // about z
    w.step(h);
    const real n = i + 1;
    const real omega = n * h * torque / moment;
    const real angle = h * h * torque * n * (n + 1) / (2 * moment);
    ASSERT_TRUE(near(w.at(id).angular_velocity(), bivector{omega, 0, 0}, tolerance(1e-12, 1e-6) * n)) << n;
    ASSERT_TRUE(near(w.at(id).to_world(vector{1, 0, 0}),
                     vector{std::cos(angle), std::sin(angle), 0}, tolerance(1e-11, 1e-5) * n))
        << n;
  }
  EXPECT_TRUE(near(w.at(id).position(), vector{}, 0));
}

// Angular damping c: ω_n = d^n ω_0 with d = 1 / (1 + h c).
TEST_F(free_motion_test, angular_damping_decays_the_spin_geometrically) {
  world w = make_world(vector{});
  w.set_damping(0, 0.5);
  const body_id id = add_sphere(w, vector{}, 0.5);
  w.at(id).set_angular_velocity(bivector{1, -2, 3});
  const real d = 1 / (1 + h * 0.5);
  simulate(w, 240);
  EXPECT_TRUE(near(w.at(id).angular_velocity(), std::pow(d, 240) * bivector{1, -2, 3}, tolerance(1e-12, 1e-4)));
}

}  // namespace
}  // namespace gaphys::testing
