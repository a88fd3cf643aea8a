// Removing bodies: a removed body's id is dead for good (at() throws, no
// later body gets it), the other ids keep naming their bodies, and a pile
// stepped after a far body's removal is bit for bit the pile that never had
// it (the state hash of the same world built without it).
#include <vector>

#include "engine_test_support.hpp"

namespace gaphys::testing {
namespace {

using remove_body_test = engine_test;

TEST_F(remove_body_test, a_removed_id_is_dead_and_the_others_keep_their_bodies) {
  world w = make_world();
  std::vector<body_id> ids;
  for (int i = 0; i < 5; ++i) ids.push_back(add_sphere(w, vector{real(3 * i), 0, 5}, 0.5));
  for (std::size_t i = 0; i < ids.size(); ++i) EXPECT_EQ(ids[i], i);  // no removal: id = index
  w.remove_body(ids[1]);
  EXPECT_FALSE(w.contains(ids[1]));
  EXPECT_TRUE(rejects([&] { (void)w.at(ids[1]); }, "no body with id"));
  EXPECT_TRUE(rejects([&] { w.remove_body(ids[1]); }, "no body with id"));
  EXPECT_EQ(w.body_count(), 4u);
  for (int i : {0, 2, 3, 4}) EXPECT_EQ(x(w.at(ids[i]).position()), 3 * i);
  // A new body reuses the slot, never the id.
  const body_id again = add_sphere(w, vector{100, 0, 5}, 0.5);
  EXPECT_NE(again, ids[1]);
  EXPECT_TRUE(rejects([&] { (void)w.at(ids[1]); }, "no body with id"));
  EXPECT_EQ(x(w.at(again).position()), 100);
  for (std::size_t index = 0; index < w.body_count(); ++index) {
    EXPECT_EQ(&w.at(w.id_of(index)), &w.bodies()[index]);
  }
  // Queries and events name bodies by id.
  const auto hit = w.ray_cast(vector{100, 0, 10}, vector{0, 0, -1}, 20);
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->body, again);
  EXPECT_EQ(w.overlap_sphere(vector{100, 0, 5}, 0.1), std::vector<body_id>{again});
  EXPECT_TRUE(rejects([&] { (void)w.at(body_id{12345}); }, "no body with id"));
}

TEST_F(remove_body_test, a_pile_steps_on_as_if_the_removed_far_body_had_never_been_there) {
  const auto pile = [](world& w) {
    add_floor(w);
    for (int i = 0; i < 30; ++i) {
      add_sphere(w, vector{real(0.3 * (i % 5)), real(0.3 * (i / 5 % 3)), real(0.5 + 0.6 * i / 15)},
                 0.2);
    }
  };
  world with = make_world(), without = make_world();
  const body_id far = add_sphere(with, vector{500, 0, 5}, 0.7);  // first: the pile's indices shift
  pile(with);
  pile(without);
  for (int i = 0; i < 120; ++i) {
    with.step(h);
    without.step(h);
  }
  with.remove_body(far);
  EXPECT_EQ(with.state_hash(), without.state_hash());
  for (int i = 0; i < 240; ++i) {
    with.step(h);
    without.step(h);
    ASSERT_EQ(with.state_hash(), without.state_hash()) << "step " << i;
  }
  EXPECT_FALSE(with.contacts().empty());
}

TEST_F(remove_body_test, a_removed_resting_body_takes_its_contacts_with_it) {
  world w = make_world();
  const body_id floor = add_floor(w);
  const body_id lower = add_sphere(w, vector{0, 0, 0.5}, 0.5);
  const body_id upper = add_sphere(w, vector{0, 0, 1.5}, 0.5);
  simulate(w, 60);
  ASSERT_EQ(w.contacts().size(), 2u);
  w.remove_body(lower);
  EXPECT_TRUE(w.contacts().empty());  // both of its contacts went with it
  simulate(w, 120);                   // the upper ball falls onto the floor and rests
  ASSERT_EQ(w.contacts().size(), 1u);
  EXPECT_EQ(w.id_of(w.contacts()[0].body_a), floor);
  EXPECT_EQ(w.id_of(w.contacts()[0].body_b), upper);
  EXPECT_NEAR(z(w.at(upper).position()), 0.5, 1e-3);
}

}  // namespace
}  // namespace gaphys::testing
