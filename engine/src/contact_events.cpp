#include "contact_events.hpp"

#include <algorithm>
#include <cstddef>
#include <utility>

#include "thread_count.hpp"

namespace gaphys::detail {

namespace {

using pair_key = std::pair<std::size_t, std::size_t>;

pair_key key_of(const contact& c) { return {c.body_a, c.body_b}; }

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
  real impulse = 0;
  for (std::size_t k = first; k < end; ++k) {
    impulse += contacts[k].impulse.normal;
    if (contacts[k].geometry.depth > deepest->geometry.depth) deepest = &contacts[k];
  }
  return contact_event{contacts[first].body_a, contacts[first].body_b, deepest->geometry.point,
                       deepest->geometry.normal, impulse};
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
  events.began.clear();
  events.persisted.clear();
  events.ended.clear();
  // (A few thousand contacts per share: a pair's summary is a few tens of ns.)
  const int shares = threads_for(threads, previous.size() + current.size(), 4096);
  if (shares == 1) {
    merge_events(previous, 0, previous.size(), current, 0, current.size(), events);
    return;
  }
  // Cut both lists before the same pairs: at even places of the current
  // list, moved to the start of their pair, and where that pair would
  // stand in the previous one.
  std::vector<std::size_t> cuts_now(shares + 1, current.size()), cuts_old(shares + 1, previous.size());
  cuts_now[0] = cuts_old[0] = 0;
  for (int s = 1; s < shares; ++s) {
    std::size_t at = current.size() * s / shares;
    while (at > 0 && at < current.size() && key_of(current[at - 1]) == key_of(current[at])) --at;
    at = std::max(at, cuts_now[s - 1]);
    cuts_now[s] = at;
    const pair_key cut_key = at < current.size() ? key_of(current[at])
                                                 : pair_key{~std::size_t{0}, ~std::size_t{0}};
    cuts_old[s] = static_cast<std::size_t>(
        std::lower_bound(previous.begin(), previous.end(), cut_key,
                         [](const contact& c, const pair_key& k) { return key_of(c) < k; }) -
        previous.begin());
    cuts_old[s] = std::max(cuts_old[s], cuts_old[s - 1]);
  }
  // The shares' lists, kept from call to call by the calling thread (grown
  // anew each step, they cost a step of 10,000 balls a page fault every few
  // events); referred to by `parts`, as inside the parallel region the
  // thread_local's own name would mean each thread's own.
  static thread_local std::vector<contact_events> kept_parts;
  std::vector<contact_events>& parts = kept_parts;
  parts.resize(static_cast<std::size_t>(shares));
#pragma omp parallel for num_threads(shares) schedule(static, 1)
  for (int s = 0; s < shares; ++s) {
    contact_events& part = parts[static_cast<std::size_t>(s)];
    part.began.clear(), part.persisted.clear(), part.ended.clear();
    merge_events(previous, cuts_old[s], cuts_old[s + 1], current, cuts_now[s], cuts_now[s + 1],
                 part);
  }
  for (const contact_events& part : parts) {
    events.began.insert(events.began.end(), part.began.begin(), part.began.end());
    events.persisted.insert(events.persisted.end(), part.persisted.begin(), part.persisted.end());
    events.ended.insert(events.ended.end(), part.ended.begin(), part.ended.end());
  }
}

}  // namespace gaphys::detail
