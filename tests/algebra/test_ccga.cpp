// The conic conformal algebra CCGA, Cl(5,3), of specs/ccga.ga (Hrdina, Navrat,
// Vasik 2018): basis o1 o2 o3 e1 e2 i1 i2 i3, oK . iK = -1, eight basis
// vectors, so its general mv is the sparse one. A point (x, y) of the plane is
//   P = o1 + x e1 + y e2 + (x^2 + y^2)/2 i1 + (x^2 - y^2)/2 i2 + xy i3,
// and with the metric, for a vector Q = q_o1 o1 + q_o2 o2 + q_o3 o3 + q_e1 e1
// + q_e2 e2 + q_i1 i1 (a dual_conic),
//   P . Q = q_e1 x + q_e2 y - q_i1 - q_o1 (x^2 + y^2)/2 - q_o2 (x^2 - y^2)/2 - q_o3 xy.
// So the conic a x^2 + b y^2 + c xy + d x + e y + f = 0 is the dual_conic
//   q_o1 = -(a + b), q_o2 = b - a, q_o3 = -c, q_e1 = d, q_e2 = e, q_i1 = -f,
// and two points have P . P' = -|p - p'|^2 / 2 (their o2, o3 parts are zero).
// Truths: these closed forms, plane geometry, and the metric the spec writes.
#include <algorithm>
#include <array>
#include <ccga/ccga.hpp>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "algebra_test_support.hpp"
#include "sparse_test_support.hpp"

namespace ccga_test {

using namespace gaphys_test;
namespace sparse = gaphys_test::sparse;
using ccga::mv;

constexpr double tol = 1e-10;

// Blade bitmaps (bit i: the i-th basis vector of o1 o2 o3 e1 e2 i1 i2 i3).
constexpr std::uint32_t o1_bit = 0x1u, o2_bit = 0x2u, o3_bit = 0x4u, e1_bit = 0x8u, e2_bit = 0x10u,
                        i1_bit = 0x20u, i2_bit = 0x40u, i3_bit = 0x80u, i8_bit = 0xffu;

// ---- comparisons on the sparse mv ------------------------------------------------

template <class X>
mv widen(const X& x) {
  return sparse::widen<mv>(x);
}
template <class X, class Y>
::testing::AssertionResult near(const X& x, const Y& y, double rel_tol = tol) {
  return sparse::near<mv>(x, y, rel_tol);
}

// ---- plane geometry in closed form --------------------------------------------------

ccga::point point_at(double x, double y) {
  return {x, y, (x * x + y * y) / 2, (x * x - y * y) / 2, x * y};
}

// a x^2 + b y^2 + c xy + d x + e y + f
struct conic {
  double a, b, c, d, e, f;
  double operator()(double x, double y) const {
    return a * x * x + b * y * y + c * x * y + d * x + e * y + f;
  }
};

ccga::dual_conic dual_conic_of(const conic& k) {
  return {-(k.a + k.b), k.b - k.a, -k.c, k.d, k.e, -k.f};
}

// A conic alpha u^2 + beta v^2 + gamma u + delta v + eps = 0 in the frame of
// origin (h, k) turned by phi: u = cos(phi) X + sin(phi) Y, v = -sin(phi) X +
// cos(phi) Y with X = x - h, Y = y - k. Expanding,
//   P X^2 + Q Y^2 + R XY + G X + H Y + eps,   P = alpha c^2 + beta s^2,
//   Q = alpha s^2 + beta c^2, R = 2cs (alpha - beta), G = gamma c - delta s,
//   H = gamma s + delta c,
// and then X = x - h, Y = y - k.
struct framed_conic {
  double alpha, beta, gamma, delta, eps;
  double h, k, phi;

