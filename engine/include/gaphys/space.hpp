// Space: the geometry side of the world (thesis chapter 4.2). It knows which
// bodies carry shapes, forms the candidate pairs and runs the narrow phase.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "gaphys/body.hpp"
#include "gaphys/contact.hpp"
#include "gaphys/contact_events.hpp"
#include "gaphys/detail/cache_padded.hpp"
#include "gaphys/detail/hidden_faces.hpp"
#include "gaphys/detail/uniform_grid.hpp"

namespace gaphys {

using body_pair = std::pair<std::size_t, std::size_t>;

// How candidate pairs are found. Both give the same pairs (all pairs tests
// every two bodies as the grid tests its cells'), so the same contacts in
// the same order and the same simulation to the bit; the grid is O(N), all
// pairs (the thesis's) O(N^2).
enum class broad_phase_kind { uniform_grid, all_pairs };

class space {
 public:
  explicit space(broad_phase_kind kind = broad_phase_kind::uniform_grid) : kind_(kind) {}

  void add(std::size_t body_index) { shaped_bodies_.push_back(body_index); }
  // Forgets the body at this index; the bodies after it move down one.
  void remove(std::size_t body_index);
  std::size_t shape_count() const { return shaped_bodies_.size(); }
  broad_phase_kind broad_phase() const { return kind_; }
  void set_broad_phase(broad_phase_kind kind) { kind_ = kind; }

  // Pairs of shaped bodies that may meet (body.hpp: not both static,
  // kinematic or asleep, unless one moves and the other sleeps) and may touch within
  // `lookahead` seconds at their present velocities, or are within
  // `margin` metres: a superset of those that do. Pairs are (a, b) with
  // a < b, in increasing order, the same with any `threads` (the grid's
  // cells are paired on that many; 0: every core).
  void candidate_pairs(const std::vector<body>& bodies, std::vector<body_pair>& pairs,
                       real lookahead = 0, real margin = 0, int threads = 1);

  // Places the shapes of the pairs' bodies, then meets each pair's shapes. Shapes
  // whose gap their velocities close within lookahead seconds make
  // speculative contacts (depth < 0); boxes, capsules and hulls also within
  // `margin` metres. Contacts come in pair order, then by shape pair, then
  // as each manifold lists them. Each contact's material combines its
  // shapes' by `rules`.
  // Shapes whose filters do not meet make none; a pair with a sensor makes
  // no contact but, when they overlap or touch, a sensor_overlap in
  // `sensors` (cleared first; none kept when it is null). With `threads`
  // > 1 (0: every core) the pairs are met on that many threads at once; the
  // contacts are the same, in the same order. With `slop` > 0 (the world's
  // linear_slop), a contact on a static shape's face that another static
  // shape hides is left out (hidden_faces.hpp: the seams of a floor of boxes).
  void find_contacts(const std::vector<body>& bodies, const std::vector<body_pair>& pairs,
                     std::vector<contact>& contacts, real lookahead = 0,
                     const material_combine_rules& rules = {}, real margin = 0,
                     std::vector<sensor_overlap>* sensors = nullptr, int threads = 1,
                     real slop = 0);

  // Whether the shapes of bodies a and b make a contact (a speculative one
  // too) as find_contacts would meet them: a sleeping body wakes when one
  // does with an awake one, whichever broad phase found the pair.
  bool make_contact(const std::vector<body>& bodies, std::size_t a, std::size_t b, real lookahead,
                    real margin) const;

  // Shape s of body b where the body's pose puts it; or where a body at
  // `position` and `attitude` would.
  static placed_shape placed(const body& b, const attached_shape& s);
  static placed_shape placed(const attached_shape& s, const vector& position,
                             const rotor& attitude);

