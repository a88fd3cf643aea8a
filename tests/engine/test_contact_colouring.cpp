// The contact solver's colouring (engine/src/contact_colouring.hpp) on
// random piles: every contact once, no moving body twice in a colour, the
// same colours for any number of blocks, and each block's own runs moving
// only bodies that no other block's runs move, which is what lets a thread
// of the sweeps solve them without waiting for the others.
#include <algorithm>
#include <cstddef>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "contact_colouring.hpp"
#include "engine_test_support.hpp"

namespace gaphys::testing {
namespace {

using part = detail::contact_colouring::part;

// Bodies on a jittered lattice, `walls` of them static and touching the
// bottom layer (as a floor does), each pair of neighbours touching at one
// to three points: contacts sorted by body pair, as the narrow phase
// makes them.
struct pile {
  std::vector<vector> positions;
  std::vector<char> moves;
  std::vector<std::pair<std::size_t, std::size_t>> pairs;  // per contact
};

pile random_pile(unsigned seed, int side, int layers, std::size_t walls) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<real> jitter(-0.2, 0.2);
  std::uniform_int_distribution<int> points(1, 3);
  pile p;
  for (std::size_t w = 0; w < walls; ++w) {
    p.positions.push_back(vector{jitter(random), jitter(random), -1});
    p.moves.push_back(0);
  }
  for (int z = 0; z < layers; ++z) {
    for (int y = 0; y < side; ++y) {
      for (int x = 0; x < side; ++x) {
        p.positions.push_back(vector{x + jitter(random), y + jitter(random), z + jitter(random)});
        p.moves.push_back(1);
      }
    }
  }
  const std::size_t bodies = p.positions.size();
  for (std::size_t a = 0; a < bodies; ++a) {
    for (std::size_t b = a + 1; b < bodies; ++b) {
      const vector d = p.positions[b] - p.positions[a];
      const bool on_floor = !p.moves[a] && p.moves[b] && p.positions[b].e3() < 0.5;
      const bool near = p.moves[a] && e3ga::scp(d, d) < real(1.3 * 1.3);
      if (!on_floor && !near) continue;
      for (int k = points(random); k > 0; --k) p.pairs.push_back({a, b});
    }
  }
  return p;
}

detail::contact_colouring colour(const pile& p, int blocks) {
  detail::contact_colouring out;
  out.pairs = p.pairs;
  out.moves = p.moves;
  detail::colour_contacts(p.positions, out, 1, blocks);
  return out;
}

// Each contact's colour (colours(): the sequential group).
std::vector<std::size_t> colours_of(const detail::contact_colouring& c) {
  std::vector<std::size_t> of(c.order.size());
  for (std::size_t colour = 0; colour < c.colour_starts.size(); ++colour) {
    const std::size_t end_run = colour + 1 < c.colour_starts.size() ? c.colour_starts[colour + 1]
                                                                     : c.runs();
    for (std::size_t s = c.run_starts[c.colour_starts[colour]]; s < c.run_starts[end_run]; ++s) {
      of[c.order[s]] = colour;
    }
  }
  return of;
}

TEST(contact_colouring_test, blocks_keep_the_colours_and_own_runs_move_only_their_blocks_bodies) {
  for (const unsigned seed : {1u, 2u, 3u}) {
    const pile p = random_pile(seed, 14, 6, 3);
    const detail::contact_colouring single = colour(p, 1);
    const std::vector<std::size_t> colours = colours_of(single);
    ASSERT_GE(single.colours(), 4u);
    for (const int blocks : {1, 2, 3, 8}) {
      SCOPED_TRACE(::testing::Message() << "seed " << seed << ", " << blocks << " blocks");
      const detail::contact_colouring c = colour(p, blocks);
      // Every contact once, each run's contacts together and in contact order.
      ASSERT_EQ(c.order.size(), p.pairs.size());
      std::vector<char> seen(p.pairs.size(), 0);
      for (std::size_t run = 0; run < c.runs(); ++run) {
        for (std::size_t s = c.run_starts[run]; s < c.run_starts[run + 1]; ++s) {
          const std::size_t i = c.order[s];
          ASSERT_FALSE(seen[i]);
          seen[i] = 1;
          EXPECT_EQ(p.pairs[i], p.pairs[c.order[c.run_starts[run]]]);
          if (s > c.run_starts[run]) {
            EXPECT_EQ(i, c.order[s - 1] + 1);
          }
        }
      }
      // The same colours as on one block: only the order within a colour changes.
      EXPECT_EQ(colours_of(c), colours);
      // Each colour's blocks, shared runs then own runs, tile it; no moving
      // body is in two runs of a colour; and the blocks moving each body.
      const auto bs = static_cast<std::size_t>(blocks);
      std::vector<std::set<std::size_t>> moved_by(p.positions.size());
      std::size_t shared = 0, coloured = 0;
      for (std::size_t colour = 0; colour < c.colours(); ++colour) {
        std::size_t next = c.colour_starts[colour];
        std::vector<char> taken(p.positions.size(), 0);
        for (std::size_t block = 0; block < bs; ++block) {
          for (const part which : {part::shared_runs, part::own_runs}) {
            const auto [first, end] = c.runs_of(colour, block, bs, which);
            ASSERT_EQ(first, next);
            next = end;
            if (which == part::shared_runs) shared += end - first;
            coloured += end - first;
            for (std::size_t run = first; run < end; ++run) {
              const auto [a, b] = p.pairs[c.order[c.run_starts[run]]];
              for (const std::size_t x : {a, b}) {
                if (!p.moves[x]) continue;
                EXPECT_FALSE(taken[x]) << "body " << x << " twice in colour " << colour;
                taken[x] = 1;
                moved_by[x].insert(block);
              }
            }
          }
        }
        ASSERT_EQ(next, c.colour_starts[colour + 1]);
      }
      // A block's own runs move no body that another block's runs move.
      for (std::size_t colour = 0; colour < c.colours(); ++colour) {
        for (std::size_t block = 0; block < bs; ++block) {
          const auto [first, end] = c.runs_of(colour, block, bs, part::own_runs);
          for (std::size_t run = first; run < end; ++run) {
            const auto [a, b] = p.pairs[c.order[c.run_starts[run]]];
            for (const std::size_t x : {a, b}) {
              if (p.moves[x]) {
                EXPECT_EQ(moved_by[x], std::set<std::size_t>{block}) << "body " << x;
              }
            }
          }
        }
      }
      // Slabs of space keep most runs to one block: only those across a
      // cut are shared (for two blocks, one cut through a pile 14 wide,
      // about 3 in 14 of the runs' bodies lie next to it).
      if (blocks == 1) {
        EXPECT_EQ(shared, 0u);
      }
      if (blocks == 2) {
        EXPECT_GT(shared, 0u);
        EXPECT_LT(shared * 4, coloured);
      }
    }
  }
}

}  // namespace
}  // namespace gaphys::testing
