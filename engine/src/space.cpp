#include "gaphys/space.hpp"

#include <algorithm>

namespace gaphys {

void space::candidate_pairs(const std::vector<body>& bodies, std::vector<body_pair>& pairs,
                            real lookahead) {
  // The grid declines coordinates too far out for integer cells.
  if (kind_ == broad_phase_kind::uniform_grid &&
      grid_.find_pairs(bodies, shaped_bodies_, lookahead, pairs)) {
    return;
  }
  all_pairs(bodies, pairs);
}

// The thesis's candidates: every two shaped bodies not both static.
void space::all_pairs(const std::vector<body>& bodies, std::vector<body_pair>& pairs) const {
  pairs.clear();
  for (std::size_t i = 0; i < shaped_bodies_.size(); ++i) {
    const std::size_t a = shaped_bodies_[i];
    for (std::size_t j = i + 1; j < shaped_bodies_.size(); ++j) {
      const std::size_t b = shaped_bodies_[j];
      if (bodies[a].is_static() && bodies[b].is_static()) continue;
      pairs.emplace_back(std::min(a, b), std::max(a, b));
    }
  }
}

void space::find_contacts(const std::vector<body>& bodies, const std::vector<body_pair>& pairs,
                          std::vector<contact>& contacts, real lookahead,
                          const material_combine_rules& rules) {
  placed_.resize(bodies.size());
  for (std::size_t index : shaped_bodies_) {
    const body& b = bodies[index];
    placed_[index] = place(*b.shape(), b.position(), b.attitude());
  }
  contacts.clear();
  for (const auto& [a, b] : pairs) {
    if (auto geometry = find_contact(placed_[a], placed_[b], lookahead, bodies[a].velocity(),
                                     bodies[b].velocity())) {
      contacts.push_back(contact{
          a, b, *geometry,
          combine(rules, bodies[a].shape()->material(), bodies[b].shape()->material())});
    }
  }
}

}  // namespace gaphys
