// gnuplot scripts for the two metrics that read best as curves: M3 (rebound
// apex against e, with the e^2 law) and M6 (step time against N, log-log).
// The scripts carry their data inline, so each is one file to rerun or edit.
#pragma once

#include <string>
#include <vector>

#include "engine_adapter.hpp"
#include "result.hpp"

namespace gaphys_compare {

// Writes m3_restitution.gp and m6_step_time.gp into dir (for the metrics
// that ran) and returns their paths.
std::vector<std::string> write_plot_scripts(const std::string& dir,
                                            const std::vector<engine>& engines,
                                            const std::vector<result>& results);

// Runs gnuplot on each script; false (with a message on stderr) when gnuplot
// is missing or fails.
bool run_gnuplot(const std::vector<std::string>& scripts);

}  // namespace gaphys_compare
