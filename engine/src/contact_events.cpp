#include "contact_events.hpp"

#include <algorithm>
#include <cstddef>
#include <optional>
#include <utility>

#include "thread_count.hpp"

namespace gaphys::detail {

namespace {

// One pair's run of contacts, summed up: whether it touches, its deepest
// point, the total normal impulse.
struct pair_summary {
  body_id a, b;
  bool touches = false;
  contact_event event;
};

// The summary of the run of contacts from `i` sharing its pair; advances i past it.
pair_summary summarize(const std::vector<contact>& contacts, std::size_t& i) {
  const contact& first = contacts[i];
  pair_summary s{
      first.body_a, first.body_b, false,
      contact_event{first.body_a, first.body_b, first.geometry.point, first.geometry.normal, 0}};
  real deepest = first.geometry.depth;
  for (; i < contacts.size() && contacts[i].body_a == s.a && contacts[i].body_b == s.b; ++i) {
    const contact& c = contacts[i];
    s.touches = s.touches || c.geometry.depth >= 0 || c.impulse.normal > 0;
    s.event.impulse += c.impulse.normal;
    if (c.geometry.depth > deepest) {
      deepest = c.geometry.depth;
      s.event.point = c.geometry.point;
      s.event.normal = c.geometry.normal;
    }
  }
  return s;
}

// The merge of previous[i, i_end) and current[j, j_end), whole pairs.
void merge_events(const std::vector<contact>& previous, std::size_t i, std::size_t i_end,
                  const std::vector<contact>& current, std::size_t j, std::size_t j_end,
                  contact_events& events) {
  std::optional<pair_summary> old, now;
  const auto next = [](const std::vector<contact>& list, std::size_t& at, std::size_t end) {
    return at < end ? std::optional<pair_summary>(summarize(list, at)) : std::nullopt;
  };
  old = next(previous, i, i_end);
  now = next(current, j, j_end);
  // A merge of the two pair-sorted runs.
  while (old || now) {
    const bool take_old =
        old && (!now || std::make_pair(old->a, old->b) <= std::make_pair(now->a, now->b));
    const bool take_now =
        now && (!old || std::make_pair(now->a, now->b) <= std::make_pair(old->a, old->b));
    const bool touched = take_old && old->touches, touches = take_now && now->touches;
    if (touches) (touched ? events.persisted : events.began).push_back(now->event);
    if (touched && !touches) events.ended.push_back(old->event);
    if (take_old) old = next(previous, i, i_end);
    if (take_now) now = next(current, j, j_end);
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
  const auto key = [](const contact& c) { return std::make_pair(c.body_a, c.body_b); };
  std::vector<std::size_t> cuts_now(shares + 1, current.size()), cuts_old(shares + 1, previous.size());
  cuts_now[0] = cuts_old[0] = 0;
  for (int s = 1; s < shares; ++s) {
    std::size_t at = current.size() * s / shares;
    while (at > 0 && at < current.size() && key(current[at - 1]) == key(current[at])) --at;
    at = std::max(at, cuts_now[s - 1]);
    cuts_now[s] = at;
    const auto cut_key = at < current.size() ? key(current[at])
                                             : std::make_pair(~std::size_t{0}, ~std::size_t{0});
    cuts_old[s] = static_cast<std::size_t>(
        std::lower_bound(previous.begin(), previous.end(), cut_key,
                         [&](const contact& c, const auto& k) { return key(c) < k; }) -
        previous.begin());
    cuts_old[s] = std::max(cuts_old[s], cuts_old[s - 1]);
  }
  std::vector<contact_events> parts(shares);
#pragma omp parallel for num_threads(shares) schedule(static, 1)
  for (int s = 0; s < shares; ++s) {
    merge_events(previous, cuts_old[s], cuts_old[s + 1], current, cuts_now[s], cuts_now[s + 1],
                 parts[s]);
  }
  for (const contact_events& part : parts) {
    events.began.insert(events.began.end(), part.began.begin(), part.began.end());
    events.persisted.insert(events.persisted.end(), part.persisted.begin(), part.persisted.end());
    events.ended.insert(events.ended.end(), part.ended.begin(), part.ended.end());
  }
}

}  // namespace gaphys::detail
