// Determinism: the same scene stepped the same way reaches bit-identical
// states, and the state hash tells states apart when a single bit differs.
#include <algorithm>
#include <cstring>
#include <random>

#include "box_helpers.hpp"
#include "engine_test_support.hpp"

namespace gaphys::testing {
namespace {

class determinism_test : public engine_test {
 protected:
  // A world on `threads` threads, awake throughout, with a floor of μ 0.5.
  static world world_on(int threads, real floor_restitution) {
    world_settings settings;
    settings.threads = threads;
    settings.sleeping = false;
    world w(settings);
    add_floor(w, 0, floor_restitution, 0.5);
    return w;
  }

  // Two layers of 12 x 12 boxes, turned at random, dropped together on a
  // floor (their corners overlapping from the first step): well over a
  // thousand contacts, enough for the solver and the narrow phase to split
  // their work over 4 threads.
  static world box_pile(int threads) {
    world w = world_on(threads, 0);
    std::mt19937_64 random(11);
    std::uniform_real_distribution<real> angle(-0.3, 0.3);
    for (int layer = 0; layer < 2; ++layer) {
      for (int i = 0; i < 12; ++i) {
        for (int j = 0; j < 12; ++j) {
          const rotor turn = e3ga::exp(bivector{angle(random), angle(random), angle(random)});
          add_box(w, vector{real(0.52) * i, real(0.52) * j, real(0.26) + real(0.53) * layer},
                  vector{0.25, 0.25, 0.25}, turn);
        }
      }
    }
    return w;
  }

  // A 70 x 70 layer of touching balls on a floor, moving a little at
  // random, half of them bouncy: enough bodies, pairs and contacts for
  // every parallel part of a step (the grid, the shapes' placing, the
  // integration, the contact events) to take several threads.
  static world ball_layer(int threads) {
    world w = world_on(threads, 0.5);
    std::mt19937_64 random(5);
    std::uniform_real_distribution<real> speed(-0.5, 0.5);
    for (int i = 0; i < 70; ++i) {
      for (int j = 0; j < 70; ++j) {
        const vector velocity{speed(random), speed(random), speed(random)};
        add_sphere(w, vector{real(0.2) * i, real(0.2) * j, real(0.1)}, real(0.1), 1, velocity,
                   (i + j) % 2 == 0 ? real(0.5) : real(0), 0.5);
      }
    }
    return w;
  }
};

TEST_F(determinism_test, the_same_scene_twice_gives_bit_identical_states) {
  world first = scenes::falling_spheres_in_box(30, 7);
  world second = scenes::falling_spheres_in_box(30, 7);
  ASSERT_EQ(first.state_hash(), second.state_hash());
  for (int i = 0; i < 360; ++i) {
    first.step(h);
    second.step(h);
    ASSERT_EQ(first.state_hash(), second.state_hash()) << "step " << i + 1;
  }
  // Compare the bits directly as well, not only through the hash.
  for (std::size_t id = 0; id < first.body_count(); ++id) {
    EXPECT_EQ(std::memcmp(&first.at(id).position(), &second.at(id).position(), sizeof(vector)), 0);
    EXPECT_EQ(std::memcmp(&first.at(id).attitude(), &second.at(id).attitude(), sizeof(rotor)), 0);
  }
  EXPECT_FALSE(first.contacts().empty());  // the run did collide
}

TEST_F(determinism_test, a_copied_world_continues_identically) {
  world original = scenes::falling_spheres_in_box(20, 3);
  simulate(original, 120);
  world copy = original;
  simulate(original, 120);
  simulate(copy, 120);
  EXPECT_EQ(original.state_hash(), copy.state_hash());
}

// A copy starts a fresh contact solver, which reads the warm start's keys
// from the last step's contacts; a world stepped on keeps them from its
// last solve. Copied before every step, a layer of turned boxes (whose
// manifolds' points are matched by feature, and by distance where the
// features change) goes exactly as the world stepped on, sleeping and
// waking included.
TEST_F(determinism_test, a_world_copied_before_every_step_steps_the_same) {
  world_settings settings;
  settings.time_to_sleep = real(0.2);
  world stepped(settings);
  add_floor(stepped, 0, 0, 0.5);
  std::mt19937_64 random(3);
  std::uniform_real_distribution<real> angle(-0.3, 0.3);
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) {
      const rotor turn = e3ga::exp(bivector{angle(random), angle(random), angle(random)});
      add_box(stepped, vector{real(0.52) * i, real(0.52) * j, real(0.26)}, vector{0.25, 0.25, 0.25},
              turn);
    }
  }
  world copied = stepped;
  const auto sleeping = [](const world& w) {
    return std::count_if(w.bodies().begin(), w.bodies().end(),
                         [](const body& b) { return b.is_sleeping(); });
  };
  bool woken = false;
  for (int i = 0; i < 180; ++i) {
    if (!woken && sleeping(stepped) > 4) {  // the islands asleep by now wake
      stepped.set_sleeping(false), stepped.set_sleeping(true);
      copied.set_sleeping(false), copied.set_sleeping(true);
      woken = true;
    }
    stepped.step(h);
    copied = world(copied);
    copied.step(h);
    ASSERT_EQ(stepped.state_hash(), copied.state_hash()) << "step " << i + 1;
  }
  EXPECT_TRUE(woken);
  EXPECT_GT(sleeping(stepped), 0);
  EXPECT_GT(stepped.contacts().size(), 60u);
}

