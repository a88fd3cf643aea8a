// gaphys as the comparison runs it: gaphys::world with its default settings.
#pragma once

#include "engine_adapter.hpp"

namespace gaphys_compare {

engine gaphys_engine();

}  // namespace gaphys_compare
