// A run of one scene on one engine that times each step and gives up once
// it has cost too much wall time (options::box_budget in all, or
// options::m6_step_budget in one step): the box scenes run every engine for
// the same simulated time, and ODE's direct solver can take minutes where the
// others take seconds.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "engine_adapter.hpp"
#include "options.hpp"
#include "result.hpp"

namespace gaphys_compare {

class budgeted_run {
 public:
  budgeted_run(const engine& e, const scene& s, const options& o);

  // One step of time_step; false, without stepping, once over budget.
  bool step();
  bool over_budget() const { return !why_over_.empty(); }
  const engine_adapter& adapter() const { return *adapter_; }

  // The p-th percentile (nearest rank, p in (0, 1]; 0.5 the median), in ms,
  // of the steps from step `first` on (NaN when there are none): of their
  // wall times, and of their processor times (timing.hpp), which hold
  // steady on a busy machine.
  double wall_ms(double p, std::size_t first = 0) const;
  double processor_ms(double p, std::size_t first = 0) const;

  // One number of the run's results.
  struct row {
    std::string quantity;
    double value;
    bool detail = false;
  };
  // Adds the rows, or, when the run went over budget, each row's quantity
  // without a number and why.
  void report(recorder& out, const scene_label& label, const std::vector<row>& rows) const;

 private:
  std::unique_ptr<engine_adapter> adapter_;
  double step_budget_, total_budget_, spent_ = 0;
  std::vector<double> wall_seconds_, processor_seconds_;  // of each step
  std::string why_over_;
};

}  // namespace gaphys_compare
