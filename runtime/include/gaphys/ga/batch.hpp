// Batches: W values of a named type in one, each coordinate a pack of W
// lanes (std::experimental::fixed_size_simd), so that a named-type kernel
// runs on W values at once. The generated <algebra>/batch.hpp names them
// (c3ga::dual_sphere_batch<4>); this header holds what every algebra shares:
// the pack, moving values in and out of lanes, and the scalar helpers'
// batch forms.
//
// Straight-line kernels (the optimized variant's polynomials) run on the
// packs themselves. Kernels with branches or the general mv path (exp, log,
// the reference variant) run lane by lane; a kernel whose result is an mv
// has no batch form.
#pragma once

#include <array>
#include <experimental/simd>
#include <stdexcept>
#include <type_traits>

#include "batch_traits.hpp"

namespace gaphys::ga {

template <class T, int W>
using batch = std::experimental::fixed_size_simd<T, W>;

// Lanes of T the target's widest vector registers hold (4 doubles with AVX2,
// 2 with SSE2): a batch of this width is one register a coordinate.
template <class T>
inline constexpr int native_lanes = static_cast<int>(std::experimental::native_simd<T>::size());

// Any pack of std::experimental::simd, of a fixed size (batch) or as wide
// as the target's registers (native_simd, whose masks are registers too).
template <class T, class Abi>
using simd_pack = std::experimental::simd<T, Abi>;

// Lane i of a pack, or of a named type's batch.
template <class T, class Abi>
T lane(const simd_pack<T, Abi>& x, int i) {
  return x[i];
}

template <template <class> class Named, class P, class = std::enable_if_t<is_batch_v<P>>>
Named<typename batch_traits<P>::scalar> lane(const Named<P>& x, int i) {
  Named<typename batch_traits<P>::scalar> value;
  for (int k = 0; k < Named<P>::size; ++k) value.c[k] = x.c[k][i];
  return value;
}

template <class T, class Abi>
void set_lane(simd_pack<T, Abi>& x, int i, T value) {
  x[i] = value;
}

template <template <class> class Named, class P, class = std::enable_if_t<is_batch_v<P>>>
void set_lane(Named<P>& x, int i, const Named<typename batch_traits<P>::scalar>& value) {
  for (int k = 0; k < Named<P>::size; ++k) x.c[k][i] = value.c[k];
}

// Named<P> for a Named<T>: a named type's batch from one of its values.
template <class Value, class P>
struct rebind;
template <template <class> class Named, class T, class P>
struct rebind<Named<T>, P> {
  using type = Named<P>;
};

// The batch type of W values of named type X: batch_of_t<c3ga::motor, 4>.
template <class X, int W>
using batch_of_t = typename rebind<X, batch<typename X::scalar_type, W>>::type;

// The batch of the W values value_of(0) ... value_of(W - 1) of one named type.
template <int W, class ValueOf>
auto gather(ValueOf value_of) {
  using value = std::decay_t<std::invoke_result_t<ValueOf&, int>>;
  using pack = batch<typename value::scalar_type, W>;
  std::array<value, W> values;
  for (int i = 0; i < W; ++i) values[i] = value_of(i);
  batch_of_t<value, W> x;
  for (int k = 0; k < value::size; ++k) {
    x.c[k] = pack([&](auto i) { return values[i].c[k]; });
  }
  return x;
}

template <class T, class Abi>
struct batch_traits<simd_pack<T, Abi>> {
  static constexpr bool is_batch = true;
  using scalar = T;
  static constexpr int lanes = static_cast<int>(simd_pack<T, Abi>::size());
  static constexpr int W = lanes;

  template <class R, class F, class... X>
  static R lanewise(F f, const X&... x) {
    R r{};
    for (int i = 0; i < W; ++i) set_lane(r, i, f(lane(x, i)...));
    return r;
  }

  // inverse_norm2's check: no lane may be null.
  static bool any_zero(const simd_pack<T, Abi>& x) { return std::experimental::any_of(x == T(0)); }
};

}  // namespace gaphys::ga
