#include "contact_events.hpp"

#include <cstddef>
#include <optional>
#include <utility>

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

}  // namespace

void find_events(const std::vector<contact>& previous, const std::vector<contact>& current,
                 contact_events& events) {
  events.began.clear();
  events.persisted.clear();
  events.ended.clear();
  std::size_t i = 0, j = 0;
  std::optional<pair_summary> old, now;
  const auto next = [](const std::vector<contact>& list, std::size_t& at) {
    return at < list.size() ? std::optional<pair_summary>(summarize(list, at)) : std::nullopt;
  };
  old = next(previous, i);
  now = next(current, j);
  // A merge of the two pair-sorted runs.
  while (old || now) {
    const bool take_old =
        old && (!now || std::make_pair(old->a, old->b) <= std::make_pair(now->a, now->b));
    const bool take_now =
        now && (!old || std::make_pair(now->a, now->b) <= std::make_pair(old->a, old->b));
    const bool touched = take_old && old->touches, touches = take_now && now->touches;
    if (touches) (touched ? events.persisted : events.began).push_back(now->event);
    if (touched && !touches) events.ended.push_back(old->event);
    if (take_old) old = next(previous, i);
    if (take_now) now = next(current, j);
  }
}

}  // namespace gaphys::detail
