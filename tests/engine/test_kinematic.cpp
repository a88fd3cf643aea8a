// Kinematic bodies against closed forms: one moves exactly at the velocity
// it is given, whatever gravity, forces, impulses and contacts do; a ball
// struck by a kinematic paddle (e = 1) leaves at twice the paddle's speed,
// the collision law of a wall of infinite mass; a box set on a moving
// kinematic platform slips v² / (2 μ g) behind it and then rides with it; move_to reaches its pose in one step;
// two kinematic bodies, or one and a static floor, pass through each other.
#include <cmath>

#include "engine_test_support.hpp"

namespace gaphys::testing {
namespace {

class kinematic_test : public engine_test {
 protected:
  static body_id add_kinematic(world& w, const shape& s, const vector& position,
                               const vector& velocity, const bivector& spin = bivector{}) {
    body_definition d;
    d.is_kinematic = true;
    d.position = position;
    d.velocity = velocity;
    d.angular_velocity = spin;
    d.shape.emplace(s);  // (assigning: a false maybe-uninitialized warning of GCC 12 at -O3)
    return w.create_body(d);
  }
};

TEST_F(kinematic_test, a_kinematic_body_moves_at_its_velocity_whatever_acts_on_it) {
  world w = make_world();
  add_floor(w, 0);
  const vector v{1, 0.5, -2};
  const bivector spin{0.3, 0, 0};
  const body_id k = add_kinematic(w, shape::box(vector{0.5, 0.5, 0.5}), vector{0, 0, 3}, v, spin);
  const vector start = w.at(k).position();
  for (int i = 0; i < 480; ++i) {  // 2 s: it sinks through the floor, which cannot stop it
    w.at(k).apply_force(vector{100, 0, 0});
    w.at(k).apply_impulse(vector{0, 0, 50}, w.bodies()[k].position());
    w.step(h);
  }
  const body& b = w.bodies()[k];
  EXPECT_EQ(b.velocity().e1(), v.e1());
  EXPECT_EQ(b.velocity().e3(), v.e3());
  EXPECT_TRUE(near(b.angular_velocity(), spin, 0));
  EXPECT_TRUE(near(b.position(), start + (480 * h) * v, tolerance(1e-12, 1e-4)));
  // Turned by 0.3 rad/s about z for 2 s: 0.6 rad.
  const vector x = e3ga::apply(b.attitude(), vector{1, 0, 0});
  EXPECT_NEAR(std::atan2(y(x), ::gaphys::testing::x(x)), 0.6, tolerance(1e-12, 5e-6));
  EXPECT_TRUE(w.contacts().empty());  // a kinematic body and a static one never pair
  EXPECT_TRUE(std::isinf(b.mass()));
  EXPECT_EQ(b.kinetic_energy(), 0);
}

TEST_F(kinematic_test, a_ball_struck_by_a_kinematic_paddle_leaves_at_twice_its_speed) {
  world w = make_world(vector{});
  const real speed = 2;
  const body_id paddle = add_kinematic(w, shape::sphere(0.5).with_restitution(1).with_friction(0),
                                       vector{-2, 0, 0}, vector{speed, 0, 0});
  const body_id ball = add_sphere(w, vector{0, 0, 0}, 0.25, 0.3, vector{}, 1, 0);
  simulate(w, 240);
  EXPECT_NEAR(x(w.at(ball).velocity()), 2 * speed, tolerance(1e-12, 1e-6));
  EXPECT_EQ(x(w.at(paddle).velocity()), speed);
}

TEST_F(kinematic_test, a_box_on_a_kinematic_platform_rides_with_it) {
  world w = make_world();
  const vector v{0.5, 0, 0};
  const body_id platform =
      add_kinematic(w, shape::box(vector{3, 3, 0.1}).with_friction(0.8), vector{0, 0, -0.1}, v);
  body_definition box;
  box.position = vector{0, 0, 0.5};  // at rest: the platform slides under it until friction
  box.shape = shape::box(vector{0.5, 0.5, 0.5}).with_friction(0.8).with_restitution(0);
  const body_id crate = w.create_body(box);
  simulate(w, 480);
  // It fell behind by the slip of a body brought to v by μ g: v² / (2 μ g)
  // (the discrete sum of the slide is within a step's slip of it).
  const vector relative = w.at(crate).position() - w.at(platform).position();
  EXPECT_NEAR(x(relative), -x(v) * x(v) / (2 * 0.8 * 9.81), x(v) * h);
  EXPECT_NEAR(z(relative), 0.6, 1e-3);  // resting on it, within the slop
  EXPECT_NEAR(x(w.at(crate).velocity()), x(v), tolerance(1e-9, 1e-5));
  EXPECT_EQ(x(w.at(platform).velocity()), x(v));  // not pushed back
}

TEST_F(kinematic_test, move_to_reaches_the_pose_in_one_step) {
  world w = make_world();
  const body_id k = add_kinematic(w, shape::box(vector{0.2, 0.3, 0.4}), vector{1, 2, 3}, vector{});
  for (int trial = 0; trial < 50; ++trial) {
    const vector target = vector{uniform(-5, 5), uniform(-5, 5), uniform(-5, 5)};
    const rotor turn = e3ga::exp(uniform(-3, 3) * e3ga::dual(random_unit_vector()));
    w.at(k).move_to(target, turn, h);
    w.step(h);
    EXPECT_TRUE(near(w.bodies()[k].position(), target, tolerance(1e-12, 1e-6)));
    // The same rotation (up to the rotor's sign).
    const rotor r = w.bodies()[k].attitude();
    EXPECT_NEAR(std::fabs(e3ga::scp(r, e3ga::reverse(turn))), 1, tolerance(1e-12, 1e-6));
  }
}

TEST_F(kinematic_test, bad_kinematic_input_is_rejected) {
  world w = make_world();
  body_definition both;
  both.is_static = both.is_kinematic = true;
  both.shape = shape::sphere(1);
  EXPECT_TRUE(rejects([&] { w.create_body(both); }, "both static and kinematic"));
  const body_id ball = add_sphere(w, vector{}, 0.5);
  EXPECT_TRUE(rejects([&] { w.at(ball).move_to(vector{}, rotor{1, 0, 0, 0}, h); }, "kinematic"));
  body_definition k;
  k.is_kinematic = true;
  k.shape = shape::sphere(1);
  const body_id mover = w.create_body(k);
  EXPECT_TRUE(rejects([&] { w.at(mover).move_to(vector{}, rotor{1, 0, 0, 0}, 0); }, "time step"));
  EXPECT_TRUE(rejects([&] { w.at(mover).move_to(vector{}, rotor{0, 0, 0, 0}, h); }, "attitude"));
  body_definition plane;
  plane.is_kinematic = true;
  plane.shape = shape::plane(vector{0, 0, 1}, 0);
  EXPECT_TRUE(rejects([&] { w.create_body(plane); }, "plane"));
}

}  // namespace
}  // namespace gaphys::testing
