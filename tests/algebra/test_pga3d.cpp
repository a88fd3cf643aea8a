// The projective algebra Cl(3,0,1) of tests/algebra/specs/pga3d.ga (e0
// squares to 0), an algebra a user brings (issue 16), with ganja.js / klein
// blade orientations (e31, e032, e013, e021): accessors, kernels that read
// nothing of their argument, inverses of null elements, log of motors.
#include <cmath>
#include <pga3d/pga3d.hpp>
#include <stdexcept>

#include "algebra_test_support.hpp"

namespace {

using namespace gaphys_test;

template <class T>
using mv = pga3d::basic_mv<T>;

template <class T>
class Pga3d : public ::testing::Test {};
TYPED_TEST_SUITE(Pga3d, scalar_types);

// Issue 16, defect 8: a coordinate declared as e3^e1 was read with e13().
// Accessors are named as declared and return the coordinate as declared.
TYPED_TEST(Pga3d, AccessorsAreNamedAsDeclared) {
  using T = TypeParam;
  const auto& names = pga3d::blade_names;
  const pga3d::basic_line<T> l{1, 2, 3, 4, 5, 6};  // e01, e02, e03, e23, e31, e12
  EXPECT_EQ(l.e31(), T(5));
  EXPECT_EQ(mv<T>(l).c[blade_index(names, "e1^e3")], T(-5));  // e3^e1 = -e1^e3
  const pga3d::basic_point<T> p{1, 2, 3};                     // e032, e013, e021; e123 = 1
  EXPECT_EQ(p.e032(), T(1));
  EXPECT_EQ(p.e013(), T(2));
  EXPECT_EQ(p.e021(), T(3));
  EXPECT_EQ(mv<T>(p).c[blade_index(names, "e0^e2^e3")], T(-1));
  EXPECT_EQ(mv<T>(p).c[blade_index(names, "e0^e1^e3")], T(2));
  EXPECT_EQ(mv<T>(p).c[blade_index(names, "e0^e1^e2")], T(-3));
  EXPECT_EQ(p.e123(), T(1));
  // As in ganja.js and klein, the point at x is e123 + x1 e032 + x2 e013 + x3 e021:
  // the translator exp(-1/2 (x1 e01 + x2 e02 + x3 e03)) takes the origin there.
  const pga3d::basic_motor<T> t{1, 0, 0, 0, T(-0.5), T(-1), T(-1.5), 0};
  const auto moved = pga3d::apply(t, pga3d::basic_point<T>{0, 0, 0});
  EXPECT_TRUE(mv_near<mv<T>>(moved, pga3d::basic_point<T>{1, 2, 3}, tolerance<T>()));
}

// Issue 16, defect 6: norm2(point) = e123 ~e123 = 1 (the other blades
// contain e0, which squares to 0): its kernel read nothing of its argument,
// and this file, compiled with -Werror, did not compile.
TYPED_TEST(Pga3d, Norm2OfPointIsOne) {
  using T = TypeParam;
  EXPECT_EQ(pga3d::norm2(pga3d::basic_point<T>{1, 2, 3}), T(1));
  EXPECT_EQ(pga3d::norm2(as_mv<mv<T>>(pga3d::basic_point<T>{1, 2, 3})), T(1));
}

// Issue 16, defect 4: an ideal line (e01, e02, e03 only) and the plane at
// infinity e0 are null, and their versor inverses divided by zero (NaN, also
// where bits were clear).
TYPED_TEST(Pga3d, VersorInverseOfNullThrows) {
  using T = TypeParam;
  const pga3d::basic_line<T> ideal_line{1, 2, 3, 0, 0, 0};
  EXPECT_THROW(pga3d::inverse(ideal_line), std::domain_error);
  EXPECT_THROW(pga3d::inverse(as_mv<mv<T>>(ideal_line)), std::domain_error);
  const pga3d::basic_plane<T> ideal_plane{1, 0, 0, 0};
  EXPECT_THROW(pga3d::inverse(ideal_plane), std::domain_error);
  // A plane with a normal is a versor (a reflection): p p^-1 = 1.
  const pga3d::basic_plane<T> p{1, 2, 3, 4};
  EXPECT_TRUE(
      mv_near<mv<T>>(pga3d::to_mv(p) * pga3d::to_mv(pga3d::inverse(p)), T(1), tolerance<T>()));
}

// Issue 16, defect 2: translator{1, -0.5, -1, -0.25} times a rotation by a
// tiny half angle: in float, <b q>_2 (about 1e-23) squared underflowed to a
// denormal and log returned a wrong translation. exp(log M) == M is the truth.
TYPED_TEST(Pga3d, LogOfMotorWithTinyRotation) {
  using T = TypeParam;
  for (const double half : {1e-11, 1e-20, 1e-30}) {
    SCOPED_TRACE(::testing::Message() << "half angle " << half);
    const pga3d::basic_translator<T> t{1, T(-0.5), T(-1), T(-0.25)};
    const pga3d::basic_rotor<T> r{T(std::cos(half)), T(-std::sin(half)), 0, 0};
    const auto m = t * r;
    const auto l = checked_call([&] { return pga3d::log(m); });
    if (!l) continue;
    EXPECT_TRUE(mv_near<mv<T>>(pga3d::exp(pga3d::to_mv(*l)), m, tolerance<T>()))
        << "log M = " << mv<T>(*l);
    // log M = -0.5 e01 - e02 - 0.25 e03 - half e23, up to O(half) in the
    // translation (the commutator of the two parts).
    const pga3d::basic_line<T> expected{T(-0.5), T(-1), T(-0.25), T(-half), 0, 0};
    EXPECT_TRUE(mv_near<mv<T>>(*l, expected, tolerance<T>()));
    EXPECT_TRUE(scalar_near(double(l->e23()) / half, -1, tolerance<T>()));  // to its own size
  }
}

}  // namespace
