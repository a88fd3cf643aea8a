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

namespace {

using namespace gaphys_bench;

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

struct e3ga_algebra {
  using mv = e3ga::mv;
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
