// How far a turning body's shape can come towards something within a step.
//
// A speculative contact lets its bodies close the gap it found at the start
// of the step, and no more; its solver row reads the contact point's speed
// linearised, v + ω × r. For a body spinning fast that linear speed is no
// measure of where its surface goes: a box turning at 50 rad/s sweeps its
// corners round, not along their tangents, and one whose corners can never
// reach a floor 3 cm below them would still be stopped by the floor's
// speculative contacts (and thrown upwards). space::meet therefore keeps a
// speculative manifold only if its bodies can close its gap: by their
// speeds along the normal, and by how far their turning sweeps each shape's
// support along it, from the shape's corners (a box's or hull's vertices, a
// capsule's segment ends, a sphere's centre) turned exactly, not tangentially.
#pragma once

#include "gaphys/algebra.hpp"
#include "gaphys/contact.hpp"

namespace gaphys::detail {

// The most that the support of `shape` along the unit direction `towards`
// (max over the shape's points x of x . towards) grows while its body turns
// at `angular_velocity` about its centre of mass `centre` for `time`
// seconds, the centre held still: >= 0, and at most the turning's chord,
// time |ω| times the shape's farthest point from `centre`. Planes (on static
// bodies, which do not turn) give 0.
real turning_approach(const placed_shape& shape, const vector& centre,
                      const bivector& angular_velocity, real time, const vector& towards);

}  // namespace gaphys::detail
