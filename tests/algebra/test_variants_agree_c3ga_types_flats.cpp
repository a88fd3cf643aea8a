// The c3ga variants agree on the unary and linear functions and operators of
// points, spheres, planes, vectors and flat points (see test_variants_agree_c3ga.cpp; one file per group of
// types, so that they compile in parallel).
#include "variants_agree_c3ga.hpp"

namespace {

using namespace gaphys_test;

template <class T>
class C3gaVariantsAgreeFlats : public ::testing::Test {};
TYPED_TEST_SUITE(C3gaVariantsAgreeFlats, scalar_types);

TYPED_TEST(C3gaVariantsAgreeFlats, EveryType) {
  using T = TypeParam;
  auto rng = make_rng(612);
  AGREE_EVERY_TYPE(c3ga, normalized_point, 5)
  AGREE_EVERY_TYPE(c3ga, dual_sphere, 5)
  AGREE_EVERY_TYPE(c3ga, dual_plane, 5)
  AGREE_EVERY_TYPE(c3ga, euclidean_vector, 5)
  AGREE_EVERY_TYPE(c3ga, flat_point, 5)
  AGREE_EVERY_TYPE(c3ga, euclidean_bivector, 5)
}

}  // namespace
