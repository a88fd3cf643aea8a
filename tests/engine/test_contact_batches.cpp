// The contact sweeps on SIMD batches (world_settings::batch_contacts,
// contact_batch.hpp) against one contact at a time: each lane does what the
// scalar solve does, in the same order, so the states are the same to the
// bit after every step, whatever runs share a batch and on any number of
// threads.
#include <random>

#include "box_helpers.hpp"
#include "contact_batch.hpp"
#include "engine_test_support.hpp"
#include "gaphys/scenes.hpp"
#include "plain_pairs.hpp"

namespace gaphys::testing {
namespace {

class contact_batches_test : public engine_test {
 protected:
  // Puts back the widest plain lanes the sweeps may take (plain_pairs.hpp),
  // which a test lowers.
  struct lanes_restored {
    ~lanes_restored() { detail::widest_plain_lanes_allowed = 8; }
  };
  // Steps `batched` (sweeps on batches) and `scalar` (one by one) `steps`
  // times, which must start alike: their states must be equal after every
  // step, and some step must have had contacts (unless `contacts_needed`
  // is false: a scene of free bodies).
  static ::testing::AssertionResult step_alike(world batched, world scalar, int steps,
                                               int batched_threads = 1,
                                               bool contacts_needed = true) {
    batched.set_batch_contacts(contact_batching::on);
    batched.set_threads(batched_threads);
    scalar.set_batch_contacts(contact_batching::off);
    scalar.set_threads(1);
    std::size_t most_contacts = 0;
    for (int i = 0; i < steps; ++i) {
      batched.step(h);
      scalar.step(h);
      if (batched.state_hash() != scalar.state_hash()) {
        return ::testing::AssertionFailure() << "the states differ after step " << i + 1;
      }
      most_contacts = std::max(most_contacts, batched.contacts().size());
    }
    if (contacts_needed && most_contacts == 0) {
      return ::testing::AssertionFailure() << "no contact to solve";
    }
    return ::testing::AssertionSuccess() << most_contacts << " contacts at most";
  }

