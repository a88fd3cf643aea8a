// The contact solver's copies of the bodies in contact (contact_solver.hpp):
// what its rows read of them, and their velocities, placed where the
// sweeps' threads find their own bodies side by side.
#include <omp.h>

#include <new>
#include <numeric>
#include <type_traits>

#include "contact_solver.hpp"
#include "counting_sort.hpp"
#include "thread_count.hpp"

namespace gaphys {

void contact_solver::mark_bodies_in_contact(const std::vector<body>& bodies) {
  row_bodies_.resize(bodies.size());
  shape_summaries_.resize(bodies.size());
  solver_bodies_.resize(bodies.size());
  impact_bodies_.resize(bodies.size());
  place_.resize(bodies.size());
  in_contact_.assign(bodies.size(), 0);
  for (const auto& [a, b] : colouring_.pairs) in_contact_[a] = in_contact_[b] = 1;
}

// What the rows read of a body in contact (row_body), and what the
// constraints read of its shapes, once; the solver's copies of its
// velocities where it is its own place (one sweep thread).
void contact_solver::prepare_body(std::size_t i, const std::vector<body>& bodies,
                                  const std::vector<body_velocity>& start, bool velocities) {
  const body& b = bodies[i];
  if (in_contact_[i]) {
    // (Made in their places, here and below: assigned from copies made
    // aside, their bytes were read back as soon as written, in wider loads
    // than the stores, each waiting for them; 2% of a step of 1,000
    // spheres, over half of these two functions.)
    static_assert(std::is_trivially_destructible_v<detail::row_body> &&
                  std::is_trivially_destructible_v<shape_summary>);
    ::new (static_cast<void*>(&row_bodies_[i])) detail::row_body(detail::row_body::of(b));
    ::new (static_cast<void*>(&shape_summaries_[i])) shape_summary(summarize(b));
  }
  if (velocities) copy_velocities(i, bodies, start);
}

void contact_solver::copy_velocities(std::size_t i, const std::vector<body>& bodies,
                                     const std::vector<body_velocity>& start) {
  const body& b = bodies[i];
  solver_body& solved = solver_bodies_[place_[i]];
  solved.velocity = b.velocity_;
  solved.angular_velocity = b.angular_velocity_;
  solved.inverse_mass = b.inverse_mass_;
  solver_body& impact = impact_bodies_[place_[i]];
  impact.velocity = start[i].linear;
  impact.angular_velocity = start[i].angular;
  impact.inverse_mass = b.inverse_mass_;
}

// visit(p) for every place p, on the sweeps' threads: each thread the places
// of the bodies its blocks move (place_bodies), so that their lines come to
// the core whose sweeps read them, and a share of the rest.
template <class Visit>
void contact_solver::for_each_place(const Visit& visit) {
  if (sweep_threads_ == 1) {
    for (std::size_t p = 0; p < place_.size(); ++p) visit(p);
    return;
  }
  const auto threads = static_cast<std::size_t>(sweep_threads_);
  const std::vector<std::size_t>& starts = owner_starts_;
#pragma omp parallel num_threads(sweep_threads_)
  {
    const auto thread = static_cast<std::size_t>(omp_get_thread_num());
    const auto team = static_cast<std::size_t>(omp_get_num_threads());
    for (std::size_t t = thread; t < threads; t += team) {
      for (std::size_t p = starts[t]; p < starts[t + 1]; ++p) visit(p);
    }
    // (The bodies no thread's runs move, in equal shares.)
    const std::size_t rest = starts[threads + 1] - starts[threads];
    const std::size_t first = starts[threads] + rest * thread / team;
    const std::size_t end = starts[threads] + rest * (thread + 1) / team;
    for (std::size_t p = first; p < end; ++p) visit(p);
  }
}

// On several sweep threads, where each body's velocities go: first the
// bodies thread 0's blocks move (contact_colouring.hpp: its slab of space),
// in body order, then thread 1's, and so on, then the rest; each thread
// then copies its own in. Placed in body order, the two threads'
// bodies alternated along solver_bodies_, and a core fetches the lines
// next to those it misses: each thread's updates took lines of the other's
// bodies away from it, and 4,000 spheres' sweeps took each of two threads
// as long as one thread took for all (2026-12-06, a 2-core Xeon).
void contact_solver::place_bodies(const std::vector<body>& bodies,
                                  const std::vector<body_velocity>& start) {
  const std::size_t count = bodies.size();
  const auto threads = static_cast<std::size_t>(sweep_threads_);
  // Each body's block: its slab's, where it has mass and a run of a colour
  // (`threads`: none). (Found per run, as the block of the first run that
  // moves it, in the colouring that one thread does while the others
  // prepare, the bodies' scattered reads and writes took it 0.1 ms of a
  // 10,000-sphere step.)
  const detail::contact_colouring::slab_cut& slabs = colouring_.slabs;
  const auto owner = [&](std::size_t i) -> std::size_t {
    const bool in_slab = slabs.any && colouring_.body_colours[i] != 0;
    return in_slab ? slabs.block_of(positions_[i]) : threads;
  };
  std::vector<std::size_t>& starts = owner_starts_;
  body_at_.resize(count);
  detail::counting_sort(sweep_threads_, 4096, count, threads + 1, owner, starts, place_scratch_,
                        [&](std::size_t i, std::size_t at) {
                          place_[i] = static_cast<std::uint32_t>(at);
                          body_at_[at] = i;
                        });
  for_each_place([&](std::size_t p) { copy_velocities(body_at_[p], bodies, start); });
}

void contact_solver::copy_to_plain_bodies() {
  // (And a spare, the empty lanes' body: plain_pairs.hpp.)
  plain_bodies_.resize(spare_place() + 1);
  plain_bodies_[spare_place()] = {};
  for_each_place([&](std::size_t p) {
    plain_bodies_[p] = {solver_bodies_[p].velocity, solver_bodies_[p].inverse_mass};
  });
}

void contact_solver::copy_from_plain_bodies() {
  for_each_place([&](std::size_t p) { solver_bodies_[p].velocity = plain_bodies_[p].velocity; });
}

void contact_solver::prepare_bodies(const std::vector<body>& bodies,
                                    const std::vector<body_velocity>& start,
                                    const std::vector<contact>& contacts,
                                    const std::vector<contact>& previous, int threads) {
  mark_bodies_in_contact(bodies);
  std::iota(place_.begin(), place_.end(), std::uint32_t{0});
  detail::parallel_for(threads, bodies.size(), 2048,
                       [&](std::size_t i) { prepare_body(i, bodies, start, true); });
  const int shares = detail::threads_for(threads, contacts.size(), 2048);
  cut_for_matches(contacts, previous, shares);
#pragma omp parallel for num_threads(shares) schedule(static, 1) if (shares > 1)
  for (int share = 0; share < shares; ++share) match_share(share, bodies, contacts, previous);
}

// On sweep_threads_ threads: one colours the contacts (its greedy pass and
// its sort cannot be shared out) while the others prepare the bodies, the
// warm start's matches, the bodies' supports and their counts of contacts
// in pieces, which the colouring thread joins when it is done. (As two
// OpenMP sections, the preparation took 0.8-1.15 ms of a 10,000-sphere
// step and the colouring 0.55-0.66 ms: one thread waited the difference,
// and on more cores the others did nothing.) Every piece writes only its
// own bodies' or contacts' data.
void contact_solver::colour_beside_preparation(const std::vector<body>& bodies,
                                               const std::vector<body_velocity>& start,
                                               const std::vector<contact>& contacts,
                                               const std::vector<contact>& previous) {
  const auto team = static_cast<std::size_t>(sweep_threads_);
  const std::size_t body_pieces = 4 * team;
  const int match_shares = detail::threads_for(2 * sweep_threads_, contacts.size(), 2048);
#pragma omp parallel num_threads(sweep_threads_)
#pragma omp single
  {
#pragma omp task
    detail::colour_contacts(positions_, colouring_, 1, sweep_threads_);
#pragma omp task
    find_supports(bodies.size());
#pragma omp task
    count_contacts(bodies.size(), colouring_.pairs);
    mark_bodies_in_contact(bodies);
    cut_for_matches(contacts, previous, match_shares);
    for (int share = 0; share < match_shares; ++share) {
#pragma omp task
      match_share(share, bodies, contacts, previous);
    }
    for (std::size_t piece = 0; piece < body_pieces; ++piece) {
      const std::size_t begin = bodies.size() * piece / body_pieces;
      const std::size_t end = bodies.size() * (piece + 1) / body_pieces;
#pragma omp task
      for (std::size_t i = begin; i < end; ++i) prepare_body(i, bodies, start, false);
    }
  }
  place_bodies(bodies, start);
}

}  // namespace gaphys
