// The touching pairs of two consecutive steps' contacts, compared.
#pragma once

#include <vector>

#include "gaphys/contact.hpp"
#include "gaphys/contact_events.hpp"

namespace gaphys::detail {

// Both lists sorted by body pair (as the narrow phase makes them), each
// contact holding its step's impulses. With `threads` > 1 (0: every core)
// the lists are cut at pair boundaries into shares merged at once; the
// events are the same, in the same order.
void find_events(const std::vector<contact>& previous, const std::vector<contact>& current,
                 contact_events& events, int threads = 1);

}  // namespace gaphys::detail
