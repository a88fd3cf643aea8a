// gaphys as the comparison runs it: gaphys::world with its default settings.
#pragma once

#include "engine_adapter.hpp"
#include "gaphys/world.hpp"

namespace gaphys_compare {

// `threads`: world_settings::threads (0: every core); `batches`:
// world_settings::batch_contacts.
engine gaphys_engine(int threads, gaphys::contact_batching batches);

}  // namespace gaphys_compare
