// Two contact lists sorted by body pair (the last step's and this step's),
// cut into shares that keep each pair whole, for work on several threads
// that must see all of a pair's contacts in both lists at once (the contact
// events, the warm start's matching).
#pragma once

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

#include "gaphys/contact.hpp"

namespace gaphys::detail {

using pair_key = std::pair<std::size_t, std::size_t>;

inline pair_key key_of(const contact& c) { return {c.body_a, c.body_b}; }

// Share s is previous[old[s], old[s + 1]) and current[now[s], now[s + 1]).
struct pair_cuts {
  std::vector<std::size_t> now, old;
};

// Cut at even places of the current list, each moved back to the start of
// its pair, and where that pair would stand in the previous one.
inline void cut_at_pairs(const std::vector<contact>& previous, const std::vector<contact>& current,
                         int shares, pair_cuts& cuts) {
  const auto count = static_cast<std::size_t>(shares);
  cuts.now.assign(count + 1, current.size());
  cuts.old.assign(count + 1, previous.size());
  cuts.now[0] = cuts.old[0] = 0;
  for (std::size_t s = 1; s < count; ++s) {
    std::size_t at = current.size() * s / count;
    while (at > 0 && at < current.size() && key_of(current[at - 1]) == key_of(current[at])) --at;
    at = std::max(at, cuts.now[s - 1]);
    cuts.now[s] = at;
    const pair_key cut_key = at < current.size() ? key_of(current[at])
                                                 : pair_key{~std::size_t{0}, ~std::size_t{0}};
    cuts.old[s] = static_cast<std::size_t>(
        std::lower_bound(previous.begin(), previous.end(), cut_key,
                         [](const contact& c, const pair_key& k) { return key_of(c) < k; }) -
        previous.begin());
    cuts.old[s] = std::max(cuts.old[s], cuts.old[s - 1]);
  }
}

}  // namespace gaphys::detail
