// Which pairs of bodies began touching in a step, which touched before it
// and still do, and which stopped: world::events(), after each step.
#pragma once

#include <cstddef>
#include <vector>

#include "gaphys/algebra.hpp"
#include "gaphys/queries.hpp"

namespace gaphys {

// A pair touches in a step when one of its contacts overlapped as the step
// began (depth >= 0) or pushed during it (a normal impulse > 0): a
// speculative contact that a landing body closes counts, one it only
// approached does not.
struct contact_event {
  body_id body_a, body_b;  // ids; body_a created before body_b
  vector point;            // the pair's deepest contact point
  vector normal;           // its normal, from B towards A
  real impulse;            // N s: the pair's total normal impulse in the step (a landing's
                           // may fall in two: docs/engine.md, "Contact events")
  // m/s: the fastest its contact points were closing as the step began
  // (contact::approach_speed; > 0 closing): in `began`, the landing's speed.
  real approach_speed;
};

// Each list in the order of the pairs in world::contacts(). An ended pair's point, normal and
// impulse are those of the last step in which it touched.
struct contact_events {
  std::vector<contact_event> began;
  std::vector<contact_event> persisted;
  std::vector<contact_event> ended;
};

// A sensor shape and a shape it overlaps or touches after a step (neither
// pushes the other): bodies and shape indices into body::shapes(). When
// both are sensors, the lower body is `sensor`.
struct sensor_overlap {
  body_id sensor;
  std::size_t sensor_shape;
  body_id other;
  std::size_t other_shape;
};

}  // namespace gaphys
