#include "metrics.hpp"

namespace gaphys_compare {

const std::vector<metric>& all_metrics() {
  static const std::vector<metric> metrics = {
      {"m1", "M1", "torque-free body, inertia (1,2,3), spin (1,2,3) rad/s, no gravity",
       free_rotation},
      {"m2", "M2", "elastic impacts, e = 1 (1 kg and 2 kg spheres; 5-ball cradle)",
       elastic_impacts},
      {"m3", "M3", "rebound of a sphere dropped 2 m (apex / drop height vs e^2)", restitution},
      {"m4", "M4", "resting columns of K spheres (r 0.5) in a tube, 10 s", resting_columns},
      {"m5", "M5", "tunnelling: sphere (r 0.1) fired at a target, no gravity", tunnelling},
      {"m6", "M6", "N spheres (r 0.1) falling into a box: wall time per step", step_time},
      {"f1", "F1", "sliding to rolling: ball (r 0.5) launched at 5 m/s without spin, mu 0.3, 3 s",
       sliding_to_rolling},
      {"f2", "F2", "backspin: ball (r 0.5) at v0 2 m/s, spin about -y, mu 0.3, 3 s", backspin},
      {"f3", "F3", "ball (r 0.5) released on a 30 deg slope, 2 s (n = 480 steps)", incline},
      {"f4", "F4", "isotropy: ball (r 0.5) sliding at 5 m/s, mu 0.3, first 0.2 s",
       friction_isotropy},
      {"f5", "F5", "M6 with friction 0.5 on every sphere and plane: wall time per step",
       friction_step_time},
      {"b1", "B1", "unit box (1 kg) on a 20 deg slope: held (mu 0.5, 5 s), sliding (mu 0.2, 2 s)",
       box_incline},
      {"b2", "B2", "unit box sliding at 3 m/s on a floor, mu 0.4, to a stop (3 s)", sliding_box},
      {"b3", "B3", "tower of 10 unit boxes, exactly touching, mu 0.5: drift", box_tower},
      {"b4", "B4", "pyramid of 55 unit boxes (base 10, 5 mm gaps in a row), mu 0.5: drift",
       box_pyramid},
      {"b5", "B5", "N boxes (half extent 0.25, mu 0.5) falling into M6's box: wall time per step",
       falling_boxes},
  };
  return metrics;
}

}  // namespace gaphys_compare
