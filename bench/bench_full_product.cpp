// The geometric product of two full multivectors (every coefficient nonzero)
// three ways, in one run (issue 16: "the full 32 x 32 c3ga product through
// mv takes 153 ns against 44.5 ns for a hand-expanded product"):
//   <algebra>/gp_full/mv             gp(a, b) on mv: what a user calls (in the
//                                    optimized variant, a profiled kernel if
//                                    the profile saw full products)
//   <algebra>/gp_full/table_product  the generic path every variant falls back
//                                    to, called directly
//   <algebra>/gp_full/hand           the hand-expanded product of
//                                    bench/full_product_kernels.hpp (896
//                                    products in c3ga), the yardstick
// Before timing, all three are checked to agree on every pool entry.
// docs/benchmarks.md ("The full product against a hand-expanded one") quotes
// a run.
#include <array>
#include <c3ga/c3ga.hpp>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <e3ga/e3ga.hpp>
#include <string>
#include <vector>

#include "bench_common.hpp"
#include "full_product_kernels.hpp"
#include "operands.hpp"

namespace {

using namespace gaphys_bench;

struct e3ga_full {
  using algebra = e3ga_algebra;
  static e3ga::mv table(const e3ga::mv& a, const e3ga::mv& b) {
    return gaphys::ga::table_product(e3ga::detail::gp_table, a, b);
  }
  static e3ga::mv hand(const e3ga::mv& a, const e3ga::mv& b) {
    e3ga::mv r(gaphys::ga::uninitialized);
    hand::e3ga_full_gp(a.c.data(), b.c.data(), r.c.data());
    r.bits = 0xffu;
    return r;
  }
};

struct c3ga_full {
  using algebra = c3ga_algebra;
  static c3ga::mv table(const c3ga::mv& a, const c3ga::mv& b) {
    return gaphys::ga::table_product(c3ga::detail::gp_table, a, b);
  }
  static c3ga::mv hand(const c3ga::mv& a, const c3ga::mv& b) {
    c3ga::mv r(gaphys::ga::uninitialized);
    hand::c3ga_full_gp(a.c.data(), b.c.data(), r.c.data());
    r.bits = 0xffffffffu;
    return r;
  }
};

// Exits unless x and y agree to rounding (relative to the operands' scale:
// each coefficient is a sum of at most 64 products of numbers in [-1, 1]).
template <class Mv>
void check_agree(const char* what, const Mv& x, const Mv& y) {
  for (std::size_t k = 0; k < x.c.size(); ++k) {
    if (std::abs(x.c[k] - y.c[k]) > 1e-13) {
      std::fprintf(stderr, "bench_full_product: %s differs at blade %zu: %.17g against %.17g\n",
                   what, k, x.c[k], y.c[k]);
      std::exit(1);
    }
  }
}

template <class Full>
void register_algebra() {
  using Alg = typename Full::algebra;
  rng g(seed);
  const auto a = make_pool(g, random_full<Alg>);
  const auto b = make_pool(g, random_full<Alg>);
  for (std::size_t i = 0; i < pool_size; ++i) {
    const auto library = gp(a[i], b[i]);
    check_agree("hand-expanded gp against gp on mv", Full::hand(a[i], b[i]), library);
    check_agree("table_product against gp on mv", Full::table(a[i], b[i]), library);
  }
  const std::string prefix = std::string(Alg::name) + "/gp_full/";
  register_benchmark(prefix + "mv", [a, b](benchmark::State& state) {
    run_over_pool(state, [&](std::size_t i) { return gp(a[i], b[i]); });
  });
  register_benchmark(prefix + "table_product", [a, b](benchmark::State& state) {
    run_over_pool(state, [&](std::size_t i) { return Full::table(a[i], b[i]); });
  });
  register_benchmark(prefix + "hand", [a, b](benchmark::State& state) {
    run_over_pool(state, [&](std::size_t i) { return Full::hand(a[i], b[i]); });
  });
}

}  // namespace

int main(int argc, char** argv) {
  return gaphys_bench::run_main(argc, argv, [] {
    register_algebra<e3ga_full>();
    register_algebra<c3ga_full>();
  });
}
