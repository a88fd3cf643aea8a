// Conversions between rotors, quaternions, matrices and axial vectors,
// against independent truth: Hamilton products written out here, Rodrigues'
// matrices (matrix3.hpp), cross products by hand, and the engine's own
// velocity, torque, inertia and integration.
#include <cmath>
#include <limits>
#include <vector>

#include "engine_test_support.hpp"
#include "gaphys/conversions.hpp"
#include "matrix3.hpp"

namespace gaphys::testing {
namespace {

// Hamilton's product, i j = k, written out.
quaternion hamilton(const quaternion& a, const quaternion& b) {
  return {
      a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
      a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}

// q v q* for a unit q.
triple turned(const quaternion& q, const triple& v) {
  const quaternion conjugate{q.w, -q.x, -q.y, -q.z};
  const quaternion p = hamilton(hamilton(q, quaternion{0, v[0], v[1], v[2]}), conjugate);
  return {p.x, p.y, p.z};
}

vector as_vector(const triple& t) { return {t[0], t[1], t[2]}; }

real distance(const triple& a, const triple& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                   (a[2] - b[2]) * (a[2] - b[2]));
}

real largest_difference(const matrix& a, const matrix& b) {
  real worst = 0;
  for (int k = 0; k < 9; ++k) worst = std::max(worst, std::abs(a[k] - b[k]));
  return worst;
}

real distance(const quaternion& a, const quaternion& b) {
  return std::sqrt((a.w - b.w) * (a.w - b.w) + (a.x - b.x) * (a.x - b.x) +
                   (a.y - b.y) * (a.y - b.y) + (a.z - b.z) * (a.z - b.z));
}

// R and -R are the same turn, as are q and -q.
real distance_up_to_sign(const rotor& a, const rotor& b) {
  return std::min(e3ga::norm(a - b), e3ga::norm(a + b));
}

real distance_up_to_sign(const quaternion& a, const quaternion& b) {
  return std::min(distance(a, b), distance(a, quaternion{-b.w, -b.x, -b.y, -b.z}));
}

class conversions_test : public engine_test {
 protected:
  triple random_axis() { return as_triple(random_unit_vector()); }
  triple random_point() { return {uniform(-2, 2), uniform(-2, 2), uniform(-2, 2)}; }

  // Angles where conversions go wrong if they do: none, tiny, a half turn
  // and near it (Shepperd's other branches), negative, beyond a half turn.
  std::vector<real> angles() {
    // clang-format off
    std::vector<real> a = {0, tolerance(1e-15, 1e-7), -tolerance(1e-15, 1e-7), tolerance(1e-9, 1e-5), -tolerance(1e-9, 1e-5),
                           pi, -pi, pi - tolerance(1e-9, 1e-5), -pi + tolerance(1e-9, 1e-5), pi + tolerance(1e-9, 1e-5), pi - tolerance(1e-15, 1e-7),
                           2 * pi - tolerance(1e-12, 1e-6), 2 * pi, 1.0, -2.5};
    // clang-format on
    for (int k = 0; k < 40; ++k) a.push_back(uniform(-2 * pi, 2 * pi));
    return a;
  }

