// The uniform grid against all pairs, the thesis's broad phase: on random
// scenes (mixed radii, large spheres, points, static spheres, tilted planes)
// the grid's candidates include every pair that touches (its contacts are
// those of every two bodies met), both give the same candidates and
// contacts in the same order, and whole simulations agree to the bit.
#include <cstring>
#include <limits>
#include <vector>

#include "engine_test_support.hpp"

namespace gaphys::testing {
namespace {

class broad_phase_test : public engine_test {
 protected:
  // A random scene's bodies, as the space sees them.
  std::vector<body> random_scene(int spheres, real extent) {
    std::vector<body> bodies;
    const auto add = [&](const body_definition& d) { bodies.emplace_back(d); };
    for (int i = 0; i < 3; ++i) {  // tilted planes through the scene
      body_definition plane;
      plane.is_static = true;
      plane.position = vector{uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)};
      plane.attitude = e3ga::exp(bivector{uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)});
      plane.shape = shape::plane(random_unit_vector(), uniform(-extent, extent) / 2);
      add(plane);
    }
    for (int i = 0; i < spheres; ++i) {
      body_definition d;
      d.position =
          vector{uniform(-extent, extent), uniform(-extent, extent), uniform(-extent, extent)};
      const real pick = uniform(0, 1);
      if (pick < 0.05) {
        d.shape = shape::sphere(uniform(1, 3));  // large: far wider than the median
      } else if (pick < 0.15) {
        d.shape = shape::point();
        d.inertia = inertia::principal(1, 1, 1);
      } else {
        d.shape = shape::sphere(uniform(0.05, 0.4));
      }
      d.is_static = uniform(0, 1) < 0.1 && d.shape->kind() == shape_kind::sphere;
      add(d);
    }
    return bodies;
  }

  static std::vector<contact> contacts_of(space& s, const std::vector<body>& bodies,
                                          std::vector<body_pair>& pairs) {
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      if (bodies[i].shape()) s.add(i);
    }
    std::vector<contact> contacts;
    s.candidate_pairs(bodies, pairs);
    s.find_contacts(bodies, pairs, contacts);
    return contacts;
  }

  static bool same_bits(const contact& a, const contact& b) {
    return a.body_a == b.body_a && a.body_b == b.body_b &&
           std::memcmp(&a.geometry, &b.geometry, sizeof(contact_geometry)) == 0;
  }
};

TEST_F(broad_phase_test, the_grid_finds_exactly_the_contacts_of_all_pairs) {
  for (int trial = 0; trial < 20; ++trial) {
    const int spheres = 20 + 20 * trial;
    const std::vector<body> bodies = random_scene(spheres, 1 + trial * real(0.15));
    space grid(broad_phase_kind::uniform_grid), all(broad_phase_kind::all_pairs);
    std::vector<body_pair> grid_pairs, all_pairs;
    const std::vector<contact> from_grid = contacts_of(grid, bodies, grid_pairs);
    const std::vector<contact> from_all = contacts_of(all, bodies, all_pairs);
    // Every two bodies that may meet, untested: the contacts the grid's
    // candidates must all make.
    std::vector<body_pair> every_pair;
    for (std::size_t a = 0; a < bodies.size(); ++a) {
      for (std::size_t b = a + 1; b < bodies.size(); ++b) {
        if (!bodies[a].shape() || !bodies[b].shape()) continue;
        if (detail::may_meet(detail::motion_of(bodies[a]), detail::motion_of(bodies[b]))) {
          every_pair.emplace_back(a, b);
        }
      }
    }
    std::vector<contact> from_every;
    all.find_contacts(bodies, every_pair, from_every);
    const std::vector<contact>* others[] = {&from_all, &from_every};
    for (const std::vector<contact>* other : others) {
      ASSERT_EQ(from_grid.size(), other->size()) << "trial " << trial;
      for (std::size_t i = 0; i < other->size(); ++i) {
        ASSERT_TRUE(same_bits(from_grid[i], (*other)[i]))
            << "trial " << trial << ": contact " << i << " between " << (*other)[i].body_a
            << " and " << (*other)[i].body_b;
      }
    }
    EXPECT_GT(from_all.size(), 0u);
    // Both hand the narrow phase the same candidates (all pairs tests each
    // pair as the grid tests its cells'), far fewer than all pairs of
    // bodies once scenes grow.
    EXPECT_TRUE(grid_pairs == all_pairs) << "trial " << trial;
    if (spheres >= 300) {
      const std::size_t every_pair = std::size_t(spheres) * std::size_t(spheres - 1) / 2;
      EXPECT_LT(grid_pairs.size() * 4, every_pair) << "trial " << trial;
    }
  }
}