 private:
  enum class met { nothing, sensed, contacts };
  // `alone`: neither body can be pushed in this step by another that moves
  // (`jostled`), so the speculative contacts their velocities cannot reach
  // are left out (space.cpp, keep_reachable).
  static met meet(const body& body_a, const body& body_b, std::size_t i, std::size_t j,
                  const placed_shape& shape_a, const placed_shape& shape_b, real lookahead,
                  real reach, real margin, bool alone, contact_manifold& manifold);
  void all_pairs(const std::vector<body>& bodies, std::vector<body_pair>& pairs, real lookahead,
                 real margin) const;
  void place_shapes(const std::vector<body>& bodies, const std::vector<body_pair>& pairs,
                    int threads = 1);
  void mark_pairs(const std::vector<body_pair>& pairs, int threads);
  // Every pair met, on `threads`, into `contacts` (find_contacts).
  void meet_all(const std::vector<body>& bodies, const std::vector<body_pair>& pairs,
                std::vector<contact>& contacts, real lookahead, const material_combine_rules& rules,
                real margin, std::vector<sensor_overlap>* sensors, int threads);
  // The pairs [first, end) met into contacts[start, start + n), over what
  // the list held there (made longer where it ends first): returns n.
  std::size_t meet_pairs(const std::vector<body>& bodies, const body_pair* first,
                         const body_pair* end, std::vector<contact>& contacts, std::size_t start,
                         real lookahead, const material_combine_rules& rules, real margin,
                         std::vector<sensor_overlap>* sensors,
                         std::vector<detail::static_contact>& on_static) const;

  broad_phase_kind kind_;
  detail::uniform_grid grid_;
  std::vector<std::size_t> shaped_bodies_;
  // Every shape at its pose: body i's are placed_[first_shape_[i], first_shape_[i + 1]).
  std::vector<placed_shape> placed_;  // reused between steps
  std::vector<std::size_t> first_shape_;
  // Per body: whether it is in some pair, and whether it is dynamic and in
  // a pair with another dynamic or a kinematic body, which may push it
  // anywhere within the step (mark_pairs).
  enum : unsigned char { in_a_pair = 1, jostled = 2 };
  std::vector<unsigned char> body_marks_;
  // The marks of the marking threads but the first (mark_pairs).
  std::vector<detail::cache_padded<std::vector<unsigned char>>> more_marks_;
  std::vector<unsigned char> static_;   // whether each body is static
  std::vector<unsigned char> dynamic_;  // whether each body is dynamic
  detail::hidden_face_lists hidden_;
  // What the meets on batches read of a body with one shape, written as its
  // shape is placed: read from the bodies and their shapes, pair by pair,
  // they were a scattered read each and 40% of meet_pairs' own time.
  struct single_shape_facts {
    vector velocity;
    material surface;
    collision_filter filter;
    bool plain = false;  // one shape, not a sensor
  };
  std::vector<single_shape_facts> singles_;  // per body index, valid for bodies in pairs
  // Each share's contacts, sensor overlaps and contacts with a static body
  // (by their places in its list), in pair order (find_contacts).
  struct share_lists {
    std::vector<contact> contacts;  // its first `made` (unless met in place)
    std::vector<sensor_overlap> sensors;
    std::vector<detail::static_contact> on_static;
    std::size_t made = 0;   // contacts
    bool in_place = false;  // met straight into the step's list (meet_all)
  };
  std::vector<detail::cache_padded<share_lists>> shares_;
  // Where each share's contacts and static contacts go in the lists.
  struct share_start {
    std::size_t contacts = 0, on_static = 0;
  };
  std::vector<share_start> share_starts_;
  // Where each share's contacts begin among those copied (not met in place).
  std::vector<std::size_t> copy_starts_;
  // The contacts between a static body and another, in order (meet_pairs
  // lists them): the first static_count_ (on_static_ keeps its length from
  // step to step, as room for the next step's).
  std::vector<detail::static_contact> on_static_;
  std::size_t static_count_ = 0;
};

}  // namespace gaphys
