#include "gaphys/detail/thread_choice.hpp"

#include <algorithm>

namespace gaphys::detail {

int thread_choice::next(int setting, int cores) {
  if (setting != 0 || cores <= 1) {
    // (A count the user sets, or one core: nothing to choose. Back at 0,
    // the choice starts over.)
    if (automatic_) *this = thread_choice{};
    return setting != 0 ? setting : 1;
  }
  automatic_ = true;
  if (probe_step_ == 0 && recent_count_ == window) {
    const double median = median_recent();
    if (weighed_median_ > 0 && (median > 2 * weighed_median_ || 2 * median < weighed_median_)) {
      // The world grew or emptied: weighed again once eight of its new
      // steps are timed (against the old ones, one thread's steps of a
      // world just grown looked fast).
      weighed_median_ = 0;
      recent_count_ = 0;
      recent_at_ = 0;
    } else if (weighed_median_ == 0 || steps_to_probe_ == 0) {
      probe_step_ = 1;
    }
  }
  const bool one = probe_step_ > 0 ? !on_one_ : on_one_;
  return one ? 1 : cores;
}

void thread_choice::record(double seconds) {
  if (!automatic_) return;
  if (probe_step_ == 1) {  // (the step that moved the data)
    probe_step_ = 2;
    return;
  }
  if (probe_step_ == 2) {
    probe_step_ = 0;
    weigh(seconds);
    return;
  }
  recent_[static_cast<std::size_t>(recent_at_)] = seconds;
  recent_at_ = (recent_at_ + 1) % window;
  recent_count_ = std::min(recent_count_ + 1, window);
  if (steps_to_probe_ > 0) --steps_to_probe_;
}

void thread_choice::weigh(double probe_seconds) {
  if (probe_seconds < 0.9 * fastest_recent()) {
    // (The new count's steps will be weighed against its probe's.)
    weighed_median_ = probe_seconds;
    on_one_ = !on_one_;
    interval_ = first_interval;
    recent_count_ = 0;
    recent_at_ = 0;
  } else {
    weighed_median_ = median_recent();
    const long growth = probe_seconds > 1.5 * weighed_median_ ? 8 : 2;
    interval_ = std::min(longest_interval, interval_ * growth);
  }
  steps_to_probe_ = interval_;
}

double thread_choice::fastest_recent() const {
  return *std::min_element(recent_.begin(), recent_.begin() + recent_count_);
}

double thread_choice::median_recent() const {
  std::array<double, window> sorted = recent_;
  const auto end = sorted.begin() + recent_count_;
  std::nth_element(sorted.begin(), sorted.begin() + recent_count_ / 2, end);
  return sorted[static_cast<std::size_t>(recent_count_ / 2)];
}

}  // namespace gaphys::detail
