// Every combination the committed profile specialized: the optimized variant
// reaches its straight-line code through dispatch, and the result equals the
// reference variant's generic path on random inputs with exactly those
// bitmaps, also when the stored bits mark more coefficients than are nonzero
// (the dispatcher's retry on exact bits), and on subsets of those bitmaps (a
// kernel made for a superset); and every kernel writes its whole result.
// (Unprofiled bitmaps, the fallback path, are covered by the random dense and
// sparse inputs of test_variants_agree_*.)
#include <gtest/gtest.h>

#include <c3ga/c3ga.hpp>
#include <c3ga_ref/c3ga_ref.hpp>
#include <cmath>
#include <e3ga/e3ga.hpp>
#include <e3ga_ref/e3ga_ref.hpp>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

#include "variants_agree.hpp"

namespace {

using namespace gaphys_test;

// A random multivector whose nonzero coefficients are exactly `bits`.
template <class MV>
MV with_bits(std::mt19937& rng, std::uint32_t bits) {
  std::uniform_real_distribution<double> magnitude(0.25, 1.0);
  std::bernoulli_distribution negative(0.5);
  auto c = MV{}.to_array();
  for (std::size_t i = 0; i < c.size(); ++i)
    if (bits >> i & 1) c[i] = (negative(rng) ? -1 : 1) * magnitude(rng);
  return MV::from_array(c);
}

// evaluate_<ns>(f, a, b, out): the library function named f of namespace ns
// (scp's scalar as the scalar blade). dispatched_<ns>(f, a, b): whether ns's
// dispatcher for f has straight-line code for these bitmaps.
#define GAPHYS_EVALUATE(ns)                                                                 \
  bool evaluate_##ns(const std::string& f, const ns::mv& a, const ns::mv& b, ns::mv& out) { \
    if (f == "gp")                                                                          \
      out = ns::gp(a, b);                                                                   \
    else if (f == "op")                                                                     \
      out = ns::op(a, b);                                                                   \
    else if (f == "lc")                                                                     \
      out = ns::lc(a, b);                                                                   \
    else if (f == "rc")                                                                     \
      out = ns::rc(a, b);                                                                   \
    else if (f == "add")                                                                    \
      out = ns::add(a, b);                                                                  \
    else if (f == "sub")                                                                    \
      out = ns::sub(a, b);                                                                  \
    else if (f == "apply")                                                                  \
      out = ns::apply(a, b);                                                                \
    else if (f == "meet")                                                                   \
      out = ns::meet(a, b);                                                                 \
    else if (f == "scp")                                                                    \
      out = ns::mv::basis_blade(0, ns::scp(a, b));                                          \
    else if (f == "neg")                                                                    \
      out = ns::neg(a);                                                                     \
    else if (f == "reverse")                                                                \
      out = ns::reverse(a);                                                                 \
    else if (f == "involute")                                                               \
      out = ns::involute(a);                                                                \
    else if (f == "conjugate")                                                              \
      out = ns::conjugate(a);                                                               \
    else if (f == "dual")                                                                   \
      out = ns::dual(a);                                                                    \
    else if (f == "undual")                                                                 \
      out = ns::undual(a);                                                                  \
    else                                                                                    \
      return false;                                                                         \
    return true;                                                                            \
  }
GAPHYS_EVALUATE(e3ga)
GAPHYS_EVALUATE(e3ga_ref)
GAPHYS_EVALUATE(c3ga)
GAPHYS_EVALUATE(c3ga_ref)

// dispatch_into_<ns>(f, a, b, r): ns's dispatcher for f writing into r, and
// whether it had straight-line code for these bitmaps (scp into s).
#define GAPHYS_DISPATCHED(ns)                                                         \
  bool dispatch_into_##ns(const std::string& f, const ns::mv& a, const ns::mv& b,    \
                          ns::mv& r, double& s) {                                    \
    namespace d = ns::detail;                                                        \
    if (f == "gp") return d::specialized_gp(a, b, r);                                \
    if (f == "op") return d::specialized_op(a, b, r);                                \
    if (f == "lc") return d::specialized_lc(a, b, r);                                \
    if (f == "rc") return d::specialized_rc(a, b, r);                                \
    if (f == "add") return d::specialized_add(a, b, r);                              \
    if (f == "sub") return d::specialized_sub(a, b, r);                              \
    if (f == "apply") return d::specialized_apply(a, b, r);                          \
    if (f == "meet") return d::specialized_meet(a, b, r);                            \
    if (f == "scp") return d::specialized_scp(a, b, s);                              \
    if (f == "neg") return d::specialized_neg(a, r);                                 \
    if (f == "reverse") return d::specialized_reverse(a, r);                         \
    if (f == "involute") return d::specialized_involute(a, r);                       \
    if (f == "conjugate") return d::specialized_conjugate(a, r);                     \
    if (f == "dual") return d::specialized_dual(a, r);                               \
    if (f == "undual") return d::specialized_undual(a, r);                           \
    return false;                                                                    \
  }                                                                                  \
  bool dispatched_##ns(const std::string& f, const ns::mv& a, const ns::mv& b) {     \
    ns::mv r;                                                                        \
    double s = 0;                                                                    \
    return dispatch_into_##ns(f, a, b, r, s);                                        \
  }
