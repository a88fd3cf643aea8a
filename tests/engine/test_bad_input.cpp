// Bad input: every public entry point rejects NaN, infinity, non-positive
// masses and radii, zero normals and the like with gaphys::invalid_input and
// a message naming what was wrong, and the world is exactly as before.
#include <cmath>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

#include "engine_test_support.hpp"

namespace gaphys::testing {
namespace {

class bad_input_test : public engine_test {
 protected:
  // A world with some history, whose state the bad calls must not touch.
  void SetUp() override {
    add_floor(w);
    ball = add_sphere(w, vector{0, 0, 1}, 0.5, 1, vector{0.1, 0, 0});
    simulate(w, 30);
    hash = w.state_hash();
    count = w.body_count();
    time = w.time();
  }
  void expect_unchanged() {
    EXPECT_EQ(w.state_hash(), hash);
    EXPECT_EQ(w.body_count(), count);
    EXPECT_EQ(w.time(), time);
    EXPECT_TRUE(near(w.at(ball).accumulated_force(), vector{}, 0));
    EXPECT_TRUE(near(w.at(ball).accumulated_torque(), bivector{}, 0));
    // And it still runs.
    world copy = w;
    simulate(copy, 10);
    EXPECT_TRUE(std::isfinite(z(copy.at(ball).position())));
  }
  body_definition valid_sphere() const {
    body_definition d;
    d.position = vector{2, 0, 1};
    d.shape = shape::sphere(0.5);
    return d;
  }

