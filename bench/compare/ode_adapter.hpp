// ODE as the comparison runs it, with either of its steppers: dWorldQuickStep
// (iterative, O(n) per step, what applications use for many bodies) or
// dWorldStep (a direct LCP solve per island, exact but O(n^3)).
#pragma once

#include "engine_adapter.hpp"

namespace gaphys_compare {

enum class ode_stepper { quick, direct };

engine ode_engine(ode_stepper stepper);

}  // namespace gaphys_compare
