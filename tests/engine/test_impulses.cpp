// Impulses and forces at world points, and each body's gravity scale and
// damping, against independent truth: plain 3x3 matrices and cross products
// (matrix3.hpp) for the inertia, the effective mass identity, and the exact
// discrete solution of semi-implicit Euler for the steps.
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <vector>

#include "engine_test_support.hpp"
#include "matrix3.hpp"

namespace gaphys::testing {
namespace {

real dot3(const triple& a, const triple& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

class impulse_test : public engine_test {
 protected:
  static constexpr real box_mass = 2;
  // Half extents of the test box, and its principal moments about its
  // centre by the textbook formula: I_x = m (b^2 + c^2) / 3, ...
  static constexpr real a = 0.3, b = 0.5, c = 0.7;
  static matrix box_tensor() {
    return diagonal(box_mass * (b * b + c * c) / 3, box_mass * (a * a + c * c) / 3,
                    box_mass * (a * a + b * b) / 3);
  }

  triple random_axis() { return as_triple(random_unit_vector()); }
  vector random_vector(real size) {
    return vector{uniform(-size, size), uniform(-size, size), uniform(-size, size)};
  }

  // The box at a random pose and velocity; `turn` is its rotation matrix.
  body_definition random_box(matrix& turn) {
    const triple axis = random_axis();
    const real angle = uniform(-3, 3);
    turn = rotation(axis, angle);
    body_definition d;
    d.mass = box_mass;
    d.shape = shape::box(vector{a, b, c});
    d.attitude = rotor_of(axis, angle);
    d.position = random_vector(2);
    d.velocity = random_vector(1);
    d.angular_velocity = plane_of(as_triple(random_vector(1)));
    return d;
  }

  // I_w⁻¹ = R diag(1 / I) R^T, by matrices.
  static matrix world_inverse_tensor(const matrix& turn) {
    const matrix i = box_tensor();
    return product(product(turn, diagonal(1 / i[0], 1 / i[4], 1 / i[8])), transposed(turn));
  }
  static matrix world_tensor(const matrix& turn) {
    return product(product(turn, box_tensor()), transposed(turn));
  }
};

// Within 1e-12 relative (1e-4 in float: damping over 240 steps).
template <class Quantity>
::testing::AssertionResult near_relative(const Quantity& actual, const Quantity& expected) {
  return near(actual, expected, tolerance(1e-12, 1e-4) * length(expected));
}

// The axis of a bivector Ω (plane_of's inverse): e23 ↔ x, e31 ↔ y, e12 ↔ z.
triple axis_of(const bivector& plane) { return {plane.e23(), -plane.e13(), plane.e12()}; }

TEST_F(impulse_test, an_impulse_at_the_centre_changes_only_the_velocity) {
  matrix turn;
  body_definition d = random_box(turn);
  d.mass = 4;  // 1/m exact: Δv = J / m to the bit
  body box(d);
  const vector v0 = box.velocity();
  const bivector omega0 = box.angular_velocity();
  const vector impulse{3, -1, 2};
  box.apply_impulse(impulse, box.position());
  EXPECT_TRUE(near(box.velocity(), v0 + real(0.25) * impulse, 0));
  EXPECT_TRUE(near(box.angular_velocity(), omega0, 0));
  // Immediate, not accumulated for the next step.
  EXPECT_TRUE(near(box.accumulated_force(), vector{}, 0));
  EXPECT_TRUE(near(box.accumulated_torque(), bivector{}, 0));
}

// Δv = J / m and Δω = I_w⁻¹ (r × J), I_w⁻¹ = R diag(1 / I) R^T.
TEST_F(impulse_test, an_off_centre_impulse_on_a_box_is_the_matrix_closed_form) {
  for (int trial = 0; trial < 50; ++trial) {
    matrix turn;
    body box(random_box(turn));
    const vector v0 = box.velocity();
    const triple omega0 = axis_of(box.angular_velocity());
    const vector point = box.position() + random_vector(0.8);
    const vector impulse = random_vector(3);
    box.apply_impulse(impulse, point);

    const triple r = as_triple(point - box.position());
    const triple turn_rate = times(world_inverse_tensor(turn), cross(r, as_triple(impulse)));
    const triple omega{omega0[0] + turn_rate[0], omega0[1] + turn_rate[1],
                       omega0[2] + turn_rate[2]};
    EXPECT_TRUE(near(box.velocity(), v0 + (1 / box_mass) * impulse, tolerance(1e-15, 1e-7)));
    EXPECT_TRUE(near(box.angular_velocity(), plane_of(omega), tolerance(1e-12, 1e-5)));
  }
}

TEST_F(impulse_test, an_off_centre_impulse_on_a_sphere_spins_it_by_r_cross_j_over_i) {
  const real mass = 3, radius = 0.4;
  const real moment = real(0.4) * mass * radius * radius;
  body_definition d;
  d.mass = mass;
  d.shape = shape::sphere(radius);
  d.position = vector{1, -2, 0.5};
  body ball(d);
  // A tangential kick e2 at the equator point +e1: spin about z (e12).
  const vector impulse{0, 1.5, 0};
  ball.apply_impulse(impulse, d.position + vector{radius, 0, 0});
  EXPECT_TRUE(near(ball.velocity(), vector{0, real(1.5) / mass, 0}, tolerance(1e-15, 1e-7)));
  EXPECT_TRUE(near(ball.angular_velocity(), bivector{radius * real(1.5) / moment, 0, 0}, tolerance(1e-15, 1e-6)));
}

// The struck point's velocity along the unit direction n of an impulse j n
// changes by j (1/m + (r × n) · I_w⁻¹ (r × n)): the effective mass identity
// every contact solver relies on.
TEST_F(impulse_test, the_struck_point_follows_the_effective_mass) {
  for (int trial = 0; trial < 50; ++trial) {
    matrix turn;
    body box(random_box(turn));
    const vector point = box.position() + random_vector(0.8);
    const vector n = random_unit_vector();
    const real j = uniform(0.1, 5);
    const real before = dot(box.velocity_at(point), n);
    box.apply_impulse(j * n, point);
    const real after = dot(box.velocity_at(point), n);

    const triple arm = cross(as_triple(point - box.position()), as_triple(n));
    const real inverse_effective_mass =
        1 / box_mass + dot3(arm, times(world_inverse_tensor(turn), arm));
    EXPECT_NEAR(after - before, j * inverse_effective_mass, tolerance(1e-12, 1e-6) * j) << "trial " << trial;
  }
}

TEST_F(impulse_test, a_static_body_ignores_impulses) {
  world w = make_world();
  const body_id floor = add_floor(w);
  const std::uint64_t hash = w.state_hash();
  w.at(floor).apply_impulse(vector{0, 0, 100}, vector{1, 0, 0});
  EXPECT_EQ(w.state_hash(), hash);
  EXPECT_TRUE(near(w.at(floor).velocity(), vector{}, 0));
  EXPECT_TRUE(near(w.at(floor).angular_velocity(), bivector{}, 0));
}

// A force at a world point is the force at the body-frame offset ~R (p - x) R.
TEST_F(impulse_test, a_force_at_a_world_point_is_the_force_at_its_body_offset) {
  for (int trial = 0; trial < 20; ++trial) {
    matrix turn;
    const body_definition d = random_box(turn);
    world by_point = make_world();
    world by_offset = make_world();
    const body_id id = by_point.create_body(d);
    by_offset.create_body(d);
    const vector point = by_point.at(id).position() + random_vector(0.8);
    const vector force = random_vector(10);
    const vector r = point - by_point.at(id).position();
    by_point.at(id).apply_force_at_world_point(force, point);
    const rotor attitude = by_offset.at(id).attitude();
    by_offset.at(id).apply_force(force, e3ga::apply(e3ga::reverse(attitude), r));

    EXPECT_TRUE(near(by_point.at(id).accumulated_force(), force, 0));
    EXPECT_TRUE(near(by_point.at(id).accumulated_torque(),
                     plane_of(cross(as_triple(r), as_triple(force))), tolerance(1e-14, 1e-6)));
    EXPECT_TRUE(
        near(by_point.at(id).accumulated_torque(), by_offset.at(id).accumulated_torque(), tolerance(1e-14, 5e-6)));
    by_point.step(h);
    by_offset.step(h);
    EXPECT_TRUE(near(by_point.at(id).velocity(), by_offset.at(id).velocity(), 0));
    EXPECT_TRUE(
        near(by_point.at(id).angular_velocity(), by_offset.at(id).angular_velocity(), tolerance(1e-14, 5e-6)));
  }
}

// One step of semi-implicit Euler with a force f at world point p:
//   v' = v + h (g + f / m),   L' = I_w ω + h r × f,   x' = x + h v',
// and L' is kept through the turn, so the angular momentum after the step
// is L' (to rounding).
TEST_F(impulse_test, a_force_at_a_world_point_steps_as_semi_implicit_euler) {
  const vector g{0, 0, -9.81};
  for (int trial = 0; trial < 20; ++trial) {
    matrix turn;
    const body_definition d = random_box(turn);
    world w = make_world(g);
    const body_id id = w.create_body(d);
    const vector x0 = w.at(id).position(), v0 = w.at(id).velocity();
    const triple omega0 = axis_of(w.at(id).angular_velocity());
    const vector point = x0 + random_vector(0.8);
    const vector force = random_vector(10);
    w.at(id).apply_force_at_world_point(force, point);
    w.step(h);

    const vector v = v0 + h * (g + (1 / box_mass) * force);
    const triple spin = times(world_tensor(turn), omega0);
    const triple torque = cross(as_triple(point - x0), as_triple(force));
    const triple momentum{spin[0] + h * torque[0], spin[1] + h * torque[1],
                          spin[2] + h * torque[2]};
    EXPECT_TRUE(near(w.at(id).velocity(), v, tolerance(1e-14, 1e-6)));
    EXPECT_TRUE(near(w.at(id).position(), x0 + h * v, tolerance(1e-14, 1e-6)));
    EXPECT_TRUE(near(w.at(id).angular_momentum(), plane_of(momentum), tolerance(1e-12, 1e-6)));
    // Cleared after the step, like apply_force.
    EXPECT_TRUE(near(w.at(id).accumulated_force(), vector{}, 0));
    EXPECT_TRUE(near(w.at(id).accumulated_torque(), bivector{}, 0));
  }
}

// Free fall at s g: v_n = v_0 + n h s g, x_n = x_0 + n h v_0 + h^2 s g n (n + 1) / 2.
TEST_F(impulse_test, a_body_falls_with_its_gravity_scale) {
  const vector g{0, 0, -9.81};
  for (real scale : {real(0), real(0.5), real(2), real(-1)}) {
    world w = make_world(g);
    const vector x0{1, 2, 3}, v0{0.5, -1, 2};
    body_definition d;
    d.shape = shape::sphere(0.2);
    d.position = x0;
    d.velocity = v0;
    d.gravity_scale = scale;
    const body_id id = w.create_body(d);
    const body_id plain = add_sphere(w, vector{10, 0, 0}, 0.2);
    simulate(w, 480, [&](int i) {
      const real n = i + 1;
      const vector a = scale * g;
      ASSERT_TRUE(near(w.at(id).velocity(), v0 + (n * h) * a, tolerance(1e-12, 1e-6) * n)) << scale << " " << n;
      ASSERT_TRUE(
          near(w.at(id).position(), x0 + (n * h) * v0 + (h * h * n * (n + 1) / 2) * a, tolerance(1e-12, 1e-6) * n))
          << scale << " " << n;
      // Its neighbour falls with the world's gravity.
      ASSERT_TRUE(near(w.at(plain).velocity(), (n * h) * g, tolerance(1e-12, 1e-6) * n)) << n;
    });
    if (scale == 0) {  // floats: not a bit of velocity gained
      EXPECT_TRUE(near(w.at(id).velocity(), v0, 0));
    }
  }
}

TEST_F(impulse_test, set_gravity_scale_applies_from_the_next_step) {
  const vector g{0, 0, -9.81};
  world w = make_world(g);
  const body_id id = add_sphere(w, vector{}, 0.2);
  EXPECT_EQ(w.at(id).gravity_scale(), 1);
  w.step(h);
  w.at(id).set_gravity_scale(0.5);
  EXPECT_EQ(w.at(id).gravity_scale(), 0.5);
  w.step(h);
  EXPECT_TRUE(near(w.at(id).velocity(), (h + h / 2) * g, tolerance(1e-15, 1e-7)));
}

// Damping c: each step v_n = v_{n-1} / (1 + h c), so v_n = v_0 / (1 + h c)^n
// (spheres: isotropic, no gyroscopic turn of Ω).
TEST_F(impulse_test, a_bodys_damping_overrides_the_worlds) {
  world w = make_world(vector{});
  const real world_linear = 0.2, world_angular = 0.1;
  w.set_damping(world_linear, world_angular);
  const vector v0{3, -1, 2};
  const bivector omega0{1, -2, 0.5};
  body_definition d;
  d.shape = shape::sphere(0.3);
  d.velocity = v0;
  d.angular_velocity = omega0;
  const body_id follows = w.create_body(d);  // no override: the world's rates
  d.position = vector{0, 10, 0};
  d.linear_damping = 1.5;
  d.angular_damping = 0.8;
  const body_id own = w.create_body(d);
  d.position = vector{0, -10, 0};
  d.linear_damping = 0;
  d.angular_damping = std::nullopt;  // overrides only the linear rate
  const body_id undamped = w.create_body(d);

  const int n = 480;
  simulate(w, n);
  const auto decayed = [&](real rate) { return std::pow(1 + h * rate, -n); };
  EXPECT_TRUE(near_relative(w.at(own).velocity(), decayed(1.5) * v0));
  EXPECT_TRUE(near_relative(w.at(own).angular_velocity(), decayed(0.8) * omega0));
  EXPECT_TRUE(near_relative(w.at(follows).velocity(), decayed(world_linear) * v0));
  EXPECT_TRUE(near_relative(w.at(follows).angular_velocity(), decayed(world_angular) * omega0));
  EXPECT_TRUE(near(w.at(undamped).velocity(), v0, 0));
  EXPECT_TRUE(near_relative(w.at(undamped).angular_velocity(), decayed(world_angular) * omega0));

  // Unset again, the body follows the world from the next step.
  w.at(own).set_damping(std::nullopt, std::nullopt);
  EXPECT_FALSE(w.at(own).linear_damping().has_value());
  const vector v = w.at(own).velocity();
  w.step(h);
  EXPECT_TRUE(near(w.at(own).velocity(), (1 / (1 + h * world_linear)) * v, 0));
}

// A body that sets its fields to what it would have anyway steps bit for bit
// like one that leaves them at their defaults (the world damped, so that
// the rates are used); one ulp of gravity scale shows that the comparison
// can fail.
TEST_F(impulse_test, bodies_at_the_defaults_step_bit_identically) {
  const std::vector<std::function<world()>> builds{
      [] { return scenes::falling_spheres_in_box(20, 7); },
      [] { return scenes::box_pyramid(4); },
      [] { return scenes::shape_mix(8); },
      [] { return scenes::compound_table(); },
  };
  for (std::size_t scene = 0; scene < builds.size(); ++scene) {
    world plain = builds[scene]();
    world explicit_defaults = builds[scene]();
    world nudged = builds[scene]();
    for (world* w : {&plain, &explicit_defaults, &nudged}) w->set_damping(0.3, 0.7);
    for (body_id id = 0; id < explicit_defaults.body_count(); ++id) {
      explicit_defaults.at(id).set_gravity_scale(1);
      explicit_defaults.at(id).set_damping(0.3, 0.7);  // the world's rates
    }
    const body_id last = nudged.body_count() - 1;  // dynamic in every scene above
    nudged.at(last).set_gravity_scale(std::nextafter(real(1), real(2)));
    for (int i = 0; i < 120; ++i) {
      plain.step(h);
      explicit_defaults.step(h);
      nudged.step(h);
      ASSERT_EQ(plain.state_hash(), explicit_defaults.state_hash())
          << "scene " << scene << " step " << i + 1;
    }
    EXPECT_NE(plain.state_hash(), nudged.state_hash()) << "scene " << scene;
  }
}

TEST_F(impulse_test, copies_keep_the_gravity_scale_and_damping) {
  body_definition d;
  d.shape = shape::sphere(0.5);
  d.gravity_scale = -0.25;
  d.linear_damping = 0.5;
  const body original(d);
  body copy = original;
  EXPECT_EQ(copy.gravity_scale(), -0.25);
  EXPECT_EQ(copy.linear_damping(), std::optional<real>(0.5));
  EXPECT_FALSE(copy.angular_damping().has_value());
  body_definition plain;
  plain.shape = d.shape;
  copy = body(plain);
  EXPECT_EQ(copy.gravity_scale(), 1);
  EXPECT_FALSE(copy.linear_damping().has_value());

  world w = make_world();
  add_floor(w);
  d.position = vector{0, 0, 2};
  d.velocity = vector{1, 0, 0};
  w.create_body(d);
  simulate(w, 60);
  world copied = w;
  simulate(w, 120);
  simulate(copied, 120);
  EXPECT_EQ(w.state_hash(), copied.state_hash());
}

TEST_F(impulse_test, bad_input_is_rejected_and_changes_nothing) {
  world w = make_world();
  const body_id floor = add_floor(w);
  const body_id ball = add_sphere(w, vector{0, 0, 1}, 0.5, 1, vector{0.1, 0, 0});
  w.at(ball).set_damping(0.5, std::nullopt);
  simulate(w, 30);
  const std::uint64_t hash = w.state_hash();
  const vector good{1, 2, 3};

  for (body_id id : {ball, floor}) {
    for (const vector& bad : {vector{nan, 0, 0}, vector{0, inf, 0}, vector{0, 0, -inf}}) {
      EXPECT_TRUE(rejects([&] { w.at(id).apply_impulse(bad, good); }, "impulse"));
      EXPECT_TRUE(rejects([&] { w.at(id).apply_impulse(good, bad); }, "impulse point"));
      EXPECT_TRUE(rejects([&] { w.at(id).apply_force_at_world_point(bad, good); }, "force"));
      EXPECT_TRUE(rejects([&] { w.at(id).apply_force_at_world_point(good, bad); }, "force point"));
    }
    EXPECT_TRUE(near(w.at(id).accumulated_force(), vector{}, 0));
    EXPECT_TRUE(near(w.at(id).accumulated_torque(), bivector{}, 0));
  }
  for (real bad : {nan, inf, -inf}) {
    EXPECT_TRUE(rejects([&] { w.at(ball).set_gravity_scale(bad); }, "gravity scale"));
  }
  for (real bad : {real(-0.1), nan, inf}) {
    EXPECT_TRUE(rejects([&] { w.at(ball).set_damping(bad, 1); }, "linear damping"));
    // A good linear rate beside a bad angular one is not taken either.
    EXPECT_TRUE(rejects([&] { w.at(ball).set_damping(2, bad); }, "angular damping"));
  }
  EXPECT_EQ(w.at(ball).gravity_scale(), 1);
  EXPECT_EQ(w.at(ball).linear_damping(), std::optional<real>(0.5));
  EXPECT_FALSE(w.at(ball).angular_damping().has_value());
  EXPECT_EQ(w.state_hash(), hash);

  const std::size_t count = w.body_count();
  body_definition d;
  d.shape = shape::sphere(0.5);
  d.position = vector{3, 0, 1};
  for (real bad : {nan, inf}) {
    body_definition scaled = d;
    scaled.gravity_scale = bad;
    EXPECT_TRUE(rejects([&] { w.create_body(scaled); }, "gravity scale"));
  }
  for (real bad : {real(-1), nan, inf}) {
    body_definition linear = d, angular = d;
    linear.linear_damping = bad;
    angular.angular_damping = bad;
    EXPECT_TRUE(rejects([&] { w.create_body(linear); }, "linear damping"));
    EXPECT_TRUE(rejects([&] { w.create_body(angular); }, "angular damping"));
  }
  EXPECT_EQ(w.body_count(), count);
  EXPECT_EQ(w.state_hash(), hash);
}

}  // namespace
}  // namespace gaphys::testing
