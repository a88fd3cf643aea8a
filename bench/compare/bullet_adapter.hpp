// Bullet as the comparison runs it: btDiscreteDynamicsWorld, one thread, a
// fixed step, settings matched to gaphys (the parameters list says which and why).
#pragma once

#include "engine_adapter.hpp"

namespace gaphys_compare {

engine bullet_engine();

}  // namespace gaphys_compare
