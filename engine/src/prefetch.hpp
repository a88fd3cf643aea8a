// Asking for memory a loop will read a few items later, where the loop's
// order says nothing the processor could guess: a contact's bodies and
// constraint, reached through an index. On two cores that hand a cache
// line over in 110-185 ns (the 2-core Xeon of the benchmarks), such reads
// of what the other core wrote were a tenth of building 10,000 spheres'
// constraints.
#pragma once

#include <cstddef>

#include "gaphys/ga/compiler.hpp"

namespace gaphys::detail {

// How many items ahead the loops below ask: far enough for a line to come
// from the other core, near enough to stay in the first-level cache.
inline constexpr std::size_t prefetch_distance = 16;

GAPHYS_ALWAYS_INLINE void prefetch(const void* at) {
#if defined(__GNUC__)
  __builtin_prefetch(at);
#else
  static_cast<void>(at);
#endif
}

// Each cache line of the bytes [first, first + bytes) (lines of 64 bytes).
GAPHYS_ALWAYS_INLINE void prefetch_bytes(const void* first, std::size_t bytes) {
  const char* begin = static_cast<const char*>(first);
  for (std::size_t at = 0; at < bytes; at += 64) prefetch(begin + at);
  prefetch(begin + bytes - 1);
}

}  // namespace gaphys::detail
