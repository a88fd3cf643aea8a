// Shared machinery of test_variants_agree_*.cpp: the optimized variant
// (namespace <alg>) and the reference variant (namespace <alg>_ref) evaluate
// the same expression on the same random inputs and must agree.
#pragma once

#include <stdexcept>
#include <string>

#include "algebra_test_support.hpp"

namespace gaphys_test {

constexpr int agreement_trials = 20;

// Agreement relative to the size of the results: the variants only differ
// in the order of their floating-point operations.
template <class T>
constexpr double agreement_tolerance() {
  return std::is_same_v<T, float> ? 1e-5 : 1e-12;
}

// exp of a general multivector sums a series and squares the result up to ~5
// times, which multiplies the variants' different rounding by 2^5: checks made
// while an iterated_algorithm is alive allow ten times the tolerance.
inline double& tolerance_factor() {
  static double factor = 1;
  return factor;
}
struct iterated_algorithm {
  iterated_algorithm() { tolerance_factor() = 10; }
  ~iterated_algorithm() { tolerance_factor() = 1; }
  iterated_algorithm(const iterated_algorithm&) = delete;
  iterated_algorithm& operator=(const iterated_algorithm&) = delete;
};

// Inputs: random coordinates; each test file specializes input_maker so that
// versor types get unit versors (exp of a random generator), the inputs log
// and apply are meant for.
template <class X>
struct input_maker {
  static X make(std::mt19937& rng, bool sparse) { return random_value<X>(rng, sparse); }
};

template <class X>
X make_input(std::mt19937& rng, int trial) {
  return input_maker<X>::make(rng, trial % 2 == 1);
}

// Both plain scalars, or both library values with equal coefficients.
template <class OptMV, class RefMV, class A, class B>
::testing::AssertionResult results_agree(const A& opt, const B& ref) {
  using T = scalar_of<OptMV>;
  if constexpr (std::is_arithmetic_v<A> != std::is_arithmetic_v<B>) {
    return ::testing::AssertionFailure() << "the variants return different kinds of result";
  } else {
    if constexpr (!std::is_arithmetic_v<A>) {
      if (size_of<A> != size_of<B>)
        return ::testing::AssertionFailure() << "the variants return different types";
    }
    return mv_near<OptMV>(as_mv<OptMV>(opt), same_coordinates<OptMV>(as_mv<RefMV>(ref)),
                          agreement_tolerance<T>() * tolerance_factor());
  }
}

// Calls f (optimized) and g (reference); both must throw std::domain_error
// or both return agreeing results.
template <class OptMV, class RefMV, class F, class G>
void expect_agree(const std::string& what, F f, G g) {
  decltype(f()) opt{};
  decltype(g()) ref{};
  bool opt_threw = false, ref_threw = false;
  try {
    opt = f();
  } catch (const std::domain_error&) {
    opt_threw = true;
  }
  try {
    ref = g();
  } catch (const std::domain_error&) {
    ref_threw = true;
  }
  EXPECT_EQ(opt_threw, ref_threw) << what << ": only one variant throws";
  if (!opt_threw && !ref_threw) {
    EXPECT_TRUE((results_agree<OptMV, RefMV>(opt, ref))) << what;
  }
}

// expr, written with the namespace alias ns and the inputs a (and b), is
// evaluated in both variants on the same random inputs of types A (and B).
// Odd trials give mv inputs a sparse bitmap; b alternates every two trials,
// so every dense/sparse pairing occurs.
#define AGREE_UNARY_EXPR(alg, A, expr)                                  \
  for (int trial = 0; trial < agreement_trials; ++trial) {              \
    const auto in_a = make_input<alg::basic_##A<T>>(rng, trial);        \
    const auto ref_a = same_coordinates<alg##_ref::basic_##A<T>>(in_a); \
    expect_agree<alg::basic_mv<T>, alg##_ref::basic_mv<T>>(             \
        std::string(#alg ": " #expr ", a: " #A " = ") +                 \
            ::testing::PrintToString(as_mv<alg::basic_mv<T>>(in_a)),    \
        [&] {                                                           \
          namespace ns = alg;                                           \
          const auto& a = in_a;                                         \
          return expr;                                                  \
        },                                                              \
        [&] {                                                           \
          namespace ns = alg##_ref;                                     \
          const auto& a = ref_a;                                        \
          return expr;                                                  \
        });                                                             \
  }

#define AGREE_BINARY_EXPR(alg, A, B, expr)                                               \
  for (int trial = 0; trial < agreement_trials; ++trial) {                               \
    const auto in_a = make_input<alg::basic_##A<T>>(rng, trial);                         \
    const auto in_b = make_input<alg::basic_##B<T>>(rng, trial / 2);                     \
    const auto ref_a = same_coordinates<alg##_ref::basic_##A<T>>(in_a);                  \
    const auto ref_b = same_coordinates<alg##_ref::basic_##B<T>>(in_b);                  \
    expect_agree<alg::basic_mv<T>, alg##_ref::basic_mv<T>>(                              \
        std::string(#alg ": " #expr ", a: " #A " = ") +                                  \
            ::testing::PrintToString(as_mv<alg::basic_mv<T>>(in_a)) + ", b: " #B " = " + \
            ::testing::PrintToString(as_mv<alg::basic_mv<T>>(in_b)),                     \
        [&] {                                                                            \
          namespace ns = alg;                                                            \
          const auto& a = in_a;                                                          \
          const auto& b = in_b;                                                          \
          return expr;                                                                   \
        },                                                                               \
        [&] {                                                                            \
          namespace ns = alg##_ref;                                                      \
          const auto& a = ref_a;                                                         \
          const auto& b = ref_b;                                                         \
          return expr;                                                                   \
        });                                                                              \
  }

// A function the spec declares.
#define AGREE1(alg, fn, A) AGREE_UNARY_EXPR(alg, A, ns::fn(a))
#define AGREE2(alg, fn, A, B) AGREE_BINARY_EXPR(alg, A, B, ns::fn(a, b))

// The functions every type gets, grade selection up to grade n, and the operators.
#define AGREE_EVERY_TYPE(alg, A, n)                                      \
  AGREE_UNARY_EXPR(alg, A, ns::neg(a))                                   \
  AGREE_UNARY_EXPR(alg, A, ns::reverse(a))                               \
  AGREE_UNARY_EXPR(alg, A, ns::involute(a))                              \
  AGREE_UNARY_EXPR(alg, A, ns::conjugate(a))                             \
  AGREE_UNARY_EXPR(alg, A, ns::dual(a))                                  \
  AGREE_UNARY_EXPR(alg, A, ns::undual(a))                                \
  AGREE_UNARY_EXPR(alg, A, ns::norm2(a))                                 \
  AGREE_UNARY_EXPR(alg, A, ns::norm(a))                                  \
  AGREE_UNARY_EXPR(alg, A, ns::unit(a))                                  \
  AGREE_UNARY_EXPR(alg, A, ns::inverse(a))                               \
  AGREE_UNARY_EXPR(alg, A, ns::general_inverse(a))                       \
  AGREE_UNARY_EXPR(alg, A, ns::smul(T(1.75), a))                         \
  AGREE_UNARY_EXPR(alg, A, -a)                                           \
  AGREE_UNARY_EXPR(alg, A, ~a)                                           \
  AGREE_UNARY_EXPR(alg, A, T(-0.5) * a)                                  \
  AGREE_UNARY_EXPR(alg, A, a* T(3))                                      \
  AGREE_UNARY_EXPR(alg, A, a / T(4))                                     \
  for (int k = 0; k <= n; ++k) AGREE_UNARY_EXPR(alg, A, ns::grade(a, k)) \
  AGREE_BINARY_EXPR(alg, A, A, ns::add(a, b))                            \
  AGREE_BINARY_EXPR(alg, A, A, ns::sub(a, b))                            \
  AGREE_BINARY_EXPR(alg, A, A, a + b)                                    \
  AGREE_BINARY_EXPR(alg, A, A, a - b)                                    \
  AGREE_BINARY_EXPR(alg, A, A, a* b)                                     \
  AGREE_BINARY_EXPR(alg, A, A, a ^ b)                                    \
  AGREE_BINARY_EXPR(alg, A, A, ns::lc(a, b))                             \
  AGREE_BINARY_EXPR(alg, A, A, ns::rc(a, b))                             \
  AGREE_BINARY_EXPR(alg, A, A, ns::scp(a, b))

}  // namespace gaphys_test
