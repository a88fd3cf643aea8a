// The projective algebra Cl(3,0,1) of specs/pga3d.ga (e0
// squares to 0), an algebra a user brings (issue 16), with ganja.js / klein
// blade orientations (e31, e032, e013, e021): accessors, kernels that read
// nothing of their argument, inverses of null elements, log of motors.
#include <array>
#include <cmath>
#include <pga3d/pga3d.hpp>
#include <stdexcept>

#include "algebra_test_support.hpp"

namespace pga3d_test {

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
  const pga3d::basic_normalized_point<T> p{1, 2, 3};          // e032, e013, e021; e123 = 1
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
  const auto moved = pga3d::apply(t, pga3d::basic_normalized_point<T>{0, 0, 0});
  EXPECT_TRUE(mv_near<mv<T>>(moved, pga3d::basic_normalized_point<T>{1, 2, 3}, tolerance<T>()));
}

// Issue 16, defect 6: norm2(point) = e123 ~e123 = 1 (the other blades
// contain e0, which squares to 0): its kernel read nothing of its argument,
// and this file, compiled with -Werror, did not compile.
TYPED_TEST(Pga3d, Norm2OfPointIsOne) {
  using T = TypeParam;
  EXPECT_EQ(pga3d::norm2(pga3d::basic_normalized_point<T>{1, 2, 3}), T(1));
  EXPECT_EQ(pga3d::norm2(as_mv<mv<T>>(pga3d::basic_normalized_point<T>{1, 2, 3})), T(1));
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

// ---- incidence: join and meet (issue 16: a degenerate metric's dual is the complement) ----

template <class T>
using point3 = std::array<T, 3>;

// A homogeneous point's Euclidean coordinates: (e032, e013, e021) / e123.
template <class T>
point3<T> coordinates(const pga3d::basic_point<T>& p) {
  return {p.e032() / p.e123(), p.e013() / p.e123(), p.e021() / p.e123()};
}

template <class T>
pga3d::basic_normalized_point<T> at(const point3<T>& x) {
  return {x[0], x[1], x[2]};
}

// The plane a x + b y + c z + d = 0 evaluated at x: zero when x lies on it.
template <class T>
T plane_at(const pga3d::basic_plane<T>& plane, const point3<T>& x) {
  return plane.e1() * x[0] + plane.e2() * x[1] + plane.e3() * x[2] + plane.e0();
}

TYPED_TEST(Pga3d, TheLineThroughTwoPointsCrossesAPlaneWhereCoordinateGeometrySays) {
  using T = TypeParam;
  const point3<T> p{1, 2, 3}, q{4, 6, 3};
  const pga3d::basic_line<T> line = pga3d::join(at(p), at(q));
  const pga3d::basic_plane<T> x_is_2_5{T(-2.5), 1, 0, 0};
  // p + t (q - p) with x = 2.5: t = 1/2.
  const point3<T> crossing = coordinates(pga3d::meet(line, x_is_2_5));
  const point3<T> expected{T(2.5), 4, 3};
  for (int i = 0; i < 3; ++i)
    EXPECT_TRUE(scalar_near(double(crossing[i]), double(expected[i]), tolerance<T>()));
  // The meet and join of lines and planes does not depend on the order but for a sign.
  EXPECT_TRUE(mv_near<mv<T>>(pga3d::join(at(q), at(p)), -line, tolerance<T>()));
  EXPECT_TRUE(
      mv_near<mv<T>>(pga3d::meet(x_is_2_5, line), pga3d::meet(line, x_is_2_5), tolerance<T>()));
}

TYPED_TEST(Pga3d, ThreePlanesMeetInTheirCommonPoint) {
  using T = TypeParam;
  const pga3d::basic_plane<T> x_is_1{-1, 1, 0, 0}, y_is_2{-2, 0, 1, 0}, z_is_3{-3, 0, 0, 1};
  const pga3d::basic_line<T> axis = pga3d::meet(x_is_1, y_is_2);
  const point3<T> corner = coordinates(pga3d::meet(axis, z_is_3));
  const point3<T> expected{1, 2, 3};
  for (int i = 0; i < 3; ++i)
    EXPECT_TRUE(scalar_near(double(corner[i]), double(expected[i]), tolerance<T>()));
  // Two parallel planes meet in a line at infinity: no direction part.
  const pga3d::basic_line<T> at_infinity = pga3d::meet(x_is_1, pga3d::basic_plane<T>{-5, 1, 0, 0});
  EXPECT_EQ(at_infinity.e23(), T(0));
  EXPECT_EQ(at_infinity.e31(), T(0));
  EXPECT_EQ(at_infinity.e12(), T(0));
}

TYPED_TEST(Pga3d, ThePlaneThroughThreePointsHoldsThemAll) {
  using T = TypeParam;
  auto rng = make_rng(16);
  for (int trial = 0; trial < 50; ++trial) {
    const point3<T> a = random_array<T, 3>(rng, -5, 5), b = random_array<T, 3>(rng, -5, 5),
                    c = random_array<T, 3>(rng, -5, 5);
    const pga3d::basic_plane<T> plane = pga3d::join(pga3d::join(at(a), at(b)), at(c));
    // Unit normal, so the plane's value at a point is its signed distance.
    const T size =
        std::sqrt(plane.e1() * plane.e1() + plane.e2() * plane.e2() + plane.e3() * plane.e3());
    if (size < T(1e-2)) continue;  // nearly collinear points
    for (const point3<T>& x : {a, b, c})
      EXPECT_TRUE(scalar_near(double(plane_at(plane, x) / size), 0, 20 * tolerance<T>()));
    // The normal is (b - a) x (c - a), up to the orientation the join fixes.
    const point3<T> u{b[0] - a[0], b[1] - a[1], b[2] - a[2]},
        v{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const point3<T> normal{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                           u[0] * v[1] - u[1] * v[0]};
    EXPECT_TRUE(scalar_near(
        double(std::abs(plane.e1() * normal[0] + plane.e2() * normal[1] + plane.e3() * normal[2])),
        double(size *
               std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2])),
        20 * tolerance<T>()));
  }
}