  world w = make_world();
  body_id ball = 0;
  std::uint64_t hash = 0;
  std::size_t count = 0;
  double time = 0;
};

TEST_F(bad_input_test, shapes_reject_bad_radii_normals_and_restitutions) {
  for (real r : {real(0), real(-1), nan, inf}) {
    EXPECT_TRUE(rejects([&] { shape::sphere(r); }, "sphere radius")) << r;
  }
  EXPECT_TRUE(rejects([] { shape::plane(vector{0, 0, 0}, 1); }, "plane normal"));
  EXPECT_TRUE(rejects([] { shape::plane(vector{0, nan, 1}, 1); }, "plane normal"));
  EXPECT_TRUE(rejects([] { shape::plane(vector{0, 0, 1}, inf); }, "plane offset"));
  for (real e : {real(-0.1), real(1.5), nan}) {
    EXPECT_TRUE(rejects([&] { shape::sphere(1).with_restitution(e); }, "restitution")) << e;
  }
  // A number is shown as the shortest text that reads back to it: just
  // above 1 is not "1".
  const real above_one = std::nextafter(real(1), real(2));
  EXPECT_TRUE(
      rejects([&] { shape::sphere(1).with_restitution(above_one); },
              std::is_same_v<real, double> ? "(got 1.0000000000000002)" : "(got 1.0000001)"));
}

TEST_F(bad_input_test, materials_reject_negative_and_non_finite_values) {
  for (real value : {real(-0.1), nan, inf, -inf}) {
    EXPECT_TRUE(rejects([&] { shape::sphere(1).with_friction(value); }, "friction")) << value;
    EXPECT_TRUE(rejects([&] { shape::plane(vector{0, 0, 1}, 0).with_rolling_resistance(value); },
                        "rolling resistance"))
        << value;
    EXPECT_TRUE(rejects([&] { shape::point().with_spinning_friction(value); }, "spinning friction"))
        << value;
  }
  // The shape a bad call started from keeps its values.
  const shape ball = shape::sphere(1).with_friction(0.7);
  EXPECT_TRUE(rejects([&] { (void)ball.with_friction(-1); }, "friction"));
  EXPECT_EQ(ball.friction(), real(0.7));
  // Zero is a valid value of each.
  EXPECT_EQ(shape::sphere(1).with_friction(0).friction(), 0);
  EXPECT_EQ(shape::sphere(1).with_rolling_resistance(0).rolling_resistance(), 0);
  EXPECT_EQ(shape::sphere(1).with_spinning_friction(0).spinning_friction(), 0);
}

TEST_F(bad_input_test, combine_rules_are_checked_and_a_bad_one_changes_nothing) {
  const auto bad = static_cast<combine_rule>(42);
  const std::pair<combine_rule material_combine_rules::*, const char*> fields[] = {
      {&material_combine_rules::restitution, "restitution combine rule"},
      {&material_combine_rules::friction, "friction combine rule"},
      {&material_combine_rules::rolling_resistance, "rolling resistance combine rule"},
      {&material_combine_rules::spinning_friction, "spinning friction combine rule"}};
  for (const auto& [field, name] : fields) {
    world_settings s;
    s.material_combine.*field = bad;
    EXPECT_TRUE(rejects([&] { world{s}; }, name));
    material_combine_rules rules;
    rules.*field = bad;
    EXPECT_TRUE(rejects([&] { w.set_material_combine(rules); }, name));
    expect_unchanged();
    EXPECT_EQ(w.settings().material_combine.*field, material_combine_rules{}.*field);
  }
}

TEST_F(bad_input_test, inertia_rejects_non_positive_and_asymmetric_tensors) {
  EXPECT_TRUE(rejects([] { inertia::principal(1, 0, 1); }, "inertia about y"));
  EXPECT_TRUE(rejects([] { inertia::principal(-1, 1, 1); }, "inertia about x"));
  EXPECT_TRUE(rejects([] { inertia::principal(1, 1, nan); }, "inertia about z"));
  EXPECT_TRUE(rejects([] { inertia::solid_sphere(0, 1); }, "mass"));
  EXPECT_TRUE(rejects([] { inertia::solid_box(1, 1, -1, 1); }, "half extent y"));
  EXPECT_TRUE(rejects([] { inertia::tensor({1, 0.5, 0, 0, 1, 0, 0, 0, 1}); }, "symmetric"));
  EXPECT_TRUE(rejects([] { inertia::tensor({1, 2, 0, 2, 1, 0, 0, 0, 1}); }, "positive definite"));
  EXPECT_TRUE(rejects([] { inertia::tensor({1, 0, 0, 0, 1, 0, 0, 0, inf}); }, "inertia tensor entry"));
}

TEST_F(bad_input_test, create_body_rejects_bad_definitions_and_adds_nothing) {
  const auto rejects_definition = [&](const body_definition& d, const std::string& what) {
    const auto result = rejects([&] { w.create_body(d); }, what);
    expect_unchanged();
    return result;
  };
  for (real m : {real(0), real(-2), nan, inf}) {
    body_definition d = valid_sphere();
    d.mass = m;
    EXPECT_TRUE(rejects_definition(d, "body mass")) << m;
  }
  body_definition d = valid_sphere();
  d.position = vector{nan, 0, 0};
  EXPECT_TRUE(rejects_definition(d, "body position"));
  d = valid_sphere();
  d.velocity = vector{0, -inf, 0};
  EXPECT_TRUE(rejects_definition(d, "body velocity"));
  d = valid_sphere();
  d.angular_velocity = bivector{0, 0, nan};
  EXPECT_TRUE(rejects_definition(d, "body angular velocity"));
  d = valid_sphere();
  d.attitude = rotor{0, 0, 0, 0};
  EXPECT_TRUE(rejects_definition(d, "body attitude"));
  d = valid_sphere();
  d.attitude = rotor{1, nan, 0, 0};
  EXPECT_TRUE(rejects_definition(d, "body attitude"));
  d = valid_sphere();
  d.shape = shape::plane(vector{0, 0, 1}, 0);
  EXPECT_TRUE(rejects_definition(d, "plane shape needs a static body"));
  d = valid_sphere();
  d.shape = shape::point();
  EXPECT_TRUE(rejects_definition(d, "explicit inertia"));
  d = valid_sphere();
  d.density = -2;
  EXPECT_TRUE(rejects_definition(d, "body density"));
  d = valid_sphere();
  d.density = nan;
  EXPECT_TRUE(rejects_definition(d, "body density"));
  d = valid_sphere();
  d.shapes.push_back({shape::box(vector{1, 1, 1}), vector{nan, 0, 0}, rotor{1, 0, 0, 0}});
  EXPECT_TRUE(rejects_definition(d, "shape offset"));
  d = valid_sphere();
  d.shapes.push_back({shape::box(vector{1, 1, 1}), vector{}, rotor{0, 0, 0, 0}});
  EXPECT_TRUE(rejects_definition(d, "shape attitude"));
  d = valid_sphere();
  d.is_static = true;
  d.shapes.push_back({shape::plane(vector{0, 0, 1}, 0), vector{}, rotor{1, 0, 0, 0}});
  EXPECT_TRUE(rejects_definition(d, "a plane must be its body's only shape"));
  d = valid_sphere();
  d.is_static = true;
  d.shape.reset();
  d.shapes.push_back({shape::plane(vector{0, 0, 1}, 0), vector{0, 0, 1}, rotor{1, 0, 0, 0}});
  EXPECT_TRUE(rejects_definition(d, "a plane shape takes no offset or attitude"));
  d = valid_sphere();
  d.density = 1000;
  d.inertia = inertia::principal(1, 1, 1);
  EXPECT_TRUE(rejects_definition(d, "density or an inertia, not both"));
  d = valid_sphere();
  d.is_static = true;
  d.velocity = vector{1, 0, 0};
  EXPECT_TRUE(rejects_definition(d, "static body cannot have a nonzero velocity"));
  d = valid_sphere();
  d.is_static = true;
  d.angular_velocity = bivector{1, 0, 0};
  EXPECT_TRUE(rejects_definition(d, "static body cannot have a nonzero angular velocity"));
}

TEST_F(bad_input_test, step_rejects_bad_time_steps_and_changes_nothing) {
  for (real bad : {real(0), real(-h), nan, inf, -inf}) {
    EXPECT_TRUE(rejects([&] { w.step(bad); }, "time step")) << bad;
    expect_unchanged();
  }
}

TEST_F(bad_input_test, setters_and_forces_reject_non_finite_values_and_change_nothing) {
  body& b = w.at(ball);
  EXPECT_TRUE(rejects([&] { b.set_position(vector{inf, 0, 0}); }, "body position"));
  EXPECT_TRUE(rejects([&] { b.set_velocity(vector{0, nan, 0}); }, "body velocity"));
  EXPECT_TRUE(rejects([&] { b.set_attitude(rotor{0, 0, 0, 0}); }, "body attitude"));
  EXPECT_TRUE(rejects([&] { b.set_angular_velocity(bivector{nan, 0, 0}); }, "body angular velocity"));
  EXPECT_TRUE(rejects([&] { b.apply_force(vector{0, 0, nan}); }, "force"));
  EXPECT_TRUE(rejects([&] { b.apply_force(vector{0, 0, 1}, vector{inf, 0, 0}); }, "force offset"));
  EXPECT_TRUE(rejects([&] { b.apply_torque(bivector{0, inf, 0}); }, "torque"));
  EXPECT_TRUE(rejects([&] { w.at(0).set_velocity(vector{0, 0, 1}); }, "static body"));
  EXPECT_TRUE(rejects([&] { w.set_gravity(vector{0, 0, nan}); }, "gravity"));
  EXPECT_TRUE(rejects([&] { w.set_damping(-1, 0); }, "linear damping"));
  EXPECT_TRUE(rejects([&] { w.set_damping(0, nan); }, "angular damping"));
  EXPECT_TRUE(rejects([&] { w.at(count); }, "no body with id"));
  expect_unchanged();
  EXPECT_TRUE(near(w.settings().gravity, vector{0, 0, -9.81}, 0));
}

// Finite numbers too large to step: the step squares every speed (in each
// norm it takes), so a speed, force or torque whose square overflows would
// turn into NaNs there (and, unchecked, once sent the broad phase's
// histogram past its end). Each call rejects its own, or what it would add
// up to, and changes nothing.
TEST_F(bad_input_test, speeds_forces_and_impulses_too_large_to_step_are_rejected) {
  body& b = w.at(ball);
  const real huge = for_scalar(1e200, 1e25);        // its square overflows
  const real steppable = for_scalar(1e150, 1e18);   // its square does not, nor twice it
  const real near_limit = for_scalar(1e154, 1e19);  // its square does not; twice it, it does
  EXPECT_TRUE(rejects([&] { b.set_velocity(vector{huge, 0, 0}); }, "body velocity"));
  EXPECT_TRUE(rejects(
      [&] {
        b.set_angular_velocity(bivector{0, huge, huge});
      },
      "body angular velocity"));
  EXPECT_TRUE(rejects([&] { b.apply_force(vector{0, huge, 0}); }, "total force"));
  EXPECT_TRUE(rejects([&] { b.apply_torque(bivector{huge, 0, 0}); }, "total torque"));
  EXPECT_TRUE(rejects(
      [&] {
        b.apply_impulse(vector{huge, 0, 0}, b.position());
      },
      "velocity after the impulse"));
  body_definition fast = valid_sphere();
  fast.velocity = vector{0, 0, -huge};
  EXPECT_TRUE(rejects([&] { w.create_body(fast); }, "body velocity"));
  expect_unchanged();
  // What one call adds to another (on a copy: an accepted force wakes the ball).
  world copy = w;
  body& c = copy.at(ball);
  c.apply_force(vector{near_limit, 0, 0});
  EXPECT_TRUE(rejects([&] { c.apply_force(vector{near_limit, 0, 0}); }, "total force"));
  EXPECT_EQ(x(c.accumulated_force()), near_limit) << "the rejected force is not added";
  const vector lever = c.position() + vector{0, near_limit, 0};
  EXPECT_TRUE(rejects(
      [&] {
        c.apply_force_at_world_point(vector{-near_limit, 0, 0}, lever);
      },
      "total torque"));
  EXPECT_EQ(x(c.accumulated_force()), near_limit) << "nor its torque's force";
  // Large but steppable: accepted, and stepped.
  c.apply_force(vector{-near_limit, 0, 0});
  c.set_velocity(vector{steppable, 0, 0});
  copy.step(h);
  EXPECT_EQ(x(copy.at(ball).velocity()), steppable);
}

// Shapes too large or too small for their volume and inertia to be real
// numbers, and a mass that scales an inertia out of range, are named as
// such (they were reported as a NaN or a singular inertia tensor).
TEST_F(bad_input_test, shapes_and_masses_beyond_real_numbers_are_named) {
  body_definition d = valid_sphere();
  // Within the lengths a shape may have, but moments of h^5 overflow (and,
  // in double, underflow to zero).
  std::vector<real> sizes{for_scalar(1e70, 5e8)};
  if (std::is_same_v<real, double>) sizes.push_back(real(1e-70));
  for (real size : sizes) {
    d.shape = shape::box(vector{size, size, size});
    EXPECT_TRUE(rejects([&] { w.create_body(d); }, "too large or too small for its volume"))
        << size;
  }
  d.shape = shape::box(vector{0.5, 0.5, 0.5});
  d.mass = for_scalar(1e-308, 1e-38);  // moments of 2e-309 (2e-39): no inverse
  EXPECT_TRUE(rejects([&] { w.create_body(d); }, "body mass"));
  // A mass whose own inverse overflows, with an inertia given.
  d.mass = std::numeric_limits<real>::denorm_min();
  d.inertia = inertia::principal(1, 1, 1);
  EXPECT_TRUE(rejects([&] { w.create_body(d); }, "too small or too large to invert"));
  // A density that makes such a mass is named as the density.
  body_definition by_density = valid_sphere();
  by_density.density = std::numeric_limits<real>::denorm_min();
  EXPECT_TRUE(rejects([&] { w.create_body(by_density); }, "density"));
  EXPECT_TRUE(rejects([&] { w.create_body(by_density); }, "too small or too large to invert"));
  expect_unchanged();
}

// The lengths of shapes (radii, half extents, a hull's span, offsets, the
// sizes of queries) lie between smallest_length and largest_length: 1e-75
// and 1e75 m in double, 1e-9 and 1e9 in float, where their fourth powers
// are still normal numbers. Beyond, each is named; a static box of half
// extent 1e-80 had NaN face normals, and a ball landing on it crashed the
// step.
TEST_F(bad_input_test, shape_lengths_beyond_the_engines_range_are_rejected) {
  const real tiny = for_scalar(1e-80, 1e-12), huge = for_scalar(1e80, 1e12);
  for (real r : {tiny, huge}) {
    EXPECT_TRUE(rejects([&] { shape::sphere(r); }, "sphere radius must be between")) << r;
    EXPECT_TRUE(rejects([&] { shape::box(vector{1, r, 1}); }, "box half extent y")) << r;
    EXPECT_TRUE(rejects([&] { shape::capsule(1, r); }, "capsule radius")) << r;
    EXPECT_TRUE(rejects([&] { shape::capsule(r, 1); }, "capsule half height")) << r;
    EXPECT_TRUE(rejects([&] { (void)w.overlap_sphere(vector{}, r); }, "overlap sphere radius"))
        << r;
    EXPECT_TRUE(rejects(
        [&] {
          (void)w.overlap_box(vector{}, vector{r, 1, 1}, rotor{1, 0, 0, 0});
        },
        "box half extent x"))
        << r;
  }
  EXPECT_TRUE(rejects([&] { shape::plane(vector{0, 0, 1}, huge); }, "plane offset"));
  EXPECT_TRUE(rejects(
      [&] {
        shape::convex_hull({vector{}, vector{tiny, 0, 0}, vector{0, tiny, 0}, vector{0, 0, tiny}});
      },
      "convex hull points must span at least"));
  EXPECT_TRUE(rejects(
      [&] {
        shape::convex_hull({vector{}, vector{huge, 0, 0}, vector{0, 1, 0}, vector{0, 0, 1}});
      },
      "convex hull points must lie within"));
  // Every coordinate within the bound, a point beyond it.
  const real far = for_scalar(0.8e75, 0.8e9);
  EXPECT_TRUE(rejects(
      [&] {
        shape::convex_hull(
            {vector{far, far, far}, vector{far, far, 0}, vector{far, 0, far}, vector{0, far, far}});
      },
      "convex hull points must lie within"));
  body_definition far_part = valid_sphere();
  far_part.is_static = true;
  far_part.shapes.push_back({shape::sphere(1), vector{huge, 0, 0}, rotor{1, 0, 0, 0}});
  EXPECT_TRUE(rejects([&] { w.create_body(far_part); }, "shape offset"));
  expect_unchanged();
}

// At the ends of that range shapes still make sound contacts: a ball
// dropped onto a static box, and beside a static hull, each of the least
// size, on a floor, comes to rest on the floor without a NaN (the box of
// 1e-80 m crashed this step), and queries of the largest size find them.
TEST_F(bad_input_test, shapes_at_the_ends_of_the_range_step_and_are_found) {
  const real least = for_scalar(1.01e-75, 1.01e-9);
  world small = make_world();
  add_floor(small);
  body_definition box;
  box.is_static = true;
  box.shape = shape::box(vector{least, least, least});
  small.create_body(box);
  body_definition hull = box;
  hull.position = vector{1, 0, 0};
  hull.shape =
      shape::convex_hull({vector{}, vector{least, 0, 0}, vector{0, least, 0}, vector{0, 0, least}});
  small.create_body(hull);
  const body_id ball = add_sphere(small, vector{0, 0, 2}, 0.5);
  simulate(small, 600);  // (it bounces off the box, whose restitution is the default 0.5)
  for (real c : small.at(ball).position().c) ASSERT_TRUE(std::isfinite(c));
  EXPECT_NEAR(z(small.at(ball).position()), 0.5, 0.01);
  EXPECT_EQ(small.overlap_sphere(vector{}, for_scalar(0.99e75, 0.99e9)).size(), 4u);
}

// A step whose move would overflow: a body's velocity after the step's
// gravity and forces, or h times it, squares to infinity (the body names
// itself by id); or h so short that the correction's 1 / h overflows.
TEST_F(bad_input_test, a_step_too_long_or_too_short_for_real_numbers_is_rejected) {
  const real too_long = for_scalar(1e160, 1e20);  // h g squares to infinity
  EXPECT_TRUE(rejects([&] { w.step(too_long); }, "body " + std::to_string(ball)));
  expect_unchanged();
  EXPECT_TRUE(rejects([&] { w.step(std::numeric_limits<real>::denorm_min()); }, "too short"));
  expect_unchanged();
  // A force the setters accept, but not over this step: h F / m overflows.
  world copy = w;
  const real force = for_scalar(1e150, 1e18), h_long = for_scalar(1e10, 1e5);
  copy.at(ball).apply_force(vector{force, 0, 0});
  const std::uint64_t before = copy.state_hash();
  EXPECT_TRUE(rejects([&] { copy.step(h_long); }, "would move or turn too far"));
  EXPECT_EQ(copy.state_hash(), before);
  EXPECT_EQ(x(copy.at(ball).accumulated_force()), force) << "nothing changes, the force included";
  EXPECT_EQ(copy.time(), w.time());
}

// A step that would carry the world's time (a double) past the largest double.
TEST_F(bad_input_test, a_step_past_the_largest_time_is_rejected) {
  if (!std::is_same_v<real, double>) {
    GTEST_SKIP() << "the time is a double: no float step carries it past the largest double";
  }
  world still = make_world();
  add_floor(still);
  const real longest = std::numeric_limits<real>::max() / 2 * real(1.5);
  still.step(longest);  // nothing moves: any step is short enough
  EXPECT_TRUE(rejects([&] { still.step(longest); }, "past the largest double"));
  EXPECT_EQ(still.time(), double(longest));
}

// Bodies placed exactly on top of each other are not an error: identical
// spheres (a zero meet), concentric ones and a point at a sphere's centre are
// pushed apart without a NaN anywhere.
TEST_F(bad_input_test, bodies_on_top_of_each_other_are_separated_without_nan) {
  world stacked = make_world();
  add_floor(stacked);
  const vector spot{0.3, -0.2, 2};
  add_sphere(stacked, spot, 0.5);
  add_sphere(stacked, spot, 0.5);
  add_sphere(stacked, spot, 0.25, 2);
  body_definition point;
  point.position = spot;
  point.shape = shape::point();
  point.inertia = inertia::principal(1, 1, 1);
  stacked.create_body(point);
  simulate(stacked, 480);
  for (const body& b : stacked.bodies()) {
    for (real c : b.position().c) ASSERT_TRUE(std::isfinite(c));
    for (real c : b.velocity().c) ASSERT_TRUE(std::isfinite(c));
    for (real c : b.attitude().c) ASSERT_TRUE(std::isfinite(c));
  }
  // The two identical spheres no longer share a centre.
  EXPECT_GT(length(stacked.at(1).position() - stacked.at(2).position()), 0.5);
}

TEST_F(bad_input_test, world_settings_are_checked) {
  const auto rejects_settings = [](const world_settings& s, const std::string& what) {
    return rejects([&] { world{s}; }, what);
  };
  world_settings s;
  s.gravity = vector{0, inf, 0};
  EXPECT_TRUE(rejects_settings(s, "gravity"));
  s = {};
  s.linear_damping = -0.1;
  EXPECT_TRUE(rejects_settings(s, "linear damping"));
  s = {};
  s.solver_iterations = 0;
  EXPECT_TRUE(rejects_settings(s, "solver iterations"));
  s = {};
  s.impact_iterations = 0;
  EXPECT_TRUE(rejects_settings(s, "impact iterations"));
  s = {};
  s.solver_iterations = 1'000'001;
  EXPECT_TRUE(rejects_settings(s, "solver iterations"));
  s = {};
  s.turning_iterations = std::numeric_limits<int>::max();
  EXPECT_TRUE(rejects_settings(s, "turning iterations"));
  s = {};
  s.solver_tolerance = -1e-6;
  EXPECT_TRUE(rejects_settings(s, "solver tolerance"));
  s = {};
  for (real relaxation : {real(0), real(2), real(-1), nan}) {
    s.solver_relaxation = relaxation;
    EXPECT_TRUE(rejects_settings(s, "solver relaxation"));
  }
  s = {};
  s.position_correction = 1.5;
  EXPECT_TRUE(rejects_settings(s, "position correction"));
  s = {};
  s.linear_slop = nan;
  EXPECT_TRUE(rejects_settings(s, "linear slop"));
  s = {};
  s.restitution_threshold = -1;
  EXPECT_TRUE(rejects_settings(s, "restitution threshold"));
  s = {};
  s.broad_phase = static_cast<broad_phase_kind>(7);
  EXPECT_TRUE(rejects_settings(s, "broad phase"));
}

}  // namespace
}  // namespace gaphys::testing
