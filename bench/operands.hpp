// Operands shared by the benchmarks and the profiling workload: random
// multivectors, blades and versors of e3ga and c3ga, from a fixed seed, so
// that what is profiled is what is measured.
#pragma once

#include <c3ga/c3ga.hpp>
#include <e3ga/e3ga.hpp>

#include <cmath>
#include <cstddef>
#include <random>
#include <vector>

namespace gaphys_bench {

// Each benchmark iteration makes one call per pool entry. 32 entries of the
// largest argument (a c3ga mv, 264 bytes) keep two pools inside L1, and
// varying the inputs keeps the compiler from hoisting a call out of the loop.
inline constexpr std::size_t pool_size = 32;

// A fixed seed: every run and every variant sees the same inputs.
using rng = std::mt19937_64;
inline constexpr rng::result_type seed = 20240521;

inline double uniform(rng& g, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(g);
}

template <class Make>
auto make_pool(rng& g, Make make) {
  std::vector<decltype(make(g))> pool;
  pool.reserve(pool_size);
  for (std::size_t i = 0; i < pool_size; ++i) pool.push_back(make(g));
  return pool;
}

// An mv whose bits say exactly which coefficients are nonzero, as if the
// caller had built it from coordinates (products set every reachable bit).
template <class Mv>
Mv exact_bits(const Mv& x) {
  return Mv::from_array(x.to_array());
}

// Every coefficient uniform in [-1, 1].
template <class Alg>
typename Alg::mv random_full(rng& g) {
  auto a = typename Alg::mv{}.to_array();
  for (auto& x : a) x = uniform(g, -1, 1);
  return Alg::mv::from_array(a);
}

// Every grade-k coefficient uniform in [-1, 1], the others zero.
template <class Alg>
typename Alg::mv random_grade(rng& g, int k) {
  auto a = typename Alg::mv{}.to_array();
  for (std::size_t i = 0; i < a.size(); ++i)
    if (Alg::grade(i) == k) a[i] = uniform(g, -1, 1);
  return Alg::mv::from_array(a);
}

// A random 2-blade: the outer product of two random vectors.
template <class Alg>
typename Alg::mv random_2_blade(rng& g) {
  const auto u = random_grade<Alg>(g, 1);
  const auto v = random_grade<Alg>(g, 1);
  return exact_bits(op(u, v));
}

// Each algebra names the named types that hold the benchmarks' vectors,
// 2-blades and versors exactly, for the same operations on named types.
struct e3ga_algebra {
  using mv = e3ga::mv;
  using vector_type = e3ga::vector;
  using two_blade_type = e3ga::bivector;
  using versor_type = e3ga::rotor;
  static constexpr bool two_blades_wedge_to_zero = true;  // grade 4 in 3-D
  static constexpr const char* name = "e3ga";
  static constexpr const char* versor_name = "rotor";
  static int grade(std::size_t i) { return e3ga::blade_grades[i]; }
  // A unit rotor: the product of two unit vectors.
  static mv random_versor(rng& g) {
    const mv u = unit(random_grade<e3ga_algebra>(g, 1));
    const mv v = unit(random_grade<e3ga_algebra>(g, 1));
    return exact_bits(gp(u, v));
  }
};

struct c3ga_algebra {
  using mv = c3ga::mv;
  using vector_type = c3ga::dual_sphere;  // all five grade-1 coordinates
  using two_blade_type = c3ga::point_pair;  // all ten grade-2 coordinates
  using versor_type = c3ga::motor;
  static constexpr bool two_blades_wedge_to_zero = false;
  static constexpr const char* name = "c3ga";
  static constexpr const char* versor_name = "motor";
  static int grade(std::size_t i) { return c3ga::blade_grades[i]; }
  // A dual plane n + d ni with unit normal n: a reflection, squares to 1.
  static mv random_reflection(rng& g) {
    const c3ga::euclidean_vector n{uniform(g, -1, 1), uniform(g, -1, 1), uniform(g, -1, 1)};
    const double len = norm(n);
    return mv(c3ga::dual_plane{n.e1() / len, n.e2() / len, n.e3() / len, uniform(g, -1, 1)});
  }
  // A unit motor (screw motion): the product of four reflections.
  static mv random_versor(rng& g) {
    const mv a = gp(random_reflection(g), random_reflection(g));
    const mv b = gp(random_reflection(g), random_reflection(g));
    return exact_bits(gp(a, b));
  }
};

// ---- c3ga named-type operands ----

// p = no + x + x^2/2 ni, x uniform in the cube [-1, 1]^3.
inline c3ga::normalized_point random_point(rng& g) {
  const double x = uniform(g, -1, 1), y = uniform(g, -1, 1), z = uniform(g, -1, 1);
  return c3ga::normalized_point{x, y, z, 0.5 * (x * x + y * y + z * z)};
}

// sigma = c - r^2/2 ni: centre c a normalized point, radius r in [0.5, 1.5],
// so that spheres with centres in the unit cube mostly intersect.
inline c3ga::dual_sphere random_dual_sphere(rng& g) {
  const c3ga::normalized_point c = random_point(g);
  const double r = uniform(g, 0.5, 1.5);
  return c3ga::dual_sphere{1.0, c.e1(), c.e2(), c.e3(), c.ni() - 0.5 * r * r};
}

// M = T R, R = cos(phi/2) - sin(phi/2) B (B a unit Euclidean bivector) and
// T = 1 - t ni / 2 (t a Euclidean vector).
inline c3ga::motor random_motor(rng& g) {
  double b12 = uniform(g, -1, 1), b13 = uniform(g, -1, 1), b23 = uniform(g, -1, 1);
  const double len = std::sqrt(b12 * b12 + b13 * b13 + b23 * b23);
  b12 /= len;
  b13 /= len;
  b23 /= len;
  const double half_angle = uniform(g, -1.5, 1.5);
  const double s = std::sin(half_angle);
  const c3ga::rotor r{std::cos(half_angle), -s * b12, -s * b13, -s * b23};
  const c3ga::translator t{1.0, -0.5 * uniform(g, -1, 1), -0.5 * uniform(g, -1, 1),
                           -0.5 * uniform(g, -1, 1)};
  return c3ga::motor(c3ga::mv(gp(t, r)));
}

}  // namespace gaphys_bench