  // Boxes, spheres and capsules dropped together into a box: runs of one to
  // four contacts, with friction; every third sphere has rolling resistance
  // and spinning friction (its runs are solved one by one, in the colours
  // that also hold batches), and a kinematic paddle sweeps through the pile
  // (a body the lanes read and never change).
  static world mixed_pile() {
    world_settings settings;
    settings.sleeping = false;
    world w(settings);
    add_floor(w, 0, 0, 0.5);
    std::mt19937_64 random(3);
    std::uniform_real_distribution<real> jitter(-0.2, 0.2);
    for (int i = 0; i < 90; ++i) {
      const vector position{real(0.6) * (i % 6) + jitter(random),
                            real(0.6) * ((i / 6) % 5) + jitter(random),
                            real(0.3) + real(0.45) * (i / 30)};
      const rotor turn = e3ga::exp(bivector{jitter(random), jitter(random), jitter(random)});
      body_definition d;
      d.mass = 1;
      d.position = position;
      d.attitude = turn;
      d.velocity = vector{jitter(random), jitter(random), 0};
      switch (i % 3) {
        case 0:
          d.shape = shape::box(vector{0.2, 0.15, 0.1}).with_friction(0.6);
          break;
        case 1:
          d.shape = shape::capsule(0.12, 0.08).with_friction(0.4).with_restitution(0.3);
          break;
        default:
          d.shape = shape::sphere(0.15)
                        .with_friction(0.5)
                        .with_rolling_resistance(i % 2 == 0 ? real(0.05) : real(0))
                        .with_spinning_friction(i % 2 == 0 ? real(0.02) : real(0));
          break;
      }
      w.create_body(d);
    }
    body_definition paddle;
    paddle.is_kinematic = true;
    paddle.position = vector{-1, 1.2, 0.3};
    paddle.velocity = vector{1, 0, 0};
    paddle.shape.emplace(shape::box(vector{0.1, 2, 0.3}));
    w.create_body(paddle);
    return w;
  }
};

TEST_F(contact_batches_test, boxes_step_to_the_same_bits_on_batches_as_one_by_one) {
  EXPECT_TRUE(step_alike(scenes::falling_boxes_in_box(64), scenes::falling_boxes_in_box(64), 360));
}

TEST_F(contact_batches_test, spheres_with_and_without_friction_step_to_the_same_bits) {
  EXPECT_TRUE(
      step_alike(scenes::falling_spheres_in_box(200), scenes::falling_spheres_in_box(200), 240));
  EXPECT_TRUE(step_alike(scenes::falling_spheres_in_box(200, 1, 0.5),
                         scenes::falling_spheres_in_box(200, 1, 0.5), 240));
}

TEST_F(contact_batches_test, a_mixed_pile_with_resistance_and_a_kinematic_body_steps_alike) {
  EXPECT_TRUE(step_alike(mixed_pile(), mixed_pile(), 300));
}

TEST_F(contact_batches_test, every_catalogued_scene_steps_alike) {
  // Bounces (the impact phase, waiting contacts), stacks, compounds, hulls.
  for (const scenes::entry& e : scenes::catalogue()) {
    EXPECT_TRUE(step_alike(e.build(), e.build(), 240, 1, e.name != "spinning_body")) << e.name;
  }
}

// Frictionless spheres resting on a static body made of spheres (an egg
// crate), each in the hollow between four of its shapes: runs of up to four
// contacts, all plain. One by one in double, the sweeps take plain contacts
// two or four at a time, each beside contacts of other runs
// (plain_pairs.hpp), and a run's contacts one after another; they must end
// where the batches and the scalar solve do.
TEST_F(contact_batches_test, frictionless_spheres_on_a_compound_step_alike_in_lanes) {
  const auto egg_crate = [] {
    world_settings settings;
    settings.sleeping = false;
    world w(settings);
    body_definition crate;
    crate.is_static = true;
    for (int i = 0; i < 12; ++i) {
      for (int j = 0; j < 12; ++j) {
        crate.shapes.push_back(attached_shape{shape::sphere(real(0.3)).with_friction(0),
                                              vector{real(0.6) * i, real(0.6) * j, 0},
                                              rotor{1, 0, 0, 0}});
      }
    }
    w.create_body(crate);
    // (More runs than a colour needs to be solved on its own, not in the
    // sequential group: contact_colouring::fewest_runs.)
    for (int k = 0; k < 121; ++k) {
      body_definition d;
      d.mass = 1;
      d.position = vector{real(0.3) + real(0.6) * (k % 11), real(0.3) + real(0.6) * (k / 11),
                          real(0.7) + real(0.002) * k};
      d.shape = shape::sphere(real(0.25)).with_friction(0);
      w.create_body(d);
    }
    return w;
  };
  // (The scene has what it is for: a ball in a hollow touches the crate at
  // several points.)
  world settled = egg_crate();
  for (int i = 0; i < 240; ++i) settled.step(h);
  std::size_t longest_run = 0, run = 0;
  for (std::size_t i = 0; i < settled.contacts().size(); ++i) {
    const contact& c = settled.contacts()[i];
    const bool same = i > 0 && settled.contacts()[i - 1].body_a == c.body_a &&
                      settled.contacts()[i - 1].body_b == c.body_b;
    run = same ? run + 1 : 1;
    longest_run = std::max(longest_run, run);
  }
  EXPECT_GE(longest_run, 3u);
  // (In eight lanes where the processor has AVX-512, four with AVX, and two.)
  lanes_restored restore;
  for (const int widest : {8, 4, 2}) {
    detail::widest_plain_lanes_allowed = widest;
    EXPECT_TRUE(step_alike(egg_crate(), egg_crate(), 240)) << widest << " lanes";
    EXPECT_TRUE(step_alike(egg_crate(), egg_crate(), 240, 2)) << widest << " lanes";
  }
}

// The plain sweeps eight contacts at a time (AVX-512, where the processor
// has it), four (AVX) and two (SSE2) end with the same bits: stepped in
// turn, each at its width, two worlds stay alike step by step.
TEST_F(contact_batches_test, plain_sweeps_in_every_width_step_alike) {
  lanes_restored restore;
  detail::widest_plain_lanes_allowed = 8;
  const int widest = detail::plain_lanes_here();
  if (!std::is_same_v<real, double> || widest < 4) {
    GTEST_SKIP() << "the plain sweeps take more than two lanes only in double, with AVX";
  }
  const auto alike = [](int wide, world wider, world two, int steps, int threads) {
    wider.set_threads(threads);
    two.set_threads(threads);
    for (int i = 0; i < steps; ++i) {
      detail::widest_plain_lanes_allowed = wide;
      wider.step(h);
      detail::widest_plain_lanes_allowed = 2;
      two.step(h);
      if (wider.state_hash() != two.state_hash()) {
        return ::testing::AssertionFailure()
               << wide << " lanes: the states differ after step " << i + 1;
      }
    }
    return ::testing::AssertionSuccess();
  };
  // (On two threads, the colours' parts on each: 300 spheres make the 512
  // contacts two threads of sweeps take from about step 115 on. On one,
  // the test above steps every width against the batches.)
  for (int wide = 4; wide <= widest; wide *= 2) {
    EXPECT_TRUE(alike(wide, scenes::falling_spheres_in_box(300),
                      scenes::falling_spheres_in_box(300), 200, 2));
  }
}

TEST_F(contact_batches_test, batches_on_two_threads_step_as_one_by_one_on_one) {
  // Each thread batches its own block of every colour: other runs share a
  // batch than on one thread.
  // (400 boxes land in their 140th step and make some 1,700 contacts, a
  // few hundred per thread and colour.)
  EXPECT_TRUE(
      step_alike(scenes::falling_boxes_in_box(400), scenes::falling_boxes_in_box(400), 180, 2));
}

TEST_F(contact_batches_test, automatic_batches_where_a_batch_holds_four_lanes) {
  EXPECT_EQ(world_settings{}.batch_contacts, contact_batching::automatic);
  for (const bool plain : {false, true}) {
    EXPECT_TRUE(detail::batches_take(contact_batching::on, plain));
    EXPECT_FALSE(detail::batches_take(contact_batching::off, plain));
  }
  const bool wide = detail::contact_lanes >= 4;
  EXPECT_EQ(detail::batches_take(contact_batching::automatic, false), wide);
  EXPECT_FALSE(detail::batches_take(contact_batching::automatic, true));
  world w;
  EXPECT_TRUE(
      rejects([&] { w.set_batch_contacts(static_cast<contact_batching>(7)); }, "batch_contacts"));
  EXPECT_EQ(w.settings().batch_contacts, contact_batching::automatic);  // unchanged
  // A machine's setting, not the state's: a restored world keeps its own.
  w.set_batch_contacts(contact_batching::off);
  world other;
  w.restore_snapshot(other.save_snapshot());
  EXPECT_EQ(w.settings().batch_contacts, contact_batching::off);
}

}  // namespace
}  // namespace gaphys::testing
