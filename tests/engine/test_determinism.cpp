// Determinism: the same scene stepped the same way reaches bit-identical
// states, and the state hash tells states apart when a single bit differs.
#include <cstring>

#include "engine_test_support.hpp"

namespace gaphys::testing {
namespace {

class determinism_test : public engine_test {};

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

}  // namespace
}  // namespace gaphys::testing
