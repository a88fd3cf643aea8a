#include "options.hpp"

#include <sstream>
#include <stdexcept>

namespace gaphys_compare {

namespace {

std::vector<std::string> split(const std::string& list) {
  std::vector<std::string> items;
  std::istringstream in(list);
  for (std::string item; std::getline(in, item, ',');) {
    if (!item.empty()) items.push_back(item);
  }
  return items;
}

double to_number(const std::string& flag, const std::string& text) {
  std::size_t used = 0;
  double value = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || !(value > 0)) {
    throw std::invalid_argument(flag + ": expected a positive number, got '" + text + "'");
  }
  return value;
}

int to_count(const std::string& flag, const std::string& text) {
  const double value = to_number(flag, text);
  if (value != static_cast<int>(value)) {
    throw std::invalid_argument(flag + ": expected a whole number, got '" + text + "'");
  }
  return static_cast<int>(value);
}

// A count that may be 0 (--gaphys-threads 0: every core).
int to_count_or_zero(const std::string& flag, const std::string& text) {
  return text == "0" ? 0 : to_count(flag, text);
}

}  // namespace

const char* usage() {
  return "usage: compare_engines [flags]\n"
         "  --engines LIST        gaphys,bullet,ode-quick,ode-lcp (default: all)\n"
         "  --metrics LIST        m1,m2,m3,m4,m5,m6 (frictionless), f1,f2,f3,f4,f5 (friction),\n"
         "                        b1,b2,b3,b4,b5 (boxes) (default: all)\n"
         "  --m1-steps N          free rotation steps (10000)\n"
         "  --m5-speeds LIST      projectile speeds, m/s (1,2,5,10,20,50,100,200,500)\n"
         "  --m6-sizes LIST       sphere counts (100,300,1000,3000,10000)\n"
         "  --f5-sizes LIST       sphere counts of F5, M6 with friction 0.5 (1000,10000)\n"
         "  --m6-warmup N         steps before timing (120)\n"
         "  --m6-steps N          steps timed per size (100)\n"
         "  --m6-step-budget S    skip a size (and larger) when one step takes > S s (2)\n"
         "  --m6-size-budget S    stop timing a size after S s of timed steps (60)\n"
         "  --stack-seconds S     simulated time of the box tower and pyramid, B3 and B4 (10)\n"
         "  --b5-sizes LIST       box counts of B5, boxes falling into M6's box (100,1000)\n"
         "  --b5-warmup N         B5 steps before timing (360)\n"
         "  --b5-steps N          B5 steps timed (360)\n"
         "  --box-budget S        skip a B3-B5 run (and larger B5 sizes) after S s of wall time\n"
         "                        or a step longer than --m6-step-budget (60)\n"
         "  --gaphys-threads N    gaphys's solver and narrow-phase threads, 0: every core (1)\n"
         "  --gaphys-batches B    gaphys's contact sweeps on SIMD batches: auto, on or off (auto)\n"
         "  --gaphys-turning-sweeps N  gaphys's sweeps beyond 20 for contacts that turn a body\n"
         "                        (world_settings::turning_iterations: 10)\n"
         "  --out-dir DIR         results.csv, results.json, plots (compare-results)\n"
         "  --no-plots            do not run gnuplot\n"
         "The --m6-warmup, --m6-steps and --m6-*-budget flags time F5 too; F1-F4 (one\n"
         "ball each, at most 3 s of steps) and B1-B2 (one box, at most 5 s) have no flags.\n";
}

options parse_options(int argc, char** argv) {
  options o;
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    if (flag == "--help" || flag == "-h") {
      o.help = true;
      continue;
    }
    if (flag == "--no-plots") {
      o.plots = false;
      continue;
    }
    if (i + 1 >= argc) throw std::invalid_argument(flag + ": missing value (or unknown flag)");
    const std::string value = argv[++i];
    if (flag == "--engines") {
      o.engines = split(value);
    } else if (flag == "--metrics") {
      o.metrics = split(value);
    } else if (flag == "--m1-steps") {
      o.m1_steps = to_count(flag, value);
    } else if (flag == "--m5-speeds") {
      o.m5_speeds.clear();
      for (const std::string& item : split(value)) o.m5_speeds.push_back(to_number(flag, item));
    } else if (flag == "--m6-sizes") {
      o.m6_sizes.clear();
      for (const std::string& item : split(value)) o.m6_sizes.push_back(to_count(flag, item));
    } else if (flag == "--f5-sizes") {
      o.f5_sizes.clear();
      for (const std::string& item : split(value)) o.f5_sizes.push_back(to_count(flag, item));
    } else if (flag == "--m6-warmup") {
      o.m6_warmup = to_count(flag, value);
    } else if (flag == "--m6-steps") {
      o.m6_steps = to_count(flag, value);
    } else if (flag == "--m6-step-budget") {
      o.m6_step_budget = to_number(flag, value);
    } else if (flag == "--m6-size-budget") {
      o.m6_size_budget = to_number(flag, value);
    } else if (flag == "--stack-seconds") {
      o.stack_seconds = to_number(flag, value);
    } else if (flag == "--b5-sizes") {
      o.b5_sizes.clear();
      for (const std::string& item : split(value)) o.b5_sizes.push_back(to_count(flag, item));
    } else if (flag == "--b5-warmup") {
      o.b5_warmup = to_count(flag, value);
    } else if (flag == "--b5-steps") {
      o.b5_steps = to_count(flag, value);
    } else if (flag == "--gaphys-threads") {
      o.gaphys_threads = to_count_or_zero(flag, value);
    } else if (flag == "--gaphys-batches") {
      if (value == "auto") {
        o.gaphys_batches = gaphys::contact_batching::automatic;
      } else if (value == "on") {
        o.gaphys_batches = gaphys::contact_batching::on;
      } else if (value == "off") {
        o.gaphys_batches = gaphys::contact_batching::off;
      } else {
        throw std::invalid_argument("--gaphys-batches takes auto, on or off, not " + value);
      }
    } else if (flag == "--gaphys-turning-sweeps") {
      o.gaphys_turning_sweeps = to_count_or_zero(flag, value);
    } else if (flag == "--box-budget") {
      o.box_budget = to_number(flag, value);
    } else if (flag == "--out-dir") {
      o.out_dir = value;
    } else {
      throw std::invalid_argument("unknown flag " + flag);
    }
  }
  return o;
}

}  // namespace gaphys_compare