  // The axes of a half turn decide which of Shepperd's four branches runs:
  // the coordinate axes and random ones.
  std::vector<triple> axes() {
    std::vector<triple> a = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (int k = 0; k < 8; ++k) a.push_back(random_axis());
    return a;
  }
};

TEST_F(conversions_test, a_rotor_its_quaternion_and_its_matrix_turn_vectors_alike) {
  for (const triple& axis : axes()) {
    for (real angle : angles()) {
      const rotor r = rotor_of(axis, angle);
      const quaternion q = to_quaternion(r);
      const matrix m = to_matrix(r);
      const matrix rodrigues = rotation(axis, angle);
      EXPECT_LE(largest_difference(m, rodrigues), tolerance(1e-12, 1e-6)) << "angle " << angle;
      for (int k = 0; k < 4; ++k) {
        const triple p = random_point();
        const triple by_rotor = as_triple(e3ga::apply(r, as_vector(p)));
        EXPECT_LE(distance(turned(q, p), by_rotor), tolerance(1e-12, 1e-6)) << "angle " << angle;
        EXPECT_LE(distance(times(m, p), by_rotor), tolerance(1e-12, 5e-6)) << "angle " << angle;
        EXPECT_LE(distance(times(rodrigues, p), by_rotor), tolerance(1e-12, 5e-6)) << "angle " << angle;
      }
    }
  }
}

TEST_F(conversions_test, the_quaternion_of_a_turn_is_cos_half_and_sin_half_axis) {
  for (const triple& axis : axes()) {
    for (real angle : angles()) {
      const real c = std::cos(angle / 2), s = std::sin(angle / 2);
      const quaternion expected{c, s * axis[0], s * axis[1], s * axis[2]};
      EXPECT_LE(distance(to_quaternion(rotor_of(axis, angle)), expected), tolerance(1e-12, 1e-6));
      EXPECT_LE(e3ga::norm(to_rotor(expected) - rotor_of(axis, angle)), tolerance(1e-12, 1e-6));
    }
  }
  // The components one by one: a quarter turn about each axis.
  const real h = std::sqrt(real(0.5));
  const quaternion about_x = to_quaternion(rotor_of({1, 0, 0}, pi / 2));
  const quaternion about_y = to_quaternion(rotor_of({0, 1, 0}, pi / 2));
  const quaternion about_z = to_quaternion(rotor_of({0, 0, 1}, pi / 2));
  EXPECT_LE(distance(about_x, quaternion{h, h, 0, 0}), tolerance(1e-15, 1e-7));
  EXPECT_LE(distance(about_y, quaternion{h, 0, h, 0}), tolerance(1e-15, 1e-7));
  EXPECT_LE(distance(about_z, quaternion{h, 0, 0, h}), tolerance(1e-15, 1e-7));
}

TEST_F(conversions_test, rotations_come_back_from_each_form) {
  for (const triple& axis : axes()) {
    for (real angle : angles()) {
      const rotor r = rotor_of(axis, angle);
      const quaternion q = to_quaternion(r);
      EXPECT_LE(e3ga::norm(to_rotor(q) - r), tolerance(1e-12, 1e-6)) << "angle " << angle;
      EXPECT_LE(distance_up_to_sign(to_rotor(to_matrix(r)), r), tolerance(1e-12, 1e-6)) << "angle " << angle;
      EXPECT_LE(distance_up_to_sign(to_quaternion(to_matrix(q)), q), tolerance(1e-12, 1e-6)) << "angle " << angle;
      EXPECT_LE(distance_up_to_sign(to_rotor(rotation(axis, angle)), r), tolerance(1e-12, 1e-6))
          << "angle " << angle;
      EXPECT_LE(largest_difference(to_matrix(q), to_matrix(r)), tolerance(1e-15, 2e-6));
    }
  }
}

TEST_F(conversions_test, a_matrix_gives_the_rotor_with_its_largest_component_positive) {
  // Half turns about x, y and z and the identity: each of Shepperd's branches.
  EXPECT_LE(e3ga::norm(to_rotor(matrix{1, 0, 0, 0, 1, 0, 0, 0, 1}) - rotor{1, 0, 0, 0}), 0);
  EXPECT_LE(e3ga::norm(to_rotor(matrix{1, 0, 0, 0, -1, 0, 0, 0, -1}) - rotor{0, 0, 0, -1}), 0);
  EXPECT_LE(e3ga::norm(to_rotor(matrix{-1, 0, 0, 0, 1, 0, 0, 0, -1}) - rotor{0, 0, 1, 0}), 0);
  EXPECT_LE(e3ga::norm(to_rotor(matrix{-1, 0, 0, 0, -1, 0, 0, 0, 1}) - rotor{0, -1, 0, 0}), 0);
  for (int trial = 0; trial < 200; ++trial) {
    const quaternion q = to_quaternion(to_matrix(rotor_of(random_axis(), uniform(-7, 7))));
    const real parts[] = {q.w, q.x, q.y, q.z};
    real largest = 0;
    for (real p : parts) largest = std::abs(p) > std::abs(largest) ? p : largest;
    EXPECT_GT(largest, 0);
    EXPECT_NEAR(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z, 1, tolerance(1e-15, 1e-6));
  }
}

TEST_F(conversions_test, quaternions_and_rotors_of_any_length_are_normalized) {
  for (int trial = 0; trial < 50; ++trial) {
    const triple axis = random_axis();
    const real angle = uniform(-pi, pi);
    const rotor r = rotor_of(axis, angle);
    const quaternion q = to_quaternion(r);
    for (real scale : {for_scalar(1e-200, 1e-20), real(1e-3), real(-2.5), real(7),
                       for_scalar(1e200, 1e20)}) {
      const quaternion scaled{scale * q.w, scale * q.x, scale * q.y, scale * q.z};
      EXPECT_LE(distance_up_to_sign(to_rotor(scaled), r), tolerance(1e-15, 5e-7)) << "scale " << scale;
      EXPECT_LE(largest_difference(to_matrix(scaled), rotation(axis, angle)), tolerance(1e-12, 1e-6));
      EXPECT_LE(distance_up_to_sign(to_quaternion(scale * r), q), tolerance(1e-15, 5e-7)) << "scale " << scale;
      EXPECT_LE(largest_difference(to_matrix(scale * r), rotation(axis, angle)), tolerance(1e-12, 1e-6));
    }
  }
}

TEST_F(conversions_test, a_matrix_within_the_tolerance_is_accepted_and_one_beyond_it_is_not) {
  const triple axis = random_axis();
  const matrix m = rotation(axis, 0.7);
  matrix nearly = m;
  nearly[4] += rotation_matrix_tolerance / 10;  // M M^T - 1 off by a fifth of it
  EXPECT_LE(distance_up_to_sign(to_rotor(nearly), rotor_of(axis, 0.7)), tolerance(1e-6, 1e-5));
  EXPECT_NEAR(e3ga::norm(to_rotor(nearly)), 1, tolerance(1e-15, 1e-7));
  matrix off = m;
  off[4] += 10 * rotation_matrix_tolerance;
  EXPECT_TRUE(rejects([&] { to_rotor(off); }, "not orthonormal"));
}

// Ω turns a point at offset r at r ⌋ Ω (body_velocity::at_offset), which must
// be ω × r for the axial ω; and to_axial is exactly the inverse of
// matrix3.hpp's plane_of, the engine's documented axis-to-plane map.
TEST_F(conversions_test, the_axial_angular_velocity_gives_point_velocities_by_the_cross_product) {
  EXPECT_TRUE(near(to_axial(bivector{3, 5, 7}), vector{7, -5, 3}, 0));
  EXPECT_TRUE(near(to_bivector(vector{7, -5, 3}), bivector{3, 5, 7}, 0));
  for (int trial = 0; trial < 200; ++trial) {
    const bivector spin{uniform(-5, 5), uniform(-5, 5), uniform(-5, 5)};
    const triple omega = as_triple(to_axial(spin));
    const triple r = random_point();
    const vector velocity = body_velocity{vector{}, spin}.at_offset(as_vector(r));
    EXPECT_TRUE(near(velocity, as_vector(cross(omega, r)), tolerance(1e-12, 1e-6)));
    EXPECT_TRUE(near(to_bivector(as_vector(omega)), spin, 0));
    const triple axis = random_axis();
    EXPECT_TRUE(near(to_bivector(as_vector(axis)), plane_of(axis), 0));
    EXPECT_TRUE(near(to_axial(plane_of(axis)), as_vector(axis), 0));
  }
}

// A body spinning at ω = to_axial(Ω) turns by |ω| h about ω in a step,
// right-handed: a sphere without gravity turns exactly by exp(-h Ω / 2).
TEST_F(conversions_test, a_body_spun_at_an_axial_angular_velocity_turns_about_it) {
  for (int trial = 0; trial < 20; ++trial) {
    const triple axis = random_axis();
    const real rate = uniform(-20, 20);
    world w = make_world(vector{});
    body_definition d;
    d.shape = shape::sphere(1);
    d.angular_velocity = to_bivector(as_vector({rate * axis[0], rate * axis[1], rate * axis[2]}));
    const body_id id = w.create_body(d);
    w.step(h);
    EXPECT_LE(largest_difference(to_matrix(w.at(id).attitude()), rotation(axis, rate * h)), tolerance(1e-12, 1e-6));
  }
}

// body::apply_force makes the torque r ∧ f (r turned to the world); its axial
// vector must be r × f.
TEST_F(conversions_test, the_axial_torque_of_a_force_is_the_cross_product) {
  for (int trial = 0; trial < 100; ++trial) {
    body_definition d;
    d.shape = shape::sphere(1);
    d.attitude = rotor_of(random_axis(), uniform(-pi, pi));
    body b(d);
    const triple offset = random_point();
    const triple force = random_point();
    b.apply_force(as_vector(force), as_vector(offset));
    const triple arm = times(to_matrix(b.attitude()), offset);
    EXPECT_TRUE(near(to_axial(b.accumulated_torque()), as_vector(cross(arm, force)), tolerance(1e-12, 5e-6)));
  }
}

// The world-frame inertia as a matrix: J_w = M J M^T with M = to_matrix(R),
// acting on axial vectors.
TEST_F(conversions_test, the_world_inertia_is_the_turned_tensor_on_axial_vectors) {
  for (int trial = 0; trial < 50; ++trial) {
    const matrix q = rotation(random_axis(), uniform(-3, 3));
    matrix j = product(product(q, diagonal(uniform(0.2, 3), uniform(0.2, 3), uniform(0.2, 3))),
                       transposed(q));
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < i; ++k) j[3 * i + k] = j[3 * k + i];
    body_definition d;
    d.shape = shape::sphere(1);
    d.inertia = inertia::tensor(j);
    d.attitude = rotor_of(random_axis(), uniform(-pi, pi));
    const body b(d);
    const matrix m = to_matrix(b.attitude());
    const matrix world_tensor = product(product(m, j), transposed(m));
    const bivector spin{uniform(-2, 2), uniform(-2, 2), uniform(-2, 2)};
    const vector expected = as_vector(times(world_tensor, as_triple(to_axial(spin))));
    EXPECT_TRUE(near(to_axial(b.world_inertia(spin)), expected, tolerance(1e-11, 1e-5)));
  }
}

// The worked example of docs/engine.md, "Conversions": a cube posed by a
// quaternion and spun by an axial vector turns on about z by 2 h.
TEST_F(conversions_test, the_worked_example_in_the_docs_turns_as_it_says) {
  body_definition d;
  d.shape = shape::box(vector{0.5, 0.5, 0.5});
  const double half = 0.3926990816987241;  // 45° about z, halved
  d.attitude = to_rotor(quaternion{real(std::cos(half)), 0, 0, real(std::sin(half))});
  d.angular_velocity = to_bivector(vector{0, 0, 2});
  world w;
  const body_id id = w.create_body(d);
  w.step(1.0 / 240);
  const real turned_half = half + 1.0 / 240;
  const quaternion expected{std::cos(turned_half), 0, 0, std::sin(turned_half)};
  EXPECT_LE(distance(to_quaternion(w.at(id).attitude()), expected), tolerance(1e-12, 1e-6));
  EXPECT_LE(
      largest_difference(to_matrix(w.at(id).attitude()), rotation({0, 0, 1}, 2 * turned_half)),
      tolerance(1e-12, 1e-6));
  EXPECT_TRUE(near(to_axial(w.at(id).angular_velocity()), vector{0, 0, 2}, tolerance(1e-12, 1e-6)));
}

TEST_F(conversions_test, bad_input_is_rejected_naming_the_problem) {
  const real nan = std::numeric_limits<real>::quiet_NaN();
  const real inf = std::numeric_limits<real>::infinity();
  EXPECT_TRUE(rejects([&] { to_rotor(quaternion{nan, 0, 0, 0}); }, "quaternion must be finite"));
  EXPECT_TRUE(rejects([&] { to_rotor(quaternion{1, 0, 0, inf}); }, "quaternion must be finite"));
  EXPECT_TRUE(rejects([&] { to_matrix(quaternion{1, -inf, 0, 0}); }, "quaternion must be finite"));
  EXPECT_TRUE(rejects([&] { to_rotor(quaternion{0, 0, 0, 0}); }, "quaternion must be nonzero"));
  EXPECT_TRUE(rejects([&] { to_matrix(quaternion{0, 0, 0, 0}); }, "quaternion must be nonzero"));
  EXPECT_TRUE(rejects([&] { to_quaternion(rotor{0, 0, 0, 0}); }, "rotor must be nonzero"));
  EXPECT_TRUE(rejects([&] { to_matrix(rotor{0, 0, 0, 0}); }, "rotor must be nonzero"));
  EXPECT_TRUE(rejects([&] { to_quaternion(rotor{1, 0, nan, 0}); }, "rotor must be finite"));
  EXPECT_TRUE(rejects([&] { to_matrix(rotor{inf, 0, 0, 0}); }, "rotor must be finite"));

  const matrix identity = diagonal(1, 1, 1);
  matrix not_finite = identity;
  not_finite[5] = nan;
  EXPECT_TRUE(rejects([&] { to_rotor(not_finite); }, "rotation matrix must be finite"));
  not_finite[5] = inf;
  EXPECT_TRUE(rejects([&] { to_quaternion(not_finite); }, "row 1, column 2"));
  EXPECT_TRUE(rejects([&] { to_rotor(diagonal(2, 2, 2)); }, "not orthonormal"));
  EXPECT_TRUE(rejects([&] { to_rotor(matrix{1, 0.1, 0, 0, 1, 0, 0, 0, 1}); }, "not orthonormal"));
  EXPECT_TRUE(rejects([&] { to_rotor(matrix{}); }, "not orthonormal"));
  EXPECT_TRUE(rejects([&] { to_rotor(diagonal(1, 1, -1)); }, "reflection"));
  EXPECT_TRUE(rejects([&] { to_quaternion(diagonal(-1, -1, -1)); }, "reflection"));

  EXPECT_TRUE(rejects([&] { to_axial(bivector{0, nan, 0}); }, "bivector must be finite"));
  EXPECT_TRUE(rejects([&] { to_bivector(vector{inf, 0, 0}); }, "axial vector must be finite"));
}

}  // namespace
}  // namespace gaphys::testing
