// The optimized variant of c3ga (namespace c3ga) against the reference variant
// (generated under c3ga_ref) on the same random inputs: here every function
// the spec declares; in test_variants_agree_c3ga_types_*.cpp the unary and
// linear functions of every named type and the operators, and in
// test_variants_agree_c3ga_general.cpp the general multivector functions on
// dense and sparse inputs. Results must agree coefficient by coefficient.
//
// check_agreement_coverage.cmake fails when a `function` line of specs/c3ga.ga
// has no AGREE1 / AGREE2 line here.
#include "variants_agree_c3ga.hpp"

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

}  // namespace
