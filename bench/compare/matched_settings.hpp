// The solver settings Bullet and ODE are given, matched to
// gaphys::world_settings' defaults (its 20 sweeps; gaphys gives contacts
// that turn a body 10 more), so that each engine is asked the same.
#pragma once

namespace gaphys_compare::matched {

constexpr int solver_iterations = 20;          // sweeps over the contacts
constexpr double restitution_threshold = 0.5;  // m/s: slower approaches do not bounce
constexpr double position_correction = 0.2;    // share of the depth corrected per step

}  // namespace gaphys_compare::matched
