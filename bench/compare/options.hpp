// The command line: which engines and metrics to run, how long, and where
// the results go. Every default is the full comparison; the flags exist so a
// quick run (the smoke test, a check while editing) takes seconds.
#pragma once

#include <string>
#include <vector>

#include "gaphys/world.hpp"

namespace gaphys_compare {

struct options {
  std::vector<std::string> engines;  // empty: all
  std::vector<std::string> metrics;  // empty: all (m1 .. m6, f1 .. f5, b1 .. b5)
  int m1_steps = 10000;
  std::vector<double> m5_speeds{1, 2, 5, 10, 20, 50, 100, 200, 500};  // m/s
  std::vector<int> m6_sizes{100, 300, 1000, 3000, 10000};
  std::vector<int> f5_sizes{1000, 10000};  // M6's scene with friction
  // The timing settings below apply to M6 and F5 alike.
  int m6_warmup = 120;  // steps before timing: the spheres have landed
  int m6_steps = 100;   // steps timed per size
  // A size is skipped, with every larger one, when one of its steps takes
  // longer than this (s); the timing of a size stops early (after at least
  // 10 steps) once its timed steps add up to m6_size_budget seconds.
  double m6_step_budget = 2;
  double m6_size_budget = 60;
  // The box scenes: B3 and B4 stand for stack_seconds; B5 runs b5_warmup
  // steps (the boxes land), then times b5_steps more. A B3-B5 run whose
  // wall time passes box_budget seconds, or one of whose steps takes longer
  // than m6_step_budget, is abandoned and reported as skipped (with every
  // larger B5 size), since numbers from a shorter run would not compare.
  double stack_seconds = 10;
  std::vector<int> b5_sizes{100, 1000};
  int b5_warmup = 360;  // 1.5 s
  int b5_steps = 360;   // 1.5 s
  double box_budget = 60;
  // gaphys's world_settings::threads: 1, as Bullet and ODE run here (0:
  // every core, gaphys's default).
  int gaphys_threads = 1;
  // gaphys's world_settings::batch_contacts (the sweeps on SIMD batches).
  gaphys::contact_batching gaphys_batches = gaphys::contact_batching::automatic;
  // gaphys's world_settings::turning_iterations, or < 0: its default.
  int gaphys_turning_sweeps = -1;
  std::string out_dir = "compare-results";
  bool plots = true;
  bool help = false;
};

// Throws std::invalid_argument naming the bad flag.
options parse_options(int argc, char** argv);
const char* usage();

}  // namespace gaphys_compare
