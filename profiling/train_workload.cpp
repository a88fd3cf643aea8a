// The training workload of the profile-guided build, in two parts:
// - the engine's standard scenes (engine/scenes), run for a few simulated
//   seconds each: the dynamics' e3ga calls and the narrow phase's c3ga meets,
//   the calls an application of libgaphys really makes;
// - the benchmarks' work on the benchmarks' operands (bench/operands.hpp):
//   thesis table 5.1 (add, gp, lc, op, scp) on mv holding full multivectors,
//   vectors, 2-blades and versors, and the c3ga kernels (sphere through four
//   points, a motor on a point, the circle of two dual spheres) on mv, so the
//   tables of docs/benchmarks.md measure profiled code.
// Every call count is fixed (the engine is deterministic), so the profile is
// reproducible: tests/profiling checks that profiling/profiles/ is what this
// program records.
#include <c3ga/c3ga.hpp>
#include <e3ga/e3ga.hpp>
#include <gaphys/scenes.hpp>

#include <vector>

#include "operands.hpp"

namespace {

using namespace gaphys_bench;

constexpr int rounds = 10;  // passes over each pool

template <class Mv>
void table_5_1(const std::vector<Mv>& a, const std::vector<Mv>& b) {
  for (int round = 0; round < rounds; ++round) {
    for (std::size_t i = 0; i < a.size(); ++i) {
      const Mv& x = a[i];
      const Mv& y = b[(i + 1) % b.size()];
      (void)add(x, y);
      (void)gp(x, y);
      (void)lc(x, y);
      (void)op(x, y);
      (void)scp(x, y);
    }
  }
}

template <class Alg>
void table_5_1_all(rng& g) {
  const auto vector = [](rng& r) { return random_grade<Alg>(r, 1); };
  table_5_1(make_pool(g, random_full<Alg>), make_pool(g, random_full<Alg>));
  table_5_1(make_pool(g, vector), make_pool(g, vector));
  table_5_1(make_pool(g, random_2_blade<Alg>), make_pool(g, random_2_blade<Alg>));
  table_5_1(make_pool(g, Alg::random_versor), make_pool(g, Alg::random_versor));
}

void c3ga_kernels(rng& g) {
  using c3ga::mv;
  const auto points = make_pool(g, random_point);
  const auto motors = make_pool(g, random_motor);
  const auto spheres = make_pool(g, random_dual_sphere);
  for (int round = 0; round < rounds; ++round) {
    for (std::size_t i = 0; i < pool_size; ++i) {
      const mv p[4] = {points[i], points[(i + 1) % pool_size], points[(i + 2) % pool_size],
                       points[(i + 3) % pool_size]};
      (void)op(op(op(p[0], p[1]), p[2]), p[3]);
      (void)apply(mv(motors[i]), p[0]);
      (void)meet(dual(mv(spheres[i])), dual(mv(spheres[(i + 1) % pool_size])));
    }
  }
}

void run(gaphys::world world, double seconds) {
  const int steps = static_cast<int>(seconds / gaphys::scenes::time_step);
  for (int i = 0; i < steps; ++i) world.step(gaphys::scenes::time_step);
}

void engine_scenes() {
  namespace scenes = gaphys::scenes;
  run(scenes::falling_spheres_in_box(40), 1.5);
  run(scenes::falling_spheres_in_box(40, 2, 0.5), 1.5);  // with friction
  run(scenes::sphere_column(), 2);
  run(scenes::rolling_ramp(), 2);
  run(scenes::newtons_cradle(2), 0.5);
  run(scenes::elastic_collision(), 1.5);
  run(scenes::bouncing_sphere(0.8), 2);
  run(scenes::spinning_body(), 1);
  // Boxes, capsules, hulls and a compound: the manifolds' turning contacts.
  run(scenes::box_tower(4), 0.5);
  run(scenes::compound_table(), 1);
  run(scenes::shape_mix(12), 1);
}

}  // namespace

int main() {
  engine_scenes();
  rng g(seed);
  table_5_1_all<e3ga_algebra>(g);
  table_5_1_all<c3ga_algebra>(g);
  c3ga_kernels(g);
  return e3ga::flush_profile() && c3ga::flush_profile() ? 0 : 1;
}
