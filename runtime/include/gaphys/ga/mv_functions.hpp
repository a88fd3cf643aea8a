// The functions of every generated algebra, written once: those on the
// general multivector (table-driven, after asking the profiled kernels), the
// overloads that send every other combination of types through it, norm and
// unit, and the operators. Each algebra re-exports them into its namespace
// with using-declarations (its mv_functions.hpp), so `e3ga::gp(a, b)` and
// argument-dependent lookup find them next to the algebra's named-type kernels.
//
// A generated type X names its algebra as `X::algebra`, a struct with:
//   template <class T> using mv;       the general multivector basic_mv<T>
//   template <class X> holds;          true for the algebra's types (is_multivector_v)
//   call, template <call F> kernels;   the call enum; F's profiled kernels (mv_dispatch.hpp)
//   on_call(F, result, args...);       the instrumented variant's recording hook
//   dimension, meet_is_regressive;     what the spec says
//   <f>_table, <f>_signs;              the product, linear-map and sign tables
#pragma once

#include <cstdint>
#include <ostream>
#include <type_traits>

#include "mv_algorithms.hpp"
#include "mv_dispatch.hpp"
#include "scalar_functions.hpp"
#include "table_product.hpp"
#include "uninitialized.hpp"

namespace gaphys::ga {

// True for a type of a generated algebra (basic_mv and the named types).
template <class X, class = void>
struct is_multivector : std::false_type {};
template <class X>
struct is_multivector<X, std::void_t<algebra_of<X>>>
    : std::bool_constant<algebra_of<X>::template holds<X>> {};
template <class X>
inline constexpr bool is_multivector_v = is_multivector<X>::value;

template <class X, class = void>
struct is_general_mv : std::false_type {};
template <class X>
struct is_general_mv<X, std::enable_if_t<is_multivector_v<X>>>
    : std::is_same<X, typename algebra_of<X>::template mv<typename X::scalar_type>> {};
template <class X>
inline constexpr bool is_general_mv_v = is_general_mv<X>::value;

template <class X>
using mv_of = typename algebra_of<X>::template mv<typename X::scalar_type>;

// A and B are types of one algebra, with one scalar type.
template <class A, class B, bool = (is_multivector_v<A> && is_multivector_v<B>)>
inline constexpr bool same_algebra_v = false;
template <class A, class B>
inline constexpr bool same_algebra_v<A, B, true> =
    (std::is_same_v<algebra_of<A>, algebra_of<B>> &&
     std::is_same_v<typename A::scalar_type, typename B::scalar_type>);

template <class X>
using if_multivector = std::enable_if_t<is_multivector_v<X>, int>;
template <class A, class B>
using if_multivectors = std::enable_if_t<same_algebra_v<A, B>, int>;
template <class X>
using if_general_mv = std::enable_if_t<is_general_mv_v<X>, int>;
// A batch of a named type (gaphys/ga/batch.hpp): never widened to an mv, so
// that a function with no named-type kernel for it is no match at all.
template <class X, class = void>
inline constexpr bool is_batch_of_named_v = false;
template <class X>
inline constexpr bool is_batch_of_named_v<X, std::void_t<typename X::scalar_type>> =
    is_batch_v<typename X::scalar_type>;

// The combinations the functions on mv do not take: some named type among them.
template <class X>
using if_widened =
    std::enable_if_t<is_multivector_v<X> && !is_general_mv_v<X> && !is_batch_of_named_v<X>, int>;
template <class A, class B>
using if_widened_pair =
    std::enable_if_t<same_algebra_v<A, B> && !(is_general_mv_v<A> && is_general_mv_v<B>) &&
                         !is_batch_of_named_v<A>,
                     int>;

namespace api {

// ---- general multivector ------------------------------------------------------
// Every function first asks dispatch::specialized_<f> for straight-line code
// for its arguments' bitmaps (profile-guided, optimized variant only), and
// reports itself to on_call, which records the call in the instrumented
// variant; both compile to nothing where they have nothing to do.
template <class MV, if_general_mv<MV> = 0>
MV gp(const MV& a, const MV& b) {
  using A = algebra_of<MV>;
  MV r(uninitialized);
  if (!dispatch::specialized_gp(a, b, r)) r = gaphys::ga::table_product(A::gp_table, a, b);
  A::on_call(A::call::gp, r, a, b);
  return r;
}
template <class MV, if_general_mv<MV> = 0>
MV op(const MV& a, const MV& b) {
  using A = algebra_of<MV>;
  MV r(uninitialized);
  if (!dispatch::specialized_op(a, b, r)) r = gaphys::ga::table_product(A::op_table, a, b);
  A::on_call(A::call::op, r, a, b);
  return r;
}
template <class MV, if_general_mv<MV> = 0>
MV lc(const MV& a, const MV& b) {
  using A = algebra_of<MV>;
  MV r(uninitialized);
  if (!dispatch::specialized_lc(a, b, r)) r = gaphys::ga::table_product(A::lc_table, a, b);
  A::on_call(A::call::lc, r, a, b);
  return r;
}
template <class MV, if_general_mv<MV> = 0>
MV rc(const MV& a, const MV& b) {
  using A = algebra_of<MV>;
  MV r(uninitialized);
  if (!dispatch::specialized_rc(a, b, r)) r = gaphys::ga::table_product(A::rc_table, a, b);
  A::on_call(A::call::rc, r, a, b);
  return r;
}
template <class MV, if_general_mv<MV> = 0>
typename MV::scalar_type scp(const MV& a, const MV& b) {
  using A = algebra_of<MV>;
  typename MV::scalar_type r = 0;
  if (!dispatch::specialized_scp(a, b, r))
    r = gaphys::ga::scalar_part(gaphys::ga::table_product(A::scp_table, a, b));
  A::on_call(A::call::scp, r, a, b);
  return r;
}
template <class MV, if_general_mv<MV> = 0>
MV add(const MV& a, const MV& b) {
  using A = algebra_of<MV>;
  using T = typename MV::scalar_type;
  MV r(uninitialized);
  if (!dispatch::specialized_add(a, b, r)) r = gaphys::ga::linear_combination(T(1), a, T(1), b);
  A::on_call(A::call::add, r, a, b);
  return r;
}
template <class MV, if_general_mv<MV> = 0>
MV sub(const MV& a, const MV& b) {
  using A = algebra_of<MV>;
  using T = typename MV::scalar_type;
  MV r(uninitialized);
  if (!dispatch::specialized_sub(a, b, r)) r = gaphys::ga::linear_combination(T(1), a, T(-1), b);
  A::on_call(A::call::sub, r, a, b);
  return r;
}
template <class MV, if_general_mv<MV> = 0>
MV smul(typename MV::scalar_type s, const MV& a) {
  using A = algebra_of<MV>;
  const MV r = gaphys::ga::scaled(a, s);
  A::on_call(A::call::smul, r, a);
  return r;
}
template <class MV, if_general_mv<MV> = 0>
MV neg(const MV& a) {
  using A = algebra_of<MV>;
  MV r(uninitialized);
  if (dispatch::specialized_neg(a, r)) return r;
  r = gaphys::ga::negated(a);
  A::on_call(A::call::neg, r, a);
  return r;
}

template <class MV, if_general_mv<MV> = 0>
MV reverse(const MV& a) {
  using A = algebra_of<MV>;
  MV r(uninitialized);
  if (dispatch::specialized_reverse(a, r)) return r;
  r = gaphys::ga::with_signs(a, A::reverse_signs);
  A::on_call(A::call::reverse, r, a);
  return r;
}
template <class MV, if_general_mv<MV> = 0>
MV involute(const MV& a) {
  using A = algebra_of<MV>;
  MV r(uninitialized);
  if (dispatch::specialized_involute(a, r)) return r;
  r = gaphys::ga::with_signs(a, A::involute_signs);
  A::on_call(A::call::involute, r, a);
  return r;
}
template <class MV, if_general_mv<MV> = 0>
MV conjugate(const MV& a) {
  using A = algebra_of<MV>;
  MV r(uninitialized);
  if (dispatch::specialized_conjugate(a, r)) return r;
  r = gaphys::ga::with_signs(a, A::conjugate_signs);
  A::on_call(A::call::conjugate, r, a);
  return r;
}
template <class MV, if_general_mv<MV> = 0>
MV grade(const MV& a, int k) {
  return gaphys::ga::keep_grades(a, MV::grade_mask(k));
}
template <class MV, if_general_mv<MV> = 0>
MV dual(const MV& a) {
  using A = algebra_of<MV>;
  MV r(uninitialized);
  if (!dispatch::specialized_dual(a, r)) r = gaphys::ga::table_linear_map(A::dual_table, a);
  A::on_call(A::call::dual, r, a);
  return r;
}
template <class MV, if_general_mv<MV> = 0>
MV undual(const MV& a) {
  using A = algebra_of<MV>;
  MV r(uninitialized);
  if (!dispatch::specialized_undual(a, r)) r = gaphys::ga::table_linear_map(A::undual_table, a);
  A::on_call(A::call::undual, r, a);
  return r;
}

// The functions below are built from the ones above; in the instrumented
// variant those inner calls are recorded too.
template <class MV, if_general_mv<MV> = 0>
typename MV::scalar_type norm2(const MV& a) {
  using A = algebra_of<MV>;
  const typename MV::scalar_type r = api::scp(a, api::reverse(a));
  A::on_call(A::call::norm2, r, a);
  return r;
}
// Versor inverse ~a / <a ~a>_0: exact for blades and versors; throws
// std::domain_error for a null a (<a ~a>_0 = 0).
template <class MV, if_general_mv<MV> = 0>
MV inverse(const MV& a) {
  using A = algebra_of<MV>;
  const MV r = api::smul(gaphys::ga::inverse_norm2(api::norm2(a)), api::reverse(a));
  A::on_call(A::call::inverse, r, a);
  return r;
}
// Inverse of any invertible multivector; throws std::domain_error if singular.
template <class MV, if_general_mv<MV> = 0>
MV general_inverse(const MV& a) {
  using A = algebra_of<MV>;
  const MV r = gaphys::ga::general_inverse(a);
  A::on_call(A::call::general_inverse, r, a);
  return r;
}
template <class MV, if_general_mv<MV> = 0>
MV exp(const MV& a) {
  using A = algebra_of<MV>;
  const MV r = gaphys::ga::exp_general(a);
  A::on_call(A::call::exp, r, a);
  return r;
}
// log whose rotation by 2 pi (for a = -1) may only turn in the bivectors of
// `planes`: a named type's log, whose result must stay in that type.
template <class MV, class Planes, if_general_mv<MV> = 0>
MV log_within(const MV& a, const Planes& planes) {
  using A = algebra_of<MV>;
  const MV r = gaphys::ga::log_general(a, planes);
  A::on_call(A::call::log, r, a);
  return r;
}
template <class MV, if_general_mv<MV> = 0>
MV log(const MV& a) {
  return api::log_within(a, MV::grade_mask(2));
}
// v x v^-1 as v x ~v / <v ~v>_0, keeping the grades x has: a versor preserves
// grade. Throws std::domain_error for a null v.
template <class MV, if_general_mv<MV> = 0>
MV apply(const MV& v, const MV& x) {
  using A = algebra_of<MV>;
  using T = typename MV::scalar_type;
  MV r(uninitialized);  // one result variable on every path: built in place
  if (!dispatch::specialized_apply(v, x, r)) {
    std::uint32_t mask = 0;
    for (int k = 0; k <= A::dimension; ++k)
      if (x.bits & MV::grade_mask(k)) mask |= MV::grade_mask(k);
    const MV rv = api::reverse(v);
    // A null v (<v ~v>_0 = 0) has no inverse: std::domain_error, not infinities.
    r = api::smul(gaphys::ga::inverse_norm2<T>(api::scp(v, rv)),
                  gaphys::ga::keep_grades(api::gp(api::gp(v, x), rv), mask));
  }
  A::on_call(A::call::apply, r, v, x);
  return r;
}
// a v b, the regressive product: left_complement(right_complement(b) ^
// right_complement(a)). The complements need no metric, so this works in a
// degenerate metric too; where I^2 = +-1 it is undual(dual(a) ^ dual(b)).
template <class MV, if_general_mv<MV> = 0>
MV regressive(const MV& a, const MV& b) {
  using A = algebra_of<MV>;
  return gaphys::ga::table_linear_map(
      A::left_complement_table,
      gaphys::ga::table_product(A::op_table,
                                gaphys::ga::table_linear_map(A::right_complement_table, b),
                                gaphys::ga::table_linear_map(A::right_complement_table, a)));
}
// Meet and join are the regressive and outer products where blades are
// direct ("representation" in the spec), the outer and regressive where dual.
template <class MV, if_general_mv<MV> = 0>
MV meet(const MV& a, const MV& b) {
  using A = algebra_of<MV>;
  MV r(uninitialized);
  if (!dispatch::specialized_meet(a, b, r)) {
    if constexpr (A::meet_is_regressive)
      r = api::regressive(a, b);
    else
      r = gaphys::ga::table_product(A::op_table, a, b);
  }
  A::on_call(A::call::meet, r, a, b);
  return r;
}
template <class MV, if_general_mv<MV> = 0>
MV join(const MV& a, const MV& b) {
  using A = algebra_of<MV>;
  MV r(uninitialized);
  if (!dispatch::specialized_join(a, b, r)) {
    if constexpr (A::meet_is_regressive)
      r = gaphys::ga::table_product(A::op_table, a, b);
    else
      r = api::regressive(a, b);
  }
  A::on_call(A::call::join, r, a, b);
  return r;
}

// ---- any other combination of types goes through basic_mv ------------------------
template <class X, if_multivector<X> = 0>
mv_of<X> to_mv(const X& x) {
  return mv_of<X>(x);
}

template <class A, class B, if_widened_pair<A, B> = 0>
mv_of<A> gp(const A& a, const B& b) {
  return api::gp(api::to_mv(a), api::to_mv(b));
}
template <class A, class B, if_widened_pair<A, B> = 0>
mv_of<A> op(const A& a, const B& b) {
  return api::op(api::to_mv(a), api::to_mv(b));
}
template <class A, class B, if_widened_pair<A, B> = 0>
mv_of<A> lc(const A& a, const B& b) {
  return api::lc(api::to_mv(a), api::to_mv(b));
}
template <class A, class B, if_widened_pair<A, B> = 0>
mv_of<A> rc(const A& a, const B& b) {
  return api::rc(api::to_mv(a), api::to_mv(b));
}
template <class A, class B, if_widened_pair<A, B> = 0>
mv_of<A> add(const A& a, const B& b) {
  return api::add(api::to_mv(a), api::to_mv(b));
}
template <class A, class B, if_widened_pair<A, B> = 0>
mv_of<A> sub(const A& a, const B& b) {
  return api::sub(api::to_mv(a), api::to_mv(b));
}
template <class A, class B, if_widened_pair<A, B> = 0>
mv_of<A> apply(const A& a, const B& b) {
  return api::apply(api::to_mv(a), api::to_mv(b));
}
template <class A, class B, if_widened_pair<A, B> = 0>
mv_of<A> meet(const A& a, const B& b) {
  return api::meet(api::to_mv(a), api::to_mv(b));
}
template <class A, class B, if_widened_pair<A, B> = 0>
mv_of<A> join(const A& a, const B& b) {
  return api::join(api::to_mv(a), api::to_mv(b));
}
template <class X, if_widened<X> = 0>
mv_of<X> neg(const X& a) {
  return api::neg(api::to_mv(a));
}
template <class X, if_widened<X> = 0>
mv_of<X> general_inverse(const X& a) {
  return api::general_inverse(api::to_mv(a));
}
template <class X, if_widened<X> = 0>
mv_of<X> exp(const X& a) {
  return api::exp(api::to_mv(a));
}
template <class X, if_widened<X> = 0>
mv_of<X> log(const X& a) {
  return api::log(api::to_mv(a));
}
template <class X, if_widened<X> = 0>
mv_of<X> inverse(const X& a) {
  return api::inverse(api::to_mv(a));
}
template <class X, if_widened<X> = 0>
mv_of<X> reverse(const X& a) {
  return api::reverse(api::to_mv(a));
}
template <class X, if_widened<X> = 0>
mv_of<X> involute(const X& a) {
  return api::involute(api::to_mv(a));
}
template <class X, if_widened<X> = 0>
mv_of<X> conjugate(const X& a) {
  return api::conjugate(api::to_mv(a));
}
template <class X, if_widened<X> = 0>
mv_of<X> dual(const X& a) {
  return api::dual(api::to_mv(a));
}
template <class X, if_widened<X> = 0>
mv_of<X> undual(const X& a) {
  return api::undual(api::to_mv(a));
}

template <class A, class B, if_widened_pair<A, B> = 0>
typename A::scalar_type scp(const A& a, const B& b) {
  return api::scp(api::to_mv(a), api::to_mv(b));
}
template <class X, if_widened<X> = 0>
typename X::scalar_type norm2(const X& a) {
  return api::norm2(api::to_mv(a));
}
template <class X, if_widened<X> = 0>
mv_of<X> smul(typename X::scalar_type s, const X& a) {
  return api::smul(s, api::to_mv(a));
}
template <class X, if_widened<X> = 0>
mv_of<X> grade(const X& a, int k) {
  return api::grade(api::to_mv(a), k);
}

// ---- for every type ---------------------------------------------------------------
// The calls below are unqualified: argument-dependent lookup finds the
// algebra's named-type kernels too.
template <class A, class B, if_multivectors<A, B> = 0>
bool approx_equal(const A& a, const B& b, typename A::scalar_type tolerance) {
  return gaphys::ga::max_abs(sub(api::to_mv(a), api::to_mv(b))) <= tolerance;
}
template <class X, if_multivector<X> = 0>
std::ostream& operator<<(std::ostream& out, const X& x) {
  return gaphys::ga::print(out, api::to_mv(x));
}
// sqrt(|<a ~a>_0|)
template <class X, if_multivector<X> = 0>
typename X::scalar_type norm(const X& a) {
  using std::abs, std::sqrt;
  return sqrt(abs(norm2(a)));
}
template <class X, if_multivector<X> = 0>
auto unit(const X& a) {
  return smul(typename X::scalar_type(1) / api::norm(a), a);
}

// ---- operators (precedence trap: ^ binds looser than +, - and ==) -----------------
// Each forwards to its function, forced inline: for named types that is a
// straight-line kernel, and where GCC's inlining budget for a large file ran
// out, a bivector sum stayed a call in the engine's contact sweeps (1,000
// boxes stepped 10% slower on one thread, 2026-12-06).
template <class A, class B, if_multivectors<A, B> = 0>
GAPHYS_ALWAYS_INLINE auto operator*(const A& a, const B& b) {
  return gp(a, b);
}
template <class A, class B, if_multivectors<A, B> = 0>
GAPHYS_ALWAYS_INLINE auto operator^(const A& a, const B& b) {
  return op(a, b);
}
template <class A, class B, if_multivectors<A, B> = 0>
GAPHYS_ALWAYS_INLINE auto operator+(const A& a, const B& b) {
  return add(a, b);
}
template <class A, class B, if_multivectors<A, B> = 0>
GAPHYS_ALWAYS_INLINE auto operator-(const A& a, const B& b) {
  return sub(a, b);
}
template <class X, if_multivector<X> = 0>
GAPHYS_ALWAYS_INLINE auto operator-(const X& a) {
  return neg(a);
}
template <class X, if_multivector<X> = 0>
GAPHYS_ALWAYS_INLINE auto operator~(const X& a) {
  return reverse(a);
}
template <class X, if_multivector<X> = 0>
GAPHYS_ALWAYS_INLINE auto operator*(typename X::scalar_type s, const X& a) {
  return smul(s, a);
}
template <class X, if_multivector<X> = 0>
GAPHYS_ALWAYS_INLINE auto operator*(const X& a, typename X::scalar_type s) {
  return smul(s, a);
}
template <class X, if_multivector<X> = 0>
GAPHYS_ALWAYS_INLINE auto operator/(const X& a, typename X::scalar_type s) {
  return smul(typename X::scalar_type(1) / s, a);
}

}  // namespace api
}  // namespace gaphys::ga
