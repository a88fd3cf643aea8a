// A count of the pose changes made through body setters (set_position,
// set_attitude), over every body of every world: the spatial queries'
// index (query_index.hpp) compares it to tell whether a body moved since it
// was built, even through a reference the caller kept from world::at.
#pragma once

#include <cstdint>

namespace gaphys::detail {

std::uint64_t pose_changes();
void note_pose_change();

}  // namespace gaphys::detail
