// M3. Dropped from rest from height h onto a plane, a sphere with restitution
// e rebounds at e times its impact speed and so rises to e^2 h. The engines
// detect the floor a fraction of a step late and handle the overlap each in
// its own way; apex / h against e^2 shows the effect on the bounce. For
// e = 1 every apex should equal the first; apex 20 / apex 1 shows the drift.
#include <algorithm>
#include <vector>

#include "metrics.hpp"
#include "number.hpp"
#include "scenes.hpp"

namespace gaphys_compare {

namespace {

constexpr double drop_height = 2;  // m, of the sphere's bottom (scenes::bouncing_sphere)

// The heights of the sphere's bottom at the tops of its first `count`
// rebounds, for at most `seconds`. A rebound starts when the vertical
// velocity turns from down to up (the contact) and ends at the first step
// it points down again; its apex is the highest bottom in between. A rise
// still going on when time runs out counts with the height reached (e = 0).
std::vector<double> rebound_apexes(const engine& e, const scene& s, int count, double seconds) {
  auto adapter = e.make();
  adapter->build(s);
  const double radius = s.bodies[0].radius;
  std::vector<double> apexes;
  bool rising = false;
  double previous_vz = 0, apex = 0;
  const int steps = static_cast<int>(seconds / time_step);
  for (int i = 0; i < steps && static_cast<int>(apexes.size()) < count; ++i) {
    adapter->step(time_step);
    const body_state state = adapter->state(0);
    const double vz = state.velocity.z, bottom = state.position.z - radius;
    if (!rising && previous_vz < 0 && vz >= 0) {
      rising = true;
      apex = bottom;
    }
    if (rising) {
      apex = std::max(apex, bottom);
      if (vz < 0) {
        apexes.push_back(apex);
        rising = false;
      }
    }
    previous_vz = vz;
  }
  if (rising) apexes.push_back(apex);
  return apexes;
}

}  // namespace

void restitution(const engine& e, const options&, recorder& out) {
  for (const double restitution : {0.0, 0.3, 0.5, 0.8, 0.95, 1.0}) {
    const scene s = bouncing_sphere(restitution);
    const scene_label label{s.name + " (e^2 " + number(restitution * restitution, 4) + ")",
                            restitution};
    // Falling 2 m takes 0.64 s and a bounce of e = 1 about 1.28 s: 20
    // rebounds fit in 28 s; 3 s holds the first rebound of any e.
    const bool drift = restitution == 1;
    const std::vector<double> apexes = rebound_apexes(e, s, drift ? 20 : 1, drift ? 30 : 3);
    if (apexes.empty()) {
      out.add_missing(label, "apex 1 / h", "no rebound");
      continue;
    }
    out.add(label, "apex 1 / h", apexes[0] / drop_height);
    if (drift) {
      if (apexes.size() == 20) {
        out.add(label, "apex 20 / apex 1", apexes[19] / apexes[0]);
      } else {
        out.add_missing(label, "apex 20 / apex 1",
                        "only " + number(static_cast<double>(apexes.size())) + " rebounds");
      }
    }
  }
}

}  // namespace gaphys_compare
