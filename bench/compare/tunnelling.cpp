// M5. Without continuous collision detection, a fast sphere can step past
// its target between two steps. A run fires the sphere from 1 m away at one
// speed and checks where it ends: a sphere whose centre ends below the
// floor, or below the target sphere's centre, went through.
//
// Whether it does depends on where the steps happen to fall: from 1 m at
// 100 m/s, one step lands the sphere 0.17 m above the target, just inside
// it, and it bounces; another start would skip it. So each speed is run
// from `phases` starting distances spread over one step's travel, and counts
// as tunnelling when any of them ends below. The speed is reported as v h / r,
// the step's travel in radii, which is independent of the step and the size.
#include <algorithm>
#include <cmath>

#include "metrics.hpp"
#include "number.hpp"
#include "scenes.hpp"

namespace gaphys_compare {

namespace {

// The share of starting phases from which the sphere ends below its target.
double tunnelled_share(const engine& e, double speed, bool sphere_target) {
  constexpr int phases = 32;
  int tunnelled = 0;
  for (int phase = 0; phase < phases; ++phase) {
    scene s = projectile(speed, sphere_target);
    body_description& sphere = s.bodies.back();
    sphere.position.z += speed * time_step * phase / phases;
    auto adapter = e.make();
    adapter->build(s);
    // Time to travel 2 m, then 1 s more for whatever follows the impact.
    const int steps = static_cast<int>(std::ceil(2 / (speed * time_step))) + 240;
    for (int i = 0; i < steps; ++i) adapter->step(time_step);
    if (adapter->state(s.bodies.size() - 1).position.z < 0) ++tunnelled;
  }
  return static_cast<double>(tunnelled) / phases;
}

}  // namespace

void tunnelling(const engine& e, const options& o, recorder& out) {
  constexpr double radius = 0.1;  // scenes.hpp's projectile
  if (o.m5_speeds.empty()) return;
  for (const bool sphere_target : {false, true}) {
    const std::string name = projectile(1, sphere_target).name;
    double lowest = 0;
    for (const double speed : o.m5_speeds) {
      const double share = tunnelled_share(e, speed, sphere_target);
      out.add_detail({name, speed}, "share of start phases that tunnel", share);
      if (share > 0 && (lowest == 0 || speed < lowest)) lowest = speed;
    }
    if (lowest > 0) {
      out.add(name, "lowest tunnelling speed (m/s)", lowest);
      out.add(name, "  as v h / r", lowest * time_step / radius);
    } else {
      const double fastest = *std::max_element(o.m5_speeds.begin(), o.m5_speeds.end());
      out.add_missing(name, "lowest tunnelling speed (m/s)", "none <= " + number(fastest));
      out.add_missing(name, "  as v h / r", "> " + number(fastest * time_step / radius, 3));
    }
  }
}

}  // namespace gaphys_compare
