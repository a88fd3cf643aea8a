// F4. Coulomb friction is isotropic: a ball sliding on a floor slows at μ g
// whichever way it slides, and friction opposes the slip, so it keeps its
// heading. The ball (v0 5 m/s, no spin, μ 0.3) still slides at 0.2 s (it
// rolls from 0.49 s on), so over 48 steps |Δv| = 48 μ g h exactly. An
// engine that bounds friction per tangent axis (a pyramid) gives up to √2
// times that, and turns the ball, when it slides between its axes.
#include <cmath>

#include "mechanics.hpp"
#include "metrics.hpp"
#include "number.hpp"
#include "scenes.hpp"

namespace gaphys_compare {

void friction_isotropy(const engine& e, const options&, recorder& out) {
  constexpr double v0 = 5, mu = 0.3, pi = 3.14159265358979323846;
  constexpr int steps = 48;  // 0.2 s
  for (const double degrees : {0.0, 30.0, 45.0}) {
    const double angle = degrees * pi / 180;
    const vec3 v{v0 * std::cos(angle), v0 * std::sin(angle), 0};
    const scene s = sphere_on_floor(number(degrees) + " deg to x", v, {}, mu);
    const scene_label label{s.name, degrees};
    auto adapter = e.make();
    adapter->build(s);
    for (int i = 0; i < steps; ++i) adapter->step(time_step);
    const vec3 after = horizontal(adapter->state(0).velocity);
    const double g = -s.gravity.z, t = steps * time_step;
    out.add(label, "|dv| / (t mu g) - 1", norm(after - v) / (t * mu * g) - 1);
    // The signed turn from v0 to v(t), positive anticlockwise seen from above.
    const double turn = std::atan2(cross(v, after).z, dot(v, after));
    out.add(label, "heading change (deg)", turn * 180 / pi);
  }
}

}  // namespace gaphys_compare
