#include "contact_events.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <utility>

#include "gaphys/detail/cache_padded.hpp"
#include "pair_cuts.hpp"
#include "thread_count.hpp"

namespace gaphys::detail {

namespace {

// Whether the run of contacts from `i` sharing its pair touches; advances i
// past the run.
bool run_touches(const std::vector<contact>& contacts, std::size_t& i, std::size_t end) {
  const contact& head = contacts[i];
  bool touches = false;
  for (; i < end && contacts[i].body_a == head.body_a && contacts[i].body_b == head.body_b; ++i) {
    touches = touches || contacts[i].geometry.depth >= 0 || contacts[i].impulse.normal > 0;
  }
  return touches;
}

// The event of the run [first, end): its deepest point, its total normal impulse.
contact_event event_of(const std::vector<contact>& contacts, std::size_t first, std::size_t end) {
  const contact* deepest = &contacts[first];
  real impulse = 0, approach_speed = contacts[first].approach_speed;
  for (std::size_t k = first; k < end; ++k) {
    impulse += contacts[k].impulse.normal;
    approach_speed = std::max(approach_speed, contacts[k].approach_speed);
    if (contacts[k].geometry.depth > deepest->geometry.depth) deepest = &contacts[k];
  }
  return contact_event{contacts[first].body_a,
                       contacts[first].body_b,
                       deepest->geometry.point,
                       deepest->geometry.normal,
                       impulse,
                       approach_speed};
}

// The merge of previous[i, i_end) and current[j, j_end), whole pairs. Only
// the runs that make an event are summed up: most steps, most pairs persist.
void merge_events(const std::vector<contact>& previous, std::size_t i, std::size_t i_end,
                  const std::vector<contact>& current, std::size_t j, std::size_t j_end,
                  contact_events& events) {
  constexpr pair_key past_the_end{~std::size_t{0}, ~std::size_t{0}};
  while (i < i_end || j < j_end) {
    const pair_key old_key = i < i_end ? key_of(previous[i]) : past_the_end;
    const pair_key now_key = j < j_end ? key_of(current[j]) : past_the_end;
    const std::size_t old_first = i, now_first = j;
    const bool touched = old_key <= now_key && run_touches(previous, i, i_end);
    const bool touches = now_key <= old_key && run_touches(current, j, j_end);
    if (touches) {
      (touched ? events.persisted : events.began).push_back(event_of(current, now_first, j));
    }
    if (touched && !touches) events.ended.push_back(event_of(previous, old_first, i));
  }
}

}  // namespace

void find_events(const std::vector<contact>& previous, const std::vector<contact>& current,
                 contact_events& events, int threads) {
  // (A few thousand contacts per share: a pair's summary is a few tens of ns.)
  const int shares = threads_for(threads, previous.size() + current.size(), 4096);
  if (shares == 1) {
    events.began.clear();
    events.persisted.clear();
    events.ended.clear();
    merge_events(previous, 0, previous.size(), current, 0, current.size(), events);
    return;
  }
  // Cut both lists before the same pairs (pair_cuts.hpp).
  pair_cuts cuts;
  cut_at_pairs(previous, current, shares, cuts);
  // The shares' lists, kept from call to call by the calling thread (grown
  // anew each step, they cost a step of 10,000 balls a page fault every few
  // events); referred to by `parts`, as inside the parallel region the
  // thread_local's own name would mean each thread's own.
  static thread_local std::vector<cache_padded<contact_events>> kept_parts;
  std::vector<cache_padded<contact_events>>& parts = kept_parts;
  parts.resize(static_cast<std::size_t>(shares));
#pragma omp parallel for num_threads(shares) schedule(static, 1)
  for (int s = 0; s < shares; ++s) {
    contact_events& part = parts[static_cast<std::size_t>(s)].value;
    part.began.clear(), part.persisted.clear(), part.ended.clear();
    merge_events(previous, cuts.old[s], cuts.old[s + 1], current, cuts.now[s], cuts.now[s + 1],
                 part);
  }
  // The join: each part copied to its place by the thread that made it. (A
  // step of 10,000 balls has as many events: copied by one thread, the
  // events took 0.60 ms of that step on two threads, against 0.50-0.53.)
  // The lists are resized, not cleared: only what they lack is constructed.
  using list = std::vector<contact_event> contact_events::*;
  constexpr std::array<list, 3> lists{&contact_events::began, &contact_events::persisted,
                                      &contact_events::ended};
  std::array<std::vector<std::size_t>, 3> starts;
  for (std::size_t l = 0; l < lists.size(); ++l) {
    starts[l].assign(parts.size() + 1, 0);
    for (std::size_t s = 0; s < parts.size(); ++s) {
      starts[l][s + 1] = starts[l][s] + (parts[s].value.*lists[l]).size();
    }
    (events.*lists[l]).resize(starts[l].back());
  }
#pragma omp parallel for num_threads(shares) schedule(static, 1)
  for (int s = 0; s < shares; ++s) {
    const auto at = static_cast<std::size_t>(s);
    for (std::size_t l = 0; l < lists.size(); ++l) {
      const std::vector<contact_event>& part = parts[at].value.*lists[l];
      std::copy(part.begin(), part.end(),
                (events.*lists[l]).begin() + static_cast<std::ptrdiff_t>(starts[l][at]));
    }
  }
}

}  // namespace gaphys::detail
