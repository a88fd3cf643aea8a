// c3ga kernels on named types that the engine's geometry relies on:
//   op4_points         p1 ^ p2 ^ p3 ^ p4, the sphere through four points
//   apply_motor_point  apply(motor, normalized_point), moving a point
//   apply_motor_points one motor moving an array of 16 points in a loop, in float
//                      and double: whether the kernel inlines into a user's loop
//                      (issue 16: a call per point ran 3.8x as long as the
//                      inlined, vectorized loop)
//   lc_point_sphere    lc(normalized_point, sphere), a product the spec does not
//                      declare (issue 16: it took the mv path, 14.6x slower than
//                      a kernel; every pair of named types now has one)
//   meet_dual_spheres  meet(dual(s1), dual(s2)) of two dual spheres: their circle
//                      (meet of the dual spheres themselves is identically zero:
//                      it wedges two grade-4 duals in a 5-D algebra)
// Each runs twice: on the named types (".../named") and on the same values
// widened to mv (".../mv"), which shows what the named types buy per variant.
#include <array>
#include <c3ga/c3ga.hpp>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "bench_common.hpp"

namespace {

using namespace gaphys_bench;

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

// The same named value in another scalar type.
template <class To, class From>
To with_scalar(const From& x) {
  To r;
  for (std::size_t i = 0; i < r.c.size(); ++i)
    r.c[i] = static_cast<typename To::scalar_type>(x.c[i]);
  return r;
}

// Per point: items are points moved. The loop is the user's, as in an engine
// moving a body's vertices; the results go to memory the benchmark keeps.
template <class T>
void register_apply_loop(const std::string& name, const std::vector<c3ga::motor>& motors,
                         const std::vector<c3ga::normalized_point>& points) {
  constexpr std::size_t count = 16;
  std::vector<c3ga::basic_motor<T>> m;
  for (const auto& x : motors) m.push_back(with_scalar<c3ga::basic_motor<T>>(x));
  std::vector<c3ga::basic_normalized_point<T>> p;
  for (std::size_t i = 0; i < count; ++i)
    p.push_back(with_scalar<c3ga::basic_normalized_point<T>>(points[i]));
  register_benchmark(name, [m = std::move(m), p = std::move(p)](benchmark::State& state) {
    std::array<c3ga::basic_normalized_point<T>, count> out;
    std::size_t k = 0;
    for (auto _ : state) {
      const c3ga::basic_motor<T>& motor = m[k];
      k = next(k, 1);
      for (std::size_t i = 0; i < count; ++i) out[i] = apply(motor, p[i]);
      benchmark::DoNotOptimize(out.data());
      benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * count));
  });
}

template <class P, class S>
void register_lc(const std::string& name, std::vector<P> p, std::vector<S> s) {
  register_benchmark(name, [p = std::move(p), s = std::move(s)](benchmark::State& state) {
    run_over_pool(state, [&](std::size_t i) { return lc(p[i], s[next(i, 1)]); });
  });
}

template <class S>
void register_meet(const std::string& name, std::vector<S> s) {
  register_benchmark(name, [s = std::move(s)](benchmark::State& state) {
    run_over_pool(state, [&](std::size_t i) { return meet(dual(s[i]), dual(s[next(i, 1)])); });
  });
}

// The cost of dispatch when it misses: gp on bitmaps no profile contains
// (a flat point times a translation-like bivector plus a scalar), so the
// optimized variant searches its switch and then takes the generic path.
// Optimized minus reference is the dispatch cost.
c3ga::mv unprofiled_operand(rng& g, std::uint32_t bits) {
  auto c = c3ga::mv{}.to_array();
  for (std::size_t i = 0; i < c.size(); ++i)
    if (bits >> i & 1) c[i] = uniform(g, -1, 1);
  return c3ga::mv::from_array(c);
}

void register_unprofiled_gp(const std::string& name, rng& g) {
  constexpr std::uint32_t flat_point =
      (1u << 12) | (1u << 14) | (1u << 15) | (1u << 9);  // e_i^ni, no^ni
  constexpr std::uint32_t scalar_and_e1 = 1u | (1u << 2);
  const auto a = make_pool(g, [&](rng& r) { return unprofiled_operand(r, flat_point); });
  const auto b = make_pool(g, [&](rng& r) { return unprofiled_operand(r, scalar_and_e1); });
  register_benchmark(name, [a, b](benchmark::State& state) {
    run_over_pool(state, [&](std::size_t i) { return gp(a[i], b[next(i, 1)]); });
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
  register_apply_loop<float>("c3ga/apply_motor_points/float", motors, points);
  register_apply_loop<double>("c3ga/apply_motor_points/double", motors, points);
  std::vector<c3ga::sphere> direct_spheres;
  for (const auto& s : spheres) direct_spheres.push_back(c3ga::dual(s));
  register_lc("c3ga/lc_point_sphere/named", points, direct_spheres);
  register_lc("c3ga/lc_point_sphere/mv", widen(points), widen(direct_spheres));
  register_meet("c3ga/meet_dual_spheres/named", spheres);
  register_meet("c3ga/meet_dual_spheres/mv", widen(spheres));
  register_unprofiled_gp("c3ga/gp_unprofiled/mv", g);
}

}  // namespace

int main(int argc, char** argv) { return gaphys_bench::run_main(argc, argv, register_all); }
