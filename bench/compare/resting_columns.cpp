// M4. A column of spheres resting on a floor is held up by a chain of
// contacts the solver must settle together. The harness measures how far
// the spheres sink into each other and the floor (from positions, the same
// way for every engine) and what motion is left after 10 s.
#include <algorithm>

#include "mechanics.hpp"
#include "metrics.hpp"
#include "overlap.hpp"
#include "scenes.hpp"

namespace gaphys_compare {

void resting_columns(const engine& e, const options&, recorder& out) {
  constexpr int steps = 2400;  // 10 s
  for (const int count : {1, 2, 5, 10}) {
    const scene s = sphere_column(count);
    const double radius = s.bodies[0].radius;
    auto adapter = e.make();
    adapter->build(s);
    double deepest = 0, last = 0;
    for (int i = 0; i < steps; ++i) {
      adapter->step(time_step);
      last = deepest_overlap(s, states_of(*adapter, s));
      deepest = std::max(deepest, last);
    }
    out.add(s.name, "max depth / r", deepest / radius);
    out.add(s.name, "final depth / r", last / radius);
    out.add(s.name, "final kinetic energy (J)", total_kinetic_energy(s, states_of(*adapter, s)));
  }
}

}  // namespace gaphys_compare