  conic in_plane() const {
    const double c = std::cos(phi), s = std::sin(phi);
    const double p = alpha * c * c + beta * s * s, q = alpha * s * s + beta * c * c;
    const double r = 2 * c * s * (alpha - beta), g = gamma * c - delta * s,
                 hh = gamma * s + delta * c;
    return {p,
            q,
            r,
            -2 * p * h - r * k + g,
            -2 * q * k - r * h + hh,
            p * h * h + q * k * k + r * h * k - g * h - hh * k + eps};
  }
  // The plane point of frame coordinates (u, v).
  std::array<double, 2> at(double u, double v) const {
    const double c = std::cos(phi), s = std::sin(phi);
    return {h + c * u - s * v, k + s * u + c * v};
  }
};

// An ellipse (semi-axes 2 and 0.8), a hyperbola (u^2/1.5^2 - v^2/0.7^2 = 1)
// and a parabola (v^2 = 4 * 0.6 u), each placed and turned, with a
// parametrization of their points.
struct named_conic {
  const char* name;
  framed_conic frame;
  std::array<double, 2> (*point)(const framed_conic&, double t);
};
const std::array<named_conic, 3> conics = {{
    {"ellipse",
     {1 / 4.0, 1 / 0.64, 0, 0, -1, 0.5, -1.2, 0.4},
     [](const framed_conic& f, double t) { return f.at(2 * std::cos(t), 0.8 * std::sin(t)); }},
    {"hyperbola",
     {1 / 2.25, -1 / 0.49, 0, 0, -1, -0.3, 0.8, -1.1},
     [](const framed_conic& f, double t) {
       return f.at((t > 0 ? 1.5 : -1.5) * std::cosh(t), 0.7 * std::sinh(t));
     }},
    {"parabola",
     {0, 1, -4 * 0.6, 0, 0, 1.5, 0.2, 2.3},
     [](const framed_conic& f, double t) { return f.at(t * t / (4 * 0.6), t); }},
}};

// The dual conic through five points: orthogonal to each, and to o2 and o3
// (no i2, i3 part: a dual_conic). P1 ^ ... ^ P5 ^ o2 ^ o3 is the 7-blade of
// the vectors it must be orthogonal to, and its dual is that vector.
mv conic_through(const std::array<std::array<double, 2>, 5>& p) {
  mv blade = widen(point_at(p[0][0], p[0][1]));
  for (int i = 1; i < 5; ++i) blade = ccga::op(blade, widen(point_at(p[i][0], p[i][1])));
  blade = ccga::op(ccga::op(blade, widen(ccga::o2())), widen(ccga::o3()));
  return ccga::dual(blade);
}

// Sum of the products of matching coefficients: for the scale between two
// proportional multivectors.
double coefficient_dot(const mv& x, const mv& y) {
  double sum = 0;
  for (const auto& t : x.terms) sum += t.value * y.coefficient(t.blade);
  return sum;
}

mv random_mv(std::mt19937& rng, std::uint32_t grades) {
  mv x;
  for (std::uint32_t blade = 0; blade < 256; ++blade)
    if (grades >> gaphys::ga::bitwise::grade(blade) & 1)
      x = ccga::add(x, mv::from_blades({{blade, uniform(rng, -1.0, 1.0)}}));
  return x;
}

// exp by its Taylor series on the mv path: independent of the closed forms.
mv exp_by_series(const mv& x) {
  mv sum = mv::from_blades({{0u, 1.0}}), term = sum;
  for (int k = 1; k <= 40; ++k) {
    term = ccga::smul(1.0 / k, ccga::gp(term, x));
    sum = ccga::add(sum, term);
  }
  return sum;
}

// ---- the metric --------------------------------------------------------------------------

// e_i e_j = e_i . e_j + e_i ^ e_j with the spec's inner products: e1, e2
// orthonormal, oK . iK = -1, everything else 0.
TEST(Ccga, BasisVectorProductsFollowTheSpecsMetric) {
  const auto inner = [](int i, int j) {
    if (i == j) return (i == 3 || i == 4) ? 1.0 : 0.0;
    const int lo = std::min(i, j), hi = std::max(i, j);
    return (lo <= 2 && hi == lo + 5) ? -1.0 : 0.0;
  };
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j) {
      const std::uint32_t bi = std::uint32_t(1) << i, bj = std::uint32_t(1) << j;
      const mv ei = mv::from_blades({{bi, 1.0}}), ej = mv::from_blades({{bj, 1.0}});
      mv expected = mv::from_blades({{0u, inner(i, j)}});
      if (i != j) expected = ccga::add(expected, mv::from_blades({{bi | bj, i < j ? 1.0 : -1.0}}));
      EXPECT_TRUE(near(ccga::gp(ei, ej), expected))
          << ccga::basis_names[i] << " " << ccga::basis_names[j];
    }
  // Cl(5,3): I^2 = (-1)^(8*7/2) (-1)^3 = -1, so dual(x) = x I^-1 = -x I.
  const mv i8 = mv::from_blades({{i8_bit, 1.0}});
  EXPECT_TRUE(near(ccga::gp(i8, i8), -1.0));
  EXPECT_EQ(mv::blade_name(255), "o1^o2^o3^e1^e2^i1^i2^i3");
  EXPECT_EQ(mv::blade_name(9), "o1^o2");
}

