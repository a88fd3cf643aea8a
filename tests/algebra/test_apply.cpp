// apply(V, X) = V X V^-1 against rigid motions computed with plain 3-D maths:
// e3ga rotors against Rodrigues' formula, c3ga rotors, translators and motors
// on points, dual spheres and dual planes.
#include <c3ga/c3ga.hpp>
#include <e3ga/e3ga.hpp>
#include <stdexcept>

#include "algebra_test_support.hpp"
#include "c3ga_test_support.hpp"

// (A namespace of its own, not an anonymous one: the suite also compiles
// as one source, a unity build, where the files' names must not meet.)
namespace apply_test {

using namespace gaphys_test;

template <class T>
using e3mv = e3ga::basic_mv<T>;
template <class T>
using c3mv = c3ga::basic_mv<T>;

constexpr int trials = 50;

template <class T>
class Apply : public ::testing::Test {};
TYPED_TEST_SUITE(Apply, scalar_types);

template <class X>
vec3 as_vec3(const X& x) {
  return {double(x.c[0]), double(x.c[1]), double(x.c[2])};
}

// A random rotation: unit axis and angle in (-2 pi, 2 pi).
struct rotation {
  vec3 axis;
  double angle;
};

rotation random_rotation(std::mt19937& rng) {
  return {random_unit_vec3(rng), uniform(rng, -2 * pi, 2 * pi)};
}

// exp(-angle/2 axis I3), the rotor of a right-handed rotation about axis.
vec3 rotor_generator(const rotation& r) { return (-r.angle / 2) * bivector_of_axis(r.axis); }

TYPED_TEST(Apply, E3gaRotorRotatesVectorsByRodrigues) {
  using T = TypeParam;
  auto rng = make_rng(401);
  for (int i = 0; i < trials; ++i) {
    const rotation rot = random_rotation(rng);
    const vec3 g = rotor_generator(rot);
    const auto r = e3ga::exp(e3ga::basic_bivector<T>{T(g[0]), T(g[1]), T(g[2])});
    const vec3 v = random_vec3(rng, -3, 3);
    const vec3 w = rodrigues(rot.axis, rot.angle, v);
    const e3ga::basic_vector<T> x{T(v[0]), T(v[1]), T(v[2])};
    const e3ga::basic_vector<T> expected{T(w[0]), T(w[1]), T(w[2])};
    EXPECT_TRUE(mv_near<e3mv<T>>(e3ga::apply(r, x), expected, tolerance<T>()));
    // apply divides by <V ~V>_0, so a scaled rotor acts the same.
    EXPECT_TRUE(mv_near<e3mv<T>>(e3ga::apply(r * T(2.5), x), expected, tolerance<T>()));
    // The sandwich written out.
    EXPECT_TRUE(mv_near<e3mv<T>>((r * x) * ~r, expected, tolerance<T>()));
  }
}

// A bivector n I3 rotates as its dual vector n does.
TYPED_TEST(Apply, E3gaRotorRotatesBivectorsLikeTheirAxes) {
  using T = TypeParam;
  auto rng = make_rng(402);
  for (int i = 0; i < trials; ++i) {
    const rotation rot = random_rotation(rng);
    const vec3 g = rotor_generator(rot);
    const auto r = e3ga::exp(e3ga::basic_bivector<T>{T(g[0]), T(g[1]), T(g[2])});
    const vec3 n = random_vec3(rng, -3, 3);
    const vec3 b = bivector_of_axis(n),
               rotated = bivector_of_axis(rodrigues(rot.axis, rot.angle, n));
    const e3ga::basic_bivector<T> x{T(b[0]), T(b[1]), T(b[2])};
    const e3ga::basic_bivector<T> expected{T(rotated[0]), T(rotated[1]), T(rotated[2])};
    EXPECT_TRUE(mv_near<e3mv<T>>(e3ga::apply(r, x), expected, tolerance<T>()));
  }
}

TYPED_TEST(Apply, E3gaRotorCompositionComposesRotations) {
  using T = TypeParam;
  auto rng = make_rng(403);
  for (int i = 0; i < trials; ++i) {
    const rotation a = random_rotation(rng), b = random_rotation(rng);
    const vec3 ga = rotor_generator(a), gb = rotor_generator(b);
    const auto ra = e3ga::exp(e3ga::basic_bivector<T>{T(ga[0]), T(ga[1]), T(ga[2])});
    const auto rb = e3ga::exp(e3ga::basic_bivector<T>{T(gb[0]), T(gb[1]), T(gb[2])});
    const vec3 v = random_vec3(rng);
    const vec3 w = rodrigues(b.axis, b.angle, rodrigues(a.axis, a.angle, v));
    // R = Rb Ra applies Ra first.
    EXPECT_TRUE(
        mv_near<e3mv<T>>(e3ga::apply(rb * ra, e3ga::basic_vector<T>{T(v[0]), T(v[1]), T(v[2])}),
                         e3ga::basic_vector<T>{T(w[0]), T(w[1]), T(w[2])}, tolerance<T>()));
  }
}

// ---- c3ga ----

// The rotor exp(-angle/2 axis I3) of c3ga.
template <class T>
c3ga::basic_rotor<T> rotor_of(const rotation& rot) {
  const vec3 g = rotor_generator(rot);
  return c3ga::exp(c3ga::basic_euclidean_bivector<T>{T(g[0]), T(g[1]), T(g[2])});
}

// The translator 1 - t ni / 2 moves points by t.
template <class T>
c3ga::basic_translator<T> translator_of(const vec3& t) {
  return {1, T(-t[0] / 2), T(-t[1] / 2), T(-t[2] / 2)};
}

TYPED_TEST(Apply, C3gaTranslatorMovesPoints) {
  using T = TypeParam;
  auto rng = make_rng(411);
  for (int i = 0; i < trials; ++i) {
    const vec3 x = random_vec3(rng, -3, 3), t = random_vec3(rng, -3, 3);
    EXPECT_TRUE(mv_near<c3mv<T>>(c3ga::apply(translator_of<T>(t), point_of<T>(x)),
                                 point_of<T>(x + t), tolerance<T>()));
  }
}

TYPED_TEST(Apply, C3gaRotorRotatesPointsAboutTheOrigin) {
  using T = TypeParam;
  auto rng = make_rng(412);
  for (int i = 0; i < trials; ++i) {
    const rotation rot = random_rotation(rng);
    const vec3 x = random_vec3(rng, -3, 3);
    EXPECT_TRUE(mv_near<c3mv<T>>(c3ga::apply(rotor_of<T>(rot), point_of<T>(x)),
                                 point_of<T>(rodrigues(rot.axis, rot.angle, x)), tolerance<T>()));
  }
}

// M = T R rotates about the origin, then translates: x -> R(x) + t.
TYPED_TEST(Apply, C3gaMotorIsRigidMotion) {
  using T = TypeParam;
  auto rng = make_rng(413);
  for (int i = 0; i < trials; ++i) {
    const rotation rot = random_rotation(rng);
    const vec3 t = random_vec3(rng, -3, 3), x = random_vec3(rng, -3, 3);
    const auto m = translator_of<T>(t) * rotor_of<T>(rot);
    const vec3 y = rodrigues(rot.axis, rot.angle, x) + t;
    EXPECT_TRUE(mv_near<c3mv<T>>(c3ga::apply(m, point_of<T>(x)), point_of<T>(y), tolerance<T>()));
    // The motor from exp(log M) moves points the same way.
    SCOPED_TRACE(::testing::Message() << "M = " << m << ", rotation angle " << rot.angle);
    const auto l = checked_call([&] { return c3ga::log(m); });
    if (l && std::abs(rot.angle - 2 * pi) >= 2 * full_turn_margin<T>()) {  // see full_turn_margin
      EXPECT_TRUE(mv_near<c3mv<T>>(c3ga::apply(c3ga::exp(*l), point_of<T>(x)), point_of<T>(y),
                                   tolerance<T>()));
    }
  }
}

TYPED_TEST(Apply, C3gaMotorCompositionComposesRigidMotions) {
  using T = TypeParam;
  auto rng = make_rng(414);
  for (int i = 0; i < trials; ++i) {
    const rotation ra = random_rotation(rng), rb = random_rotation(rng);
    const vec3 ta = random_vec3(rng), tb = random_vec3(rng), x = random_vec3(rng);
    const auto ma = translator_of<T>(ta) * rotor_of<T>(ra);
    const auto mb = translator_of<T>(tb) * rotor_of<T>(rb);
    const vec3 y = rodrigues(rb.axis, rb.angle, rodrigues(ra.axis, ra.angle, x) + ta) + tb;
    EXPECT_TRUE(
        mv_near<c3mv<T>>(c3ga::apply(mb * ma, point_of<T>(x)), point_of<T>(y), tolerance<T>()));
  }
}

// A rigid motion moves a sphere's centre and keeps its radius.
TYPED_TEST(Apply, C3gaMotorMovesDualSpheres) {
  using T = TypeParam;
  auto rng = make_rng(415);
  for (int i = 0; i < trials; ++i) {
    const rotation rot = random_rotation(rng);
    const vec3 t = random_vec3(rng, -3, 3), c = random_vec3(rng, -3, 3);
    const double r = uniform(rng, 0.1, 2.0);
    const auto m = translator_of<T>(t) * rotor_of<T>(rot);
    EXPECT_TRUE(mv_near<c3mv<T>>(c3ga::apply(m, dual_sphere_of<T>(c, r)),
                                 dual_sphere_of<T>(rodrigues(rot.axis, rot.angle, c) + t, r),
                                 tolerance<T>()));
  }
}

// The dual plane n + d ni ({x : x.n = d}) moves to R(n) + (d + R(n).t) ni.
TYPED_TEST(Apply, C3gaMotorMovesDualPlanes) {
  using T = TypeParam;
  auto rng = make_rng(416);
  for (int i = 0; i < trials; ++i) {
    const rotation rot = random_rotation(rng);
    const vec3 t = random_vec3(rng, -3, 3), n = random_unit_vec3(rng);
    const double d = uniform(rng, -2.0, 2.0);
    const auto m = translator_of<T>(t) * rotor_of<T>(rot);
    const vec3 rn = rodrigues(rot.axis, rot.angle, n);
    const auto plane = make_dual_plane<c3ga::basic_dual_plane<T>>(n, d);
    const auto expected = make_dual_plane<c3ga::basic_dual_plane<T>>(rn, d + dot(rn, t));
    EXPECT_TRUE(mv_near<c3mv<T>>(c3ga::apply(m, plane), expected, tolerance<T>()));
  }
}

// A null versor (ni: <ni ~ni>_0 = 0) has no inverse: apply on mv says so
// instead of returning infinities.
TYPED_TEST(Apply, ApplyOfANullVersorOnMvThrows) {
  using T = TypeParam;
  const c3mv<T> null_versor = c3ga::ni<T>();
  const c3mv<T> point = c3ga::basic_normalized_point<T>(T(1), T(2), T(3), T(7));
  EXPECT_THROW(c3ga::apply(null_versor, point), std::domain_error);
  EXPECT_NO_THROW(c3ga::apply(c3mv<T>(c3ga::basic_rotor<T>(T(1), T(0), T(0), T(0))), point));
}

}  // namespace apply_test
