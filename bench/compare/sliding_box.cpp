// B2. A unit box launched at v0 = 3 m/s on a floor with friction μ 0.4
// slows at μ g and stops after v0² / (2 μ g) = 1.147 m, at 0.76 s. Semi-
// implicit Euler takes off μ g h per step until the speed left is less than
// that, which the last step removes without moving: after
// K = floor(v0 / (μ g h)) moving steps the box has gone
// d_K = h (K v0 - μ g h K (K + 1) / 2), what an exact contact solve gives.
// It slides along a face normal (yaw 0) and at 45° to the face normals (the
// box turned 45° about z, still sliding along x, so ODE's friction pyramid,
// whose axes are x and y here, plays no part). Friction at the bottom face
// tries to tip the box forward; it shifts the centre of pressure by
// 0.5 μ = 0.2 m, inside the face, so the box must not tilt. Once stopped it
// must stay still: static friction holds it with no force left to resist.
#include <algorithm>
#include <cmath>

#include "mechanics.hpp"
#include "metrics.hpp"
#include "number.hpp"
#include "overlap.hpp"
#include "scenes.hpp"

namespace gaphys_compare {

void sliding_box(const engine& e, const options&, recorder& out) {
  constexpr double v0 = 3, mu = 0.4, pi = 3.14159265358979323846;
  constexpr int settled = 360, steps = 720;  // stopped by 1.5 s, watched until 3 s
  for (const double yaw : {0.0, 45.0}) {
    const scene s = sliding_box(v0, yaw, mu);
    const double g = -s.gravity.z, dv = mu * g * time_step;
    const double moving_steps = std::floor(v0 / dv);
    const double discrete =
        time_step * (moving_steps * v0 - dv * moving_steps * (moving_steps + 1) / 2);
    const double continuous = v0 * v0 / (2 * mu * g);
    const scene_label label{s.name +
                                (yaw == 0 ? " (along a face normal" : " (at 45 deg to the faces") +
                                ", mu 0.4, d_K " + number(discrete, 5) + " m, v0^2/(2 mu g) " +
                                number(continuous, 5) + " m)",
                            yaw};

    auto adapter = e.make();
    adapter->build(s);
    const body_description& box = s.bodies[0];
    double tilt = 0, depth = 0, speed_after = 0, spin_after = 0;
    body_state state, at_stop;
    for (int i = 1; i <= steps; ++i) {
      adapter->step(time_step);
      state = adapter->state(0);
      tilt = std::max(tilt, angle_between(rotate(state.attitude, {0, 0, 1}), {0, 0, 1}));
      depth = std::max(depth, plane_depth({&box, state.position, state.attitude}, s.planes[0]));
      if (i == settled) at_stop = state;
      if (i > settled) {
        speed_after = std::max(speed_after, norm(state.velocity));
        spin_after = std::max(spin_after, norm(state.angular_velocity));
      }
    }
    const vec3 moved = horizontal(at_stop.position - box.position);
    const double d = moved.x;
    out.add(label, "stop distance at 1.5 s (m)", d);
    out.add(label, "d / d_K - 1", d / discrete - 1);
    out.add(label, "d / (v0^2 / (2 mu g)) - 1", d / continuous - 1);
    out.add(label, "max tilt (rad)", tilt);
    out.add(label, "drift from 1.5 s to 3 s (m)", norm(state.position - at_stop.position));
    out.add(label, "max |v| after 1.5 s (m/s)", speed_after);
    out.add_detail(label, "max |w| after 1.5 s (rad/s)", spin_after);
    out.add_detail(label, "|sideways drift| at 1.5 s (m)", std::abs(moved.y));
    // The turn about z, from the box's x axis seen from above.
    const vec3 axis = rotate(at_stop.attitude, {1, 0, 0});
    out.add_detail(label, "yaw change at 1.5 s (deg)", std::atan2(axis.y, axis.x) * 180 / pi - yaw);
    out.add_detail(label, "max depth (m)", depth);
  }
}

}  // namespace gaphys_compare
