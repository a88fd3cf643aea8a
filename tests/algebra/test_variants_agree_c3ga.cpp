// The optimized variant of c3ga (namespace c3ga) against the reference variant
// (generated under c3ga_ref) on the same random inputs: every function the
// spec declares, the unary and linear functions of every named type, the
// operators, and the general multivector functions on dense and sparse inputs.
// Results must agree coefficient by coefficient.
//
// check_agreement_coverage.cmake fails when a `function` line of specs/c3ga.ga
// has no AGREE1 / AGREE2 line here.
#include <c3ga/c3ga.hpp>
#include <c3ga_ref/c3ga_ref.hpp>

#include "variants_agree.hpp"

namespace gaphys_test {

// Unit rotors, translators and motors for log, apply and inverse.
template <class T>
struct input_maker<c3ga::basic_rotor<T>> {
  static c3ga::basic_rotor<T> make(std::mt19937& rng, bool) {
    return c3ga::exp(random_named<c3ga::basic_euclidean_bivector<T>>(rng, T(-2), T(2)));
  }
};
template <class T>
struct input_maker<c3ga::basic_translator<T>> {
  static c3ga::basic_translator<T> make(std::mt19937& rng, bool) {
    auto x = random_named<c3ga::basic_translator<T>>(rng, T(-2), T(2));
    x.c[0] = 1;
    return x;
  }
};
template <class T>
struct input_maker<c3ga::basic_motor<T>> {
  static c3ga::basic_motor<T> make(std::mt19937& rng, bool) {
    return c3ga::exp(random_named<c3ga::basic_dual_line<T>>(rng, T(-2), T(2)));
  }
};

}  // namespace gaphys_test

namespace {

using namespace gaphys_test;

template <class T>
class C3gaVariantsAgree : public ::testing::Test {};
TYPED_TEST_SUITE(C3gaVariantsAgree, scalar_types);

TYPED_TEST(C3gaVariantsAgree, SpecFunctions) {
  using T = TypeParam;
  auto rng = make_rng(611);
  AGREE2(c3ga, op, normalized_point, normalized_point)
  AGREE2(c3ga, op, line, normalized_point)
  AGREE2(c3ga, op, flat_point, normalized_point)
  AGREE2(c3ga, op, point_pair, normalized_point)
  AGREE2(c3ga, op, circle, normalized_point)
  AGREE2(c3ga, op, normalized_point, dual_plane)
  AGREE2(c3ga, gp, dual_sphere, dual_sphere)
  AGREE2(c3ga, scp, normalized_point, normalized_point)
  AGREE2(c3ga, scp, dual_sphere, dual_sphere)
  AGREE2(c3ga, scp, normalized_point, dual_sphere)
  AGREE2(c3ga, lc, normalized_point, dual_sphere)
  AGREE2(c3ga, op, dual_sphere, dual_sphere)
  AGREE2(c3ga, op, dual_sphere, dual_plane)
  AGREE2(c3ga, meet, sphere, sphere)
  AGREE2(c3ga, meet, sphere, plane)
  AGREE1(c3ga, dual, dual_sphere)
  AGREE1(c3ga, dual, circle)
  AGREE1(c3ga, undual, sphere)
  AGREE2(c3ga, gp, circle, circle)
  AGREE2(c3ga, gp, rotor, rotor)
  AGREE2(c3ga, gp, translator, translator)
  AGREE2(c3ga, gp, rotor, translator)
  AGREE2(c3ga, gp, translator, rotor)
  AGREE2(c3ga, gp, motor, motor)
  AGREE2(c3ga, apply, motor, normalized_point)
  AGREE2(c3ga, apply, motor, dual_sphere)
  AGREE2(c3ga, apply, rotor, normalized_point)
  AGREE2(c3ga, apply, translator, normalized_point)
  AGREE2(c3ga, apply, motor, dual_plane)
  AGREE1(c3ga, exp, euclidean_bivector)
  AGREE1(c3ga, exp, dual_line)
  AGREE1(c3ga, log, rotor)
  AGREE1(c3ga, log, translator)
  AGREE1(c3ga, log, motor)
  AGREE1(c3ga, inverse, motor)
  AGREE2(c3ga, lc, dual_sphere, dual_sphere)
  AGREE2(c3ga, gp, point_pair, point_pair)
  AGREE2(c3ga, lc, point_pair, point_pair)
  AGREE2(c3ga, op, point_pair, point_pair)
  AGREE2(c3ga, scp, point_pair, point_pair)
  AGREE2(c3ga, lc, motor, motor)
  AGREE2(c3ga, op, motor, motor)
  AGREE2(c3ga, scp, motor, motor)
}

TYPED_TEST(C3gaVariantsAgree, EveryType) {
  using T = TypeParam;
  auto rng = make_rng(612);
  AGREE_EVERY_TYPE(c3ga, normalized_point, 5)
  AGREE_EVERY_TYPE(c3ga, dual_sphere, 5)
  AGREE_EVERY_TYPE(c3ga, dual_plane, 5)
  AGREE_EVERY_TYPE(c3ga, euclidean_vector, 5)
  AGREE_EVERY_TYPE(c3ga, flat_point, 5)
  AGREE_EVERY_TYPE(c3ga, euclidean_bivector, 5)
  AGREE_EVERY_TYPE(c3ga, point_pair, 5)
  AGREE_EVERY_TYPE(c3ga, dual_line, 5)
  AGREE_EVERY_TYPE(c3ga, line, 5)
  AGREE_EVERY_TYPE(c3ga, circle, 5)
  AGREE_EVERY_TYPE(c3ga, sphere, 5)
  AGREE_EVERY_TYPE(c3ga, plane, 5)
  AGREE_EVERY_TYPE(c3ga, pseudoscalar, 5)
  AGREE_EVERY_TYPE(c3ga, rotor, 5)
  AGREE_EVERY_TYPE(c3ga, translator, 5)
  AGREE_EVERY_TYPE(c3ga, motor, 5)
  AGREE_EVERY_TYPE(c3ga, mv, 5)
}

TYPED_TEST(C3gaVariantsAgree, MixedAndGeneral) {
  using T = TypeParam;
  auto rng = make_rng(613);
  AGREE2(c3ga, gp, motor, normalized_point)
  AGREE2(c3ga, op, dual_sphere, circle)
  AGREE2(c3ga, lc, dual_plane, circle)
  AGREE2(c3ga, meet, dual_sphere, dual_sphere)
  AGREE2(c3ga, meet, mv, mv)
  AGREE2(c3ga, apply, mv, mv)
  AGREE2(c3ga, apply, motor, line)
  {
    const iterated_algorithm series;  // see iterated_algorithm
    AGREE1(c3ga, exp, mv)
  }
  AGREE_UNARY_EXPR(c3ga, dual_line, ns::exp(ns::basic_mv<T>(a)))
  AGREE_UNARY_EXPR(c3ga, motor, ns::log(ns::basic_mv<T>(a)))
}

}  // namespace
