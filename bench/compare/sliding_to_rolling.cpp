// F1. A ball launched sliding without spin on a floor with friction μ:
// kinetic friction μ m g slows the centre at μ g and spins the ball up at
// 5 μ g / (2 r) until its contact point stops, at t* = 2 v0 / (7 μ g); then
// it rolls at 5/7 v0 for ever (no rolling resistance). Friction leaves the
// angular momentum about the contact point unchanged, so 5/7 v0 holds after
// the discrete steps too, and the slip, which falls by 7/2 μ g h per step,
// should vanish in the first step after t*, step ceil(t* / h).
#include <algorithm>
#include <cmath>

#include "mechanics.hpp"
#include "metrics.hpp"
#include "number.hpp"
#include "scenes.hpp"

namespace gaphys_compare {

void sliding_to_rolling(const engine& e, const options&, recorder& out) {
  constexpr double v0 = 5, mu = 0.3, stopped = 1e-6;  // m/s, -, m/s
  constexpr int steps = 720;                          // 3 s
  const scene s = sphere_on_floor("v0 5, mu 0.3", {v0, 0, 0}, {}, mu);
  const double g = -s.gravity.z;
  const double rolling_at = 2 * v0 / (7 * mu * g) / time_step;  // t* in steps
  const scene_label label{s.name + " (t*/h " + number(rolling_at, 5) + ")", mu};

  auto adapter = e.make();
  adapter->build(s);
  int first_rolling = 0;
  double least_slip = v0;
  body_state state;
  for (int i = 1; i <= steps; ++i) {
    adapter->step(time_step);
    state = adapter->state(0);
    const double slip = norm(contact_slip(s.bodies[0], state, s.planes[0]));
    if (first_rolling == 0 && slip < stopped) first_rolling = i;
    least_slip = std::min(least_slip, slip);
  }
  const double rolling_speed = 5.0 / 7 * v0;
  out.add(label, "|v(3 s) / (5/7 v0) - 1|", std::abs(state.velocity.x / rolling_speed - 1));
  if (first_rolling > 0) {
    out.add(label, "first step with |slip| < 1e-6 m/s", first_rolling);
    out.add(label, "  minus t*/h (ideal: ceil(t*/h) - t*/h)", first_rolling - rolling_at);
  } else {
    out.add_missing(label, "first step with |slip| < 1e-6 m/s",
                    "none in 3 s (least " + number(least_slip, 2) + ")");
    out.add_missing(label, "  minus t*/h (ideal: ceil(t*/h) - t*/h)", "-");
  }
  out.add_detail(label, "vx at 3 s (m/s)", state.velocity.x);
  out.add_detail(label, "|slip| at 3 s (m/s)", norm(contact_slip(s.bodies[0], state, s.planes[0])));
  out.add_detail(label, "|v| off the x axis at 3 s (m/s)",
                 std::hypot(state.velocity.y, state.velocity.z));
}

}  // namespace gaphys_compare
