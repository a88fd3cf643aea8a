// Space: the geometry side of the world (thesis chapter 4.2). It knows which
// bodies carry shapes, forms the candidate pairs and runs the narrow phase.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "gaphys/body.hpp"
#include "gaphys/contact.hpp"

namespace gaphys {

using body_pair = std::pair<std::size_t, std::size_t>;

class space {
 public:
  void add(std::size_t body_index) { shaped_bodies_.push_back(body_index); }
  std::size_t shape_count() const { return shaped_bodies_.size(); }

  // All pairs, as in the thesis (a broad phase is future work): every two
  // shaped bodies that are not both static. Pairs are (a, b) with a < b.
  void candidate_pairs(const std::vector<body>& bodies, std::vector<body_pair>& pairs) const;

  // Places every shape once, then meets each candidate pair.
  void find_contacts(const std::vector<body>& bodies, const std::vector<body_pair>& pairs,
                     std::vector<contact>& contacts);

 private:
  std::vector<std::size_t> shaped_bodies_;
  std::vector<placed_shape> placed_;  // indexed by body; reused between steps
};

}  // namespace gaphys