TEST(Ccga, ScalarProductOfPointsIsMinusHalfTheSquaredDistance) {
  auto rng = make_rng(61);
  for (int trial = 0; trial < 20; ++trial) {
    const double x = uniform(rng, -3.0, 3.0), y = uniform(rng, -3.0, 3.0);
    const double u = uniform(rng, -3.0, 3.0), v = uniform(rng, -3.0, 3.0);
    const double expected = -((x - u) * (x - u) + (y - v) * (y - v)) / 2;
    EXPECT_TRUE(scalar_near(ccga::scp(point_at(x, y), point_at(u, v)), expected, tol));
    EXPECT_TRUE(
        scalar_near(ccga::scp(widen(point_at(x, y)), widen(point_at(u, v))), expected, tol));
    EXPECT_TRUE(scalar_near(ccga::norm2(point_at(x, y)), 0, tol));
    EXPECT_TRUE(scalar_near(ccga::norm2(widen(point_at(x, y))), 0, tol));
  }
  // A point is null, so it has no versor inverse (exact zero: small integers).
  EXPECT_THROW(ccga::inverse(point_at(1, 2)), std::domain_error);
  EXPECT_THROW(ccga::inverse(widen(point_at(1, 2))), std::domain_error);
}

// For vectors, P P' = P . P' + P ^ P', and the outer product is antisymmetric.
TEST(Ccga, ProductOfTwoPointsSplitsIntoScalarAndOuterProducts) {
  auto rng = make_rng(69);
  for (int trial = 0; trial < 5; ++trial) {
    const ccga::point p = point_at(uniform(rng, -2.0, 2.0), uniform(rng, -2.0, 2.0));
    const ccga::point q = point_at(uniform(rng, -2.0, 2.0), uniform(rng, -2.0, 2.0));
    const mv pq = ccga::op(p, q);
    EXPECT_EQ(pq.bits, mv::grade_mask(2));
    EXPECT_TRUE(near(pq, ccga::neg(ccga::op(q, p))));
    EXPECT_TRUE(near(ccga::op(p, p), mv()));
    EXPECT_TRUE(near(ccga::gp(p, q), ccga::add(widen(ccga::scp(p, q)), pq)));
    EXPECT_TRUE(near(ccga::gp(widen(p), widen(q)), ccga::add(widen(ccga::scp(p, q)), pq)));
  }
}

// ---- conics --------------------------------------------------------------------------------