// Above a few thousand bounds the grid pairs cells, tests planes and sorts
// each body's pairs on the threads: the candidates are the same, in the
// same order, on any number.
TEST_F(broad_phase_test, the_grid_finds_the_same_pairs_on_any_number_of_threads) {
  std::vector<body> bodies = random_scene(9000, 6);
  std::vector<body_pair> one_thread;
  for (const int threads : {1, 2, 8}) {
    space grid(broad_phase_kind::uniform_grid);
    for (std::size_t i = 0; i < bodies.size(); ++i) grid.add(i);
    std::vector<body_pair> pairs;
    grid.candidate_pairs(bodies, pairs, real(1) / 240, real(0.001), threads);
    if (threads == 1) {
      one_thread = pairs;
      EXPECT_GT(pairs.size(), bodies.size());
      continue;
    }
    EXPECT_TRUE(pairs == one_thread) << threads << " threads";
  }
  // Asked for two threads inside an application's own parallel region
  // (where OpenMP gives a nested region one thread): the same pairs.
  std::vector<body_pair> nested;
#pragma omp parallel num_threads(2)
#pragma omp single
  {
    space grid(broad_phase_kind::uniform_grid);
    for (std::size_t i = 0; i < bodies.size(); ++i) grid.add(i);
    grid.candidate_pairs(bodies, nested, real(1) / 240, real(0.001), 2);
  }
  EXPECT_TRUE(nested == one_thread);
  // And from kept candidates (uniform_grid.hpp), checked and tested on the
  // threads: the bodies nudged within the skin.
  std::vector<std::size_t> shaped(bodies.size());
  for (std::size_t i = 0; i < bodies.size(); ++i) shaped[i] = i;
  detail::uniform_grid grids[3];
  const int thread_counts[] = {1, 2, 8};
  for (int call = 0; call < 3; ++call) {
    std::vector<body_pair> first;
    for (int g = 0; g < 3; ++g) {
      std::vector<body_pair> pairs;
      ASSERT_TRUE(
          grids[g].find_pairs(bodies, shaped, real(1) / 240, real(0.001), pairs, thread_counts[g]));
      EXPECT_EQ(grids[g].used_kept_pairs(), call > 0);
      if (g == 0) first = pairs;
      EXPECT_TRUE(pairs == first) << thread_counts[g] << " threads, call " << call;
    }
    for (std::size_t i = 3; i < bodies.size(); ++i) {
      if (!bodies[i].is_static()) {
        bodies[i].set_position(bodies[i].position() + real(0.002) * random_unit_vector());
      }
    }
  }
}

// Kept candidates (uniform_grid.hpp): the grid keeps the pairs of bounds
// grown by a skin, and while every bound stays within its skin it tests
// only those. Bodies nudged call after call, some drifting steadily, one
// now and then jumping far or speeding up, a static sphere moved and a
// plane turned: each call's
// pairs are all pairs', and most calls use the kept pairs. Then every body
// jumps at every call (lists that last a call: the grid pairs its cells
// again): still all pairs' pairs.
TEST_F(broad_phase_test, kept_candidates_give_the_pairs_of_all_pairs_as_bodies_move) {
  std::vector<body> bodies = random_scene(1000, real(1.5));
  std::vector<std::size_t> shaped(bodies.size());
  for (std::size_t i = 0; i < bodies.size(); ++i) shaped[i] = i;
  space all(broad_phase_kind::all_pairs);
  for (std::size_t i = 0; i < bodies.size(); ++i) all.add(i);
  detail::uniform_grid grid;
  const real lookahead = real(1) / 60, margin = real(0.001);
  const auto nudge_all = [&](real distance) {
    for (std::size_t i = 3; i < bodies.size(); ++i) {
      body& b = bodies[i];
      if (!b.is_static()) b.set_position(b.position() + distance * random_unit_vector());
    }
  };
  const vector drift[] = {{real(0.043), 0, 0}, {0, real(-0.037), 0}, {0, 0, real(0.051)}};
  int kept_calls = 0;
  for (int call = 0; call < 88; ++call) {
    std::vector<body_pair> expected, pairs;
    all.candidate_pairs(bodies, expected, lookahead, margin);
    ASSERT_TRUE(grid.find_pairs(bodies, shaped, lookahead, margin, pairs));
    ASSERT_TRUE(pairs == expected) << "call " << call;
    if (call >= 72) {
      if (call >= 76) {
        EXPECT_FALSE(grid.used_kept_pairs()) << "call " << call;
      }
      nudge_all(real(0.5));
      continue;
    }
    nudge_all(real(0.003));
    if (call >= 48) {  // some drifting steadily out of their skins
      for (std::size_t i = 3; i < 40; ++i) {
        if (!bodies[i].is_static()) bodies[i].set_position(bodies[i].position() + drift[i % 3]);
      }
      continue;
    }
    kept_calls += grid.used_kept_pairs();
    const std::size_t some = 3 + static_cast<std::size_t>(uniform(0, real(bodies.size() - 4)));
    if (call % 8 == 3 && !bodies[some].is_static()) {  // far beyond the skin
      bodies[some].set_position(bodies[some].position() + real(0.5) * random_unit_vector());
    }
    if (call % 8 == 5 && !bodies[some].is_static()) {  // a bound grown by h |v|
      bodies[some].set_velocity(real(30) * random_unit_vector());
    }
    if (call == 24) {  // a static sphere moved: now a mover (detail::motion_of)
      for (body& b : bodies) {
        if (b.is_static() && b.shape()->kind() == shape_kind::sphere) {
          b.set_position(b.position() + vector{real(0.01), 0, 0});
          break;
        }
      }
    }
    if (call == 40) {
      bodies[0].set_attitude(e3ga::exp(bivector{real(0.01), 0, 0}) * bodies[0].attitude());
    }
  }
  EXPECT_GT(kept_calls, 28);
}

