// exp and log of e3ga and c3ga bivectors and versors: closed forms, an
// independent Taylor series, unit versors, round trips and edge cases
// (zero, rotations by nearly pi and nearly 2 pi, tiny angles, translations).
#include <c3ga/c3ga.hpp>
#include <cmath>
#include <e3ga/e3ga.hpp>
#include <stdexcept>
#include <vector>

#include "algebra_test_support.hpp"

namespace exp_log_test {

using namespace gaphys_test;

template <class T>
using e3mv = e3ga::basic_mv<T>;
template <class T>
using c3mv = c3ga::basic_mv<T>;

constexpr int trials = 50;

// Half angles |B| (a rotor exp(B) rotates by 2|B|) at the edges of log's range.
const std::vector<double> edge_half_angles = {
    1e-8, 1e-4, 0.5, pi / 2 - 1e-6, pi / 2, pi / 2 + 1e-6, pi - 1e-2, pi - 1e-3, pi - 1e-6};

// Below this half angle log(exp(B)) must give B back; beyond, the plane of
// rotation is carried by a bivector part too small to resolve it accurately.
constexpr double resolvable_half_angle = pi - 1e-2;

template <class T>
class ExpLog : public ::testing::Test {};
TYPED_TEST_SUITE(ExpLog, scalar_types);

// The closed form exp(B) = cos|B| + sin|B| B/|B| for a Euclidean bivector with
// coordinates b (e1^e2, e1^e3, e2^e3), as e3ga coefficients.
template <class T>
std::array<T, 8> e3ga_exp_closed_form(const vec3& b) {
  const double t = length(b);
  const double k = t == 0 ? 1 : std::sin(t) / t;
  return {T(std::cos(t)), 0, 0, 0, T(k * b[0]), T(k * b[1]), T(k * b[2]), 0};
}

template <class X>
vec3 as_vec3(const X& x) {
  return {double(x.c[0]), double(x.c[1]), double(x.c[2])};
}

// ---- e3ga rotors ----

TYPED_TEST(ExpLog, E3gaExpMatchesClosedFormAndSeries) {
  using T = TypeParam;
  auto rng = make_rng(301);
  for (int i = 0; i < trials; ++i) {
    const auto b = random_named<e3ga::basic_bivector<T>>(rng, T(-2), T(2));
    const auto r = e3ga::exp(b);
    EXPECT_TRUE(mv_near<e3mv<T>>(r, e3mv<T>::from_array(e3ga_exp_closed_form<T>(as_vec3(b))),
                                 tolerance<T>()));
    const e3mv<double> series = exp_taylor(convert_mv<e3mv<double>>(as_mv<e3mv<T>>(b)));
    EXPECT_TRUE(
        mv_near<e3mv<double>>(convert_mv<e3mv<double>>(as_mv<e3mv<T>>(r)), series, tolerance<T>()));
    // exp on a general multivector holding a bivector agrees with the named overload.
    EXPECT_TRUE(mv_near<e3mv<T>>(e3ga::exp(as_mv<e3mv<T>>(b)), r, tolerance<T>()));
  }
}

TYPED_TEST(ExpLog, E3gaExpOfBivectorIsUnitRotor) {
  using T = TypeParam;
  auto rng = make_rng(302);
  for (int i = 0; i < trials; ++i) {
    const auto r = e3ga::exp(random_named<e3ga::basic_bivector<T>>(rng, T(-3), T(3)));
    EXPECT_TRUE(mv_near<e3mv<T>>(r * ~r, T(1), tolerance<T>()));
  }
}

TYPED_TEST(ExpLog, E3gaLogInvertsExp) {
  using T = TypeParam;
  auto rng = make_rng(303);
  for (int i = 0; i < trials; ++i) {
    const vec3 n = random_unit_vec3(rng);
    const double half = uniform(rng, 0.0, resolvable_half_angle);
    const vec3 bv = half * n;
    const e3ga::basic_bivector<T> b{T(bv[0]), T(bv[1]), T(bv[2])};
    EXPECT_TRUE(mv_near<e3mv<T>>(e3ga::log(e3ga::exp(b)), b, tolerance<T>()));
    // exp(log R) = R for random unit rotors.
    const auto q = random_named<e3ga::basic_rotor<T>>(rng, T(-1), T(1));
    const auto r = q * (T(1) / e3ga::norm(q));
    EXPECT_TRUE(mv_near<e3mv<T>>(e3ga::exp(e3ga::log(r)), r, tolerance<T>()));
  }
}

TYPED_TEST(ExpLog, E3gaEdgeAngles) {
  using T = TypeParam;
  auto rng = make_rng(304);
  for (const double half : edge_half_angles) {
    for (int i = 0; i < 5; ++i) {
      const vec3 bv = half * random_unit_vec3(rng);
      const e3ga::basic_bivector<T> b{T(bv[0]), T(bv[1]), T(bv[2])};
      const auto r = e3ga::exp(b);
      SCOPED_TRACE(::testing::Message() << "half angle " << half << ", B = " << e3mv<T>(b));
      EXPECT_TRUE(mv_near<e3mv<T>>(r, e3mv<T>::from_array(e3ga_exp_closed_form<T>(as_vec3(b))),
                                   tolerance<T>()));
      EXPECT_TRUE(mv_near<e3mv<T>>(r * ~r, T(1), tolerance<T>()));
      EXPECT_TRUE(mv_near<e3mv<T>>(e3ga::exp(e3ga::log(r)), r, tolerance<T>()));
      // Tiny angles must keep their relative accuracy (no cancellation in cos).
      const double abs_tol = half < 1e-3 ? tolerance<T>() * half : tolerance<T>();
      if (half <= resolvable_half_angle) {
        EXPECT_TRUE(mv_within<e3mv<T>>(e3ga::log(r), b, abs_tol));
      }
    }
  }
}

TYPED_TEST(ExpLog, E3gaZeroAndMinusOne) {
  using T = TypeParam;
  const e3ga::basic_bivector<T> zero{0, 0, 0};
  EXPECT_TRUE(mv_within<e3mv<T>>(e3ga::exp(zero), T(1), 0));
  const e3ga::basic_rotor<T> one{1, 0, 0, 0};
  EXPECT_TRUE(mv_within<e3mv<T>>(e3ga::log(one), zero, 0));
  // -1 is a rotation by 2 pi in some plane: log picks one, exp gives -1 back.
  const e3ga::basic_rotor<T> minus_one{-1, 0, 0, 0};
  EXPECT_TRUE(mv_near<e3mv<T>>(e3ga::exp(e3ga::log(minus_one)), minus_one, tolerance<T>()));
  EXPECT_TRUE(scalar_near(double(e3ga::norm(e3ga::log(minus_one))), pi, tolerance<T>()));
}

// ---- c3ga rotors, translators and motors ----

template <class T>
c3ga::basic_dual_line<T> dual_line_of(const vec3& euclidean, const vec3& null) {
  return {T(euclidean[0]), T(euclidean[1]), T(euclidean[2]), T(null[0]), T(null[1]), T(null[2])};
}

// Coefficients of a c3ga mv for the blades 1, e1^e2, e1^e3, e2^e3 (a rotor).
template <class T>
c3mv<T> c3ga_rotor_mv(const std::array<T, 8>& e3ga_coefficients) {
  std::array<T, 32> a{};
  const auto& names = c3ga::blade_names;
  a[0] = e3ga_coefficients[0];
  a[blade_index(names, "e1^e2")] = e3ga_coefficients[4];
  a[blade_index(names, "e1^e3")] = e3ga_coefficients[5];
  a[blade_index(names, "e2^e3")] = e3ga_coefficients[6];
  return c3mv<T>::from_array(a);
}

TYPED_TEST(ExpLog, C3gaRotorExpAndLog) {
  using T = TypeParam;
  auto rng = make_rng(311);
  for (int i = 0; i < trials; ++i) {
    const auto b = random_named<c3ga::basic_euclidean_bivector<T>>(rng, T(-1.5), T(1.5));
    const auto r = c3ga::exp(b);
    EXPECT_TRUE(
        mv_near<c3mv<T>>(r, c3ga_rotor_mv(e3ga_exp_closed_form<T>(as_vec3(b))), tolerance<T>()));
    EXPECT_TRUE(mv_near<c3mv<T>>(r * ~r, T(1), tolerance<T>()));
    if (length(as_vec3(b)) <= resolvable_half_angle) {
      EXPECT_TRUE(mv_near<c3mv<T>>(c3ga::log(r), b, tolerance<T>()));
    }
    EXPECT_TRUE(mv_near<c3mv<T>>(c3ga::exp(c3ga::log(r)), r, tolerance<T>()));
  }
  for (const double half : edge_half_angles) {
    const vec3 bv = half * random_unit_vec3(rng);
    const c3ga::basic_euclidean_bivector<T> b{T(bv[0]), T(bv[1]), T(bv[2])};
    SCOPED_TRACE(::testing::Message() << "half angle " << half);
    const auto r = c3ga::exp(b);
    EXPECT_TRUE(mv_near<c3mv<T>>(r * ~r, T(1), tolerance<T>()));
    EXPECT_TRUE(mv_near<c3mv<T>>(c3ga::exp(c3ga::log(r)), r, tolerance<T>()));
    const double abs_tol = half < 1e-3 ? tolerance<T>() * half : tolerance<T>();
    if (half <= resolvable_half_angle) {
      EXPECT_TRUE(mv_within<c3mv<T>>(c3ga::log(r), b, abs_tol));
    }
  }
}

// (b ^ ni)^2 = 0, so exp(b ^ ni) = 1 + b ^ ni exactly: a translator.
TYPED_TEST(ExpLog, C3gaTranslatorExpAndLog) {
  using T = TypeParam;
  auto rng = make_rng(312);
  for (int i = 0; i < trials; ++i) {
    const vec3 t = random_vec3(rng, -3, 3);
    const auto b = dual_line_of<T>({0, 0, 0}, t);
    const c3ga::basic_translator<T> expected{1, T(t[0]), T(t[1]), T(t[2])};
    const auto x = c3ga::exp(b);
    EXPECT_TRUE(mv_near<c3mv<T>>(x, expected, tolerance<T>()));
    EXPECT_TRUE(mv_near<c3mv<T>>(x * ~x, T(1), tolerance<T>()));
    EXPECT_TRUE(mv_near<c3mv<T>>(c3ga::log(expected), b, tolerance<T>()));
    EXPECT_TRUE(mv_near<c3mv<T>>(c3ga::exp(c3ga::log(expected)), expected, tolerance<T>()));
  }
}

TYPED_TEST(ExpLog, C3gaMotorExpMatchesSeries) {
  using T = TypeParam;
  auto rng = make_rng(313);
  for (int i = 0; i < trials; ++i) {
    const auto b = dual_line_of<T>(random_vec3(rng, -1.5, 1.5), random_vec3(rng, -2, 2));
    const auto m = c3ga::exp(b);
    const c3mv<double> series = exp_taylor(convert_mv<c3mv<double>>(as_mv<c3mv<T>>(b)));
    EXPECT_TRUE(
        mv_near<c3mv<double>>(convert_mv<c3mv<double>>(as_mv<c3mv<T>>(m)), series, tolerance<T>()));
    EXPECT_TRUE(mv_near<c3mv<T>>(m * ~m, T(1), tolerance<T>()));
    EXPECT_TRUE(mv_near<c3mv<T>>(c3ga::exp(as_mv<c3mv<T>>(b)), m, tolerance<T>()));
  }
}

TYPED_TEST(ExpLog, C3gaMotorLogInvertsExp) {
  using T = TypeParam;
  auto rng = make_rng(314);
  for (int i = 0; i < trials; ++i) {
    const vec3 e = uniform(rng, 0.1, 2.5) * random_unit_vec3(rng);
    const auto b = dual_line_of<T>(e, random_vec3(rng, -2, 2));
    const auto l = checked_call([&] { return c3ga::log(c3ga::exp(b)); });
    if (l) {
      EXPECT_TRUE(mv_near<c3mv<T>>(*l, b, tolerance<T>())) << "B = " << c3mv<T>(b);
    }
    // Motors built as translator * rotor.
    const auto q = random_named<c3ga::basic_rotor<T>>(rng);
    const auto r = q * (T(1) / c3ga::norm(q));
    const vec3 t = random_vec3(rng, -2, 2);
    const c3ga::basic_translator<T> tr{1, T(t[0]), T(t[1]), T(t[2])};
    const auto m = tr * r;
    const auto lm = checked_call([&] { return c3ga::log(m); });
    if (lm) {
      EXPECT_TRUE(mv_near<c3mv<T>>(c3ga::exp(*lm), m, tolerance<T>())) << "M = " << c3mv<T>(m);
    }
  }
}

TYPED_TEST(ExpLog, C3gaMotorEdgeCases) {
  using T = TypeParam;
  auto rng = make_rng(315);
  std::vector<double> halves = edge_half_angles;
  halves.push_back(0);
  for (const double half : halves) {
    for (int i = 0; i < 5; ++i) {
      const auto b = dual_line_of<T>(half * random_unit_vec3(rng), random_vec3(rng, -2, 2));
      SCOPED_TRACE(::testing::Message() << "half angle " << half << ", B = " << c3mv<T>(b));
      const auto m = c3ga::exp(b);
      EXPECT_TRUE(mv_near<c3mv<T>>(m * ~m, T(1), tolerance<T>()));
      const c3mv<double> series = exp_taylor(convert_mv<c3mv<double>>(as_mv<c3mv<T>>(b)));
      EXPECT_TRUE(mv_near<c3mv<double>>(convert_mv<c3mv<double>>(as_mv<c3mv<T>>(m)), series,
                                        tolerance<T>()));
      const auto l = checked_call([&] { return c3ga::log(m); });
      if (!l) continue;
      if (pi - half >= full_turn_margin<T>()) {
        EXPECT_TRUE(mv_near<c3mv<T>>(c3ga::exp(*l), m, tolerance<T>()));
      } else {
        for (const T x : as_mv<c3mv<T>>(*l).c) EXPECT_TRUE(std::isfinite(x));
      }
      if (pi - half >= resolvable_full_turn_distance<T>()) {
        EXPECT_TRUE(mv_near<c3mv<T>>(*l, b, tolerance<T>()));
      }
    }
  }
}

// Issue 16, defect 1: -exp(B) for a boost or null B has no logarithm in the
// plane of B, and log returned the log of +exp(B) instead (whose exp is -M).
TYPED_TEST(ExpLog, C3gaLogOfNegatedBoostOrTranslatorThrows) {
  using T = TypeParam;
  const auto& names = c3ga::blade_names;
  // -(cosh 1 + sinh 1 no^ni): no^ni squares to +1, a boost.
  const auto boost = c3mv<T>::from_terms(
      {{0, T(-std::cosh(1.0))}, {int(blade_index(names, "no^ni")), T(-std::sinh(1.0))}});
  EXPECT_THROW(c3ga::log(boost), std::domain_error);
  // -(1 + e1^ni): a negated translator, named and general.
  const c3ga::basic_translator<T> translator{-1, -1, 0, 0};
  EXPECT_THROW(c3ga::log(translator), std::domain_error);
  EXPECT_THROW(c3ga::log(as_mv<c3mv<T>>(translator)), std::domain_error);
  const c3ga::basic_motor<T> motor{-1, 0, 0, 0, -1, 0, 0, 0};
  EXPECT_THROW(c3ga::log(motor), std::domain_error);
  // The boost itself, and -1 (a rotation by 2 pi), have logarithms.
  const auto positive = c3ga::neg(boost);
  const auto l = c3ga::log(positive);
  EXPECT_TRUE(mv_near<c3mv<T>>(l, c3mv<T>::from_terms({{int(blade_index(names, "no^ni")), T(1)}}),
                               tolerance<T>()));
  const c3ga::basic_motor<T> minus_one{-1, 0, 0, 0, 0, 0, 0, 0};
  EXPECT_TRUE(mv_near<c3mv<T>>(c3ga::exp(c3ga::log(minus_one)), minus_one, tolerance<T>()));
}

// Issue 16, defect 2: a motor whose rotation half angle is tiny (1e-11) next
// to a translation: in float <b q>_2 (about 1e-23) squared underflowed, and
// log threw. exp(log M) == M is the truth.
TYPED_TEST(ExpLog, C3gaLogOfMotorWithTinyRotation) {
  using T = TypeParam;
  for (const double half : {1e-11, 1e-20, 1e-30}) {
    SCOPED_TRACE(::testing::Message() << "half angle " << half);
    const c3ga::basic_translator<T> t{1, T(-0.5), T(-1), T(-0.25)};
    const c3ga::basic_rotor<T> r{T(std::cos(half)), T(-std::sin(half)), 0, 0};
    const auto m = t * r;
    const auto l = checked_call([&] { return c3ga::log(m); });
    if (!l) continue;
    EXPECT_TRUE(mv_near<c3mv<T>>(c3ga::exp(*l), m, tolerance<T>())) << "log M = " << c3mv<T>(*l);
    // log M = -half e1^e2 - 0.5 e1^ni - e2^ni - 0.25 e3^ni, up to O(half) in the
    // translation (the commutator of the two parts).
    const c3ga::basic_dual_line<T> expected{T(-half), 0, 0, T(-0.5), T(-1), T(-0.25)};
    EXPECT_TRUE(mv_near<c3mv<T>>(*l, expected, tolerance<T>()));
    EXPECT_TRUE(scalar_near(double(l->e12()) / half, -1, tolerance<T>()));  // to its own size
  }
}

TYPED_TEST(ExpLog, C3gaZero) {
  using T = TypeParam;
  const c3ga::basic_dual_line<T> zero{0, 0, 0, 0, 0, 0};
  EXPECT_TRUE(mv_within<c3mv<T>>(c3ga::exp(zero), T(1), 0));
  const c3ga::basic_motor<T> one{1, 0, 0, 0, 0, 0, 0, 0};
  EXPECT_TRUE(mv_within<c3mv<T>>(c3ga::log(one), zero, 0));
  const c3ga::basic_euclidean_bivector<T> zero_rotation{0, 0, 0};
  EXPECT_TRUE(mv_within<c3mv<T>>(c3ga::exp(zero_rotation), T(1), 0));
}

}  // namespace exp_log_test