TEST(Ccga, ScalarProductWithADualConicIsTheConicsPolynomial) {
  auto rng = make_rng(62);
  std::vector<conic> polynomials = {{1, 1, 0, 0, 0, -4},     // the circle of radius 2
                                    {1, -1, 0, 0, 0, -1},    // x^2 - y^2 = 1
                                    {0, 0, 1, 0, 0, -1},     // xy = 1
                                    {0, 0, 0, 2, -3, 0.5}};  // a line
  for (const auto& k : conics) polynomials.push_back(k.frame.in_plane());
  for (int trial = 0; trial < 3; ++trial) {
    conic random;
    random.a = uniform(rng, -2.0, 2.0), random.b = uniform(rng, -2.0, 2.0),
    random.c = uniform(rng, -2.0, 2.0);
    random.d = uniform(rng, -2.0, 2.0), random.e = uniform(rng, -2.0, 2.0),
    random.f = uniform(rng, -2.0, 2.0);
    polynomials.push_back(random);
  }
  for (const conic& k : polynomials) {
    const ccga::dual_conic q = dual_conic_of(k);
    for (int i = 0; i < 5; ++i) {
      const double x = uniform(rng, -3.0, 3.0), y = uniform(rng, -3.0, 3.0);
      EXPECT_TRUE(scalar_near(ccga::scp(point_at(x, y), q), k(x, y), tol));
      EXPECT_TRUE(scalar_near(ccga::scp(widen(point_at(x, y)), widen(q)), k(x, y), tol));
      EXPECT_TRUE(scalar_near(ccga::lc(point_at(x, y), q), k(x, y), tol));
    }
  }
}

// Q = dual(P1 ^ ... ^ P5 ^ o2 ^ o3) is the conic through the five points, up
// to scale: proportional to its closed form, zero at a sixth point of the same
// conic, and elsewhere its polynomial times that scale.
TEST(Ccga, TheConicThroughFivePointsHoldsASixth) {
  auto rng = make_rng(63);
  for (const auto& k : conics) {
    SCOPED_TRACE(k.name);
    const conic truth = k.frame.in_plane();
    std::array<std::array<double, 2>, 5> p;
    for (int i = 0; i < 5; ++i) {
      p[i] = k.point(k.frame, uniform(rng, -2.0, 2.0));
      ASSERT_TRUE(scalar_near(truth(p[i][0], p[i][1]), 0, tol))
          << "the parametrization is off the conic";
    }
    const mv q = conic_through(p);
    ASSERT_EQ(q.bits, mv::grade_mask(1)) << q;
    EXPECT_EQ(q.coefficient(i2_bit), 0.0);
    EXPECT_EQ(q.coefficient(i3_bit), 0.0);
    const mv expected = widen(dual_conic_of(truth));
    const double scale = coefficient_dot(q, expected) / coefficient_dot(expected, expected);
    ASSERT_GT(std::abs(scale), 1e-6);
    EXPECT_TRUE(near(ccga::smul(1 / scale, q), expected, 1e-9));
    const ccga::dual_conic named(q);
    for (int i = 0; i < 3; ++i) {
      const auto on = k.point(k.frame, uniform(rng, -2.0, 2.0));
      EXPECT_TRUE(scalar_near(ccga::scp(point_at(on[0], on[1]), named) / scale, 0, 1e-9));
      const double x = uniform(rng, -3.0, 3.0), y = uniform(rng, -3.0, 3.0);
      EXPECT_TRUE(scalar_near(ccga::scp(point_at(x, y), named) / scale, truth(x, y), 1e-9));
    }
  }
}

// ---- vectors, duality, inverses -------------------------------------------------------------

TEST(Ccga, InverseOfAVectorAndTheGeneralInverse) {
  auto rng = make_rng(64);
  for (int trial = 0; trial < 10; ++trial) {
    const auto v = random_named<ccga::vector>(rng);
    ASSERT_GT(std::abs(ccga::norm2(v)), 1e-3);
    EXPECT_TRUE(near(ccga::gp(ccga::inverse(v), v), 1.0));
    EXPECT_TRUE(near(ccga::gp(v, ccga::inverse(v)), 1.0));
    EXPECT_TRUE(near(ccga::gp(ccga::inverse(widen(v)), widen(v)), 1.0));
    // A vector's square is its norm: v v = v . v.
    EXPECT_TRUE(near(ccga::gp(v, v), ccga::scp(v, v)));
  }
  // The general inverse solves x y = 1 on a 256 x 256 system.
  const mv x = ccga::add(random_mv(rng, 0x7u), mv::from_blades({{0u, 4.0}}));
  const auto y = checked_call([&] { return ccga::general_inverse(x); });
  if (y) {
    EXPECT_TRUE(near(ccga::gp(x, *y), 1.0, 1e-9));
    EXPECT_TRUE(near(ccga::gp(*y, x), 1.0, 1e-9));
  }
}