TEST_F(broad_phase_test, touching_spheres_on_cell_boundaries_are_found) {
  // Spheres of one size in a row, each just touching the next (1e-9 m
  // overlap), so centres sit on cell boundaries (cells are one diameter).
  std::vector<body> bodies;
  const real r = 0.25;
  for (int i = 0; i < 40; ++i) {
    body_definition d;
    d.position = vector{i * (2 * r - real(1e-9)), 0, 0};
    d.shape = shape::sphere(r);
    bodies.emplace_back(d);
  }
  space grid(broad_phase_kind::uniform_grid), all(broad_phase_kind::all_pairs);
  std::vector<body_pair> grid_pairs, all_pairs;
  const auto from_grid = contacts_of(grid, bodies, grid_pairs);
  const auto from_all = contacts_of(all, bodies, all_pairs);
  EXPECT_EQ(from_all.size(), 39u);
  ASSERT_EQ(from_grid.size(), from_all.size());
  for (std::size_t i = 0; i < from_all.size(); ++i)
    EXPECT_TRUE(same_bits(from_grid[i], from_all[i]));
}

TEST_F(broad_phase_test, coincident_and_far_away_bodies_are_handled) {
  std::vector<body> bodies;
  body_definition d;
  d.shape = shape::sphere(0.5);
  for (int i = 0; i < 10; ++i) bodies.emplace_back(d);  // all at the origin
  // (Near the largest real: 1e300 in double, 1e30 in float.)
  const real far_away = std::numeric_limits<real>::max() > 1e300 ? real(1e300) : real(1e30);
  d.position = vector{far_away, 0, 0};  // beyond integer cells: the grid defers to all pairs
  bodies.emplace_back(d);
  d.position = vector{far_away, 0, 0.5};
  bodies.emplace_back(d);
  space grid(broad_phase_kind::uniform_grid), all(broad_phase_kind::all_pairs);
  std::vector<body_pair> grid_pairs, all_pairs;
  const auto from_grid = contacts_of(grid, bodies, grid_pairs);
  const auto from_all = contacts_of(all, bodies, all_pairs);
  ASSERT_EQ(from_grid.size(), from_all.size());
  // Every two of the ten coincident spheres, and the far pair: its meet is
  // computed at the pair (detail::meet_origin), where the conformal
  // embedding's |x|^2 / 2 would overflow in the world frame. The same with
  // either broad phase.
  ASSERT_EQ(from_all.size(), 46u);
  for (std::size_t i = 0; i < from_all.size(); ++i)
    EXPECT_TRUE(same_bits(from_grid[i], from_all[i]));
  const contact& far = from_all.back();
  EXPECT_EQ(far.body_a, 10u);
  EXPECT_EQ(far.body_b, 11u);
  EXPECT_TRUE(near(far.geometry.normal, vector{0, 0, -1}, tolerance(1e-15, 1e-6)));
  EXPECT_NEAR(far.geometry.depth, 0.5, tolerance(1e-15, 1e-6));
  EXPECT_EQ(far.geometry.point.e1(), far_away);
  EXPECT_NEAR(far.geometry.point.e3(), 0.25, tolerance(1e-15, 1e-6));
}

