// F2. A ball moving at v0 along +x with backspin ω0: spin about -y, so its
// contact point slides forward at v0 + r ω0 (ω × (-r e_z) = +r ω0 e_x).
// Friction acts at the contact point, so the angular momentum about it,
// m r v - 2/5 m r² ω0, is kept until the ball rolls: then (7/5) m r v, so
// v_final = (5 v0 - 2 r ω0) / 7, exact for the discrete steps too. With
// 2 r ω0 > 5 v0 the ball stops and comes back.
#include <cmath>
#include <string>

#include "mechanics.hpp"
#include "metrics.hpp"
#include "number.hpp"
#include "scenes.hpp"

namespace gaphys_compare {

void backspin(const engine& e, const options&, recorder& out) {
  constexpr double v0 = 2, mu = 0.3, radius = 0.5;  // sphere_on_floor's ball
  constexpr int steps = 720;                        // 3 s; the slowest rolls after 0.9 s
  // 2 r ω0 (m/s): a forward roll, one that nearly stops, and one that comes back.
  for (const double spin_speed : {4.0, 8.0, 14.0}) {
    const double omega = spin_speed / (2 * radius);
    const double closed = (5 * v0 - spin_speed) / 7;
    const scene s =
        sphere_on_floor("2 r w0 " + number(spin_speed) + " m/s", {v0, 0, 0}, {0, -omega, 0}, mu);
    const scene_label label{s.name + " (v_final " + number(closed, 4) + ")", spin_speed};
    auto adapter = e.make();
    adapter->build(s);
    for (int i = 0; i < steps; ++i) adapter->step(time_step);
    const body_state state = adapter->state(0);
    out.add(label, "vx at 3 s (m/s)", state.velocity.x);
    out.add(label, "vx / v_final - 1", state.velocity.x / closed - 1);
    out.add_detail(label, "|slip| at 3 s (m/s)",
                   norm(contact_slip(s.bodies[0], state, s.planes[0])));
  }
}

}  // namespace gaphys_compare
