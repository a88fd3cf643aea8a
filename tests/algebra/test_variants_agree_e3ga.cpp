// The optimized variant of e3ga (namespace e3ga) against the reference variant
// (generated under e3ga_ref) on the same random inputs: every function the
// spec declares and the general multivector functions on dense and sparse
// inputs here, the unary and linear functions of every named type and the
// operators in test_variants_agree_e3ga_types.cpp.
// Results must agree coefficient by coefficient.
//
// check_agreement_coverage.cmake fails when a `function` line of specs/e3ga.ga
// has no AGREE1 / AGREE2 line here.
#include "variants_agree_e3ga.hpp"


namespace {

using namespace gaphys_test;

template <class T>
class E3gaVariantsAgree : public ::testing::Test {};
TYPED_TEST_SUITE(E3gaVariantsAgree, scalar_types);

TYPED_TEST(E3gaVariantsAgree, SpecFunctions) {
  using T = TypeParam;
  auto rng = make_rng(601);
  AGREE2(e3ga, gp, vector, vector)
  AGREE2(e3ga, gp, rotor, rotor)
  AGREE2(e3ga, gp, rotor, vector)
  AGREE2(e3ga, gp, vector, rotor)
  AGREE2(e3ga, gp, bivector, bivector)
  AGREE2(e3ga, gp, rotor, bivector)
  AGREE2(e3ga, gp, bivector, rotor)
  AGREE2(e3ga, gp, bivector, vector)
  AGREE2(e3ga, gp, vector, bivector)
  AGREE2(e3ga, op, vector, vector)
  AGREE2(e3ga, op, vector, bivector)
  AGREE2(e3ga, op, bivector, vector)
  AGREE2(e3ga, lc, vector, bivector)
  AGREE2(e3ga, lc, vector, vector)
  AGREE2(e3ga, lc, bivector, bivector)
  AGREE2(e3ga, rc, bivector, vector)
  AGREE2(e3ga, scp, vector, vector)
  AGREE2(e3ga, scp, bivector, bivector)
  AGREE2(e3ga, scp, rotor, rotor)
  AGREE2(e3ga, apply, rotor, vector)
  AGREE2(e3ga, apply, rotor, bivector)
  AGREE1(e3ga, exp, bivector)
  AGREE1(e3ga, log, rotor)
  AGREE1(e3ga, inverse, rotor)
  AGREE2(e3ga, lc, rotor, rotor)
  AGREE2(e3ga, op, rotor, rotor)
  AGREE1(e3ga, inverse, vector)
  AGREE2(e3ga, meet, bivector, bivector)
}

// Combinations the spec does not declare go through mv in both variants.
TYPED_TEST(E3gaVariantsAgree, MixedAndGeneral) {
  using T = TypeParam;
  auto rng = make_rng(603);
  AGREE2(e3ga, gp, vector, trivector)
  AGREE2(e3ga, op, rotor, vector)
  AGREE2(e3ga, lc, trivector, mv)
  AGREE2(e3ga, apply, mv, mv)
  AGREE2(e3ga, apply, vector, bivector)
  AGREE2(e3ga, meet, mv, mv)
  AGREE2(e3ga, meet, trivector, vector)
  {
    const iterated_algorithm series;  // see iterated_algorithm
    AGREE1(e3ga, exp, mv)
  }
  AGREE_UNARY_EXPR(e3ga, bivector, ns::exp(ns::basic_mv<T>(a)))
  AGREE_UNARY_EXPR(e3ga, rotor, ns::log(ns::basic_mv<T>(a)))
}

}  // namespace
