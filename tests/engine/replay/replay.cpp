// Replay: runs the catalogue scenes (all but the box pyramid) for a number
// of steps and prints, per scene, the state hash and every body's state in
// full precision. compare_replays.py runs it twice per variant (reruns must
// agree to the bit) and compares the variants with each other.
//
//   replay STEPS
#include <cstdio>
#include <cstdlib>

#include "gaphys/scenes.hpp"

int main(int argc, char** argv) {
  const long steps = argc == 2 ? std::strtol(argv[1], nullptr, 10) : 0;
  if (steps <= 0) {
    std::fprintf(stderr, "usage: replay STEPS\n");
    return 2;
  }
  for (const gaphys::scenes::entry& scene : gaphys::scenes::catalogue()) {
    // 400 box contacts: 1200 steps of the reference variant take ~10 s, and
    // the scene's contacts are the tower's kind (engine_stack_tests runs it).
    if (scene.name == "box_pyramid") continue;
    gaphys::world w = scene.build();
    for (long i = 0; i < steps; ++i) w.step(gaphys::scenes::time_step);
    std::printf("scene %s %016llx\n", scene.name.c_str(),
                static_cast<unsigned long long>(w.state_hash()));
    for (std::size_t id = 0; id < w.body_count(); ++id) {
      const gaphys::body& b = w.at(id);
      std::printf("body %zu", id);
      for (double x : b.position().c) std::printf(" %.17g", x);
      for (double x : b.velocity().c) std::printf(" %.17g", x);
      for (double x : b.attitude().c) std::printf(" %.17g", x);
      for (double x : b.angular_velocity().c) std::printf(" %.17g", x);
      std::printf("\n");
    }
  }
  return 0;
}
