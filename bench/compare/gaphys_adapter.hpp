// gaphys as the comparison runs it: gaphys::world with its default settings.
#pragma once

#include "engine_adapter.hpp"

namespace gaphys_compare {

// `threads`: world_settings::threads (0: every core).
engine gaphys_engine(int threads);

}  // namespace gaphys_compare
