// The quadric conformal algebra QCGA, Cl(9,6), of tests/algebra/specs/qcga.ga
// (Breuils, Nozick, Sugimoto, Hitzer 2018): basis e1 e2 e3, eo1..eo6,
// ei1..ei6 with eoK . eiK = -1; 15 basis vectors, 32,768 blades, so its
// general mv is the sparse one. A point (x, y, z) is
//   P = x e1 + y e2 + z e3 + eo1 + eo2 + eo3
//       + x^2/2 ei1 + y^2/2 ei2 + z^2/2 ei3 + xy ei4 + xz ei5 + yz ei6,
// and with the metric, for a vector Q with coefficients q_e1.., q_o1.., q_i1..,
//   P . Q = q_e1 x + q_e2 y + q_e3 z - (q_i1 + q_i2 + q_i3)
//           - q_o1 x^2/2 - q_o2 y^2/2 - q_o3 z^2/2 - q_o4 xy - q_o5 xz - q_o6 yz
// (a point has no eo4..eo6 part, so q_i4..q_i6 do not count). So the quadric
// a x^2 + b y^2 + c z^2 + d xy + e xz + f yz + g x + h y + i z + j = 0 is
//   q_o = (-2a, -2b, -2c, -d, -e, -f), q_e = (g, h, i), q_i1 + q_i2 + q_i3 = -j,
// and two points have P . P' = -|p - p'|^2 / 2. The 15-D mv path is sparse
// and slow next to the kernels: these tests stay small.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <qcga/qcga.hpp>
#include <string>
#include <type_traits>
#include <vector>

#include "algebra_test_support.hpp"
#include "sparse_test_support.hpp"

