// Batches (c3ga/batch.hpp) against the scalar kernels, per element, on the
// two functions issue 18 names:
//   apply_motor_point  apply(motor, normalized_point)
//   meet_dual_spheres  undual(op(σ1, σ2)), the circle two dual spheres meet in
// Each runs as
//   scalar            one call per element
//   batch<W>/packed   one call per W elements held as batches (structure of
//                     arrays: what a batch-minded data layout pays)
//   batch<W>/gathered W elements gathered from arrays of named values into a
//                     batch and the results written back lane by lane (what
//                     an engine keeping arrays of structures pays)
// for W = 4 and W = the target's native lanes (2 doubles for SSE2, 4 for AVX2:
// build with -march=native for the latter). Items are elements; compare
// items_per_second within one run.
#include <c3ga/batch.hpp>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "bench_common.hpp"

namespace {

using namespace gaphys_bench;

// (Both forced inline: left to itself GCC inlined the scalar calls and
// called the batch of 8 lanes out of line, its result through memory.)
struct apply_motor_point {
  template <class M, class P>
  GAPHYS_ALWAYS_INLINE auto operator()(const M& motor, const P& point) const {
    return c3ga::apply(motor, point);
  }
};

struct meet_dual_spheres {
  template <class S>
  GAPHYS_ALWAYS_INLINE auto operator()(const S& a, const S& b) const {
    return c3ga::undual(c3ga::op(a, b));
  }
};

template <class F, class A, class B>
void register_scalar(const std::string& name, std::vector<A> a, std::vector<B> b) {
  register_benchmark(name, [a = std::move(a), b = std::move(b)](benchmark::State& state) {
    for (auto _ : state) {
      for (std::size_t i = 0; i < pool_size; ++i) {
        auto r = F{}(a[i], b[i]);
        benchmark::DoNotOptimize(r);
      }
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * pool_size));
  });
}

template <int W, class X>
std::vector<c3ga::batch_of_t<X, W>> packed(const std::vector<X>& values) {
  std::vector<c3ga::batch_of_t<X, W>> batches;
  for (std::size_t i = 0; i + W <= values.size(); i += W) {
    batches.push_back(c3ga::gather<W>([&](int k) { return values[i + static_cast<std::size_t>(k)]; }));
  }
  return batches;
}

template <class F, int W, class A, class B>
void register_packed(const std::string& name, const std::vector<A>& a, const std::vector<B>& b) {
  register_benchmark(name, [a = packed<W>(a), b = packed<W>(b)](benchmark::State& state) {
    for (auto _ : state) {
      for (std::size_t i = 0; i < a.size(); ++i) {
        auto r = F{}(a[i], b[i]);
        benchmark::DoNotOptimize(r);
      }
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * a.size() * W));
  });
}

template <class F, int W, class A, class B>
void register_gathered(const std::string& name, std::vector<A> a, std::vector<B> b) {
  using result = decltype(F{}(a[0], b[0]));
  register_benchmark(name, [a = std::move(a), b = std::move(b)](benchmark::State& state) {
    std::vector<result> out(pool_size);
    for (auto _ : state) {
      for (std::size_t i = 0; i + W <= pool_size; i += W) {
        const auto x = c3ga::gather<W>([&](int k) { return a[i + static_cast<std::size_t>(k)]; });
        const auto y = c3ga::gather<W>([&](int k) { return b[i + static_cast<std::size_t>(k)]; });
        const auto r = F{}(x, y);
        for (int k = 0; k < W; ++k) out[i + static_cast<std::size_t>(k)] = c3ga::lane(r, k);
      }
      benchmark::DoNotOptimize(out.data());
      benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * (pool_size / W * W)));
  });
}

template <class F, int W, class A, class B>
void register_batches(const std::string& name, const std::vector<A>& a, const std::vector<B>& b) {
  const std::string width = "/batch" + std::to_string(W);
  register_packed<F, W>(name + width + "/packed", a, b);
  register_gathered<F, W>(name + width + "/gathered", a, b);
}

template <class F, class A, class B>
void register_function(const std::string& name, const std::vector<A>& a, const std::vector<B>& b) {
  register_scalar<F>(name + "/scalar", a, b);
  register_batches<F, 4>(name, a, b);
  if constexpr (c3ga::native_lanes != 4) register_batches<F, c3ga::native_lanes>(name, a, b);
}

void register_all() {
  rng g(seed);
  const auto points = make_pool(g, random_point);
  const auto motors = make_pool(g, random_motor);
  const auto spheres = make_pool(g, random_dual_sphere);
  std::vector<c3ga::dual_sphere> others(spheres.size());
  for (std::size_t i = 0; i < spheres.size(); ++i) others[i] = spheres[next(i, 1)];
  register_function<apply_motor_point>("c3ga/apply_motor_point", motors, points);
  register_function<meet_dual_spheres>("c3ga/meet_dual_spheres", spheres, others);
}

}  // namespace

int main(int argc, char** argv) { return gaphys_bench::run_main(argc, argv, register_all); }
