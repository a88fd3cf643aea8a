// Results built without zeroing first. gaphys::ga::uninitialized asks a
// generated basic_mv to leave its coefficients indeterminate, for code that
// writes every one of them next: the profiled kernels, which write their
// values one by one and the runs of zeros between them with set_zero.
#pragma once

#include <array>
#include <cstddef>

namespace gaphys::ga {

struct uninitialized_t {
  explicit uninitialized_t() = default;
};
inline constexpr uninitialized_t uninitialized{};

// c[Begin .. Begin + Count) = 0. An unrolled loop, which compilers turn into
// vector stores; a run of single zero assignments became one scalar store each.
template <int Begin, int Count, class T, std::size_t N>
inline void set_zero(std::array<T, N>& c) {
  static_assert(Begin >= 0 && Count > 0 && Begin + Count <= int(N),
                "set_zero: run outside the array");
#pragma GCC unroll 64
  for (int i = Begin; i < Begin + Count; ++i) c[i] = T(0);
}

}  // namespace gaphys::ga
