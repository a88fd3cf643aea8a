// B1. A unit box released from rest with a face on a 20° slope. Static
// friction holds it when μ >= tan 20° = 0.364, so with μ 0.5 it should not
// move at all: its drift over 5 s is what the solver lets creep. With μ 0.2
// it slides at a = g (sin θ - μ cos θ) = 1.511 m/s²; as in F3, semi-implicit
// Euler (v_n = n a h, x_n = x_{n-1} + h v_n) moves it d_n = a h² n (n + 1) / 2
// in n steps, what an exact contact solve gives, and ½ a t² is the
// continuous answer (0.21% less at 2 s). Friction acts on the bottom face,
// 0.5 m below the centre, so the centre of pressure moves downhill by 0.5 m
// times friction / normal force (0.1 m sliding, 0.18 m held), well inside
// the face: the box must not tip, and its tilt (the angle between its face
// normal and the slope's) should stay 0.
#include <algorithm>
#include <cmath>

#include "metrics.hpp"
#include "number.hpp"
#include "overlap.hpp"
#include "scenes.hpp"

namespace gaphys_compare {

namespace {

constexpr double degrees = 20;

// Steps the box on the slope, returning its state at the end, the largest
// tilt (rad) and the largest depth below the slope (m) on the way.
body_state slide(const engine& e, const scene& s, int steps, double& tilt, double& depth) {
  auto adapter = e.make();
  adapter->build(s);
  const plane_description& slope = s.planes[0];
  tilt = depth = 0;
  body_state state;
  for (int i = 0; i < steps; ++i) {
    adapter->step(time_step);
    state = adapter->state(0);
    tilt = std::max(tilt, angle_between(rotate(state.attitude, {0, 0, 1}), slope.normal));
    depth = std::max(depth, plane_depth({&s.bodies[0], state.position, state.attitude}, slope));
  }
  return state;
}

}  // namespace

void box_incline(const engine& e, const options&, recorder& out) {
  double tilt = 0, depth = 0;
  {
    constexpr int steps = 1200;  // 5 s
    const scene s = box_on_incline(degrees, 0.5);
    const scene_label label{s.name + ", holds (tan 20 = 0.364)", 0.5};
    const body_state end = slide(e, s, steps, tilt, depth);
    out.add(label, "drift in 5 s (m)", norm(end.position - s.bodies[0].position));
    out.add(label, "max tilt (rad)", tilt);
    out.add(label, "max depth (m)", depth);
    out.add_detail(label, "|v| at 5 s (m/s)", norm(end.velocity));
  }
  {
    constexpr int steps = 480;  // 2 s
    constexpr double mu = 0.2;
    const scene s = box_on_incline(degrees, mu);
    const double g = -s.gravity.z, angle = std::acos(s.planes[0].normal.z);
    const double a = g * (std::sin(angle) - mu * std::cos(angle));
    const double n = steps, t = steps * time_step;
    const double discrete = a * time_step * time_step * n * (n + 1) / 2;
    const double continuous = 0.5 * a * t * t;
    const scene_label label{s.name + ", slides (a " + number(a, 4) + " m/s^2, d_n " +
                                number(discrete, 5) + " m, 1/2 a t^2 " + number(continuous, 5) +
                                " m)",
                            mu};
    const body_state end = slide(e, s, steps, tilt, depth);
    const vec3 moved = end.position - s.bodies[0].position;
    const double d = dot(moved, down_the_incline(degrees));
    out.add(label, "distance down the slope at 2 s (m)", d);
    out.add(label, "d / d_n - 1", d / discrete - 1);
    out.add(label, "d / (1/2 a t^2) - 1", d / continuous - 1);
    out.add(label, "max tilt (rad)", tilt);
    out.add(label, "max depth (m)", depth);
    out.add_detail(label, "|sideways drift| at 2 s (m)", std::abs(moved.y));
  }
}

}  // namespace gaphys_compare
