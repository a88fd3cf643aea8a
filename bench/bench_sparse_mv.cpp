// Algebras of more than 5 basis vectors, whose general mv is sparse (a list
// of terms multiplied bitwise in an orthogonal basis: gaphys/ga/sparse_mv.hpp):
// what a named-type kernel costs next to the same values through mv, in the
// 4-D conformal algebra c4ga (6 basis vectors, 64 blades) and the conic
// algebra ccga (8, 256 blades). Optimized variant.
//   c4ga/gp_point_point     gp of two normalized points (a scalar and a bivector)
//   c4ga/apply_rotor_point  a 4-D rotation of a point
//   c4ga/meet_spheres       meet of two spheres (grade 5): their intersection
//   c4ga/gp_full            gp of two mv with all 64 coefficients (mv only)
//   ccga/scp_point_conic    a conic's polynomial at a point
#include <c4ga/c4ga.hpp>
#include <ccga/ccga.hpp>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "bench_common.hpp"

namespace {

using namespace gaphys_bench;

template <class MV, class T>
std::vector<MV> widen(const std::vector<T>& pool) {
  return std::vector<MV>(pool.begin(), pool.end());
}

c4ga::normalized_point random_c4ga_point(rng& g) {
  const double x[4] = {uniform(g, -2, 2), uniform(g, -2, 2), uniform(g, -2, 2), uniform(g, -2, 2)};
  const double half_square = (x[0] * x[0] + x[1] * x[1] + x[2] * x[2] + x[3] * x[3]) / 2;
  return {x[0], x[1], x[2], x[3], half_square};
}

c4ga::rotor random_c4ga_rotor(rng& g) {
  const c4ga::euclidean_bivector b{uniform(g, -1, 1), uniform(g, -1, 1), uniform(g, -1, 1),
                                   uniform(g, -1, 1), uniform(g, -1, 1), uniform(g, -1, 1)};
  return c4ga::rotor(c4ga::exp(c4ga::mv(b)));
}

c4ga::sphere random_c4ga_sphere(rng& g) {
  return c4ga::sphere(c4ga::op(
      c4ga::op(c4ga::op(c4ga::op(random_c4ga_point(g), random_c4ga_point(g)), random_c4ga_point(g)),
               random_c4ga_point(g)),
      random_c4ga_point(g)));
}

c4ga::mv random_full_c4ga(rng& g) {
  c4ga::mv m;
  for (int i = 0; i < c4ga::blade_count; ++i) m = m + c4ga::mv::basis_blade(i, uniform(g, -1, 1));
  return m;
}

ccga::point random_ccga_point(rng& g) {
  const double x = uniform(g, -2, 2), y = uniform(g, -2, 2);
  return {x, y, (x * x + y * y) / 2, (x * x - y * y) / 2, x * y};
}

ccga::dual_conic random_conic(rng& g) {
  return {uniform(g, -1, 1), uniform(g, -1, 1), uniform(g, -1, 1),
          uniform(g, -1, 1), uniform(g, -1, 1), uniform(g, -1, 1)};
}

template <class A, class B, class F>
void register_pair(const std::string& name, std::vector<A> a, std::vector<B> b, F f) {
  register_benchmark(name, [a = std::move(a), b = std::move(b), f](benchmark::State& state) {
    run_over_pool(state, [&](std::size_t i) { return f(a[i], b[next(i, 1)]); });
  });
}

// Registers name/named on the pools and name/mv on the same values in mv.
template <class MV, class A, class B, class F>
void register_both(const std::string& name, const std::vector<A>& a, const std::vector<B>& b, F f) {
  register_pair(name + "/named", a, b, f);
  register_pair(name + "/mv", widen<MV>(a), widen<MV>(b), f);
}

void register_all() {
  rng g(seed);
  const auto points = make_pool(g, random_c4ga_point);
  const auto rotors = make_pool(g, random_c4ga_rotor);
  const auto spheres = make_pool(g, random_c4ga_sphere);
  const auto full = make_pool(g, random_full_c4ga);
  const auto conic_points = make_pool(g, random_ccga_point);
  const auto conics = make_pool(g, random_conic);
  register_both<c4ga::mv>("c4ga/gp_point_point", points, points,
                          [](const auto& a, const auto& b) { return gp(a, b); });
  register_both<c4ga::mv>("c4ga/apply_rotor_point", rotors, points,
                          [](const auto& a, const auto& b) { return apply(a, b); });
  register_both<c4ga::mv>("c4ga/meet_spheres", spheres, spheres,
                          [](const auto& a, const auto& b) { return meet(a, b); });
  register_pair("c4ga/gp_full/mv", full, full,
                [](const auto& a, const auto& b) { return gp(a, b); });
  register_both<ccga::mv>("ccga/scp_point_conic", conic_points, conics,
                          [](const auto& a, const auto& b) { return scp(a, b); });
}

}  // namespace

int main(int argc, char** argv) { return run_main(argc, argv, register_all); }
