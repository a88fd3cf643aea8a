// The c3ga variants agree on the unary and linear functions and operators of
// point pairs, lines, circles, spheres and planes (see test_variants_agree_c3ga.cpp; one file per group of
// types, so that they compile in parallel).
#include "variants_agree_c3ga.hpp"

namespace {

using namespace gaphys_test;

template <class T>
class C3gaVariantsAgreeRounds : public ::testing::Test {};
TYPED_TEST_SUITE(C3gaVariantsAgreeRounds, scalar_types);

TYPED_TEST(C3gaVariantsAgreeRounds, EveryType) {
  using T = TypeParam;
  auto rng = make_rng(614);
  AGREE_EVERY_TYPE(c3ga, point_pair, 5)
  AGREE_EVERY_TYPE(c3ga, dual_line, 5)
  AGREE_EVERY_TYPE(c3ga, line, 5)
  AGREE_EVERY_TYPE(c3ga, circle, 5)
  AGREE_EVERY_TYPE(c3ga, sphere, 5)
  AGREE_EVERY_TYPE(c3ga, plane, 5)
}

}  // namespace
