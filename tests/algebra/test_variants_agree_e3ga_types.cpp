// The e3ga variants agree on every named type's unary and linear functions
// and operators (see test_variants_agree_e3ga.cpp).
#include "variants_agree_e3ga.hpp"

namespace {

using namespace gaphys_test;

template <class T>
class E3gaVariantsAgreeTypes : public ::testing::Test {};
TYPED_TEST_SUITE(E3gaVariantsAgreeTypes, scalar_types);

TYPED_TEST(E3gaVariantsAgreeTypes, EveryType) {
  using T = TypeParam;
  auto rng = make_rng(602);
  AGREE_EVERY_TYPE(e3ga, scalar, 3)
  AGREE_EVERY_TYPE(e3ga, vector, 3)
  AGREE_EVERY_TYPE(e3ga, bivector, 3)
  AGREE_EVERY_TYPE(e3ga, trivector, 3)
  AGREE_EVERY_TYPE(e3ga, rotor, 3)
  AGREE_EVERY_TYPE(e3ga, mv, 3)
}

}  // namespace
