// Algebraic identities of e3ga on random inputs: products, reverse and the
// other involutions, grade selection, duality, inverses and norms.
#include <e3ga/e3ga.hpp>
#include <stdexcept>

#include "algebra_test_support.hpp"

namespace e3ga_identities_test {

using namespace gaphys_test;

template <class T>
using mv = e3ga::basic_mv<T>;

constexpr int trials = 100;

template <class T>
class E3gaIdentities : public ::testing::Test {};
TYPED_TEST_SUITE(E3gaIdentities, scalar_types);

// Coordinates of a named type as a plain vec3 (for vector-like types).
template <class X>
vec3 as_vec3(const X& x) {
  return {double(x.c[0]), double(x.c[1]), double(x.c[2])};
}

TYPED_TEST(E3gaIdentities, GeometricProductIsAssociative) {
  using T = TypeParam;
  auto rng = make_rng(101);
  for (int i = 0; i < trials; ++i) {
    const auto a = random_mv<mv<T>>(rng), b = random_mv<mv<T>>(rng), c = random_mv<mv<T>>(rng);
    EXPECT_TRUE(mv_near<mv<T>>((a * b) * c, a * (b * c), tolerance<T>()));
  }
}

TYPED_TEST(E3gaIdentities, GeometricProductOfNamedTypesIsAssociative) {
  using T = TypeParam;
  auto rng = make_rng(102);
  for (int i = 0; i < trials; ++i) {
    const auto r = random_named<e3ga::basic_rotor<T>>(rng);
    const auto s = random_named<e3ga::basic_rotor<T>>(rng);
    const auto v = random_named<e3ga::basic_vector<T>>(rng);
    const auto b = random_named<e3ga::basic_bivector<T>>(rng);
    EXPECT_TRUE(mv_near<mv<T>>((r * s) * v, r * (s * v), tolerance<T>()));
    EXPECT_TRUE(mv_near<mv<T>>((v * b) * r, v * (b * r), tolerance<T>()));
    EXPECT_TRUE(mv_near<mv<T>>((b * v) * v, b * (v * v), tolerance<T>()));
  }
}

// For vectors a b = a . b + a ^ b, each part checked against plain 3-D maths.
TYPED_TEST(E3gaIdentities, VectorProductSplitsIntoInnerAndOuter) {
  using T = TypeParam;
  auto rng = make_rng(103);
  for (int i = 0; i < trials; ++i) {
    const auto a = random_named<e3ga::basic_vector<T>>(rng);
    const auto b = random_named<e3ga::basic_vector<T>>(rng);
    const mv<T> inner = as_mv<mv<T>>(e3ga::lc(a, b));
    const mv<T> outer = as_mv<mv<T>>(e3ga::op(a, b));
    EXPECT_TRUE(mv_near<mv<T>>(a * b, inner + outer, tolerance<T>()));
    EXPECT_TRUE(mv_near<mv<T>>(a ^ b, outer, tolerance<T>()));

    const vec3 x = as_vec3(a), y = as_vec3(b);
    std::array<T, 8> expected{};
    expected[0] = T(dot(x, y));
    expected[4] = T(x[0] * y[1] - x[1] * y[0]);  // e1^e2
    expected[5] = T(x[0] * y[2] - x[2] * y[0]);  // e1^e3
    expected[6] = T(x[1] * y[2] - x[2] * y[1]);  // e2^e3
    EXPECT_TRUE(mv_near<mv<T>>(a * b, mv<T>::from_array(expected), tolerance<T>()));
    EXPECT_TRUE(scalar_near(double(e3ga::scp(a, b)), dot(x, y), tolerance<T>()));
  }
}

TYPED_TEST(E3gaIdentities, ContractionsOfVectorAndBivector) {
  using T = TypeParam;
  auto rng = make_rng(104);
  for (int i = 0; i < trials; ++i) {
    const auto a = random_named<e3ga::basic_vector<T>>(rng);
    const auto b = random_named<e3ga::basic_vector<T>>(rng);
    const auto c = random_named<e3ga::basic_vector<T>>(rng);
    const mv<T> bc = as_mv<mv<T>>(b ^ c);
    // a _| (b ^ c) = (a . b) c - (a . c) b, and B |_ a = -(a _| B) for a bivector B.
    const mv<T> expected = as_mv<mv<T>>(e3ga::scp(a, b) * c) - as_mv<mv<T>>(e3ga::scp(a, c) * b);
    EXPECT_TRUE(mv_near<mv<T>>(e3ga::lc(a, e3ga::basic_bivector<T>(bc)), expected, tolerance<T>()));
    EXPECT_TRUE(
        mv_near<mv<T>>(e3ga::rc(e3ga::basic_bivector<T>(bc), a), -expected, tolerance<T>()));
    // The vector parts of a B and B a are the contractions, the trivector parts the outer products.
    const e3ga::basic_bivector<T> bv(bc);
    EXPECT_TRUE(mv_near<mv<T>>(a * bv, as_mv<mv<T>>(e3ga::lc(a, bv)) + as_mv<mv<T>>(a ^ bv),
                               tolerance<T>()));
    EXPECT_TRUE(mv_near<mv<T>>(bv * a, as_mv<mv<T>>(e3ga::rc(bv, a)) + as_mv<mv<T>>(bv ^ a),
                               tolerance<T>()));
  }
}

TYPED_TEST(E3gaIdentities, ReverseOfProductIsProductOfReverses) {
  using T = TypeParam;
  auto rng = make_rng(105);
  for (int i = 0; i < trials; ++i) {
    const auto a = random_mv<mv<T>>(rng), b = random_mv<mv<T>>(rng);
    EXPECT_TRUE(mv_near<mv<T>>(~(a * b), ~b * ~a, tolerance<T>()));
    EXPECT_TRUE(
        mv_near<mv<T>>(e3ga::reverse(a * b), e3ga::reverse(b) * e3ga::reverse(a), tolerance<T>()));
    const auto r = random_named<e3ga::basic_rotor<T>>(rng);
    const auto v = random_named<e3ga::basic_vector<T>>(rng);
    EXPECT_TRUE(mv_near<mv<T>>(~(r * v), ~v * ~r, tolerance<T>()));
  }
}

// Reverse, grade involution and Clifford conjugate flip grade k by
// (-1)^(k(k-1)/2), (-1)^k and their product.
TYPED_TEST(E3gaIdentities, InvolutionsFlipSignsByGrade) {
  using T = TypeParam;
  auto rng = make_rng(106);
  const auto x = random_mv<mv<T>>(rng);
  std::array<T, 8> rev{}, inv{}, conj{};
  for (int i = 0; i < 8; ++i) {
    const int k = int(e3ga::blade_grades[i]);
    const T r = (k * (k - 1) / 2) % 2 ? T(-1) : T(1);
    const T g = k % 2 ? T(-1) : T(1);
    rev[i] = r * x[i];
    inv[i] = g * x[i];
    conj[i] = r * g * x[i];
  }
  EXPECT_TRUE(mv_within<mv<T>>(e3ga::reverse(x), mv<T>::from_array(rev), 0));
  EXPECT_TRUE(mv_within<mv<T>>(e3ga::involute(x), mv<T>::from_array(inv), 0));
  EXPECT_TRUE(mv_within<mv<T>>(e3ga::conjugate(x), mv<T>::from_array(conj), 0));
  EXPECT_TRUE(mv_within<mv<T>>(-x, T(-1) * x, 0));
}

TYPED_TEST(E3gaIdentities, GradeSelectionKeepsOneGradeAndSumsBack) {
  using T = TypeParam;
  auto rng = make_rng(107);
  for (int i = 0; i < trials; ++i) {
    const auto x = random_mv<mv<T>>(rng);
    mv<T> sum;
    for (int k = 0; k <= 3; ++k) {
      const mv<T> part = e3ga::grade(x, k);
      EXPECT_TRUE(bits_consistent(part));
      for (int j = 0; j < 8; ++j) EXPECT_EQ(part[j], int(e3ga::blade_grades[j]) == k ? x[j] : T(0));
      sum = sum + part;
    }
    EXPECT_TRUE(mv_within<mv<T>>(sum, x, 0));
  }
  const auto v = random_named<e3ga::basic_vector<T>>(rng);
  EXPECT_TRUE(mv_within<mv<T>>(e3ga::grade(v, 1), v, 0));
  EXPECT_TRUE(mv_within<mv<T>>(e3ga::grade(v, 2), mv<T>(), 0));
}

// dual(x) = x I3^-1 with I3^2 = -1, so I3^-1 = -I3.
TYPED_TEST(E3gaIdentities, DualIsProductWithInversePseudoscalar) {
  using T = TypeParam;
  auto rng = make_rng(108);
  const mv<T> i3 = as_mv<mv<T>>(e3ga::I3<T>());
  EXPECT_TRUE(mv_within<mv<T>>(i3 * i3, T(-1), 0));
  for (int i = 0; i < trials; ++i) {
    const auto x = random_mv<mv<T>>(rng);
    EXPECT_TRUE(mv_near<mv<T>>(e3ga::dual(x), x * -i3, tolerance<T>()));
    EXPECT_TRUE(mv_near<mv<T>>(e3ga::undual(e3ga::dual(x)), x, tolerance<T>()));
    EXPECT_TRUE(mv_near<mv<T>>(e3ga::dual(e3ga::undual(x)), x, tolerance<T>()));
    // The dual of a vector is the bivector -(v1 e23 - v2 e13 + v3 e12).
    const auto v = random_named<e3ga::basic_vector<T>>(rng);
    const vec3 b = bivector_of_axis(as_vec3(v));
    const std::array<T, 8> expected{0, 0, 0, 0, T(-b[0]), T(-b[1]), T(-b[2]), 0};
    EXPECT_TRUE(mv_near<mv<T>>(e3ga::dual(v), mv<T>::from_array(expected), tolerance<T>()));
    EXPECT_TRUE(mv_near<mv<T>>(e3ga::undual(e3ga::dual(v)), v, tolerance<T>()));
    const auto bv = random_named<e3ga::basic_bivector<T>>(rng);
    EXPECT_TRUE(mv_near<mv<T>>(e3ga::undual(e3ga::dual(bv)), bv, tolerance<T>()));
  }
}

TYPED_TEST(E3gaIdentities, VersorInverses) {
  using T = TypeParam;
  auto rng = make_rng(109);
  for (int i = 0; i < trials; ++i) {
    const auto v = random_named<e3ga::basic_vector<T>>(rng, T(0.1), T(1));
    const auto vi = e3ga::inverse(v);
    EXPECT_TRUE(mv_near<mv<T>>(v * vi, T(1), tolerance<T>()));
    EXPECT_TRUE(mv_near<mv<T>>(vi * v, T(1), tolerance<T>()));
    // v^-1 = v / |v|^2.
    const vec3 x = as_vec3(v);
    const double n2 = dot(x, x);
    EXPECT_TRUE(mv_near<mv<T>>(vi, e3ga::basic_vector<T>{T(x[0] / n2), T(x[1] / n2), T(x[2] / n2)},
                               tolerance<T>()));
    // Any element of the even subalgebra is a scaled rotor.
    const auto r = random_named<e3ga::basic_rotor<T>>(rng, T(0.1), T(1));
    EXPECT_TRUE(mv_near<mv<T>>(r * e3ga::inverse(r), T(1), tolerance<T>()));
    EXPECT_TRUE(mv_near<mv<T>>(e3ga::inverse(r) * r, T(1), tolerance<T>()));
  }
}

TYPED_TEST(E3gaIdentities, GeneralInverseOfRandomMultivector) {
  using T = TypeParam;
  auto rng = make_rng(110);
  int checked = 0;
  for (int i = 0; i < trials; ++i) {
    const auto x = random_mv<mv<T>>(rng);
    const mv<T> y = e3ga::general_inverse(x);
    // x y = 1 is only as accurate as the conditioning of x allows.
    const double scale = double(max_abs(x.to_array())) * double(max_abs(y.to_array())) * 8;
    if (scale > 1e3) continue;
    ++checked;
    EXPECT_TRUE(mv_within<mv<T>>(x * y, T(1), tolerance<T>() * scale)) << "x = " << x;
    EXPECT_TRUE(mv_within<mv<T>>(y * x, T(1), tolerance<T>() * scale)) << "x = " << x;
  }
  EXPECT_GT(checked, trials / 2);
}

// (1 + e1)(1 - e1) = 0, so 1 + e1 is a zero divisor.
TYPED_TEST(E3gaIdentities, GeneralInverseOfSingularThrows) {
  using T = TypeParam;
  const mv<T> x = mv<T>::from_array({1, 1, 0, 0, 0, 0, 0, 0});
  EXPECT_THROW(e3ga::general_inverse(x), std::domain_error);
}

TYPED_TEST(E3gaIdentities, NormsAndUnit) {
  using T = TypeParam;
  auto rng = make_rng(111);
  for (int i = 0; i < trials; ++i) {
    // Euclidean metric: <x ~x>_0 is the sum of squared coefficients.
    const auto x = random_mv<mv<T>>(rng);
    double sum2 = 0;
    for (int j = 0; j < 8; ++j) sum2 += double(x[j]) * double(x[j]);
    EXPECT_TRUE(scalar_near(double(e3ga::norm2(x)), sum2, tolerance<T>()));
    EXPECT_TRUE(scalar_near(double(e3ga::norm(x)), std::sqrt(sum2), tolerance<T>()));
    EXPECT_TRUE(scalar_near(double(e3ga::norm(e3ga::unit(x))), 1, tolerance<T>()));
    EXPECT_TRUE(mv_near<mv<T>>(e3ga::unit(x) * T(std::sqrt(sum2)), x, tolerance<T>()));

    const auto v = random_named<e3ga::basic_vector<T>>(rng);
    EXPECT_TRUE(scalar_near(double(e3ga::norm(v)), length(as_vec3(v)), tolerance<T>()));
    const auto u = e3ga::unit(v);
    EXPECT_TRUE(scalar_near(double(e3ga::norm2(u)), 1, tolerance<T>()));
    EXPECT_TRUE(mv_near<mv<T>>(u * e3ga::norm(v), v, tolerance<T>()));
    const auto b = random_named<e3ga::basic_bivector<T>>(rng);
    EXPECT_TRUE(scalar_near(double(e3ga::norm2(b)), dot(as_vec3(b), as_vec3(b)), tolerance<T>()));
  }
}

TYPED_TEST(E3gaIdentities, ConstantsAreBasisBlades) {
  using T = TypeParam;
  EXPECT_TRUE(mv_within<mv<T>>(e3ga::e1<T>(), mv<T>::from_array({0, 1, 0, 0, 0, 0, 0, 0}), 0));
  EXPECT_TRUE(mv_within<mv<T>>(e3ga::e2<T>(), mv<T>::from_array({0, 0, 1, 0, 0, 0, 0, 0}), 0));
  EXPECT_TRUE(mv_within<mv<T>>(e3ga::e3<T>(), mv<T>::from_array({0, 0, 0, 1, 0, 0, 0, 0}), 0));
  EXPECT_TRUE(mv_within<mv<T>>(e3ga::I3<T>(), (e3ga::e1<T>() ^ e3ga::e2<T>()) ^ e3ga::e3<T>(), 0));
  EXPECT_TRUE(mv_within<mv<T>>(e3ga::e1<T>() * e3ga::e2<T>(),
                               mv<T>::from_array({0, 0, 0, 0, 1, 0, 0, 0}), 0));
  EXPECT_TRUE(mv_within<mv<T>>(e3ga::e2<T>() * e3ga::e1<T>(),
                               mv<T>::from_array({0, 0, 0, 0, -1, 0, 0, 0}), 0));
}

TYPED_TEST(E3gaIdentities, ProductResultsKeepTheBitInvariant) {
  using T = TypeParam;
  auto rng = make_rng(112);
  for (int i = 0; i < trials; ++i) {
    const auto a = random_sparse_mv<mv<T>>(rng), b = random_sparse_mv<mv<T>>(rng);
    EXPECT_TRUE(bits_consistent(a * b));
    EXPECT_TRUE(bits_consistent(a ^ b));
    EXPECT_TRUE(bits_consistent(e3ga::lc(a, b)));
    EXPECT_TRUE(bits_consistent(a + b));
    EXPECT_TRUE(bits_consistent(e3ga::dual(a)));
    // Sparse inputs give the same product as their dense (all bits set) copies.
    mv<T> dense_a = a;
    dense_a.bits = 0xff;
    EXPECT_TRUE(mv_near<mv<T>>(a * b, dense_a * b, tolerance<T>()));
  }
}

}  // namespace e3ga_identities_test
