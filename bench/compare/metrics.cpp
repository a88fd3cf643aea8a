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
  };
  return metrics;
}

}  // namespace gaphys_compare