// The line through two normalized points has the length of the segment as its norm.
TYPED_TEST(Pga3d, TheNormOfAJoinIsTheDistance) {
  using T = TypeParam;
  const point3<T> p{1, -2, 3}, q{-3, 1, 3};
  EXPECT_TRUE(scalar_near(double(pga3d::norm(pga3d::join(at(p), at(q)))), 5, tolerance<T>()));
}

// Incidence does not depend on where you stand: a motor moves a join and a
// meet as it moves their arguments.
TYPED_TEST(Pga3d, JoinAndMeetCommuteWithMotors) {
  using T = TypeParam;
  auto rng = make_rng(17);
  for (int trial = 0; trial < 50; ++trial) {
    const auto m = pga3d::exp(random_named<pga3d::basic_line<T>>(rng));
    const auto p = at(random_array<T, 3>(rng, -2, 2)), q = at(random_array<T, 3>(rng, -2, 2));
    const auto a = random_named<pga3d::basic_plane<T>>(rng),
               b = random_named<pga3d::basic_plane<T>>(rng);
    EXPECT_TRUE(mv_near<mv<T>>(pga3d::apply(m, pga3d::join(p, q)),
                               pga3d::join(pga3d::apply(m, p), pga3d::apply(m, q)),
                               10 * tolerance<T>()));
    EXPECT_TRUE(mv_near<mv<T>>(pga3d::apply(m, pga3d::meet(a, b)),
                               pga3d::meet(pga3d::apply(m, a), pga3d::apply(m, b)),
                               10 * tolerance<T>()));
  }
}

// With e0^2 = 0 there is no I^-1: dual is the right complement, e_A ^ dual(e_A)
// = I = e0^e1^e2^e3, and undual its inverse, on mv and on named types alike.
TYPED_TEST(Pga3d, DualIsTheComplement) {
  using T = TypeParam;
  const mv<T> pseudoscalar = mv<T>::basis_blade(pga3d::blade_count - 1);
  for (int i = 0; i < pga3d::blade_count; ++i) {
    const mv<T> blade = mv<T>::basis_blade(i);
    EXPECT_TRUE(mv_near<mv<T>>(pga3d::op(blade, pga3d::dual(blade)), pseudoscalar, T(0)))
        << pga3d::blade_names[i];
    EXPECT_TRUE(mv_near<mv<T>>(pga3d::undual(pga3d::dual(blade)), blade, T(0)))
        << pga3d::blade_names[i];
  }
  const pga3d::basic_plane<T> plane{1, 2, 3, 4};
  EXPECT_TRUE(mv_near<mv<T>>(pga3d::dual(plane), pga3d::dual(pga3d::to_mv(plane)), T(0)));
  EXPECT_TRUE(mv_near<mv<T>>(pga3d::undual(pga3d::dual(plane)), plane, T(0)));
  // The named kernels and the mv path agree on meet and join.
  const pga3d::basic_plane<T> other{-1, 0, 2, 1};
  EXPECT_TRUE(mv_near<mv<T>>(pga3d::meet(plane, other),
                             pga3d::meet(pga3d::to_mv(plane), pga3d::to_mv(other)),
                             tolerance<T>()));
  const auto p = at(point3<T>{1, 2, 3}), q = at(point3<T>{0, 1, -1});
  EXPECT_TRUE(mv_near<mv<T>>(pga3d::join(p, q), pga3d::join(pga3d::to_mv(p), pga3d::to_mv(q)),
                             tolerance<T>()));
}

}  // namespace pga3d_test