// Whole runs: 100 spheres falling into the box for 1.5 s, with either broad
// phase: every step's state is the same to the bit.
TEST_F(broad_phase_test, simulations_agree_to_the_bit) {
  world grid = scenes::falling_spheres_in_box(100, 11);
  world all = scenes::falling_spheres_in_box(100, 11);
  ASSERT_EQ(grid.settings().broad_phase, broad_phase_kind::uniform_grid);
  all.set_broad_phase(broad_phase_kind::all_pairs);
  for (int i = 0; i < 360; ++i) {
    grid.step(h);
    all.step(h);
    ASSERT_EQ(grid.state_hash(), all.state_hash()) << "step " << i + 1;
    ASSERT_EQ(grid.contacts().size(), all.contacts().size()) << "step " << i + 1;
  }
  EXPECT_GT(grid.contacts().size(), 100u);
}

// Boxes, capsules, hulls and spheres falling into a box of planes: the grid
// bounds each body by a sphere about its centre reaching its shapes, grown by
// its turning and half the contact margin, and a plane reaches a bound within
// the other half: the same contacts as all pairs, to the bit.
TEST_F(broad_phase_test, simulations_of_every_shape_agree_to_the_bit) {
  world grid = scenes::shape_mix(24, 3);
  world all = scenes::shape_mix(24, 3);
  all.set_broad_phase(broad_phase_kind::all_pairs);
  for (int i = 0; i < 480; ++i) {
    grid.step(h);
    all.step(h);
    ASSERT_EQ(grid.state_hash(), all.state_hash()) << "step " << i + 1;
    ASSERT_EQ(grid.contacts().size(), all.contacts().size()) << "step " << i + 1;
  }
  EXPECT_GT(grid.contacts().size(), 24u);
}

// Two turning boxes 10 m apart landing on a floor: all pairs hands the
// narrow phase the pair of boxes as well, which the grid never pairs. Which
// pairs there are says whether a body has a moving body near it (then its
// speculative contacts with the floor are all kept: space.cpp,
// keep_reachable), so all pairs must test each pair as the grid does: it
// had kept a box's unreachable contacts, and stepped differently from step 53.
TEST_F(broad_phase_test, bodies_far_apart_are_paired_by_neither_broad_phase) {
  world grid = make_world();
  world all = make_world();
  all.set_broad_phase(broad_phase_kind::all_pairs);
  for (world* w : {&grid, &all}) {
    add_floor(*w);
    for (int i = 0; i < 2; ++i) {
      body_definition box;
      box.shape = shape::box(vector{real(0.1), real(0.15), real(0.2)});
      box.position = vector{real(10 * i), 0, real(0.5)};
      box.attitude = e3ga::exp(bivector{0, real(-0.15), real(-0.3)});  // tilted
      box.angular_velocity = bivector{3, 0, 0};                        // about z
      w->create_body(box);
    }
  }
  for (int i = 0; i < 240; ++i) {
    grid.step(h);
    all.step(h);
    ASSERT_EQ(grid.state_hash(), all.state_hash()) << "step " << i + 1;
  }
  EXPECT_GT(grid.contacts().size(), 0u);
}

// An upright capsule at rest 0.7 mm above a floor: within the 1 mm contact
// margin, more than the half of it a bound holds. Both broad phases hand the
// pair to the narrow phase, which makes a speculative contact.
TEST_F(broad_phase_test, a_plane_reaches_bounds_within_the_whole_contact_margin) {
  for (broad_phase_kind kind : {broad_phase_kind::uniform_grid, broad_phase_kind::all_pairs}) {
    world w = make_world(vector{});
    w.set_broad_phase(kind);
    add_floor(w);
    body_definition capsule;
    capsule.position = vector{0, 0, real(0.5) + real(0.25) + real(0.0007)};
    capsule.shape = shape::capsule(0.5, 0.25);
    w.create_body(capsule);
    w.step(h);
    ASSERT_EQ(w.contacts().size(), 1u)
        << (kind == broad_phase_kind::all_pairs ? "all pairs" : "grid");
    EXPECT_NEAR(w.contacts()[0].geometry.depth, -0.0007, tolerance(1e-12, 1e-6));
  }
}

}  // namespace
}  // namespace gaphys::testing
