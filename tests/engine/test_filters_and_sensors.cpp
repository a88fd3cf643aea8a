// Collision filters and sensors against free fall and the geometry of the
// overlap: a ball whose mask leaves out the floor's category falls through
// it exactly as through nothing; a ball falling through a sensor box moves
// bit for bit as without it, and the sensor lists the ball in exactly the
// steps whose start puts the two solids in touch.
#include <cmath>
#include <vector>

#include "engine_test_support.hpp"

namespace gaphys::testing {
namespace {

class filter_test : public engine_test {
 protected:
  static body_id add_ball(world& w, const vector& position, const shape& s) {
    body_definition ball;
    ball.position = position;
    ball.shape = s;
    return w.create_body(ball);
  }
};

TEST_F(filter_test, two_filters_meet_only_when_each_category_is_in_the_other_mask) {
  const collision_filter a{1, 2}, b{2, 1}, c{2, 2}, none{1, 0};
  EXPECT_TRUE(a.meets(b));
  EXPECT_TRUE(b.meets(a));
  EXPECT_FALSE(a.meets(c));  // c's mask takes 2, a is 1
  EXPECT_FALSE(c.meets(a));
  EXPECT_TRUE(c.meets(c));
  EXPECT_FALSE(none.meets(collision_filter{}));
  EXPECT_TRUE(collision_filter{}.meets(collision_filter{}));
}

TEST_F(filter_test, a_ball_filtered_from_the_floor_falls_through_it_as_through_nothing) {
  world with_floor = make_world(), without = make_world();
  body_definition floor;
  floor.is_static = true;
  floor.shape = shape::plane(vector{0, 0, 1}, 0).with_filter(2, 0xffffffff);
  with_floor.create_body(floor);
  const shape ball = shape::sphere(0.5).with_filter(1, ~std::uint32_t{2});  // meets all but 2
  const body_id in_with = add_ball(with_floor, vector{0, 0, 1}, ball);
  const body_id in_without = add_ball(without, vector{0, 0, 1}, ball);
  for (int i = 0; i < 240; ++i) {
    with_floor.step(h);
    without.step(h);
  }
  EXPECT_TRUE(with_floor.contacts().empty());
  EXPECT_EQ(with_floor.at(in_with).position().e3(), without.at(in_without).position().e3());
  EXPECT_LT(with_floor.at(in_with).position().e3(), -2);  // fell 1 s below the floor
  // The same ball meeting the floor's category rests on it.
  world resting = make_world();
  resting.create_body(floor);
  const body_id kept = add_ball(resting, vector{0, 0, 1}, shape::sphere(0.5).with_filter(1, 2));
  for (int i = 0; i < 240; ++i) resting.step(h);
  EXPECT_NEAR(resting.at(kept).position().e3(), 0.5, 1e-3);
}

TEST_F(filter_test, a_sensor_reports_the_ball_falling_through_it_and_never_pushes_it) {
  world sensed = make_world(), plain = make_world();
  const real radius = 0.25, zc = 2, hz = 0.5;
  const body_id ball = add_ball(sensed, vector{0, 0, 5}, shape::sphere(radius));
  add_ball(plain, vector{0, 0, 5}, shape::sphere(radius));
  body_definition trigger;
  trigger.is_static = true;
  trigger.position = vector{0, 0, zc};
  trigger.shape = shape::box(vector{1, 1, hz}).as_sensor();
  const body_id sensor = sensed.create_body(trigger);
  int overlapping_steps = 0;
  for (int i = 0; i < 300; ++i) {
    const real z_start = sensed.at(ball).position().e3();
    sensed.step(h);
    plain.step(h);
    ASSERT_EQ(sensed.at(ball).position().e3(), plain.at(0).position().e3()) << "step " << i;
    ASSERT_TRUE(sensed.contacts().empty());
    // The narrow phase meets the shapes where the step began.
    const bool touching = std::fabs(z_start - zc) <= hz + radius;
    ASSERT_EQ(sensed.sensor_overlaps().size(), touching ? 1u : 0u) << "step " << i;
    if (!touching) continue;
    ++overlapping_steps;
    const sensor_overlap& o = sensed.sensor_overlaps().front();
    EXPECT_EQ(o.sensor, sensor);
    EXPECT_EQ(o.sensor_shape, 0u);
    EXPECT_EQ(o.other, ball);
    EXPECT_EQ(o.other_shape, 0u);
  }
  EXPECT_GT(overlapping_steps, 10);
  // Ray casts pass through the sensor.
  EXPECT_FALSE(sensed.ray_cast(vector{0, 0, 2.4}, vector{0, 0, -1}, 0.3));
}

TEST_F(filter_test, a_sensor_adds_no_mass_and_cannot_be_a_bodys_only_solid) {
  body_definition d;
  d.density = 1000;
  d.shapes = {attached_shape{shape::box(vector{0.5, 0.5, 0.5}), vector{}, rotor{1, 0, 0, 0}},
              attached_shape{shape::sphere(3).as_sensor(), vector{4, 0, 0}, rotor{1, 0, 0, 0}}};
  const body b(d);
  EXPECT_NEAR(b.mass(), 1000, tolerance(1e-9, 2e-4));
  EXPECT_TRUE(near(b.position(), vector{}, tolerance(1e-15, 1e-7)));  // the centre of mass stays the box's
  EXPECT_NEAR(b.bounding_radius(), 7, tolerance(1e-12, 1e-6));        // the broad phase still bounds the sensor
  body_definition only_sensor;
  only_sensor.shape = shape::sphere(1).as_sensor();
  EXPECT_TRUE(rejects([&] { (void)body(only_sensor); }, "inertia"));
  EXPECT_TRUE(rejects([] { (void)shape::plane(vector{0, 0, 1}, 0).as_sensor(); }, "sensor"));
  EXPECT_TRUE(rejects([] { (void)shape::point().as_sensor(); }, "sensor"));
}

}  // namespace
}  // namespace gaphys::testing
