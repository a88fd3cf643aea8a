// gaphys as the comparison runs it: gaphys::world with its default settings.
#pragma once

#include "engine_adapter.hpp"
#include "gaphys/world.hpp"

namespace gaphys_compare {

// `threads`: world_settings::threads (0: every core); `batches`:
// world_settings::batch_contacts; `turning_sweeps`:
// world_settings::turning_iterations (< 0: the default).
engine gaphys_engine(int threads, gaphys::contact_batching batches, int turning_sweeps);

}  // namespace gaphys_compare
