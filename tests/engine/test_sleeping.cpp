// Sleeping and islands: a resting island falls asleep after time_to_sleep
// and then stands exactly still at no cost; contacts with awake bodies,
// forces, impulses, setters, removals and a new gravity wake it, with its
// warm start intact; sleeping can be switched off.
#include <limits>
#include <utility>

#include "box_helpers.hpp"
#include "engine_test_support.hpp"

namespace gaphys::testing {
namespace {

class sleeping_test : public engine_test {
 protected:
  // A floor and a box resting on it (set down 1 mm above, to settle).
  world resting_box(body_id& box, const world_settings& settings = {}) {
    world w(settings);
    add_floor(w);
    box = add_box(w, vector{0, 0, 0.501}, vector{0.5, 0.5, 0.5});
    return w;
  }

  // Two unit boxes stacked on the floor at z = 0 (set down just above it,
  // to settle): {bottom, top}.
  static std::pair<body_id, body_id> two_boxes(world& w) {
    const body_id bottom = add_box(w, vector{0, 0, 0.5005}, vector{0.5, 0.5, 0.5});
    return {bottom, add_box(w, vector{0, 0, 1.501}, vector{0.5, 0.5, 0.5})};
  }

  // Steps until every dynamic body sleeps; fails after `most` steps.
  static ::testing::AssertionResult sleep(world& w, int most = 480) {
    for (int i = 0; i < most; ++i) {
      w.step(h);
      bool all = true;
      for (const body& b : w.bodies()) all = all && (!b.is_dynamic() || b.is_sleeping());
      if (all) return ::testing::AssertionSuccess();
    }
    return ::testing::AssertionFailure() << "still awake after " << most << " steps";
  }
};

TEST_F(sleeping_test, a_resting_box_sleeps_and_then_stands_exactly_still_with_its_contacts) {
  body_id box;
  world w = resting_box(box);
  ASSERT_TRUE(sleep(w));
  const body& b = w.at(box);
  EXPECT_EQ(length(b.velocity()), 0);
  EXPECT_EQ(length(b.angular_velocity()), 0);
  const vector position = b.position();
  const rotor attitude = b.attitude();
  const std::size_t contacts = w.contacts().size();
  EXPECT_EQ(contacts, 4u) << "the resting face's corners";
  simulate(w, 240);
  const body& later = w.at(box);
  EXPECT_TRUE(later.is_sleeping());
  for (int k = 0; k < 3; ++k) EXPECT_EQ(later.position().c[k], position.c[k]);
  for (int k = 0; k < 4; ++k) EXPECT_EQ(later.attitude().c[k], attitude.c[k]);
  EXPECT_EQ(w.contacts().size(), contacts) << "a sleeping island keeps its contacts";
  EXPECT_EQ(w.last_step_timings().candidate_pairs, 0u) << "nothing awake: no pair to meet";
  // A sleeping pair is silent: neither persisted nor ended.
  EXPECT_TRUE(w.events().began.empty());
  EXPECT_TRUE(w.events().persisted.empty());
  EXPECT_TRUE(w.events().ended.empty());
}

TEST_F(sleeping_test, it_takes_time_to_sleep_of_stillness) {
  world_settings settings;
  settings.time_to_sleep = 1;
  body_id box;
  world w = resting_box(box, settings);
  // It settles within a few steps and is then still for the full second.
  int steps = 0;
  while (!w.at(box).is_sleeping() && steps < 600) w.step(h), ++steps;
  EXPECT_GE(steps, 240);
  EXPECT_LT(steps, 300);
}

TEST_F(sleeping_test, switched_off_nothing_sleeps) {
  world_settings settings;
  settings.sleeping = false;
  body_id box;
  world w = resting_box(box, settings);
  simulate(w, 480);
  EXPECT_FALSE(w.at(box).is_sleeping());
  EXPECT_GT(w.last_step_timings().candidate_pairs, 0u);
  // And switching it off wakes a sleeping world.
  body_id other;
  world v = resting_box(other);
  ASSERT_TRUE(sleep(v));
  v.set_sleeping(false);
  EXPECT_FALSE(v.at(other).is_sleeping());
  simulate(v, 240);
  EXPECT_FALSE(v.at(other).is_sleeping());
}

TEST_F(sleeping_test, a_body_that_may_not_sleep_keeps_its_island_awake) {
  world w = make_world();
  add_floor(w);
  const body_id bottom = add_box(w, vector{0, 0, 0.5005}, vector{0.5, 0.5, 0.5});
  body_definition top;
  top.position = vector{0, 0, 1.501};
  top.shape = shape::box(vector{0.5, 0.5, 0.5}).with_restitution(0);
  top.can_sleep = false;
  const body_id upper = w.create_body(top);
  simulate(w, 480);
  EXPECT_FALSE(w.at(upper).is_sleeping());
  EXPECT_FALSE(w.at(bottom).is_sleeping()) << "one island with the body that may not sleep";
  w.at(upper).set_can_sleep(true);
  EXPECT_TRUE(sleep(w));
}

TEST_F(sleeping_test, islands_sleep_apart_and_a_body_pushed_every_step_stays_awake) {
  world w = make_world();
  add_floor(w);
  const body_id quiet = add_box(w, vector{0, 0, 0.501}, vector{0.5, 0.5, 0.5});
  const body_id pushed = add_box(w, vector{5, 0, 0.501}, vector{0.5, 0.5, 0.5});
  simulate(w, 360, [&](int) {
    // Within the friction bound: it never moves, but a force keeps it awake.
    w.at(pushed).apply_force(vector{1, 0, 0});
  });
  EXPECT_TRUE(w.at(quiet).is_sleeping());
  EXPECT_FALSE(w.at(pushed).is_sleeping());
}

TEST_F(sleeping_test, a_falling_body_wakes_the_island_it_lands_on) {
  world w = make_world();
  add_floor(w);
  // (Plain names, not a structured binding: the lambda below captures one.)
  const std::pair<body_id, body_id> stack = two_boxes(w);
  const body_id bottom = stack.first, middle = stack.second;
  ASSERT_TRUE(sleep(w));
  // A ball dropped onto the stack from 0.5 m.
  const body_id ball = add_sphere(w, vector{0.1, 0, 2.5}, 0.25);
  bool woke = false;
  simulate(w, 120, [&](int) { woke = woke || !w.at(bottom).is_sleeping(); });
  EXPECT_TRUE(woke) << "the ball's landing woke the whole island";
  EXPECT_TRUE(sleep(w, 2400)) << "and the three fall asleep together";
  EXPECT_NEAR(z(w.at(ball).position()), 2.25, 5e-3) << "the ball rests on the stack";
  EXPECT_NEAR(z(w.at(middle).position()), 1.5, 2e-3);
}

TEST_F(sleeping_test, forces_impulses_and_setters_wake_the_whole_island) {
  const std::function<void(world&, body_id)> wakers[] = {
      [](world& w, body_id b) {
        w.at(b).apply_force(vector{0, 0, 1});
      },
      [](world& w, body_id b) {
        w.at(b).apply_torque(bivector{0, 0, 0.1});
      },
      [](world& w, body_id b) {
        w.at(b).apply_impulse(vector{0, 0, 0.01}, w.at(b).position());
      },
      [](world& w, body_id b) {
        w.at(b).set_velocity(vector{0.1, 0, 0});
      },
      [](world& w, body_id b) { w.at(b).set_position(w.at(b).position()); },
      [](world& w, body_id b) { w.at(b).wake_up(); },
      [](world& w, body_id) {
        w.set_gravity(vector{0, 0, -9.8});
      },
  };
  for (const auto& wake : wakers) {
    world w = make_world();
    add_floor(w);
    const auto [bottom, top] = two_boxes(w);
    ASSERT_TRUE(sleep(w));
    wake(w, top);
    w.step(h);
    EXPECT_FALSE(w.at(top).is_sleeping());
    EXPECT_FALSE(w.at(bottom).is_sleeping()) << "its island wakes with it";
    EXPECT_GT(w.last_step_timings().candidate_pairs, 0u);
  }
}

TEST_F(sleeping_test, a_woken_stack_resumes_from_its_warm_start_without_sinking) {
  world w = make_world();
  add_floor(w);
  const auto [bottom, top] = two_boxes(w);
  ASSERT_TRUE(sleep(w));
  const real before = z(w.at(top).position());
  real held = 0;  // the contacts' normal impulses per step, when it fell asleep
  for (const contact& c : w.contacts()) held += c.impulse.normal;
  w.at(bottom).wake_up();
  w.step(h);
  real now = 0;
  for (const contact& c : w.contacts()) now += c.impulse.normal;
  // The two boxes weigh 2 g; each step's impulses hold them at once.
  EXPECT_NEAR(now, held, 1e-6 * held);
  EXPECT_NEAR(z(w.at(top).position()), before, 1e-6);
}

TEST_F(sleeping_test, removing_a_support_wakes_what_rested_on_it) {
  world w = make_world();
  const body_id floor = add_floor(w);
  const auto [bottom, top] = two_boxes(w);
  ASSERT_TRUE(sleep(w));
  const real height = z(w.at(top).position());
  w.remove_body(bottom);
  EXPECT_FALSE(w.at(top).is_sleeping());
  simulate(w, 60);
  EXPECT_LT(z(w.at(top).position()), height - 0.1) << "it falls";
  // Removing the floor under a sleeping body wakes it too.
  ASSERT_TRUE(sleep(w, 2400));
  w.remove_body(floor);
  EXPECT_FALSE(w.at(top).is_sleeping());
}

// A box asleep on a static or kinematic slab wakes when the user moves the
// slab with set_position, even where the slab then no longer reaches it:
// lowered by 30 cm it lands on it again (the free fall's discrete drop),
// moved 10 m aside it falls freely. (It once slept on where it was.)
TEST_F(sleeping_test, moving_a_support_with_set_position_wakes_what_rested_on_it) {
  for (const bool kinematic : {false, true}) {
    for (const vector& move : {vector{0, 0, -0.3}, vector{10, 0, 0}}) {
      world w = make_world();
      body_definition slab;
      slab.is_static = !kinematic;
      slab.is_kinematic = kinematic;
      slab.position = vector{0, 0, -0.5};
      slab.shape = shape::box(vector{2, 2, 0.5});
      const body_id support = w.create_body(slab);
      const body_id box = add_box(w, vector{0, 0, 0.501}, vector{0.5, 0.5, 0.5});
      ASSERT_TRUE(sleep(w));
      const real height = z(w.at(box).position());
      w.at(support).set_position(w.at(support).position() + move);
      const std::string what = std::string(kinematic ? "kinematic" : "static") +
                               " slab moved by (" + std::to_string(x(move)) + ", " +
                               std::to_string(z(move)) + ")";
      w.step(h);
      EXPECT_FALSE(w.at(box).is_sleeping()) << what;
      simulate(w, 240);
      if (z(move) < 0) {
        EXPECT_NEAR(z(w.at(box).position()), height + z(move), 2e-3)
            << what << ": lands on it again";
      } else {
        // 241 steps of free fall from rest: x_n = g h^2 n (n + 1) / 2.
        EXPECT_NEAR(z(w.at(box).position()), height - 9.81 * h * h * 241 * 242 / 2,
                    tolerance(1e-6, 1e-5))
            << what;
      }
    }
  }
}

TEST_F(sleeping_test, a_moving_kinematic_body_wakes_what_it_reaches_and_keeps_riders_awake) {
  world w = make_world();
  add_floor(w);
  const body_id box = add_box(w, vector{0, 0, 0.501}, vector{0.5, 0.5, 0.5});
  body_definition pusher;
  pusher.is_kinematic = true;
  pusher.position = vector{-2, 0, 0.5};
  pusher.velocity = vector{1, 0, 0};
  pusher.shape = shape::box(vector{0.25, 0.25, 0.25});
  const body_id kinematic = w.create_body(pusher);
  ASSERT_TRUE(sleep(w));  // the pusher is 1.25 m away and needs 1.25 s
  simulate(w, 480);
  EXPECT_FALSE(w.at(box).is_sleeping());
  EXPECT_GT(x(w.at(box).position()), 0.5) << "pushed along";
  EXPECT_GT(x(w.at(kinematic).position()), 0);
}

TEST_F(sleeping_test, a_static_sensor_keeps_reporting_a_body_asleep_inside_it) {
  world w = make_world();
  add_floor(w);
  body_definition zone;
  zone.is_static = true;
  zone.shape = shape::box(vector{2, 2, 2}).as_sensor();
  const body_id sensor = w.create_body(zone);
  const body_id box = add_box(w, vector{0, 0, 0.501}, vector{0.5, 0.5, 0.5});
  ASSERT_TRUE(sleep(w));
  simulate(w, 10);
  ASSERT_EQ(w.sensor_overlaps().size(), 1u);
  EXPECT_EQ(w.sensor_overlaps()[0].sensor, sensor);
  EXPECT_EQ(w.sensor_overlaps()[0].other, box);
}

TEST_F(sleeping_test, the_state_hash_is_deterministic_through_sleep_and_waking) {
  const auto run = [this] {
    world w = make_world();
    add_floor(w);
    for (int i = 0; i < 3; ++i)
      add_box(w, vector{real(0.1 * i), 0, real(0.5005 + 1.001 * i)}, vector{0.5, 0.5, 0.5});
    std::vector<std::uint64_t> hashes;
    simulate(w, 360, [&](int step) {
      if (step == 240)
        w.at(w.id_of(2)).apply_impulse(vector{0.5, 0, 0}, w.at(w.id_of(2)).position());
      hashes.push_back(w.state_hash());
    });
    return hashes;
  };
  EXPECT_EQ(run(), run());
}

TEST_F(sleeping_test, settings_out_of_range_are_rejected) {
  for (auto [field, what] : {std::pair{&world_settings::sleep_linear_speed, "sleep linear speed"},
                             std::pair{&world_settings::sleep_angular_speed, "sleep angular speed"},
                             std::pair{&world_settings::time_to_sleep, "time to sleep"}}) {
    for (real bad : {real(-1), std::numeric_limits<real>::quiet_NaN()}) {
      world_settings settings;
      settings.*field = bad;
      EXPECT_TRUE(rejects([&] { world w(settings); }, what));
    }
  }
}

}  // namespace
}  // namespace gaphys::testing
