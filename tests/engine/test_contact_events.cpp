// world::events() against what the contact list and free fall say: a ball
// dropped on a floor begins touching it in the step that free fall puts its
// landing in, keeps touching while it rests (pushing its weight times the
// step), and once it is thrown up its pair ends, with the event of the last
// step it touched in; an elastic ball begins and ends once per bounce.
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "engine_test_support.hpp"

namespace gaphys::testing {
namespace {

class contact_events_test : public engine_test {
 protected:
  // Whether the pair touches in the last step, read from the contact list
  // as contact_events.hpp defines it.
  static bool touching(const world& w, body_id a, body_id b) {
    for (const contact& c : w.contacts()) {
      if (c.body_a == a && c.body_b == b && (c.geometry.depth >= 0 || c.impulse.normal > 0))
        return true;
    }
    return false;
  }
  static int count(const std::vector<contact_event>& events, body_id a, body_id b) {
    int n = 0;
    for (const contact_event& e : events) n += e.body_a == a && e.body_b == b;
    return n;
  }
};

TEST_F(contact_events_test, a_dropped_ball_begins_touching_when_free_fall_lands_it_and_rests) {
  world_settings settings;
  settings.sleeping = false;  // asleep, a pair is silent (test_sleeping.cpp)
  world w(settings);
  const body_id floor = add_floor(w);
  const real radius = 0.5, drop = 1.2;  // falls 1.2 m before touching
  const body_id ball = add_sphere(w, vector{0, 0, radius + drop}, radius, 2);
  const real landing = std::sqrt(2 * drop / 9.81);  // s
  int began_at = -1;
  bool was_touching = false;
  for (int step = 0; step < 480; ++step) {
    w.step(h);
    const contact_events& e = w.events();
    const bool now = touching(w, floor, ball);
    EXPECT_EQ(count(e.began, floor, ball), now && !was_touching ? 1 : 0) << "step " << step;
    EXPECT_EQ(count(e.persisted, floor, ball), now && was_touching ? 1 : 0) << "step " << step;
    EXPECT_EQ(count(e.ended, floor, ball), !now && was_touching ? 1 : 0) << "step " << step;
    if (count(e.began, floor, ball) == 1 && began_at < 0) began_at = step;
    was_touching = now;
  }
  // The step whose end first reaches the landing time (semi-implicit Euler
  // lands within a step of it).
  ASSERT_GE(began_at, 0);
  EXPECT_NEAR(began_at + 1, landing / h, 1.5);
  // Resting: the floor pushes the ball's weight over the step, along +z.
  const contact_events& e = w.events();
  ASSERT_EQ(e.persisted.size(), 1u);
  EXPECT_NEAR(e.persisted[0].impulse, 2 * 9.81 * h, tolerance(1e-9, 1e-5));
  EXPECT_TRUE(
      near(e.persisted[0].normal, vector{0, 0, -1}, tolerance(1e-12, 1e-6)));  // from B (ball) towards A (floor)
  EXPECT_NEAR(z(e.persisted[0].point), 0, 1e-3);

  // Thrown up: the pair, still overlapping by the slop as the next step
  // begins, touches in it and ends in the one after, carrying the event of
  // the last step it touched in.
  w.at(ball).set_velocity(vector{0, 0, 5});
  w.step(h);
  ASSERT_EQ(w.events().persisted.size(), 1u);
  const contact_event last = w.events().persisted[0];
  w.step(h);
  ASSERT_EQ(w.events().ended.size(), 1u);
  EXPECT_EQ(w.events().ended[0].body_b, ball);
  EXPECT_EQ(w.events().ended[0].impulse, last.impulse);
  EXPECT_TRUE(near(w.events().ended[0].point, last.point, 0));
  EXPECT_TRUE(w.events().began.empty());
  EXPECT_TRUE(w.events().persisted.empty());
}

// A landing's impulse falls partly in the step it begins, partly in the
// next, depending on where in the step the ball arrives (from 0.50 m 88% in
// the first, from 0.51 m 11%); its approach speed is the speed the ball
// fell at as the step began: sqrt(2 g H) to within two steps of free fall,
// wherever it lands. Resting, the pair does not approach.
TEST_F(contact_events_test, a_landing_begins_with_the_speed_it_lands_at) {
  real smallest_share = 1, largest_share = 0;
  for (int drop_cm = 50; drop_cm <= 110; drop_cm += 3) {
    world_settings settings;
    settings.sleeping = false;
    world w(settings);
    const body_id floor = add_floor(w);
    const real radius = real(0.1), drop = real(drop_cm) / 100;
    const body_id ball = add_sphere(w, vector{0, 0, radius + drop}, radius, 2);
    const real landing_speed = std::sqrt(2 * real(9.81) * drop);
    bool began = false;
    for (int step = 0; step < 240; ++step) {
      w.step(h);
      const contact_events& e = w.events();
      if (!began && count(e.began, floor, ball) == 1) {
        began = true;
        // (Within two steps' fall: the step it begins in may start up to a
        // step before the landing, and semi-implicit Euler falls half a step
        // ahead of free fall.)
        EXPECT_NEAR(e.began[0].approach_speed, landing_speed, 2 * 9.81 * h) << drop_cm << " cm";
        // 2 kg stopped from the landing speed: its share in this step.
        const real share = e.began[0].impulse / (2 * landing_speed);
        smallest_share = std::min(smallest_share, share);
        largest_share = std::max(largest_share, share);
      }
    }
    ASSERT_TRUE(began) << drop_cm << " cm";
    ASSERT_EQ(w.events().persisted.size(), 1u);
    EXPECT_NEAR(w.events().persisted[0].approach_speed, 0, 9.81 * h) << drop_cm << " cm";
  }
  // (Why the impulse alone does not tell a landing's speed.)
  EXPECT_LT(smallest_share, 0.3);
  EXPECT_GT(largest_share, 0.7);
}

TEST_F(contact_events_test, an_elastic_ball_begins_and_ends_once_per_bounce) {
  world w = make_world();
  const body_id floor = add_floor(w, 0, 1);
  const body_id ball = add_sphere(w, vector{0, 0, 1.5}, 0.5, 1, vector{}, 1);
  int began = 0, ended = 0;
  simulate(w, 3 * 240, [&](int) {
    began += count(w.events().began, floor, ball);
    ended += count(w.events().ended, floor, ball);
  });
  // Falling 1 m takes 0.4515 s; a bounce period is twice that: 3 s hold
  // bounces at 0.45, 1.35, 2.26 s (and the pair is apart between them).
  EXPECT_EQ(began, 3);
  EXPECT_GE(ended, began - 1);
  EXPECT_LE(ended, began);
}

TEST_F(contact_events_test, events_are_sorted_by_pair_and_a_copied_world_keeps_them) {
  world w = make_world();
  add_floor(w);
  for (int i = 0; i < 5; ++i) add_sphere(w, vector{real(2 * i), 0, real(0.5)}, 0.5);
  w.step(h);
  const std::vector<contact_event>& began = w.events().began;
  ASSERT_EQ(began.size(), 5u);
  for (std::size_t i = 1; i < began.size(); ++i) {
    EXPECT_LT(std::make_pair(began[i - 1].body_a, began[i - 1].body_b),
              std::make_pair(began[i].body_a, began[i].body_b));
  }
  const world copy = w;
  EXPECT_EQ(copy.events().began.size(), 5u);
}

// The events are found when first read after a step (world::events()):
// read late, after whatever changes a world between steps, they are those
// an identical world read at once. Both worlds step alike; one reads its
// events after every step, the other every seventh step, in each step an
// island falls asleep in (its pairs persist in that step), and after
// removing and adding bodies, waking every island, copying itself and
// going through a snapshot.
TEST_F(contact_events_test, events_read_late_are_those_read_at_once) {
  const auto make = [&] {
    world_settings settings;
    settings.time_to_sleep = real(0.3);
    world w(settings);
    add_floor(w, 0, real(0.5));
    for (int i = 0; i < 6; ++i) add_sphere(w, vector{real(i), 0, real(0.5)}, real(0.5));
    for (int i = 0; i < 4; ++i) {
      add_sphere(w, vector{real(i) + real(0.5), 0, real(2 + i)}, real(0.5), 1, vector{}, real(0.5));
    }
    return w;
  };
  const auto same = [](const contact_events& x, const contact_events& y, int step) {
    const auto lists = [](const contact_events& e) {
      return std::array<const std::vector<contact_event>*, 3>{&e.began, &e.persisted, &e.ended};
    };
    for (std::size_t l = 0; l < 3; ++l) {
      const std::vector<contact_event>& a = *lists(x)[l];
      const std::vector<contact_event>& b = *lists(y)[l];
      ASSERT_EQ(a.size(), b.size()) << "list " << l << ", step " << step;
      for (std::size_t k = 0; k < a.size(); ++k) {
        EXPECT_EQ(a[k].body_a, b[k].body_a);
        EXPECT_EQ(a[k].body_b, b[k].body_b);
        for (int c = 0; c < 3; ++c) {
          EXPECT_EQ(a[k].point.c[c], b[k].point.c[c]);
          EXPECT_EQ(a[k].normal.c[c], b[k].normal.c[c]);
        }
        EXPECT_EQ(a[k].impulse, b[k].impulse);
        EXPECT_EQ(a[k].approach_speed, b[k].approach_speed);
      }
    }
  };
  const auto sleepers = [](const world& w) {
    return std::count_if(w.bodies().begin(), w.bodies().end(),
                         [](const body& b) { return b.is_sleeping(); });
  };
  world at_once = make(), late = make();
  int fell_asleep = 0, seen = 0;
  for (int step = 0; step < 600; ++step) {
    const auto asleep_before = sleepers(late);
    at_once.step(h);
    late.step(h);
    const contact_events expected = at_once.events();
    seen += !expected.began.empty() + !expected.persisted.empty() + !expected.ended.empty();
    const bool fell = sleepers(late) > asleep_before;
    fell_asleep += fell;
    if (fell || step % 7 == 0) same(expected, late.events(), step);
    if (fell) {
      // The pairs of the bodies that fell asleep persist (or begin) in this
      // step, then fall silent (engine.md, "Contact events").
      for (const contact& c : late.contacts()) {
        if (!late.bodies()[c.body_a].is_sleeping() && !late.bodies()[c.body_b].is_sleeping())
          continue;
        if (!(c.geometry.depth >= 0 || c.impulse.normal > 0)) continue;
        const body_id a = late.id_of(c.body_a), b = late.id_of(c.body_b);
        EXPECT_EQ(count(late.events().persisted, a, b) + count(late.events().began, a, b), 1)
            << "step " << step;
      }
    }
    if (step == 100) {  // a resting ball goes: the indices after it move down
      at_once.remove_body(at_once.id_of(2));
      late.remove_body(late.id_of(2));
      same(at_once.events(), late.events(), step);
    }
    if (step == 101) {
      add_sphere(at_once, vector{10, 0, real(0.5)}, real(0.5));
      add_sphere(late, vector{10, 0, real(0.5)}, real(0.5));
    }
    if (step == 102) {
      const world copy = late;
      same(expected, copy.events(), step);
    }
    if (step == 103) {
      world restored;
      restored.restore_snapshot(late.save_snapshot());
      same(expected, restored.events(), step);
    }
    if (step == 400) {  // every island wakes: their contacts rejoin the awake ones
      ASSERT_GT(sleepers(late), 0);
      at_once.set_sleeping(false);
      late.set_sleeping(false);
      at_once.set_sleeping(true);
      late.set_sleeping(true);
      same(expected, late.events(), step);
    }
    ASSERT_EQ(at_once.state_hash(), late.state_hash()) << "step " << step;
  }
  same(at_once.events(), late.events(), 600);
  EXPECT_GE(fell_asleep, 2) << "islands fell asleep in the run";
  EXPECT_GT(seen, 100) << "steps with events";
}

}  // namespace
}  // namespace gaphys::testing