TEST(Ccga, UndualOfDualIsTheIdentityAndDualIsMinusTheProductWithI) {
  auto rng = make_rng(65);
  const mv i8 = mv::from_blades({{i8_bit, 1.0}});
  for (int trial = 0; trial < 3; ++trial) {
    const auto v = random_named<ccga::vector>(rng);
    EXPECT_TRUE(near(ccga::undual(ccga::dual(v)), v));
    EXPECT_TRUE(near(ccga::dual(v), ccga::smul(-1.0, ccga::gp(widen(v), i8))));
    const mv x = random_mv(rng, 0x1ffu);  // all 256 blades
    EXPECT_TRUE(near(ccga::undual(ccga::dual(x)), x));
    EXPECT_TRUE(near(ccga::dual(x), ccga::smul(-1.0, ccga::gp(x, i8))));
  }
}

// ---- rotations --------------------------------------------------------------------------------

// exp(t e12) = cos t + sin t e12 (e12^2 = -1). e12 as a versor is the half
// turn: e12 e1 e12^-1 = -e1, e12 e2 e12^-1 = -e2, and it commutes with the
// o and i vectors, so it maps P(x, y) to P(-x, -y).
TEST(Ccga, ExpOfE12AndTheHalfTurn) {
  for (const double t : {0.0, 1e-4, 0.6, 2.0, -2.8}) {
    const mv expected = mv::from_blades({{0u, std::cos(t)}, {e1_bit | e2_bit, std::sin(t)}});
    EXPECT_TRUE(near(ccga::exp(widen(ccga::euclidean_bivector{t})), expected)) << t;
    EXPECT_TRUE(near(ccga::exp(ccga::euclidean_bivector{t}), expected)) << t;  // the named kernel
  }
  auto rng = make_rng(66);
  for (int trial = 0; trial < 5; ++trial) {
    const double x = uniform(rng, -3.0, 3.0), y = uniform(rng, -3.0, 3.0);
    const ccga::euclidean_bivector b{uniform(rng, 0.5, 2.0)};
    EXPECT_TRUE(near(ccga::apply(b, point_at(x, y)), point_at(-x, -y)));
    EXPECT_TRUE(near(ccga::apply(widen(b), widen(point_at(x, y))), point_at(-x, -y)));
  }
}

// A rotation by theta turns (x, y) and, with it, (x^2 - y^2, 2xy) = z^2 by
// 2 theta. exp(-theta/2 e12) turns e1, e2; G = o2^i3 - o3^i2 acts on vectors
// as x -> x . G with i2 -> -i3, i3 -> i2 (and o2 -> -o3, o3 -> o2): J^2 = -1,
// so exp(-psi/2 G) turns (i2, i3) by exp(psi J), and psi = -2 theta gives z^2's
// turn. The planes are orthogonal, so R = exp(-theta/2 e12) exp(theta G) maps
// P(x, y) to the point of (x, y) turned by theta.
TEST(Ccga, TheRotorOfCcgaTurnsPoints) {
  auto rng = make_rng(67);
  const mv g = mv::from_blades({{o2_bit | i3_bit, 1.0}, {o3_bit | i2_bit, -1.0}});
  for (const double theta : {0.3, 1.0, -2.2}) {
    SCOPED_TRACE(::testing::Message() << "theta " << theta);
    const mv r1 = ccga::exp(widen(ccga::euclidean_bivector{-theta / 2}));
    const mv r2 = ccga::exp(ccga::smul(theta, g));
    EXPECT_TRUE(near(r2, exp_by_series(ccga::smul(theta, g)), 1e-9));
    const mv r = ccga::gp(r1, r2);
    EXPECT_TRUE(near(ccga::gp(r, ccga::reverse(r)), 1.0));
    for (int k = 0; k < 3; ++k) {
      const double x = uniform(rng, -2.0, 2.0), y = uniform(rng, -2.0, 2.0);
      const double c = std::cos(theta), s = std::sin(theta);
      EXPECT_TRUE(
          near(ccga::apply(r, widen(point_at(x, y))), point_at(c * x - s * y, s * x + c * y)));
    }
  }
}

