// c3ga kernels on named types that the engine's geometry relies on:
//   op4_points         p1 ^ p2 ^ p3 ^ p4, the sphere through four points
//   apply_motor_point  apply(motor, normalized_point), moving a point
//   meet_dual_spheres  meet(dual(s1), dual(s2)) of two dual spheres: their circle
//                      (meet of the dual spheres themselves is identically zero:
//                      it wedges two grade-4 duals in a 5-D algebra)
// Each runs twice: on the named types (".../named") and on the same values
// widened to mv (".../mv"), which shows what the named types buy per variant.
#include <c3ga/c3ga.hpp>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "bench_common.hpp"

namespace {

using namespace gaphys_bench;

// p = no + x + x^2/2 ni, x uniform in the cube [-1, 1]^3.
c3ga::normalized_point random_point(rng& g) {
  const double x = uniform(g, -1, 1), y = uniform(g, -1, 1), z = uniform(g, -1, 1);
  return c3ga::normalized_point{x, y, z, 0.5 * (x * x + y * y + z * z)};
}

// sigma = c - r^2/2 ni: centre c a normalized point, radius r in [0.5, 1.5],
// so that spheres with centres in the unit cube mostly intersect.
c3ga::dual_sphere random_dual_sphere(rng& g) {
  const c3ga::normalized_point c = random_point(g);
  const double r = uniform(g, 0.5, 1.5);
  return c3ga::dual_sphere{1.0, c.e1(), c.e2(), c.e3(), c.ni() - 0.5 * r * r};
}

// M = T R, R = cos(phi/2) - sin(phi/2) B (B a unit Euclidean bivector) and
// T = 1 - t ni / 2 (t a Euclidean vector).
c3ga::motor random_motor(rng& g) {
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

template <class T>
std::vector<c3ga::mv> widen(const std::vector<T>& pool) {
  return std::vector<c3ga::mv>(pool.begin(), pool.end());
}

template <class P>
void register_op4_points(const std::string& name, std::vector<P> p) {
  register_benchmark(name, [p = std::move(p)](benchmark::State& state) {
    run_over_pool(state, [&](std::size_t i) {
      return op(op(op(p[i], p[next(i, 1)]), p[next(i, 2)]), p[next(i, 3)]);
    });
  });
}

template <class M, class P>
void register_apply(const std::string& name, std::vector<M> m, std::vector<P> p) {
  register_benchmark(name, [m = std::move(m), p = std::move(p)](benchmark::State& state) {
    run_over_pool(state, [&](std::size_t i) { return apply(m[i], p[i]); });
  });
}

template <class S>
void register_meet(const std::string& name, std::vector<S> s) {
  register_benchmark(name, [s = std::move(s)](benchmark::State& state) {
    run_over_pool(state, [&](std::size_t i) { return meet(dual(s[i]), dual(s[next(i, 1)])); });
  });
}

void register_all() {
  rng g(seed);
  const auto points = make_pool(g, random_point);
  const auto motors = make_pool(g, random_motor);
  const auto spheres = make_pool(g, random_dual_sphere);
  register_op4_points("c3ga/op4_points/named", points);
  register_op4_points("c3ga/op4_points/mv", widen(points));
  register_apply("c3ga/apply_motor_point/named", motors, points);
  register_apply("c3ga/apply_motor_point/mv", widen(motors), widen(points));
  register_meet("c3ga/meet_dual_spheres/named", spheres);
  register_meet("c3ga/meet_dual_spheres/mv", widen(spheres));
}

}  // namespace

int main(int argc, char** argv) { return gaphys_bench::run_main(argc, argv, register_all); }
