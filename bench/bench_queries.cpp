// Ray casts per second against a scene of N bodies (spheres, boxes and
// capsules scattered in a cube, one per 8 m^3, and a floor), through the
// world's query grid and, for comparison, by testing every shape (what a
// query without a broad phase costs). Rays start at random points of the
// cube, in random directions, up to 100 m; one iteration is one ray. The
// index is built before timing (the first query builds it); its build,
// which a query pays once after the bodies move, is timed on its own.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

#include "gaphys/world.hpp"
#include "ray_shape.hpp"

namespace {

using gaphys::real;
using gaphys::vector;

struct ray {
  vector origin, direction;
};

class scene {
 public:
  explicit scene(int bodies) : half_(real(0.5) * std::cbrt(real(8) * bodies)) {
    gaphys::body_definition floor;
    floor.is_static = true;
    floor.shape = gaphys::shape::plane(vector{0, 0, 1}, -half_);
    world_.create_body(floor);
    for (int i = 0; i < bodies; ++i) {
      gaphys::body_definition d;
      d.position = point();
      d.attitude = e3ga::exp(uniform(-3, 3) * e3ga::dual(direction()));
      switch (i % 3) {
        case 0:
          d.shape = gaphys::shape::sphere(uniform(0.2, 0.5));
          break;
        case 1:
          d.shape =
              gaphys::shape::box(vector{uniform(0.1, 0.4), uniform(0.1, 0.4), uniform(0.1, 0.4)});
          break;
        default:
          d.shape = gaphys::shape::capsule(uniform(0, 0.4), uniform(0.1, 0.3));
      }
      world_.create_body(d);
    }
    for (int i = 0; i < 4096; ++i) rays_.push_back({point(), direction()});
  }

  gaphys::world& world() { return world_; }
  const ray& next_ray() { return rays_[next_++ % rays_.size()]; }

 private:
  real uniform(real low, real high) {
    return std::uniform_real_distribution<real>(low, high)(random_);
  }
  vector point() {
    return vector{uniform(-half_, half_), uniform(-half_, half_), uniform(-half_, half_)};
  }
  vector direction() {
    for (;;) {
      const vector v{uniform(-1, 1), uniform(-1, 1), uniform(-1, 1)};
      const real l = e3ga::norm(v);
      if (l > real(0.1) && l <= 1) return (1 / l) * v;
    }
  }

  real half_;
  std::mt19937_64 random_{7};
  gaphys::world world_;
  std::vector<ray> rays_;
  std::size_t next_ = 0;
};

constexpr real reach = 100;

void ray_cast_grid(benchmark::State& state) {
  scene s(static_cast<int>(state.range(0)));
  const gaphys::world& w = s.world();
  (void)w.ray_cast(vector{}, vector{1, 0, 0}, reach);  // builds the index
  std::int64_t hits = 0;
  for (auto _ : state) {
    const ray& r = s.next_ray();
    const auto hit = w.ray_cast(r.origin, r.direction, reach);
    hits += hit.has_value();
    benchmark::DoNotOptimize(hit);
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["hit_fraction"] =
      static_cast<double>(hits) / static_cast<double>(state.iterations());
}

void ray_cast_every_shape(benchmark::State& state) {
  scene s(static_cast<int>(state.range(0)));
  const gaphys::world& w = s.world();
  std::vector<gaphys::placed_shape> shapes;
  for (const gaphys::body& b : w.bodies()) {
    shapes.push_back(gaphys::place(*b.shape(), b.position(), b.attitude()));
  }
  std::int64_t hits = 0;
  for (auto _ : state) {
    const ray& r = s.next_ray();
    real best = reach;
    bool hit = false;
    for (const gaphys::placed_shape& shape : shapes) {
      if (const auto h = gaphys::detail::cast_ray(shape, r.origin, r.direction, best)) {
        best = h->distance;
        hit = true;
      }
    }
    hits += hit;
    benchmark::DoNotOptimize(best);
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["hit_fraction"] =
      static_cast<double>(hits) / static_cast<double>(state.iterations());
}

// The index rebuilt after a body moved, then one ray.
void query_index_build(benchmark::State& state) {
  scene s(static_cast<int>(state.range(0)));
  gaphys::world& w = s.world();
  for (auto _ : state) {
    w.at(1).set_position(w.bodies()[1].position());  // a pose setter: the index is out of date
    const ray& r = s.next_ray();
    benchmark::DoNotOptimize(w.ray_cast(r.origin, r.direction, reach));
  }
}

}  // namespace

BENCHMARK(ray_cast_grid)->Arg(100)->Arg(1000)->Arg(10000);
BENCHMARK(ray_cast_every_shape)->Arg(100)->Arg(1000)->Arg(10000);
BENCHMARK(query_index_build)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