TEST_F(determinism_test, the_hash_sees_a_one_bit_change) {
  world a = scenes::falling_spheres_in_box(10, 5);
  world b = scenes::falling_spheres_in_box(10, 5);
  const body_id last = b.body_count() - 1;
  const vector p = b.at(last).position();
  b.at(last).set_position(vector{p.e1(), std::nextafter(p.e2(), real(1)), p.e3()});
  EXPECT_NE(a.state_hash(), b.state_hash());
  // Different seeds are different scenes.
  EXPECT_NE(scenes::falling_spheres_in_box(10, 5).state_hash(),
            scenes::falling_spheres_in_box(10, 6).state_hash());
}

TEST_F(determinism_test, every_number_of_threads_steps_to_the_same_bits) {
  // The contact solver's colours and the narrow phase's shares make each
  // thread compute what one thread would: the states are identical after
  // every step, not only close.
  world one = box_pile(1);
  world two = box_pile(2);
  world eight = box_pile(8);
  std::size_t most_contacts = 0;
  for (int i = 0; i < 20; ++i) {
    one.step(h);
    two.step(h);
    eight.step(h);
    ASSERT_EQ(one.state_hash(), two.state_hash()) << "step " << i + 1;
    ASSERT_EQ(one.state_hash(), eight.state_hash()) << "step " << i + 1;
    most_contacts = std::max(most_contacts, one.contacts().size());
  }
  EXPECT_GE(most_contacts, 1024u);  // the parallel paths did run
}

TEST_F(determinism_test, every_part_of_a_large_step_is_the_same_on_any_number_of_threads) {
  world one = ball_layer(1);
  world two = ball_layer(2);
  world eight = ball_layer(8);
  for (int i = 0; i < 5; ++i) {
    one.step(h);
    two.step(h);
    eight.step(h);
    ASSERT_EQ(one.state_hash(), two.state_hash()) << "step " << i + 1;
    ASSERT_EQ(one.state_hash(), eight.state_hash()) << "step " << i + 1;
    // The events too, which the state hash does not see.
    const auto same_events = [](const world& a, const world& b) {
      const contact_events& x = a.events();
      const contact_events& y = b.events();
      const auto same = [](const std::vector<contact_event>& p, const std::vector<contact_event>& q) {
        if (p.size() != q.size()) return false;
        for (std::size_t k = 0; k < p.size(); ++k) {
          if (p[k].body_a != q[k].body_a || p[k].body_b != q[k].body_b ||
              p[k].impulse != q[k].impulse) {
            return false;
          }
        }
        return true;
      };
      return same(x.began, y.began) && same(x.persisted, y.persisted) && same(x.ended, y.ended);
    };
    ASSERT_TRUE(same_events(one, two)) << "step " << i + 1;
    ASSERT_TRUE(same_events(one, eight)) << "step " << i + 1;
  }
  // Enough for the contact events' shares (4,096 contacts in the two lists).
  EXPECT_GE(one.contacts().size(), 4096u);
  EXPECT_FALSE(one.events().persisted.empty());
}

TEST_F(determinism_test, a_world_stepped_inside_an_applications_parallel_region_steps_the_same) {
  // An application stepping its worlds on its own threads: a world set to
  // two threads then gets one from OpenMP in each of its parallel parts.
  world one = ball_layer(1);
  world nested = ball_layer(2);
  for (int i = 0; i < 5; ++i) {
    one.step(h);
#pragma omp parallel num_threads(2)
#pragma omp single
    nested.step(h);
    ASSERT_EQ(one.state_hash(), nested.state_hash()) << "step " << i + 1;
  }
}

TEST_F(determinism_test, threads_are_a_setting_of_the_machine_not_of_the_state) {
  EXPECT_EQ(world_settings{}.threads, 0);  // every core
  world_settings negative;
  negative.threads = -1;
  EXPECT_THROW(world{negative}, invalid_input);
  world w = box_pile(2);
  EXPECT_THROW(w.set_threads(-2), invalid_input);
  EXPECT_EQ(w.settings().threads, 2);
  const std::uint64_t two = w.state_hash();
  w.set_threads(1);
  EXPECT_EQ(w.settings().threads, 1);
  EXPECT_EQ(w.state_hash(), two);
  // A restored world keeps its own threads.
  world restored = box_pile(3);
  restored.restore_snapshot(w.save_snapshot());
  EXPECT_EQ(restored.settings().threads, 3);
  EXPECT_EQ(restored.state_hash(), w.state_hash());
}

}  // namespace
}  // namespace gaphys::testing
