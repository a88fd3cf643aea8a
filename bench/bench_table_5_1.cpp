// Table 5.1 of the thesis (section 5.1.3) for gaphys: add, gp, lc, op and scp
// on the general multivector `mv`, in e3ga and c3ga. As in the thesis, the
// arguments are random full multivectors or random blades and versors (here
// stored in an mv, so every call goes through the general functions), and
// the same values in the named types that hold them (".../named": the
// straight-line kernels the spec asks for).
// Benchmark names are <algebra>/<function>/<arguments>; bench/print_table.py
// turns the JSON output into the table of docs/benchmarks.md.
#include <c3ga/c3ga.hpp>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
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

template <class X>
struct argument_kind {
  std::string name;
  std::vector<X> a, b;  // first and second arguments, drawn independently
};

template <class Call, class X>
void register_call(const std::string& algebra, const argument_kind<X>& kind) {
  register_benchmark(algebra + "/" + Call::name + "/" + kind.name,
                     [a = kind.a, b = kind.b](benchmark::State& state) {
                       run_over_pool(state, [&](std::size_t i) { return Call{}(a[i], b[i]); });
                     });
}

// The values of an mv pool in a named type that holds them exactly, so that a
// ".../named" row measures the same operands as its mv row.
template <class Named, class Mv>
std::vector<Named> as_named(const std::vector<Mv>& pool) {
  std::vector<Named> named;
  for (const Mv& x : pool) {
    const Named n(x);
    if (Mv(n).to_array() != x.to_array()) {
      std::fprintf(stderr, "bench_table_5_1: a named type does not hold its operand exactly\n");
      std::exit(1);
    }
    named.push_back(n);
  }
  return named;
}

template <class Named, class... Calls, class Mv>
void register_named(const std::string& algebra, const argument_kind<Mv>& kind) {
  const argument_kind<Named> named{kind.name + "/named", as_named<Named>(kind.a),
                                   as_named<Named>(kind.b)};
  (register_call<Calls>(algebra, named), ...);
}

template <class Alg>
void register_algebra() {
  using mv = typename Alg::mv;
  rng g(seed);
  const auto vector = [](rng& r) { return random_grade<Alg>(r, 1); };
  const argument_kind<mv> full{"mv", make_pool(g, random_full<Alg>),
                               make_pool(g, random_full<Alg>)};
  const argument_kind<mv> vectors{"vector", make_pool(g, vector), make_pool(g, vector)};
  const argument_kind<mv> blades{"bivector", make_pool(g, random_2_blade<Alg>),
                                 make_pool(g, random_2_blade<Alg>)};
  const argument_kind<mv> versors{Alg::versor_name, make_pool(g, Alg::random_versor),
                                  make_pool(g, Alg::random_versor)};
  for (const auto* kind : {&full, &vectors, &blades, &versors}) {
    register_call<add_call>(Alg::name, *kind);
    register_call<gp_call>(Alg::name, *kind);
    register_call<lc_call>(Alg::name, *kind);
    register_call<op_call>(Alg::name, *kind);
    register_call<scp_call>(Alg::name, *kind);
  }
  // The same operations on the named types (straight-line kernels from the
  // spec alone). The outer product of two e3ga bivectors is identically zero
  // (grade 4 in 3-D), so the spec has no kernel for it and the row is left out.
  register_named<typename Alg::vector_type, add_call, gp_call, lc_call, op_call, scp_call>(
      Alg::name, vectors);
  register_named<typename Alg::two_blade_type, add_call, gp_call, lc_call, scp_call>(Alg::name,
                                                                                     blades);
  if constexpr (!Alg::two_blades_wedge_to_zero)
    register_named<typename Alg::two_blade_type, op_call>(Alg::name, blades);
  register_named<typename Alg::versor_type, add_call, gp_call, lc_call, op_call, scp_call>(
      Alg::name, versors);
}

}  // namespace

int main(int argc, char** argv) {
  return gaphys_bench::run_main(argc, argv, [] {
    register_algebra<e3ga_algebra>();
    register_algebra<c3ga_algebra>();
  });
}
