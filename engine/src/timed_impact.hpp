// When, inside a step, two bodies' surfaces meet, and along which normal.
//
// Semi-implicit Euler moves each body exactly along a parabola when its
// step's velocity is read as the one at the middle of the step: the velocity
// at the start of the step is the mean of the velocities before and after
// the step's forces, and the acceleration is their difference over h. A
// contact found at the start of a step (speculatively, or overlapping a
// step late) can therefore be timed: the solver bounces the bodies at that
// moment instead of where the step found them.
#pragma once

#include <optional>

#include "gaphys/algebra.hpp"

namespace gaphys {

// A's motion relative to B over one step, of their centres.
struct relative_motion {
  vector offset;          // centre of A minus centre of B at the start of the step
  vector velocity_start;  // vA - vB before the step's forces
  vector velocity_now;    // vA - vB after them
};

struct timed_impact {
  real time;     // s from the start of the step; < 0: the surfaces crossed in the last step
  vector normal; // unit, from B towards A, at that moment
  real speed;    // approach speed along the normal at that moment, > 0
};

// A body meeting a plane with normal n (from the plane towards A) across
// `gap` (m; < 0 for an overlap). Nothing when the bodies do not meet within
// the step, or met more than a step ago.
std::optional<timed_impact> impact_across_plane(real gap, const vector& normal,
                                                const relative_motion& motion, real h);

// Two round bodies whose surfaces touch when their centres are `distance`
// apart (the sum of the radii): the normal turns with the line of centres.
std::optional<timed_impact> impact_of_centres(real distance, const relative_motion& motion,
                                              real h);

}  // namespace gaphys
