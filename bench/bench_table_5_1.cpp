// Table 5.1 of the thesis (section 5.1.3) for gaphys: add, gp, lc, op and scp
// on the general multivector `mv`, in e3ga and c3ga. As in the thesis, the
// arguments are random full multivectors or random blades and versors (here
// stored in an mv, so every call goes through the general functions).
// Benchmark names are <algebra>/<function>/<arguments>; bench/print_table.py
// turns the JSON output into the README's table.
#include <c3ga/c3ga.hpp>
#include <cstddef>
#include <e3ga/e3ga.hpp>
#include <string>
#include <vector>

#include "bench_common.hpp"
#include "operands.hpp"

namespace {

using namespace gaphys_bench;

// The five functions of table 5.1. Unqualified calls find the algebra's
// functions by argument-dependent lookup.
struct add_call {
  static constexpr const char* name = "add";
  template <class A, class B>
  auto operator()(const A& a, const B& b) const {
    return add(a, b);
  }
};
struct gp_call {
  static constexpr const char* name = "gp";
  template <class A, class B>
  auto operator()(const A& a, const B& b) const {
    return gp(a, b);
  }
};
struct lc_call {
  static constexpr const char* name = "lc";
  template <class A, class B>
  auto operator()(const A& a, const B& b) const {
    return lc(a, b);
  }
};
struct op_call {
  static constexpr const char* name = "op";
  template <class A, class B>
  auto operator()(const A& a, const B& b) const {
    return op(a, b);
  }
};
struct scp_call {
  static constexpr const char* name = "scp";
  template <class A, class B>
  auto operator()(const A& a, const B& b) const {
    return scp(a, b);
  }
};

template <class Mv>
struct argument_kind {
  std::string name;
  std::vector<Mv> a, b;  // first and second arguments, drawn independently
};

template <class Call, class Mv>
void register_call(const std::string& algebra, const argument_kind<Mv>& kind) {
  register_benchmark(algebra + "/" + Call::name + "/" + kind.name,
                     [a = kind.a, b = kind.b](benchmark::State& state) {
                       run_over_pool(state, [&](std::size_t i) { return Call{}(a[i], b[i]); });
                     });
}

template <class Alg>
void register_algebra() {
  using mv = typename Alg::mv;
  rng g(seed);
  const auto vector = [](rng& r) { return random_grade<Alg>(r, 1); };
  const std::vector<argument_kind<mv>> kinds = {
      {"mv", make_pool(g, random_full<Alg>), make_pool(g, random_full<Alg>)},
      {"vector", make_pool(g, vector), make_pool(g, vector)},
      {"bivector", make_pool(g, random_2_blade<Alg>), make_pool(g, random_2_blade<Alg>)},
      {Alg::versor_name, make_pool(g, Alg::random_versor), make_pool(g, Alg::random_versor)},
  };
  for (const auto& kind : kinds) {
    register_call<add_call>(Alg::name, kind);
    register_call<gp_call>(Alg::name, kind);
    register_call<lc_call>(Alg::name, kind);
    register_call<op_call>(Alg::name, kind);
    register_call<scp_call>(Alg::name, kind);
  }
}

}  // namespace

int main(int argc, char** argv) {
  return gaphys_bench::run_main(argc, argv, [] {
    register_algebra<e3ga_algebra>();
    register_algebra<c3ga_algebra>();
  });
}
