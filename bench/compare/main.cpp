// compare_engines: the same scenes in gaphys, Bullet and ODE, at the same
// step (1/240 s), single threaded, with parameters matched as the printed
// settings explain; measures accuracy (M1-M5) and speed (M6) and writes a
// table, results.csv, results.json and gnuplot plots. `--help` lists the flags.
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <stdexcept>

#include "bullet_adapter.hpp"
#include "gaphys_adapter.hpp"
#include "metrics.hpp"
#include "ode_adapter.hpp"
#include "options.hpp"
#include "plots.hpp"
#include "report.hpp"

namespace {

using namespace gaphys_compare;

// An empty list selects everything.
bool selected(const std::vector<std::string>& wanted, const std::string& name) {
  return wanted.empty() || std::find(wanted.begin(), wanted.end(), name) != wanted.end();
}

int run(const options& o) {
  std::vector<engine> engines;
  for (engine e :
       {gaphys_engine(o.gaphys_threads, o.gaphys_batches, o.gaphys_turning_sweeps), bullet_engine(),
        ode_engine(ode_stepper::quick), ode_engine(ode_stepper::direct)}) {
    if (selected(o.engines, e.name)) engines.push_back(std::move(e));
  }
  if (engines.empty()) throw std::invalid_argument("--engines selects no engine");

  std::vector<result> results;
  for (const metric& m : all_metrics()) {
    if (!selected(o.metrics, m.id)) continue;
    for (const engine& e : engines) {
      std::cerr << m.label << " " << e.name << "\n";
      recorder out(m.label, e.name, results);
      m.run(e, o, out);
    }
  }

  print_parameters(std::cout, engines);
  print_table(std::cout, engines, results);

  std::filesystem::create_directories(o.out_dir);
  write_csv(o.out_dir + "/results.csv", results);
  write_json(o.out_dir + "/results.json", o, engines, results);
  const std::vector<std::string> scripts = write_plot_scripts(o.out_dir, engines, results);
  const bool plotted = o.plots && !scripts.empty() && run_gnuplot(scripts);
  std::cout << "\nwrote " << o.out_dir << "/results.csv, results.json";
  for (const std::string& s : scripts) {
    std::cout << ", " << std::filesystem::path(s).filename().string();
  }
  std::cout << (plotted ? " and their PNGs" : "") << "\n";
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const options o = parse_options(argc, argv);
    if (o.help) {
      std::cout << usage();
      return 0;
    }
    return run(o);
  } catch (const std::invalid_argument& error) {
    std::cerr << "compare_engines: " << error.what() << "\n" << usage();
    return 2;
  } catch (const std::exception& error) {
    std::cerr << "compare_engines: " << error.what() << "\n";
    return 1;
  }
}
