// Algebraic identities of c3ga (null basis no, e1, e2, e3, ni) on random
// inputs: the metric, products, reverse, grades, duality, inverses, norms.
#include <c3ga/c3ga.hpp>
#include <stdexcept>

#include "algebra_test_support.hpp"

namespace c3ga_identities_test {

using namespace gaphys_test;

template <class T>
using mv = c3ga::basic_mv<T>;

constexpr int trials = 50;

template <class T>
class C3gaIdentities : public ::testing::Test {};
TYPED_TEST_SUITE(C3gaIdentities, scalar_types);

// The inner product of grade-1 elements given as (no, e1, e2, e3, ni)
// coordinates: e_i . e_j = delta_ij, no . ni = -1, no . no = ni . ni = 0.
double metric(const std::array<double, 5>& a, const std::array<double, 5>& b) {
  return a[1] * b[1] + a[2] * b[2] + a[3] * b[3] - a[0] * b[4] - a[4] * b[0];
}

template <class X>
std::array<double, 5> as_array5(const X& x) {
  return {double(x.c[0]), double(x.c[1]), double(x.c[2]), double(x.c[3]), double(x.c[4])};
}

TYPED_TEST(C3gaIdentities, MetricOfTheNullBasis) {
  using T = TypeParam;
  const auto no = c3ga::no<T>();
  const auto ni = c3ga::ni<T>();
  EXPECT_EQ(double(c3ga::scp(no, ni)), -1.0);
  EXPECT_EQ(double(c3ga::scp(ni, no)), -1.0);
  EXPECT_EQ(double(c3ga::scp(no, no)), 0.0);
  EXPECT_EQ(double(c3ga::scp(ni, ni)), 0.0);
  EXPECT_EQ(double(c3ga::scp(c3ga::e1<T>(), c3ga::e1<T>())), 1.0);
  EXPECT_EQ(double(c3ga::scp(c3ga::e1<T>(), c3ga::e2<T>())), 0.0);
  EXPECT_EQ(double(c3ga::scp(c3ga::e2<T>(), no)), 0.0);
  // no ni = -1 + no^ni, and ni no = -1 - no^ni.
  const mv<T> minus_one = as_mv<mv<T>>(T(-1));
  const mv<T> no_ni = as_mv<mv<T>>(no ^ ni);
  EXPECT_TRUE(mv_within<mv<T>>(no * ni, minus_one + no_ni, 0));
  EXPECT_TRUE(mv_within<mv<T>>(ni * no, minus_one - no_ni, 0));
}

TYPED_TEST(C3gaIdentities, VectorProductSplitsIntoInnerAndOuter) {
  using T = TypeParam;
  auto rng = make_rng(201);
  for (int i = 0; i < trials; ++i) {
    const auto a = random_named<c3ga::basic_dual_sphere<T>>(rng);
    const auto b = random_named<c3ga::basic_dual_sphere<T>>(rng);
    const mv<T> sum = as_mv<mv<T>>(c3ga::lc(a, b)) + as_mv<mv<T>>(c3ga::op(a, b));
    EXPECT_TRUE(mv_near<mv<T>>(a * b, sum, tolerance<T>()));
    EXPECT_TRUE(
        scalar_near(double(c3ga::scp(a, b)), metric(as_array5(a), as_array5(b)), tolerance<T>()));
    EXPECT_TRUE(scalar_near(double(as_mv<mv<T>>(a * b)[0]), metric(as_array5(a), as_array5(b)),
                            tolerance<T>()));
    EXPECT_TRUE(
        scalar_near(double(c3ga::norm2(a)), metric(as_array5(a), as_array5(a)), tolerance<T>()));
    EXPECT_TRUE(mv_near<mv<T>>(a ^ b, -(b ^ a), tolerance<T>()));
    EXPECT_TRUE(mv_within<mv<T>>(a ^ a, mv<T>(), tolerance<T>()));
  }
}

TYPED_TEST(C3gaIdentities, GeometricProductIsAssociative) {
  using T = TypeParam;
  auto rng = make_rng(202);
  for (int i = 0; i < trials; ++i) {
    const auto a = random_mv<mv<T>>(rng), b = random_mv<mv<T>>(rng), c = random_mv<mv<T>>(rng);
    EXPECT_TRUE(mv_near<mv<T>>((a * b) * c, a * (b * c), tolerance<T>()));
    const auto m = random_named<c3ga::basic_motor<T>>(rng);
    const auto n = random_named<c3ga::basic_motor<T>>(rng);
    const auto p = random_named<c3ga::basic_normalized_point<T>>(rng);
    EXPECT_TRUE(mv_near<mv<T>>((m * n) * p, m * (n * p), tolerance<T>()));
  }
}

TYPED_TEST(C3gaIdentities, OuterProductIsAssociative) {
  using T = TypeParam;
  auto rng = make_rng(203);
  for (int i = 0; i < trials; ++i) {
    const auto a = random_mv<mv<T>>(rng), b = random_mv<mv<T>>(rng), c = random_mv<mv<T>>(rng);
    EXPECT_TRUE(mv_near<mv<T>>((a ^ b) ^ c, a ^ (b ^ c), tolerance<T>()));
  }
}

TYPED_TEST(C3gaIdentities, ReverseOfProductIsProductOfReverses) {
  using T = TypeParam;
  auto rng = make_rng(204);
  for (int i = 0; i < trials; ++i) {
    const auto a = random_mv<mv<T>>(rng), b = random_mv<mv<T>>(rng);
    EXPECT_TRUE(mv_near<mv<T>>(~(a * b), ~b * ~a, tolerance<T>()));
    const auto m = random_named<c3ga::basic_motor<T>>(rng);
    const auto c = random_named<c3ga::basic_circle<T>>(rng);
    EXPECT_TRUE(
        mv_near<mv<T>>(c3ga::reverse(m * c), c3ga::reverse(c) * c3ga::reverse(m), tolerance<T>()));
  }
}

TYPED_TEST(C3gaIdentities, InvolutionsFlipSignsByGrade) {
  using T = TypeParam;
  auto rng = make_rng(205);
  const auto x = random_mv<mv<T>>(rng);
  std::array<T, 32> rev{}, inv{}, conj{};
  for (int i = 0; i < 32; ++i) {
    const int k = int(c3ga::blade_grades[i]);
    const T r = (k * (k - 1) / 2) % 2 ? T(-1) : T(1);
    const T g = k % 2 ? T(-1) : T(1);
    rev[i] = r * x[i];
    inv[i] = g * x[i];
    conj[i] = r * g * x[i];
  }
  EXPECT_TRUE(mv_within<mv<T>>(c3ga::reverse(x), mv<T>::from_array(rev), 0));
  EXPECT_TRUE(mv_within<mv<T>>(c3ga::involute(x), mv<T>::from_array(inv), 0));
  EXPECT_TRUE(mv_within<mv<T>>(c3ga::conjugate(x), mv<T>::from_array(conj), 0));
}

TYPED_TEST(C3gaIdentities, GradeSelectionKeepsOneGradeAndSumsBack) {
  using T = TypeParam;
  auto rng = make_rng(206);
  for (int i = 0; i < trials; ++i) {
    const auto x = random_mv<mv<T>>(rng);
    mv<T> sum;
    for (int k = 0; k <= 5; ++k) {
      const mv<T> part = c3ga::grade(x, k);
      EXPECT_TRUE(bits_consistent(part));
      for (int j = 0; j < 32; ++j)
        EXPECT_EQ(part[j], int(c3ga::blade_grades[j]) == k ? x[j] : T(0));
      sum = sum + part;
    }
    EXPECT_TRUE(mv_within<mv<T>>(sum, x, 0));
  }
}

// I5 = no^e1^e2^e3^ni squares to -1 in Cl(4,1), so dual(x) = x I5^-1 = -x I5.
TYPED_TEST(C3gaIdentities, DualRoundTrips) {
  using T = TypeParam;
  auto rng = make_rng(207);
  const mv<T> i5 = as_mv<mv<T>>(c3ga::I5<T>());
  EXPECT_TRUE(mv_within<mv<T>>(i5 * i5, T(-1), 0));
  for (int i = 0; i < trials; ++i) {
    const auto x = random_mv<mv<T>>(rng);
    EXPECT_TRUE(mv_near<mv<T>>(c3ga::dual(x), x * -i5, tolerance<T>()));
    EXPECT_TRUE(mv_near<mv<T>>(c3ga::undual(c3ga::dual(x)), x, tolerance<T>()));
    EXPECT_TRUE(mv_near<mv<T>>(c3ga::dual(c3ga::undual(x)), x, tolerance<T>()));
    const auto s = random_named<c3ga::basic_dual_sphere<T>>(rng);
    EXPECT_TRUE(mv_near<mv<T>>(c3ga::undual(c3ga::dual(s)), s, tolerance<T>()));
    const auto c = random_named<c3ga::basic_circle<T>>(rng);
    EXPECT_TRUE(mv_near<mv<T>>(c3ga::undual(c3ga::dual(c)), c, tolerance<T>()));
    const auto sp = random_named<c3ga::basic_sphere<T>>(rng);
    EXPECT_TRUE(mv_near<mv<T>>(c3ga::dual(c3ga::undual(sp)), sp, tolerance<T>()));
  }
}

TYPED_TEST(C3gaIdentities, VersorInverses) {
  using T = TypeParam;
  auto rng = make_rng(208);
  for (int i = 0; i < trials; ++i) {
    // A motor built as a product of a rotor and a translator is a versor.
    const auto r = random_named<c3ga::basic_rotor<T>>(rng, T(0.1), T(1));
    const auto t = c3ga::basic_translator<T>{T(1), uniform(rng, T(-2), T(2)),
                                             uniform(rng, T(-2), T(2)), uniform(rng, T(-2), T(2))};
    const auto m = t * r;
    EXPECT_TRUE(mv_near<mv<T>>(m * c3ga::inverse(m), T(1), tolerance<T>()));
    EXPECT_TRUE(mv_near<mv<T>>(c3ga::inverse(m) * m, T(1), tolerance<T>()));
    // A non-null vector (dual sphere of nonzero radius) is invertible.
    const auto s = random_named<c3ga::basic_dual_sphere<T>>(rng);
    if (std::abs(double(c3ga::norm2(s))) < 0.05) continue;
    const double scale = 1 / std::abs(double(c3ga::norm2(s)));
    EXPECT_TRUE(mv_near<mv<T>>(s * c3ga::inverse(s), T(1), tolerance<T>() * scale));
  }
}

TYPED_TEST(C3gaIdentities, GeneralInverseOfRandomMultivector) {
  using T = TypeParam;
  auto rng = make_rng(209);
  int checked = 0;
  for (int i = 0; i < trials; ++i) {
    const auto x = random_mv<mv<T>>(rng);
    const mv<T> y = c3ga::general_inverse(x);
    const double scale = double(max_abs(x.to_array())) * double(max_abs(y.to_array())) * 32;
    if (scale > 1e3) continue;
    ++checked;
    EXPECT_TRUE(mv_within<mv<T>>(x * y, T(1), tolerance<T>() * scale)) << "x = " << x;
    EXPECT_TRUE(mv_within<mv<T>>(y * x, T(1), tolerance<T>() * scale)) << "x = " << x;
  }
  EXPECT_GT(checked, trials / 2);
}

// Null vectors have no inverse: ni ni = 0.
TYPED_TEST(C3gaIdentities, GeneralInverseOfNullVectorThrows) {
  using T = TypeParam;
  EXPECT_THROW(c3ga::general_inverse(as_mv<mv<T>>(c3ga::ni<T>())), std::domain_error);
  EXPECT_THROW(c3ga::general_inverse(as_mv<mv<T>>(c3ga::no<T>())), std::domain_error);
}

// Issue 16, defect 4: the versor inverse ~x / <x ~x>_0 of a null x divided by
// zero and returned NaN, also in coefficients whose bit was clear.
TYPED_TEST(C3gaIdentities, VersorInverseOfNullVectorThrows) {
  using T = TypeParam;
  EXPECT_THROW(c3ga::inverse(c3ga::ni<T>()), std::domain_error);  // dual_plane kernel
  EXPECT_THROW(c3ga::inverse(c3ga::no<T>()), std::domain_error);  // normalized_point kernel
  EXPECT_THROW(c3ga::inverse(as_mv<mv<T>>(c3ga::ni<T>())), std::domain_error);
  const c3ga::basic_normalized_point<T> p{1, 2, 3, 7};  // x^2 / 2 = 7: null
  EXPECT_THROW(c3ga::inverse(p), std::domain_error);
  EXPECT_THROW(c3ga::inverse(as_mv<mv<T>>(p)), std::domain_error);
}

TYPED_TEST(C3gaIdentities, NormOfUnitIsOne) {
  using T = TypeParam;
  auto rng = make_rng(210);
  for (int i = 0; i < trials; ++i) {
    const auto s = random_named<c3ga::basic_dual_sphere<T>>(rng);
    if (std::abs(double(c3ga::norm2(s))) < 0.05) continue;
    EXPECT_TRUE(scalar_near(double(c3ga::norm(s)),
                            std::sqrt(std::abs(metric(as_array5(s), as_array5(s)))),
                            tolerance<T>()));
    EXPECT_TRUE(scalar_near(std::abs(double(c3ga::norm2(c3ga::unit(s)))), 1, tolerance<T>()));
  }
}

}  // namespace c3ga_identities_test
