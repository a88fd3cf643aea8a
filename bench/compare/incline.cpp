// F3. A ball released from rest on a 30° slope. With μ >= 2/7 tan θ static
// friction makes it roll without slipping, a = 5/7 g sin θ; below that it
// slides, a = g (sin θ - μ cos θ). Either way the acceleration is constant,
// and semi-implicit Euler (v_n = n a h, x_n = x_{n-1} + h v_n) moves it
// d_n = a h² n (n + 1) / 2 in n steps: ½ a t² (1 + h / t), 0.21% beyond the
// continuous answer at 2 s. Every engine integrates that way, so d_n is
// what a solver that gets the contact exactly right returns.
#include <cmath>

#include "mechanics.hpp"
#include "metrics.hpp"
#include "number.hpp"
#include "scenes.hpp"

namespace gaphys_compare {

void incline(const engine& e, const options&, recorder& out) {
  constexpr double degrees = 30;
  constexpr int steps = 480;  // 2 s
  for (const double mu : {0.5, 0.05}) {
    const scene s = sphere_on_incline(degrees, mu);
    const double g = -s.gravity.z, angle = std::acos(s.planes[0].normal.z);  // the tilt
    const bool rolls = mu >= 2.0 / 7 * std::tan(angle);
    const double a =
        rolls ? 5.0 / 7 * g * std::sin(angle) : g * (std::sin(angle) - mu * std::cos(angle));
    const double n = steps, t = steps * time_step;
    const double discrete = a * time_step * time_step * n * (n + 1) / 2;
    const double continuous = 0.5 * a * t * t;
    const scene_label label{s.name + (rolls ? ", rolls" : ", slides") + " (a " + number(a, 4) +
                                " m/s^2, d_n " + number(discrete, 5) + " m, 1/2 a t^2 " +
                                number(continuous, 5) + " m)",
                            mu};

    auto adapter = e.make();
    adapter->build(s);
    const vec3 start = adapter->state(0).position;
    for (int i = 0; i < steps; ++i) adapter->step(time_step);
    const body_state state = adapter->state(0);
    const double d = dot(state.position - start, down_the_incline(degrees));
    out.add(label, "distance down the slope at 2 s (m)", d);
    out.add(label, "d / d_n - 1", d / discrete - 1);
    out.add_detail(label, "d / (1/2 a t^2) - 1", d / continuous - 1);
    out.add_detail(label, "|slip| at 2 s (m/s)",
                   norm(contact_slip(s.bodies[0], state, s.planes[0])));
  }
}

}  // namespace gaphys_compare
