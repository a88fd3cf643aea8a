// The median of a benchmark's own timings (the middle one of an odd count,
// the upper middle of an even one), for figures taken by hand rather than
// by Google Benchmark's repetitions.
#pragma once

#include <algorithm>
#include <vector>

namespace gaphys_bench {

inline double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

}  // namespace gaphys_bench