GAPHYS_DISPATCHED(e3ga)
GAPHYS_DISPATCHED(c3ga)

#define GAPHYS_CHECK_PROFILED(ns)                                                                \
  std::mt19937 rng(2024);                                                                        \
  int checked = 0;                                                                               \
  for (const auto* c = ns::detail::specialized_combinations; c->function != nullptr; ++c) {      \
    SCOPED_TRACE(std::string(c->function) + " on bitmaps " + std::to_string(c->a) + ", " +       \
                 std::to_string(c->b));                                                          \
    for (int trial = 0; trial < 4; ++trial) {                                                    \
      const ns::mv a = with_bits<ns::mv>(rng, c->a), b = with_bits<ns::mv>(rng, c->b);           \
      const auto ra = same_coordinates<ns##_ref::mv>(a), rb = same_coordinates<ns##_ref::mv>(b); \
      ns::mv opt;                                                                                \
      ns##_ref::mv ref;                                                                          \
      ASSERT_TRUE(evaluate_##ns(c->function, a, b, opt));                                        \
      ASSERT_TRUE(evaluate_##ns##_ref(c->function, ra, rb, ref));                                \
      EXPECT_TRUE(dispatched_##ns(c->function, a, b)) << "dispatch missed the kernel";           \
      EXPECT_TRUE((results_agree<ns::mv, ns##_ref::mv>(opt, ref)));                              \
      /* Stored bits that also mark exact zeros reach the kernel through the retry. */           \
      ns::mv wide_a = a, wide_b = b, wide_opt;                                                   \
      wide_a.bits = wide_b.bits = ~std::uint32_t(0) >> (32 - ns::blade_count);                   \
      ASSERT_TRUE(evaluate_##ns(c->function, wide_a, wide_b, wide_opt));                         \
      EXPECT_TRUE(dispatched_##ns(c->function, wide_a, wide_b)) << "retry missed the kernel";    \
      EXPECT_TRUE((results_agree<ns::mv, ns##_ref::mv>(wide_opt, ref)));                         \
      ++checked;                                                                                 \
    }                                                                                            \
  }                                                                                              \
  EXPECT_GT(checked, 0) << "the committed profile specialized nothing";

// Bitmaps the profile never showed, inside a kernel's: one coefficient of each
// argument with two or more left out. The dispatcher serves them with that
// kernel (or another that covers them) where it is cheaper than the generic
// path; either way the result is the reference's.
#define GAPHYS_CHECK_SUBSETS(ns)                                                                 \
  std::mt19937 rng(7);                                                                           \
  int checked = 0, served = 0;                                                                   \
  for (const auto* c = ns::detail::specialized_combinations; c->function != nullptr; ++c) {      \
    if (!c->covers_subsets) continue;                                                            \
    const auto fewer = [](std::uint32_t bits) { return bits & (bits - 1) ? bits & (bits - 1) : bits; }; \
    const std::uint32_t sub_a = fewer(c->a), sub_b = fewer(c->b);                                \
    if (sub_a == c->a && sub_b == c->b) continue;                                                \
    SCOPED_TRACE(std::string(c->function) + " on subsets " + std::to_string(sub_a) + ", " +      \
                 std::to_string(sub_b));                                                         \
    for (int trial = 0; trial < 4; ++trial) {                                                    \
      const ns::mv a = with_bits<ns::mv>(rng, sub_a), b = with_bits<ns::mv>(rng, sub_b);         \
      const auto ra = same_coordinates<ns##_ref::mv>(a), rb = same_coordinates<ns##_ref::mv>(b); \
      ns::mv opt;                                                                                \
      ns##_ref::mv ref;                                                                          \
      ASSERT_TRUE(evaluate_##ns(c->function, a, b, opt));                                        \
      ASSERT_TRUE(evaluate_##ns##_ref(c->function, ra, rb, ref));                                \
      EXPECT_TRUE((results_agree<ns::mv, ns##_ref::mv>(opt, ref)));                              \
      served += dispatched_##ns(c->function, a, b);                                              \
      ++checked;                                                                                 \
    }                                                                                            \
  }                                                                                              \
  EXPECT_GT(checked, 0);                                                                         \
  EXPECT_GT(served, 0) << "no superset kernel served an unprofiled subset";

// The mv functions hand the kernels a result that was not zeroed, so every
// kernel must write every coefficient: a result filled with NaN beforehand
// comes back equal to the reference's (NaN equals nothing), with its bits.
#define GAPHYS_CHECK_WRITES_EVERY_COEFFICIENT(ns)                                                  \
  std::mt19937 rng(99);                                                                          \
  int checked = 0;                                                                               \
  for (const auto* c = ns::detail::specialized_combinations; c->function != nullptr; ++c) {      \
    if (std::string(c->function) == "scp") continue; /* a scalar result */                      \
    SCOPED_TRACE(std::string(c->function) + " on bitmaps " + std::to_string(c->a) + ", " +       \
                 std::to_string(c->b));                                                          \
    const ns::mv a = with_bits<ns::mv>(rng, c->a), b = with_bits<ns::mv>(rng, c->b);             \
    const auto ra = same_coordinates<ns##_ref::mv>(a), rb = same_coordinates<ns##_ref::mv>(b);   \
    ns##_ref::mv ref;                                                                            \
    ASSERT_TRUE(evaluate_##ns##_ref(c->function, ra, rb, ref));                                  \
    ns::mv poisoned(gaphys::ga::uninitialized);                                                  \
    for (auto& x : poisoned.c) x = std::numeric_limits<double>::quiet_NaN();                     \
    double s = 0;                                                                                \
    ASSERT_TRUE(dispatch_into_##ns(c->function, a, b, poisoned, s));                             \
    for (double x : poisoned.c) ASSERT_FALSE(std::isnan(x)) << "a coefficient was not written";  \
    EXPECT_TRUE((results_agree<ns::mv, ns##_ref::mv>(poisoned, ref)));                           \
    ++checked;                                                                                   \
  }                                                                                              \
  EXPECT_GT(checked, 0);

// A null versor (<v ~v>_0 = 0) with a profiled bitmap: apply and inverse on
// mv throw std::domain_error in the optimized variant as in the reference,
// also where the result would be zero (x = 0). (The profiled kernels
// divided by zero: NaN, where the reference threw.)
template <class F>
void expect_domain_error(F&& f) {
  EXPECT_THROW(f(), std::domain_error);
}
#define GAPHYS_CHECK_NULL_VERSORS(ns)                                                          \
  std::mt19937 rng(5);                                                                         \
  int checked = 0;                                                                             \
  for (const auto* c = ns::detail::specialized_combinations; c->function != nullptr; ++c) {    \
    const std::string f = c->function;                                                         \
    if (f != "apply" && f != "inverse") continue;                                              \
    SCOPED_TRACE(f + " on bitmaps " + std::to_string(c->a) + ", " + std::to_string(c->b));     \
    ns::mv v; /* zero coefficients, stored bits of the kernel */                               \
    v.bits = c->a;                                                                             \
    const ns::mv x = with_bits<ns::mv>(rng, c->b);                                             \
    const auto rv = same_coordinates<ns##_ref::mv>(v), rx = same_coordinates<ns##_ref::mv>(x); \
    if (f == "apply") {                                                                        \
      /* the kernel itself throws, not only the generic path */                                \
      expect_domain_error([&] { (void)dispatched_##ns(f, v, x); });                            \
      expect_domain_error([&] { (void)ns::apply(v, x); });                                     \
      expect_domain_error([&] { (void)ns##_ref::apply(rv, rx); });                             \
    } else {                                                                                   \
      expect_domain_error([&] { (void)ns::inverse(v); });                                      \
      expect_domain_error([&] { (void)ns##_ref::inverse(rv); });                               \
    }                                                                                          \
    ++checked;                                                                                 \
  }                                                                                            \
  EXPECT_GT(checked, 0) << "the committed profile specialized no apply";

TEST(ProfiledKernels, E3gaNullVersorsThrowAsInTheReference){
    GAPHYS_CHECK_NULL_VERSORS(e3ga)} TEST(ProfiledKernels, C3gaNullVersorsThrowAsInTheReference){
    GAPHYS_CHECK_NULL_VERSORS(c3ga)}

TEST(ProfiledKernels, E3gaKernelsWriteEveryCoefficient){
    GAPHYS_CHECK_WRITES_EVERY_COEFFICIENT(e3ga)} TEST(ProfiledKernels,
                                                      C3gaKernelsWriteEveryCoefficient){
    GAPHYS_CHECK_WRITES_EVERY_COEFFICIENT(c3ga)}

TEST(ProfiledKernels, E3gaSupersetKernelsServeSubsets){
    GAPHYS_CHECK_SUBSETS(e3ga)} TEST(ProfiledKernels,
                                     C3gaSupersetKernelsServeSubsets){GAPHYS_CHECK_SUBSETS(c3ga)}

// A named type widened to mv marks only its nonzero coordinates (and its
// constant ones), so its exact zeros reach the kernels made for them.
TEST(ProfiledKernels, WideningMarksNonzeroCoordinatesOnly) {
  const c3ga::mv e3_plane = c3ga::dual_plane{0, 0, 1, 0};  // e1 e2 e3 ni at canonical 2..5
  EXPECT_EQ(e3_plane.bits, 1u << 4);
  const c3ga::mv origin = c3ga::normalized_point{0, 0, 0, 0};  // no = 1, a constant
  EXPECT_EQ(origin.bits, 1u << 1);
  EXPECT_EQ(c3ga::mv(c3ga::ni()).bits, 1u << 5);
  const e3ga::mv zero = e3ga::vector{0, 0, 0};
  EXPECT_EQ(zero.bits, 0u);
}

TEST(ProfiledKernels, E3gaAgreeWithReference){
    GAPHYS_CHECK_PROFILED(e3ga)} TEST(ProfiledKernels, C3gaAgreeWithReference) {
  GAPHYS_CHECK_PROFILED(c3ga)
}

}  // namespace