namespace qcga_test {

using namespace gaphys_test;
namespace sparse = gaphys_test::sparse;
using qcga::mv;

constexpr double tol = 1e-10;

// Blade bitmaps: bit i is the i-th basis vector of e1 e2 e3 eo1..eo6 ei1..ei6.
constexpr std::uint32_t bit(int i) { return std::uint32_t(1) << i; }
constexpr int e_index = 0, eo_index = 3, ei_index = 9;  // e1, eo1, ei1
constexpr std::uint32_t pseudoscalar_bit = 0x7fffu;

// ---- comparisons on the sparse mv ------------------------------------------------

template <class X>
mv widen(const X& x) {
  return sparse::widen<mv>(x);
}
double largest(const mv& x) { return sparse::largest(x); }
template <class X, class Y>
::testing::AssertionResult near(const X& x, const Y& y, double rel_tol = tol) {
  return sparse::near<mv>(x, y, rel_tol);
}

// ---- 3-D geometry in closed form --------------------------------------------------

qcga::point point_at(const vec3& p) {
  const double x = p[0], y = p[1], z = p[2];
  return {x, y, z, x * x / 2, y * y / 2, z * z / 2, x * y, x * z, y * z};
}

// a x^2 + b y^2 + c z^2 + d xy + e xz + f yz + g x + h y + i z + j
using quadric_coefficients = std::array<double, 10>;

double polynomial(const quadric_coefficients& q, const vec3& p) {
  const double x = p[0], y = p[1], z = p[2];
  return q[0] * x * x + q[1] * y * y + q[2] * z * z + q[3] * x * y + q[4] * x * z + q[5] * y * z +
         q[6] * x + q[7] * y + q[8] * z + q[9];
}

// The dual quadric with -j split as `split` among q_i1..q_i3, and q_i4..q_i6
// = `free` (both invisible to points).
qcga::quadric quadric_of(const quadric_coefficients& q, std::array<double, 3> split = {1, 0, 0},
                         std::array<double, 3> free = {0, 0, 0}) {
  const double j = q[9];
  return {q[6],          q[7],          q[8],                                // e1 e2 e3
          -2 * q[0],     -2 * q[1],     -2 * q[2],     -q[3], -q[4], -q[5],  // eo1 .. eo6
          -j * split[0], -j * split[1], -j * split[2],                       // ei1 ei2 ei3
          free[0],       free[1],       free[2]};                            // ei4 ei5 ei6
}

// The ellipsoid of semi-axes (2, 1, 0.5) centred at (0.5, -1, 2):
// (x - 0.5)^2/4 + (y + 1)^2 + (z - 2)^2/0.25 - 1 = 0, and its points.
const vec3 ellipsoid_centre{0.5, -1, 2}, ellipsoid_axes{2, 1, 0.5};
const quadric_coefficients ellipsoid = {
    1 / 4.0, 1, 4, 0, 0, 0, -2 * 0.5 / 4.0, 2 * 1.0, -2 * 2 * 4.0, 0.25 / 4.0 + 1 + 4 * 4 - 1};
vec3 on_ellipsoid(double theta, double phi) {
  return {ellipsoid_centre[0] + ellipsoid_axes[0] * std::sin(theta) * std::cos(phi),
          ellipsoid_centre[1] + ellipsoid_axes[1] * std::sin(theta) * std::sin(phi),
          ellipsoid_centre[2] + ellipsoid_axes[2] * std::cos(theta)};
}

// ---- the metric and the basis ------------------------------------------------------

// e_i e_j = e_i . e_j + e_i ^ e_j with the spec's inner products: e1..e3
// orthonormal, eoK . eiK = -1, everything else 0.
TEST(Qcga, BasisVectorProductsFollowTheSpecsMetric) {
  const auto inner = [](int i, int j) {
    if (i == j) return i < eo_index ? 1.0 : 0.0;
    const int lo = std::min(i, j), hi = std::max(i, j);
    return (lo >= eo_index && lo < ei_index && hi == lo + 6) ? -1.0 : 0.0;
  };
  for (int i = 0; i < 15; ++i)
    for (int j = 0; j < 15; ++j) {
      const mv ei = mv::from_blades({{bit(i), 1.0}}), ej = mv::from_blades({{bit(j), 1.0}});
      mv expected = mv::from_blades({{0u, inner(i, j)}});
      if (i != j)
        expected = qcga::add(expected, mv::from_blades({{bit(i) | bit(j), i < j ? 1.0 : -1.0}}));
      EXPECT_TRUE(near(qcga::gp(ei, ej), expected))
          << qcga::basis_names[i] << " " << qcga::basis_names[j];
    }
  // Cl(9,6): I^2 = (-1)^(15*14/2) (-1)^6 = -1.
  const mv i15 = mv::from_blades({{pseudoscalar_bit, 1.0}});
  EXPECT_TRUE(near(qcga::gp(i15, i15), -1.0));
}

// Canonical order (by grade, then lexicographic in the basis order) for the
// scalar, the vectors and the bivectors, and the last index.
TEST(Qcga, CanonicalIndicesNamesAndBitmapsAgree) {
  std::vector<std::pair<std::string, std::uint32_t>> expected = {{"1", 0u}};
  for (int i = 0; i < 15; ++i) expected.push_back({qcga::basis_names[i], bit(i)});
  for (int i = 0; i < 15; ++i)
    for (int j = i + 1; j < 15; ++j)
      expected.push_back(
          {std::string(qcga::basis_names[i]) + "^" + qcga::basis_names[j], bit(i) | bit(j)});
  for (int index = 0; index < int(expected.size()); ++index) {
    const auto& [name, blade] = expected[index];
    EXPECT_EQ(mv::blade_name(index), name);
    const mv x = mv::from_terms({{index, 2.5}});
    EXPECT_EQ(x.coefficient(blade), 2.5) << name;
    EXPECT_EQ(x[index], 2.5) << name;
  }
  EXPECT_EQ(mv::blade_name(15), "ei6");
  EXPECT_EQ(mv::blade_name(16), "e1^e2");
  EXPECT_EQ(qcga::blade_count, 32768);
  EXPECT_EQ(mv::basis_blade(qcga::blade_count - 1).coefficient(pseudoscalar_bit), 1.0);
  EXPECT_EQ(mv::blade_name(qcga::blade_count - 1),
            "e1^e2^e3^eo1^eo2^eo3^eo4^eo5^eo6^ei1^ei2^ei3^ei4^ei5^ei6");
}

// ---- points ---------------------------------------------------------------------------

TEST(Qcga, ScalarProductOfPointsIsMinusHalfTheSquaredDistance) {
  auto rng = make_rng(81);
  for (int trial = 0; trial < 10; ++trial) {
    const vec3 p = random_vec3(rng, -3, 3), q = random_vec3(rng, -3, 3);
    const double expected = -dot(p - q, p - q) / 2;
    EXPECT_TRUE(scalar_near(qcga::scp(point_at(p), point_at(q)), expected, tol));
    EXPECT_TRUE(scalar_near(qcga::scp(widen(point_at(p)), widen(point_at(q))), expected, tol));
    // A point is null: norm2(P) = P . P = 0.
    EXPECT_TRUE(scalar_near(qcga::norm2(point_at(p)), 0, tol));
    EXPECT_TRUE(scalar_near(qcga::norm2(widen(point_at(p))), 0, tol));
  }
}

// For vectors, P P' = P . P' + P ^ P', and the outer product is antisymmetric.
TEST(Qcga, OuterProductOfPointsIsAntisymmetric) {
  auto rng = make_rng(82);
  for (int trial = 0; trial < 3; ++trial) {
    const qcga::point p = point_at(random_vec3(rng, -2, 2)), q = point_at(random_vec3(rng, -2, 2));
    const mv pq = qcga::op(p, q);
    EXPECT_EQ(pq.bits, mv::grade_mask(2));
    EXPECT_TRUE(near(pq, qcga::op(widen(p), widen(q))));
    EXPECT_TRUE(near(pq, qcga::neg(qcga::op(q, p))));
    EXPECT_TRUE(near(qcga::op(p, p), mv()));
    EXPECT_TRUE(near(qcga::gp(widen(p), widen(q)), qcga::add(widen(qcga::scp(p, q)), pq)));
    EXPECT_TRUE(near(qcga::gp(p, q), qcga::gp(widen(p), widen(q))));
  }
}

// ---- quadrics ---------------------------------------------------------------------------

TEST(Qcga, ScalarProductWithAQuadricIsItsPolynomial) {
  auto rng = make_rng(83);
  std::vector<quadric_coefficients> quadrics = {
      ellipsoid,
      {1, 1, -1, 0, 0, 0, 0, 0, 0, -1},   // hyperboloid of one sheet x^2 + y^2 - z^2 = 1
      {0, 0, 0, 0, 0, 0, 1, -2, 0.5, 3},  // the plane x - 2y + z/2 + 3 = 0
      {0, 0, 0, 1, -1, 2, 0, 0, 0, 0}};   // xy - xz + 2yz = 0: the cross terms
  quadric_coefficients random;
  for (double& v : random) v = uniform(rng, -2.0, 2.0);
  quadrics.push_back(random);
  for (const auto& q : quadrics) {
    const qcga::quadric dual = quadric_of(q);
    // -j split another way and arbitrary q_i4..q_i6: the same polynomial.
    const qcga::quadric other = quadric_of(q, {0.2, 0.5, 0.3}, {1.5, -2, 0.7});
    for (int k = 0; k < 3; ++k) {
      const vec3 p = random_vec3(rng, -3, 3);
      const double value = polynomial(q, p);
      EXPECT_TRUE(scalar_near(qcga::scp(point_at(p), dual), value, tol));
      EXPECT_TRUE(scalar_near(qcga::scp(point_at(p), other), value, tol));
      EXPECT_TRUE(scalar_near(qcga::scp(widen(point_at(p)), widen(dual)), value, tol));
      // For vectors the contractions are the scalar product.
      EXPECT_TRUE(scalar_near(qcga::lc(point_at(p), dual), value, tol));
      EXPECT_TRUE(scalar_near(qcga::rc(dual, point_at(p)), value, tol));
      EXPECT_TRUE(near(qcga::lc(widen(point_at(p)), widen(dual)), value));
    }
  }
}

TEST(Qcga, PointsOfAnEllipsoidLieOnItsQuadric) {
  auto rng = make_rng(84);
  const qcga::quadric q = quadric_of(ellipsoid);
  for (int k = 0; k < 10; ++k) {
    const vec3 p = on_ellipsoid(uniform(rng, 0.0, pi), uniform(rng, 0.0, 2 * pi));
    EXPECT_TRUE(scalar_near(qcga::scp(point_at(p), q), 0, tol));
    // Its offset from the centre along the first axis stretched by 1.3: the
    // term (x - 0.5)^2/4 = u^2 grows by the factor 1.3^2, the others stay.
    const double u = (p[0] - ellipsoid_centre[0]) / 2;
    const vec3 out{ellipsoid_centre[0] + 1.3 * (p[0] - ellipsoid_centre[0]), p[1], p[2]};
    EXPECT_TRUE(scalar_near(qcga::scp(point_at(out), q), u * u * (1.3 * 1.3 - 1), tol));
  }
}

// The dual quadric through nine points is orthogonal to each and to eo4,
// eo5, eo6 and eo1 - eo2, eo2 - eo3 (so q_i4..q_i6 = 0 and q_i1 = q_i2 =
// q_i3): the dual of P1 ^ ... ^ P9 ^ (eo1 - eo2) ^ (eo2 - eo3) ^ eo4 ^ eo5 ^ eo6.
TEST(Qcga, TheQuadricThroughNinePointsIsTheEllipsoid) {
  auto rng = make_rng(85);
  mv blade = mv::from_blades({{0u, 1.0}});
  for (int k = 0; k < 9; ++k)
    blade = qcga::op(
        blade,
        widen(point_at(on_ellipsoid(uniform(rng, 0.2, pi - 0.2), uniform(rng, 0.0, 2 * pi)))));
  const auto eo = [](int k) { return mv::from_blades({{bit(eo_index + k - 1), 1.0}}); };
  blade = qcga::op(blade, qcga::sub(eo(1), eo(2)));
  blade = qcga::op(blade, qcga::sub(eo(2), eo(3)));
  for (int k = 4; k <= 6; ++k) blade = qcga::op(blade, eo(k));
  ASSERT_EQ(blade.bits, mv::grade_mask(14));
  const mv q = qcga::dual(blade);
  ASSERT_EQ(q.bits, mv::grade_mask(1));
  // Proportional to the closed form with -j split evenly.
  const mv expected = widen(quadric_of(ellipsoid, {1 / 3.0, 1 / 3.0, 1 / 3.0}));
  double qe = 0, ee = 0;
  for (const auto& t : expected.terms) {
    qe += t.value * q.coefficient(t.blade);
    ee += t.value * t.value;
  }
  const double scale = qe / ee;
  ASSERT_GT(std::abs(scale), 1e-9 * largest(q));
  EXPECT_TRUE(near(qcga::smul(1 / scale, q), expected, 1e-8));
  const qcga::quadric named(q);
  const vec3 on = on_ellipsoid(1.0, 2.0), off{0, 0, 0};
  EXPECT_TRUE(scalar_near(qcga::scp(point_at(on), named) / scale, 0, 1e-8));
  EXPECT_TRUE(
      scalar_near(qcga::scp(point_at(off), named) / scale, polynomial(ellipsoid, off), 1e-8));
}

// ---- named-type kernels against the mv path ----------------------------------------------

TEST(Qcga, NamedTypeKernelsAgreeWithTheMvPath) {
  auto rng = make_rng(86);
  const auto p = random_named<qcga::point>(rng), p2 = random_named<qcga::point>(rng);
  const auto q = random_named<qcga::quadric>(rng), q2 = random_named<qcga::quadric>(rng);
  const mv mp = widen(p), mp2 = widen(p2), mq = widen(q), mq2 = widen(q2);
  EXPECT_TRUE(near(qcga::scp(p, q), qcga::scp(mp, mq)));
  EXPECT_TRUE(near(qcga::lc(p, q), qcga::lc(mp, mq)));
  EXPECT_TRUE(near(qcga::op(p, p2), qcga::op(mp, mp2)));
  EXPECT_TRUE(near(qcga::gp(p, q), qcga::gp(mp, mq)));
  EXPECT_TRUE(near(qcga::gp(q, q2), qcga::gp(mq, mq2)));
  EXPECT_TRUE(near(qcga::op(q, p), qcga::op(mq, mp)));
  EXPECT_TRUE(near(qcga::rc(q, q2), qcga::rc(mq, mq2)));
  EXPECT_TRUE(near(qcga::norm2(q), qcga::norm2(mq)));
  EXPECT_TRUE(near(qcga::reverse(q), qcga::reverse(mq)));
  EXPECT_TRUE(near(qcga::involute(p), qcga::involute(mp)));
  EXPECT_TRUE(near(qcga::dual(q), qcga::dual(mq)));
  EXPECT_TRUE(near(qcga::undual(q), qcga::undual(mq)));
  EXPECT_TRUE(near(qcga::undual(qcga::dual(q)), q));
  EXPECT_TRUE(near(qcga::apply(q, p), qcga::apply(mq, mp)));
  EXPECT_TRUE(near(qcga::gp(qcga::inverse(q), q), 1.0));
}

}  // namespace qcga_test