// ---- named-type kernels against the mv path ----------------------------------------------

template <class A, class B>
void expect_products_agree(const A& a, const B& b) {
  const mv x = widen(a), y = widen(b);
  EXPECT_TRUE(near(ccga::gp(a, b), ccga::gp(x, y))) << "gp";
  EXPECT_TRUE(near(ccga::op(a, b), ccga::op(x, y))) << "op";
  EXPECT_TRUE(near(ccga::lc(a, b), ccga::lc(x, y))) << "lc";
  EXPECT_TRUE(near(ccga::rc(a, b), ccga::rc(x, y))) << "rc";
  EXPECT_TRUE(near(ccga::scp(a, b), ccga::scp(x, y))) << "scp";
  EXPECT_TRUE(near(ccga::meet(a, b), ccga::meet(x, y))) << "meet";
  EXPECT_TRUE(near(ccga::join(a, b), ccga::join(x, y))) << "join";
}

template <class A>
void expect_unary_agree(const A& a) {
  const mv x = widen(a);
  EXPECT_TRUE(near(ccga::neg(a), ccga::neg(x))) << "neg";
  EXPECT_TRUE(near(ccga::reverse(a), ccga::reverse(x))) << "reverse";
  EXPECT_TRUE(near(ccga::involute(a), ccga::involute(x))) << "involute";
  EXPECT_TRUE(near(ccga::conjugate(a), ccga::conjugate(x))) << "conjugate";
  EXPECT_TRUE(near(ccga::dual(a), ccga::dual(x))) << "dual";
  EXPECT_TRUE(near(ccga::undual(a), ccga::undual(x))) << "undual";
  EXPECT_TRUE(near(ccga::norm2(a), ccga::norm2(x))) << "norm2";
}

TEST(Ccga, NamedTypeKernelsAgreeWithTheMvPath) {
  auto rng = make_rng(68);
  for (int trial = 0; trial < 3; ++trial) {
    const auto p = random_named<ccga::point>(rng), p2 = random_named<ccga::point>(rng);
    const auto q = random_named<ccga::dual_conic>(rng);
    const auto v = random_named<ccga::vector>(rng), v2 = random_named<ccga::vector>(rng);
    const auto b = random_named<ccga::euclidean_bivector>(rng);
    {
      SCOPED_TRACE("declared pairs");
      expect_products_agree(p, p2);
      expect_products_agree(p, q);
      EXPECT_TRUE(near(ccga::apply(b, p), ccga::apply(widen(b), widen(p))));
      EXPECT_TRUE(near(ccga::inverse(v), ccga::inverse(widen(v))));
    }
    {
      SCOPED_TRACE("undeclared pairs");
      expect_products_agree(q, p);
      expect_products_agree(v, v2);
      expect_products_agree(q, v);
      expect_products_agree(b, p);
      expect_products_agree(v, b);
      EXPECT_TRUE(near(ccga::apply(v, q), ccga::apply(widen(v), widen(q))));
      EXPECT_TRUE(near(ccga::apply(b, v), ccga::apply(widen(b), widen(v))));
    }
    {
      SCOPED_TRACE("unary");
      expect_unary_agree(p);
      expect_unary_agree(q);
      expect_unary_agree(v);
      expect_unary_agree(b);
    }
  }
}

}  // namespace ccga_test
