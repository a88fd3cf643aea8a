// The dispatch from a function on mv to the straight-line kernels a profile
// asked for (optimized variant). A generated algebra supplies, per function F,
// a struct `detail::kernels<F>`: `profiled` false (no kernel: always the
// generic path), or `profiled` true with
//   by_key(key, args..., r):          the switch over the profiled bitmaps;
//   covering(bits..., args..., r):    the cheapest kernel made for a superset
//                                     of the bitmaps `bits`, if one is worth it.
// A covering kernel reads exact zeros where the arguments have no coefficient,
// so its result is the generic path's; its result bits may mark some exact
// zeros. The generator lists them cheapest first and ends the search at one
// costing more per term than the generic path (expand.OPERATIONS_PER_GENERIC_TERM);
// kernels that divide never serve subsets (a divisor that vanishes on the
// subset is the generic path's to handle).
// Kernels write every coefficient of r (which need not be zeroed first) and
// its bits; r is none of the arguments (kernels take it restrict-qualified).
#pragma once

#include <cstdint>

#include "compiler.hpp"
#include "mv_algorithms.hpp"

namespace gaphys::ga {

// The algebra a generated type belongs to (see mv_functions.hpp), and the
// profiled kernels of its function F.
template <class X>
using algebra_of = typename X::algebra;
template <class X, auto F>
using kernels_of = typename algebra_of<X>::template kernels<F>;

// The switch key of two argument bitmaps.
constexpr std::uint64_t pair_key(std::uint32_t a, std::uint32_t b) {
  return std::uint64_t(a) << 32 | b;
}

// One (function, argument bitmaps) combination with straight-line code, and
// whether its kernel also serves subsets of its bitmaps: for tests and reports.
struct specialized_combination {
  const char* function;
  std::uint32_t a, b;
  bool covers_subsets;
};

// The kernels of a function the profile made none for.
struct no_kernels {
  static constexpr bool profiled = false;
};

// The profile keys on the really nonzero coefficients, while stored bits may
// still mark exact zeros (a product's structure): on a miss, retry with the
// exactly nonzero ones, then with a kernel made for a superset of them.
template <class Kernels, class MV, class R>
bool specialized_on_exact_bits(const MV& a, const MV& b, R& r) {
  const std::uint32_t a_bits = exact_bits(a);
  const std::uint32_t b_bits = exact_bits(b);
  const std::uint64_t exact = pair_key(a_bits, b_bits);
  if (exact != pair_key(a.bits, b.bits) && Kernels::by_key(exact, a, b, r)) return true;
  return Kernels::covering(a_bits, b_bits, a, b, r);
}
template <class Kernels, class MV, class R>
bool specialized_on_exact_bits(const MV& a, R& r) {
  const std::uint32_t a_bits = exact_bits(a);
  if (a_bits != a.bits && Kernels::by_key(a_bits, a, r)) return true;
  return Kernels::covering(a_bits, a, r);
}

// True when a kernel wrote r; false sends the caller down the generic path.
// Kept small, and the switch forced inline (by_key), so that a hit runs
// inside the mv function (one call in all); only a miss calls the retry.
template <class Kernels, class MV, class R>
inline bool specialized([[maybe_unused]] const MV& a, [[maybe_unused]] const MV& b,
                        [[maybe_unused]] R& r) {
  if constexpr (Kernels::profiled) {
    return Kernels::by_key(pair_key(a.bits, b.bits), a, b, r) ||
           specialized_on_exact_bits<Kernels>(a, b, r);
  } else {
    return false;
  }
}
template <class Kernels, class MV, class R>
inline bool specialized([[maybe_unused]] const MV& a, [[maybe_unused]] R& r) {
  if constexpr (Kernels::profiled) {
    return Kernels::by_key(a.bits, a, r) || specialized_on_exact_bits<Kernels>(a, r);
  } else {
    return false;
  }
}

// The hooks the functions on mv call, one per function that may have kernels;
// each algebra declares them in its detail namespace.
namespace dispatch {
template <class MV>
GAPHYS_ALWAYS_INLINE bool specialized_gp(const MV& a, const MV& b, MV& r) {
  return specialized<kernels_of<MV, algebra_of<MV>::call::gp>>(a, b, r);
}
template <class MV>
GAPHYS_ALWAYS_INLINE bool specialized_op(const MV& a, const MV& b, MV& r) {
  return specialized<kernels_of<MV, algebra_of<MV>::call::op>>(a, b, r);
}
template <class MV>
GAPHYS_ALWAYS_INLINE bool specialized_lc(const MV& a, const MV& b, MV& r) {
  return specialized<kernels_of<MV, algebra_of<MV>::call::lc>>(a, b, r);
}
template <class MV>
GAPHYS_ALWAYS_INLINE bool specialized_rc(const MV& a, const MV& b, MV& r) {
  return specialized<kernels_of<MV, algebra_of<MV>::call::rc>>(a, b, r);
}
template <class MV>
GAPHYS_ALWAYS_INLINE bool specialized_scp(const MV& a, const MV& b, typename MV::scalar_type& r) {
  return specialized<kernels_of<MV, algebra_of<MV>::call::scp>>(a, b, r);
}
template <class MV>
GAPHYS_ALWAYS_INLINE bool specialized_add(const MV& a, const MV& b, MV& r) {
  return specialized<kernels_of<MV, algebra_of<MV>::call::add>>(a, b, r);
}
template <class MV>
GAPHYS_ALWAYS_INLINE bool specialized_sub(const MV& a, const MV& b, MV& r) {
  return specialized<kernels_of<MV, algebra_of<MV>::call::sub>>(a, b, r);
}
template <class MV>
GAPHYS_ALWAYS_INLINE bool specialized_apply(const MV& a, const MV& b, MV& r) {
  return specialized<kernels_of<MV, algebra_of<MV>::call::apply>>(a, b, r);
}
template <class MV>
GAPHYS_ALWAYS_INLINE bool specialized_meet(const MV& a, const MV& b, MV& r) {
  return specialized<kernels_of<MV, algebra_of<MV>::call::meet>>(a, b, r);
}
template <class MV>
GAPHYS_ALWAYS_INLINE bool specialized_join(const MV& a, const MV& b, MV& r) {
  return specialized<kernels_of<MV, algebra_of<MV>::call::join>>(a, b, r);
}
template <class MV>
GAPHYS_ALWAYS_INLINE bool specialized_neg(const MV& a, MV& r) {
  return specialized<kernels_of<MV, algebra_of<MV>::call::neg>>(a, r);
}
template <class MV>
GAPHYS_ALWAYS_INLINE bool specialized_reverse(const MV& a, MV& r) {
  return specialized<kernels_of<MV, algebra_of<MV>::call::reverse>>(a, r);
}
template <class MV>
GAPHYS_ALWAYS_INLINE bool specialized_involute(const MV& a, MV& r) {
  return specialized<kernels_of<MV, algebra_of<MV>::call::involute>>(a, r);
}
template <class MV>
GAPHYS_ALWAYS_INLINE bool specialized_conjugate(const MV& a, MV& r) {
  return specialized<kernels_of<MV, algebra_of<MV>::call::conjugate>>(a, r);
}
template <class MV>
GAPHYS_ALWAYS_INLINE bool specialized_dual(const MV& a, MV& r) {
  return specialized<kernels_of<MV, algebra_of<MV>::call::dual>>(a, r);
}
template <class MV>
GAPHYS_ALWAYS_INLINE bool specialized_undual(const MV& a, MV& r) {
  return specialized<kernels_of<MV, algebra_of<MV>::call::undual>>(a, r);
}
}  // namespace dispatch

}  // namespace gaphys::ga
