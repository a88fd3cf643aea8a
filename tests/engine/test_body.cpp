// A body's conventions and its inertia, against plain 3x3 matrix algebra
// written here independently of the engine's bivector code.
#include <array>
#include <limits>

#include "engine_test_support.hpp"
#include "matrix3.hpp"

namespace gaphys::testing {
namespace {

class body_test : public engine_test {
 protected:
  triple random_axis() {
    const vector v = random_unit_vector();
    return {x(v), y(v), z(v)};
  }
  // A random symmetric positive definite tensor: Q diag(d) Q^T.
  matrix random_tensor() {
    const matrix q = rotation(random_axis(), uniform(-3, 3));
    const matrix d{uniform(0.2, 3), 0, 0, 0, uniform(0.2, 3), 0, 0, 0, uniform(0.2, 3)};
    matrix m = product(product(q, d), transposed(q));
    for (int i = 0; i < 3; ++i)  // symmetric to the last bit
      for (int j = 0; j < i; ++j) m[3 * i + j] = m[3 * j + i];
    return m;
  }
};

TEST_F(body_test, rotors_turn_vectors_like_rotation_matrices) {
  for (int trial = 0; trial < 50; ++trial) {
    const triple axis = random_axis();
    const real angle = uniform(-3, 3);
    const matrix m = rotation(axis, angle);
    const triple p{uniform(-2, 2), uniform(-2, 2), uniform(-2, 2)};
    const triple expected = times(m, p);
    body_definition d;
    d.shape = shape::sphere(1);
    d.attitude = rotor_of(axis, angle);
    const body b(d);
    EXPECT_TRUE(near(b.to_world(vector{p[0], p[1], p[2]}),
                     vector{expected[0], expected[1], expected[2]}, tolerance(1e-12, 1e-6)));
  }
}

TEST_F(body_test, the_attitude_is_normalized_on_creation_and_when_set) {
  body_definition d;
  d.shape = shape::sphere(1);
  d.attitude = rotor{2, 0, 0, 0};
  body b(d);
  EXPECT_NEAR(e3ga::norm(b.attitude()), 1, tolerance(1e-15, 1e-7));
  b.set_attitude(rotor{3, 4, 0, 0});
  EXPECT_NEAR(b.attitude().scalar(), 0.6, tolerance(1e-15, 1e-7));
  EXPECT_NEAR(b.attitude().e12(), 0.8, tolerance(1e-15, 1e-7));
}

// Rotors whose squared norm overflows or underflows normalize as well.
TEST_F(body_test, huge_and_tiny_attitudes_normalize_too) {
  body_definition d;
  d.shape = shape::sphere(1);
  // (denorm_min: dividing by it overflowed, and the attitude was NaN.)
  for (real scale : {for_scalar(1e200, 1e20), for_scalar(1e-200, 1e-20), for_scalar(1e300, 1e30),
                     for_scalar(1e-300, 1e-30), std::numeric_limits<real>::denorm_min()}) {
    d.attitude = rotor{3 * scale, 4 * scale, 0, 0};
    body b(d);
    EXPECT_NEAR(b.attitude().scalar(), 0.6, tolerance(1e-15, 1e-7)) << scale;
    EXPECT_NEAR(b.attitude().e12(), 0.8, tolerance(1e-15, 1e-7)) << scale;
    b.set_attitude(rotor{0, 0, -scale, 0});
    EXPECT_EQ(b.attitude().e13(), -1) << scale;
  }
}

TEST_F(body_test, principal_inertia_acts_plane_by_plane) {
  const inertia j = inertia::principal(1, 2, 3);
  // About x is the e23 plane, about y e31 = -e13, about z e12.
  EXPECT_TRUE(near(j(bivector{0, 0, 1}), bivector{0, 0, 1}, tolerance(1e-15, 1e-7)));
  EXPECT_TRUE(near(j(bivector{0, -1, 0}), bivector{0, -2, 0}, tolerance(1e-15, 1e-7)));
  EXPECT_TRUE(near(j(bivector{1, 0, 0}), bivector{3, 0, 0}, tolerance(1e-15, 1e-7)));
  EXPECT_TRUE(near(j.inverse(bivector{3, -2, 1}), bivector{1, -1, 1}, tolerance(1e-15, 1e-7)));
}

TEST_F(body_test, solid_shapes_have_their_textbook_moments) {
  const real m = 3, r = 0.5;
  const inertia ball = inertia::solid_sphere(m, r);
  EXPECT_TRUE(near(ball(bivector{1, 1, 1}), real(0.4) * m * r * r * bivector{1, 1, 1}, tolerance(1e-15, 1e-7)));
  const real a = 0.1, b = 0.2, c = 0.3;
  const inertia box = inertia::solid_box(m, a, b, c);
  // A box with half extents (a, b, c): J_zz = m (a^2 + b^2) / 3 on e12.
  EXPECT_NEAR(box(bivector{1, 0, 0}).e12(), m * (a * a + b * b) / 3, tolerance(1e-15, 1e-7));
  EXPECT_NEAR(-box(bivector{0, -1, 0}).e13(), m * (a * a + c * c) / 3, tolerance(1e-15, 1e-7));
  EXPECT_NEAR(box(bivector{0, 0, 1}).e23(), m * (b * b + c * c) / 3, tolerance(1e-15, 1e-7));
}

TEST_F(body_test, a_general_tensor_is_the_matrix_on_the_rotation_axis) {
  for (int trial = 0; trial < 50; ++trial) {
    const matrix m = random_tensor();
    const inertia j = inertia::tensor(m);
    const triple w{uniform(-2, 2), uniform(-2, 2), uniform(-2, 2)};
    const bivector omega = plane_of(w);
    EXPECT_TRUE(near(j(omega), plane_of(times(m, w)), tolerance(1e-12, 1e-6)));
    EXPECT_TRUE(near(j.inverse(j(omega)), omega, tolerance(1e-10, 1e-5)));
  }
}

// L = R J R^T w in matrix terms, for a body at any attitude.
TEST_F(body_test, world_inertia_turns_with_the_body) {
  for (int trial = 0; trial < 50; ++trial) {
    const matrix m = random_tensor();
    const triple axis = random_axis();
    const real angle = uniform(-3, 3);
    const matrix r = rotation(axis, angle);
    const matrix world_tensor = product(product(r, m), transposed(r));

    body_definition d;
    d.inertia = inertia::tensor(m);
    d.shape = shape::sphere(1);
    d.attitude = rotor_of(axis, angle);
    const triple w{uniform(-2, 2), uniform(-2, 2), uniform(-2, 2)};
    d.angular_velocity = plane_of(w);
    const body b(d);
    const bivector expected = plane_of(times(world_tensor, w));
    EXPECT_TRUE(near(b.world_inertia(plane_of(w)), expected, tolerance(1e-11, 1e-5)));
    EXPECT_TRUE(near(b.angular_momentum(), expected, tolerance(1e-11, 1e-5)));
    EXPECT_TRUE(near(b.world_inverse_inertia(expected), plane_of(w), tolerance(1e-9, 1e-5)));
  }
}

TEST_F(body_test, kinetic_energy_is_translation_plus_rotation) {
  body_definition d;
  d.mass = 2;
  d.inertia = inertia::principal(1, 2, 3);
  d.velocity = vector{1, 2, 2};
  d.angular_velocity = plane_of({1, 2, 3});
  const body b(d);
  // 1/2 m |v|^2 = 9; 1/2 w . J w = 1/2 (1 + 8 + 27) = 18.
  EXPECT_NEAR(b.kinetic_energy(), 27, tolerance(1e-12, 1e-6));
}

// A point at offset r turns with the body: v + r ⌋ Ω, which is v + ω × r.
TEST_F(body_test, points_move_with_the_angular_velocity) {
  body_definition d;
  d.shape = shape::sphere(1);
  d.position = vector{1, 1, 1};
  d.velocity = vector{0.5, 0, 0};
  d.angular_velocity = bivector{2, 0, 0};  // 2 rad/s in e12: about z
  const body b(d);
  EXPECT_TRUE(near(b.velocity_at(vector{2, 1, 1}), vector{0.5, 2, 0}, tolerance(1e-15, 1e-7)));
  EXPECT_TRUE(near(b.velocity_at(vector{1, 2, 1}), vector{-1.5, 0, 0}, tolerance(1e-15, 1e-7)));
  EXPECT_TRUE(near(b.velocity_at(vector{1, 1, 3}), vector{0.5, 0, 0}, tolerance(1e-15, 1e-7)));
}

// r ∧ f with r the body-frame offset turned into the world: force e2 at
// offset e1 is the torque e12 (about z, turning e1 towards e2).
TEST_F(body_test, an_offset_force_exerts_the_torque_r_wedge_f) {
  body_definition d;
  d.shape = shape::sphere(1);
  body b(d);
  b.apply_force(vector{0, 2, 0}, vector{1, 0, 0});
  EXPECT_TRUE(near(b.accumulated_force(), vector{0, 2, 0}, 0));
  EXPECT_TRUE(near(b.accumulated_torque(), bivector{2, 0, 0}, tolerance(1e-15, 1e-7)));
  b.apply_force(vector{0, 0, 1});  // no offset: no torque
  b.apply_torque(bivector{0, 0, 0.5});
  EXPECT_TRUE(near(b.accumulated_force(), vector{0, 2, 1}, 0));
  EXPECT_TRUE(near(b.accumulated_torque(), bivector{2, 0, 0.5}, tolerance(1e-15, 1e-7)));

  // Turned a quarter about z, the body's e1 points along world e2: a force e1
  // there gives e2 ∧ e1 = -e12.
  body_definition turned = d;
  turned.attitude = rotor_of({0, 0, 1}, std::acos(real(-1)) / 2);
  body t(turned);
  t.apply_force(vector{1, 0, 0}, vector{1, 0, 0});
  EXPECT_TRUE(near(t.accumulated_torque(), bivector{-1, 0, 0}, tolerance(1e-15, 1e-7)));
}

// One step of an offset force from rest: the body's centre speeds up by
// h f / m, it spins by h I⁻¹(r ∧ f), and the offset point swings towards f.
TEST_F(body_test, an_offset_force_pushes_and_spins_the_body) {
  world w = make_world(vector{});
  const real mass = 2, radius = 0.5;
  const body_id id = add_sphere(w, vector{}, radius, mass);
  w.at(id).apply_force(vector{0, 3, 0}, vector{radius, 0, 0});
  w.step(h);
  const real moment = real(0.4) * mass * radius * radius;
  EXPECT_TRUE(near(w.at(id).velocity(), vector{0, h * 3 / mass, 0}, tolerance(1e-15, 1e-7)));
  EXPECT_TRUE(near(w.at(id).angular_velocity(), bivector{h * 3 * radius / moment, 0, 0}, tolerance(1e-13, 1e-6)));
  EXPECT_GT(y(w.at(id).to_world(vector{radius, 0, 0})), h * h * 3 / mass);
  // Forces and torques last one step.
  EXPECT_TRUE(near(w.at(id).accumulated_force(), vector{}, 0));
  EXPECT_TRUE(near(w.at(id).accumulated_torque(), bivector{}, 0));
}

TEST_F(body_test, static_bodies_have_infinite_mass_and_no_inertia) {
  world w = make_world();
  const body_id floor = add_floor(w);
  const body& b = w.at(floor);
  EXPECT_TRUE(b.is_static());
  EXPECT_TRUE(std::isinf(b.mass()));
  EXPECT_EQ(b.inverse_mass(), 0);
  EXPECT_TRUE(near(b.world_inverse_inertia(bivector{1, 2, 3}), bivector{}, 0));
  EXPECT_EQ(b.kinetic_energy(), 0);
  w.at(floor).apply_force(vector{0, 0, 100}, vector{1, 0, 0});
  simulate(w, 10);
  EXPECT_TRUE(near(w.at(floor).position(), vector{}, 0));
  EXPECT_TRUE(near(w.at(floor).velocity(), vector{}, 0));
}

}  // namespace
}  // namespace gaphys::testing
