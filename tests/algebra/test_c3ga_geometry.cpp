// c3ga geometry against closed-form Euclidean geometry: distances between
// points, inside/outside of spheres, sphere-sphere and sphere-plane meets
// (the contact test of the engine) and the contact point of touching objects.
//
// Sign convention (checked below): for C = meet(S1, S2) of two spheres
// S = dual(sigma), <C C>_0 = r1^2 r2^2 - (sigma1 . sigma2)^2, which is
//   > 0 when the spheres intersect in a circle,
//   = 0 when they touch,
//   < 0 when they are apart (or one lies inside the other).
// For a sphere and a plane, <C C>_0 = r^2 - dist^2 with the same meaning.
#include <c3ga/c3ga.hpp>
#include <vector>

#include "algebra_test_support.hpp"
#include "c3ga_test_support.hpp"

namespace c3ga_geometry_test {

using namespace gaphys_test;

template <class T>
using mv = c3ga::basic_mv<T>;

constexpr int trials = 50;

template <class T>
class C3gaGeometry : public ::testing::Test {};
TYPED_TEST_SUITE(C3gaGeometry, scalar_types);

// The Euclidean point of a (scaled) conformal point: x / (-ni . x).
template <class T>
vec3 euclidean_point(const mv<T>& x) {
  const double w = -double(c3ga::scp(c3ga::ni<T>(), x));
  const auto& names = c3ga::blade_names;
  return {double(x[blade_index(names, "e1")]) / w, double(x[blade_index(names, "e2")]) / w,
          double(x[blade_index(names, "e3")]) / w};
}

::testing::AssertionResult points_near(const vec3& a, const vec3& b, double rel_tol) {
  const double tol = rel_tol * std::max({1.0, length(a), length(b)});
  if (length(a - b) <= tol) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "(" << a[0] << ", " << a[1] << ", " << a[2] << ") vs (" << b[0] << ", " << b[1] << ", "
         << b[2] << "), tolerance " << tol;
}

// Two unit vectors orthogonal to the unit vector u.
std::pair<vec3, vec3> orthonormal_complement(const vec3& u) {
  const vec3 helper = std::abs(u[0]) < 0.6 ? vec3{1, 0, 0} : vec3{0, 1, 0};
  const vec3 v = cross(u, helper);
  const vec3 a = (1 / length(v)) * v;
  return {a, cross(u, a)};
}

TYPED_TEST(C3gaGeometry, PointInnerProductIsMinusHalfSquaredDistance) {
  using T = TypeParam;
  auto rng = make_rng(501);
  for (int i = 0; i < trials; ++i) {
    const vec3 x = random_vec3(rng, -5, 5), y = random_vec3(rng, -5, 5);
    const auto p = point_of<T>(x), q = point_of<T>(y);
    const double d2 = dot(x - y, x - y);
    EXPECT_TRUE(scalar_near(double(c3ga::scp(p, q)), -d2 / 2, tolerance<T>() * 10));
    EXPECT_TRUE(scalar_near(double(c3ga::scp(p, p)), 0, tolerance<T>() * 10));
    EXPECT_EQ(double(p.no()), 1.0);
  }
}

// sigma . sigma = r^2 and p . sigma = (r^2 - |x - c|^2) / 2: positive inside.
TYPED_TEST(C3gaGeometry, DualSphereTellsInsideFromOutside) {
  using T = TypeParam;
  auto rng = make_rng(502);
  int inside = 0, outside = 0;
  for (int i = 0; i < trials; ++i) {
    const vec3 c = random_vec3(rng, -3, 3), x = random_vec3(rng, -3, 3);
    const double r = uniform(rng, 0.5, 3.0);
    const auto sigma = dual_sphere_of<T>(c, r);
    const auto p = point_of<T>(x);
    const double expected = (r * r - dot(x - c, x - c)) / 2;
    EXPECT_TRUE(scalar_near(double(c3ga::scp(p, sigma)), expected, tolerance<T>() * 10));
    EXPECT_TRUE(scalar_near(double(c3ga::lc(p, sigma)), expected, tolerance<T>() * 10));
    EXPECT_TRUE(scalar_near(double(c3ga::scp(sigma, sigma)), r * r, tolerance<T>() * 10));
    if (std::abs(expected) > 1e-2) {
      EXPECT_EQ(c3ga::scp(p, sigma) > 0, length(x - c) < r);
      (length(x - c) < r ? inside : outside) += 1;
    }
  }
  EXPECT_GT(inside, 0);
  EXPECT_GT(outside, 0);
}

// Two spheres in a known relation: centres c1, c1 + d u.
struct sphere_pair {
  vec3 c1, u;
  double r1, r2, d;
  vec3 c2() const { return c1 + d * u; }
};

enum class relation { apart, nested, touching_outside, touching_inside, intersecting };

sphere_pair random_pair(std::mt19937& rng, relation rel) {
  sphere_pair s{random_vec3(rng, -3, 3), random_unit_vec3(rng), uniform(rng, 0.5, 2.0),
                uniform(rng, 0.5, 2.0), 0};
  if (rel == relation::nested || rel == relation::touching_inside) {
    if (s.r1 < s.r2) std::swap(s.r1, s.r2);
    s.r1 += 0.5;  // keep the radii apart so nesting is clear
  }
  const double sum = s.r1 + s.r2, diff = s.r1 - s.r2;
  switch (rel) {
    case relation::apart:
      s.d = sum + uniform(rng, 0.1, 2.0);
      break;
    case relation::nested:
      s.d = diff * uniform(rng, 0.0, 0.8);
      break;
    case relation::touching_outside:
      s.d = sum;
      break;
    case relation::touching_inside:
      s.d = diff;
      break;
    case relation::intersecting:
      s.d = uniform(rng, std::abs(diff) + 0.1, sum - 0.1);
      break;
  }
  return s;
}

template <class T>
struct sphere_meet {
  mv<T> circle;
  double square;  // <C C>_0
};

template <class T>
sphere_meet<T> meet_spheres(const sphere_pair& s) {
  const auto s1 = c3ga::dual(dual_sphere_of<T>(s.c1, s.r1));
  const auto s2 = c3ga::dual(dual_sphere_of<T>(s.c2(), s.r2));
  const auto c = c3ga::meet(s1, s2);
  return {as_mv<mv<T>>(c), double(as_mv<mv<T>>(c * c)[0])};
}

// The closed form of <C C>_0 and a magnitude to measure its rounding against.
double expected_square(const sphere_pair& s) {
  const double s12 = (s.r1 * s.r1 + s.r2 * s.r2 - s.d * s.d) / 2;  // sigma1 . sigma2
  return s.r1 * s.r1 * s.r2 * s.r2 - s12 * s12;
}

double square_scale(const sphere_pair& s) {
  const double m = std::max({1.0, dot(s.c1, s.c1), dot(s.c2(), s.c2()), s.r1 * s.r1, s.r2 * s.r2});
  return m * m;
}

TYPED_TEST(C3gaGeometry, SphereMeetSquareClassifiesPairs) {
  using T = TypeParam;
  auto rng = make_rng(503);
  const std::vector<std::pair<relation, int>> cases = {{relation::apart, -1},
                                                       {relation::nested, -1},
                                                       {relation::touching_outside, 0},
                                                       {relation::touching_inside, 0},
                                                       {relation::intersecting, 1}};
  for (const auto& [rel, sign] : cases) {
    for (int i = 0; i < trials; ++i) {
      const sphere_pair s = random_pair(rng, rel);
      const double t = meet_spheres<T>(s).square;
      const double scale = square_scale(s);
      SCOPED_TRACE(::testing::Message() << "relation " << int(rel) << ", r1 " << s.r1 << ", r2 "
                                        << s.r2 << ", d " << s.d);
      EXPECT_NEAR(t, expected_square(s), tolerance<T>() * scale);
      if (sign > 0) {
        EXPECT_GT(t, tolerance<T>() * scale);
      }
      if (sign < 0) {
        EXPECT_LT(t, -tolerance<T>() * scale);
      }
    }
  }
}

// For intersecting spheres the meet is the circle of centre c1 + a u and
// radius h, a = (d^2 + r1^2 - r2^2) / 2d, h^2 = r1^2 - a^2.
TYPED_TEST(C3gaGeometry, SphereMeetIsTheIntersectionCircle) {
  using T = TypeParam;
  auto rng = make_rng(504);
  for (int i = 0; i < trials; ++i) {
    const sphere_pair s = random_pair(rng, relation::intersecting);
    const double a = (s.d * s.d + s.r1 * s.r1 - s.r2 * s.r2) / (2 * s.d);
    const double h = std::sqrt(s.r1 * s.r1 - a * a);
    const vec3 centre = s.c1 + a * s.u;
    const mv<T> c = meet_spheres<T>(s).circle;
    const mv<T> ni = as_mv<mv<T>>(c3ga::ni<T>());

    // The centre is C ni C, the squared radius -<C C>_0 / <(ni _| C)^2>_0.
    EXPECT_TRUE(points_near(euclidean_point<T>(c * ni * c), centre, tolerance<T>() * 10));
    const mv<T> nc = c3ga::lc(ni, c);
    const double radius2 = -double((c * c)[0]) / double((nc * nc)[0]);
    EXPECT_TRUE(scalar_near(radius2, h * h, tolerance<T>() * 10));

    // Points of the closed-form circle lie on C (C ^ q = 0); a point off it does not.
    const auto [v1, v2] = orthonormal_complement(s.u);
    const double phi = uniform(rng, 0.0, 2 * pi);
    const vec3 dir = std::cos(phi) * v1 + std::sin(phi) * v2;
    const auto on = point_of<T>(centre + h * dir);
    const auto off = point_of<T>(centre + (1.2 * h) * dir);
    const double scale =
        double(max_abs(c.to_array())) * std::max(1.0, double(max_abs(as_mv<mv<T>>(on).to_array())));
    EXPECT_TRUE(mv_within<mv<T>>(c3ga::op(c3ga::basic_circle<T>(c), on), mv<T>(),
                                 tolerance<T>() * 10 * scale));
    EXPECT_GT(double(max_abs(as_mv<mv<T>>(c3ga::op(c3ga::basic_circle<T>(c), off)).to_array())),
              1e-3 * scale);
  }
}

// Touching spheres meet in a zero-radius circle; C ni C is the contact point.
TYPED_TEST(C3gaGeometry, TouchingSpheresGiveTheContactPoint) {
  using T = TypeParam;
  auto rng = make_rng(505);
  for (int i = 0; i < trials; ++i) {
    const sphere_pair outside = random_pair(rng, relation::touching_outside);
    const mv<T> c = meet_spheres<T>(outside).circle;
    const mv<T> ni = as_mv<mv<T>>(c3ga::ni<T>());
    EXPECT_TRUE(points_near(euclidean_point<T>(c * ni * c), outside.c1 + outside.r1 * outside.u,
                            tolerance<T>() * 10));

    // Sphere 2 inside sphere 1, touching it on the far side from c1.
    const sphere_pair inside = random_pair(rng, relation::touching_inside);
    const mv<T> ci = meet_spheres<T>(inside).circle;
    EXPECT_TRUE(points_near(euclidean_point<T>(ci * ni * ci), inside.c1 + inside.r1 * inside.u,
                            tolerance<T>() * 10));
  }
}

// Sphere (centre c, radius r) and plane {x : x . n = delta}: signed distance
// dist = c . n - delta; they meet in the circle of centre c - dist n and
// radius sqrt(r^2 - dist^2), and touch at c - dist n when |dist| = r.
TYPED_TEST(C3gaGeometry, SpherePlaneMeet) {
  using T = TypeParam;
  auto rng = make_rng(506);
  int cut = 0, apart = 0;
  for (int i = 0; i < trials; ++i) {
    const vec3 c = random_vec3(rng, -3, 3), n = random_unit_vec3(rng);
    const double r = uniform(rng, 0.5, 2.0);
    const double dist = uniform(rng, -2.5, 2.5);
    const double delta = dot(c, n) - dist;
    const auto sphere = c3ga::dual(dual_sphere_of<T>(c, r));
    const auto plane = c3ga::dual(make_dual_plane<c3ga::basic_dual_plane<T>>(n, delta));
    const mv<T> circle = as_mv<mv<T>>(c3ga::meet(sphere, plane));
    const double t = double((circle * circle)[0]);
    const double scale = std::max({1.0, dot(c, c), r * r}) * std::max({1.0, dot(c, c), r * r});
    EXPECT_NEAR(t, r * r - dist * dist, tolerance<T>() * scale);
    if (std::abs(r * r - dist * dist) > 1e-2) {
      EXPECT_EQ(t > 0, std::abs(dist) < r);
      (std::abs(dist) < r ? cut : apart) += 1;
    }
    if (std::abs(dist) < r - 1e-2) {
      const mv<T> ni = as_mv<mv<T>>(c3ga::ni<T>());
      EXPECT_TRUE(
          points_near(euclidean_point<T>(circle * ni * circle), c - dist * n, tolerance<T>() * 10));
      const mv<T> nc = c3ga::lc(ni, circle);
      EXPECT_TRUE(scalar_near(-double((circle * circle)[0]) / double((nc * nc)[0]),
                              r * r - dist * dist, tolerance<T>() * 10));
    }
  }
  EXPECT_GT(cut, 0);
  EXPECT_GT(apart, 0);
}

TYPED_TEST(C3gaGeometry, SphereTouchingPlaneGivesTheContactPoint) {
  using T = TypeParam;
  auto rng = make_rng(507);
  for (int i = 0; i < trials; ++i) {
    const vec3 c = random_vec3(rng, -3, 3), n = random_unit_vec3(rng);
    const double r = uniform(rng, 0.5, 2.0);
    const double dist = i % 2 ? r : -r;
    const auto sphere = c3ga::dual(dual_sphere_of<T>(c, r));
    const auto plane = c3ga::dual(make_dual_plane<c3ga::basic_dual_plane<T>>(n, dot(c, n) - dist));
    const mv<T> circle = as_mv<mv<T>>(c3ga::meet(sphere, plane));
    const mv<T> ni = as_mv<mv<T>>(c3ga::ni<T>());
    const double scale = std::max({1.0, dot(c, c), r * r}) * std::max({1.0, dot(c, c), r * r});
    EXPECT_NEAR(double((circle * circle)[0]), 0, tolerance<T>() * scale);
    EXPECT_TRUE(
        points_near(euclidean_point<T>(circle * ni * circle), c - dist * n, tolerance<T>() * 10));
  }
}

}  // namespace c3ga_geometry_test
