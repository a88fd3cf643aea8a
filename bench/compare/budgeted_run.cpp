#include "budgeted_run.hpp"

#include "metrics.hpp"
#include "number.hpp"
#include "timing.hpp"

namespace gaphys_compare {

namespace {

double percentile_ms(const std::vector<double>& seconds, double p, std::size_t first) {
  if (first >= seconds.size()) return no_number;
  std::vector<double> samples(seconds.begin() + static_cast<std::ptrdiff_t>(first), seconds.end());
  return 1e3 * percentile(samples, p);
}

}  // namespace

budgeted_run::budgeted_run(const engine& e, const scene& s, const options& o)
    : adapter_(e.make()), step_budget_(o.m6_step_budget), total_budget_(o.box_budget) {
  adapter_->build(s);
}

bool budgeted_run::step() {
  if (over_budget()) return false;
  const double processor_start = processor_seconds();
  const double seconds = timed_step(*adapter_, time_step);
  processor_seconds_.push_back(processor_seconds() - processor_start);
  wall_seconds_.push_back(seconds);
  spent_ += seconds;
  if (seconds > step_budget_) {
    why_over_ = "skipped (a step > " + number(step_budget_) + " s)";
  } else if (spent_ > total_budget_) {
    why_over_ = "skipped (> " + number(total_budget_) + " s)";
  }
  return !over_budget();
}

double budgeted_run::wall_ms(double p, std::size_t first) const {
  return percentile_ms(wall_seconds_, p, first);
}

double budgeted_run::processor_ms(double p, std::size_t first) const {
  return percentile_ms(processor_seconds_, p, first);
}

void budgeted_run::report(recorder& out, const scene_label& label,
                          const std::vector<row>& rows) const {
  for (const row& r : rows) {
    if (over_budget()) {
      if (!r.detail) out.add_missing(label, r.quantity, why_over_);
    } else if (r.detail) {
      out.add_detail(label, r.quantity, r.value);
    } else {
      out.add(label, r.quantity, r.value);
    }
  }
}

}  // namespace gaphys_compare
