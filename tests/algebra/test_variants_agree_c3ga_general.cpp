// The c3ga variants agree on mixed-type products and the general
// multivector functions (see test_variants_agree_c3ga.cpp).
#include "variants_agree_c3ga.hpp"

namespace {

using namespace gaphys_test;

template <class T>
class C3gaVariantsAgreeGeneral : public ::testing::Test {};
TYPED_TEST_SUITE(C3gaVariantsAgreeGeneral, scalar_types);

TYPED_TEST(C3gaVariantsAgreeGeneral, MixedAndGeneral) {
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
