// The c3ga variants agree on the unary and linear functions and operators of
// the pseudoscalar, rotors, translators, motors and mv (see test_variants_agree_c3ga.cpp; one file per group of
// types, so that they compile in parallel).
#include "variants_agree_c3ga.hpp"

namespace {

using namespace gaphys_test;

template <class T>
class C3gaVariantsAgreeVersors : public ::testing::Test {};
TYPED_TEST_SUITE(C3gaVariantsAgreeVersors, scalar_types);

TYPED_TEST(C3gaVariantsAgreeVersors, EveryType) {
  using T = TypeParam;
  auto rng = make_rng(615);
  AGREE_EVERY_TYPE(c3ga, pseudoscalar, 5)
  AGREE_EVERY_TYPE(c3ga, rotor, 5)
  AGREE_EVERY_TYPE(c3ga, translator, 5)
  AGREE_EVERY_TYPE(c3ga, motor, 5)
  AGREE_EVERY_TYPE(c3ga, mv, 5)
}

}  // namespace
