// The order in which the contact phase's sweeps visit contacts: by colour.
//
// Contacts between the same two bodies (a manifold's points, consecutive in
// the sorted contact list) form a run, solved together by one thread. Runs
// are coloured greedily, in contact order, so that no two runs of a colour
// share a body the solver changes, one with mass (static and kinematic
// bodies are only read, so any number of runs of a colour may touch the
// floor). The runs of one colour can then be solved in any order, or at
// once on several threads, with the same result to the bit; colours are
// solved one after the other. The colours depend on the contacts only,
// never on the number of threads (the blocks below only reorder runs
// within a colour): a step is the same with 1, 2 or 8.
//
// Colours with few runs would cost the threads a wait each for little work:
// runs that find no colour among the first `most_colours`, and the runs of
// colours smaller than `fewest_runs` (both fixed, so the order stays
// independent of the threads), go to a last, sequential group.
//
// For T threads, each colour's runs are ordered in T blocks, one per
// thread: the runs whose moving body (for two, body_a) lies in the thread's
// slab of space. The slabs are cut across the axis along which those
// bodies spread most, into shares of about equal numbers of contacts. A
// body then stays with one thread from colour to colour and from sweep to
// sweep, its velocities in that core's cache, but for bodies touching
// across a cut; and each thread reads its contacts front to back. (Split by
// position in each colour's list instead, bodies, whose indices say nothing
// of where they are, changed cores at every colour: 10,000 spheres stepped
// slower on two threads than on one.)
//
// Each block is ordered in two parts: first its shared runs, those with a
// moving body that a run of another thread's block (of any colour) also
// moves, then its own runs, whose moving bodies only its thread's runs
// move. A thread's own runs need nothing from the other threads, so it
// needs to wait for the others only before its shared runs of a colour,
// and only for their shared runs of the colour before: it solves its own
// runs of a colour meanwhile (contact_solver::solve_in_parts).
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "gaphys/body.hpp"
#include "gaphys/contact.hpp"
#include "thread_count.hpp"

namespace gaphys::detail {

struct contact_colouring {
  // The contacts (indices into the contact list) in solving order: colour
  // by colour, runs kept whole and in contact order within a colour (or
  // within each thread's block of it, for several blocks), the sequential
  // group last.
  std::vector<std::size_t> order;
  // Run r is order[run_starts[r]] .. order[run_starts[r + 1] - 1].
  std::vector<std::size_t> run_starts;
  // Colour c is runs colour_starts[c] .. colour_starts[c + 1] - 1; the last
  // group, runs colour_starts.back() .. the end, is solved in order by one
  // thread (it may be empty).
  std::vector<std::size_t> colour_starts;

  // For T > 1 blocks: thread t solves runs
  // thread_starts[c * (T + 1) + t] .. thread_starts[c * (T + 1) + t + 1] - 1
  // of colour c. (Empty for one.)
  std::vector<std::size_t> thread_starts;
  // For T > 1 blocks: block t of colour c has its shared runs first, runs
  // thread_starts[c * (T + 1) + t] .. shared_ends[c * T + t] - 1, and its
  // own runs from there. (Empty for one.)
  std::vector<std::size_t> shared_ends;
  // For T > 1 blocks: space cut into the blocks' slabs across `axis`, in
  // `bins` slices from `start` over `span`, each slice's block in
  // bin_blocks (`any`: some run is coloured, else nothing is cut). A
  // coloured run's block is the slab of its moving body (the one with mass,
  // body_a where both have); the solver keeps the bodies of each slab
  // together (contact_solver::place_bodies).
  static constexpr std::size_t bins = 1024;
  struct slab_cut {
    int axis = 0;
    real start = 0, span = 0;
    real scale = 0;  // bins per metre: (bins - 1) / span
    bool any = false;
    std::vector<std::uint32_t> bin_blocks;
    std::size_t bin_of(const vector& p) const;
    std::uint32_t block_of(const vector& p) const { return bin_blocks[bin_of(p)]; }
  };
  slab_cut slabs;

  // A part of a colour's runs as the sweeps solve it: block t's shared
  // runs (part 0) or own runs (part 1), the first run and one past the
  // last. (With one block, no run is shared.)
  enum part { shared_runs = 0, own_runs = 1 };
  std::pair<std::size_t, std::size_t> runs_of(std::size_t colour, std::size_t block,
                                              std::size_t blocks, part p) const {
    if (blocks == 1) {
      const std::size_t first = colour_starts[colour], end = colour_starts[colour + 1];
      return p == shared_runs ? std::pair{first, first} : std::pair{first, end};
    }
    const std::size_t* starts = &thread_starts[colour * (blocks + 1) + block];
    const std::size_t middle = shared_ends[colour * blocks + block];
    return p == shared_runs ? std::pair{starts[0], middle} : std::pair{middle, starts[1]};
  }

  std::size_t runs() const { return run_starts.size() - 1; }
  std::size_t colours() const { return colour_starts.size() - 1; }

  static constexpr int most_colours = 32;
  static constexpr std::size_t fewest_runs = 32;

  // Scratch, kept to reuse its memory from step to step.
  std::vector<std::pair<std::size_t, std::size_t>> pairs;  // per contact: its bodies (read_pairs)
  std::vector<char> moves;                                 // per body: it has mass (the caller's)
  std::vector<std::uint32_t> body_colours;  // bit c: the body has a run of colour c
  // Per run, in contact order:
  std::vector<std::size_t> run_begins;  // its first contact (and then the end)
  std::vector<int> run_colours;         // its colour (the sequential group: colours())
  std::vector<std::uint32_t> movers;    // its moving body (coloured runs)
  std::vector<std::size_t> run_bins, run_blocks;  // run_blocks: 2 x block + part (T > 1)
  std::vector<std::uint32_t> partners;  // its other body, where that has mass (coloured runs)
  // Per body with mass: its bin as the mover of runs (or none), and the
  // lowest and the highest bin of the runs that move it as their partner
  // (none: lowest > highest).
  std::vector<std::uint16_t> own_bins, lowest_bins, highest_bins;
  std::vector<char> spans_blocks;  // per body: runs of two blocks move it
  std::vector<std::size_t> colour_counts, bin_weights, sorted_runs, sort_scratch;
};

// Each contact's bodies into out.pairs, and also(i) for each contact i, in
// one pass on `threads` (world_settings::threads; from 1,024 contacts a
// thread, the solver's also() taking about 12 ns a contact): colour_contacts
// reads the pairs, and so does the solver's preparation beside it (16 bytes
// a contact; a contact is 248 in double, and each pass over the list read
// them all).
template <class Also>
void read_pairs(const std::vector<contact>& contacts, contact_colouring& out, int threads,
                const Also& also) {
  out.pairs.resize(contacts.size());
  parallel_for(threads, contacts.size(), 1024, [&](std::size_t i) {
    out.pairs[i] = {contacts[i].body_a, contacts[i].body_b};
    also(i);
  });
}

// The contacts whose bodies read_pairs put in out.pairs, sorted by body
// pair as the narrow phase makes them, with out.moves filled (each body:
// whether it has mass). `threads` (world_settings::threads) sort the runs;
// the colours are the same with any number. `blocks`: the threads that
// will solve the colours (thread_starts), 1 for none; for more,
// `positions` holds each body's position. (The caller reads both from the
// bodies in a pass it makes anyway: read here, inside the colouring that
// one thread does while the others prepare, the bodies, large and
// scattered, were a sixth of it.)
void colour_contacts(const std::vector<vector>& positions, contact_colouring& out, int threads,
                     int blocks);

}  // namespace gaphys::detail
