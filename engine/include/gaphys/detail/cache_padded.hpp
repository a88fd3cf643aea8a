// A value that one thread writes while other threads write the values
// beside it in an array (each thread's share of a result, a list it grows):
// on cache lines of its own.
//
// Side by side, the lists' ends shared a cache line, and every append by
// one thread took that line from the other's core: meeting the pairs of
// 10,000 spheres took 1.9 times one thread's processor time on two, the
// broad phase's appends 5 times (2026-12-06, a 2-core Xeon whose cores
// hand a line over in 110-185 ns). 128 bytes, not 64: a core fetches the
// neighbouring line of each line it misses along with it.
#pragma once

namespace gaphys::detail {

template <class T>
struct alignas(128) cache_padded {
  T value;
};

}  // namespace gaphys::detail
