// How many threads a step runs on where world_settings::threads is 0
// ("every core"): every core, unless one thread is measured faster
// (docs/engine.md, "Threads"). A step computes the same bits on any number
// of threads, so the choice changes the time of a step, never its result.
//
// Where the cores share no cache, every line one thread writes and the
// other reads crosses between them slowly, and a small world's step is
// mostly such crossings: 1,000 spheres took 1.9-2.1 times as long on two
// threads as on one with this machine's two vCPUs 310-330 ns apart (a
// round trip of a cache line), against 0.8 times with them 55 ns apart.
// A process given less processor time than it has cores (a container's
// quota) has its threads wait for each other, and should fare alike (not
// measured here).
//
// So now and then the world steps on the other count: once to move the
// step's data to the cores that will read it (not counted), then once
// more, timed. That step must beat nine tenths of the fastest of the last
// eight on the current count to change it: a count that pays a little
// is kept, as is the count a noisy step would have changed. The first
// probe comes once eight steps are timed. A count kept is weighed again
// twice as many steps later as the last time (eight times as many where
// the probe took over half as long again as the current count's steps),
// from 32, at most 1,024 steps later (near 0.2% of a 10,000-sphere run's
// time spent on the slower count); a count changed, 32 steps later; and
// either anew, once eight steps are timed, when the steps take twice or
// half as long as when it was last weighed (the world grew or emptied).
#pragma once

#include <array>

namespace gaphys::detail {

class thread_choice {
 public:
  // The threads the next step runs on: `setting` where it is not 0; for 0,
  // `cores` or 1, as measured.
  int next(int setting, int cores);
  // The wall-clock seconds that step took.
  void record(double seconds);

  static constexpr int window = 8;           // steps on the current count weighed
  static constexpr long first_interval = 32;  // steps from a probe to the next, at first
  static constexpr long longest_interval = 1024;

 private:
  double fastest_recent() const;
  double median_recent() const;
  void weigh(double probe_seconds);

  bool automatic_ = false;  // the last next() chose (setting 0, more than one core)
  bool on_one_ = false;     // the count chosen is one thread
  int probe_step_ = 0;      // steps of the probe made so far; 0: none under way
  long interval_ = first_interval;
  long steps_to_probe_ = 0;
  double weighed_median_ = 0;  // the current count's steps when last weighed; 0: never
  std::array<double, window> recent_{};
  int recent_count_ = 0;
  int recent_at_ = 0;
};

}  // namespace gaphys::detail
